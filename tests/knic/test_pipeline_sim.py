"""The whole inference pipeline on the real simulator: camera frame -> LLKU -> CKU -> facts agreeing with the
simulator's ground truth."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from core.robot import NavState
from knic.bus import Message
from knic.pipeline import Pipeline, build_pipeline
from knic.scheduler import Scheduler
from knic.seed import seed_kb_from_world
from knic.units import CKU, LLKU
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from tests.knic.synthetic import DOMAIN
from worlds.api import NoiseConfig
from worlds.model import World
from worlds.simulation import Simulation


@pytest.fixture()
def sim(paper_world: World) -> Iterator[Simulation]:
    simulation = Simulation(paper_world, seed=3, noise=NoiseConfig())
    yield simulation
    simulation.close()


def drive_to(sim: Simulation, scheduler: Scheduler, room: str, limit_s: float = 60.0) -> None:
    sim.navigate_to_room(room)
    end = sim.time + limit_s
    while sim.nav_status().state is NavState.ACTIVE and sim.time < end:
        sim.step(0.1)
        scheduler.tick(sim.time)
    assert sim.nav_status().state is NavState.SUCCEEDED


def test_camera_to_facts_agree_with_ground_truth(sim: Simulation, paper_world: World) -> None:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: sim.time)
    seed_kb_from_world(kb, paper_world)
    pipeline: Pipeline = build_pipeline(kb, sim, paper_world, role="companion")
    units: dict[str, object] = {}

    def record(message: Message) -> None:
        unit = message.payload
        if isinstance(unit, LLKU | CKU):
            units[unit.uid] = unit

    pipeline.bus.subscribe("percept.vision", record)
    pipeline.bus.subscribe("cognition.object", record)
    scheduler = Scheduler(real_time_factor=1.0)
    for component in pipeline:
        scheduler.add(component)
    assert kb.holds("possibly_at", "glasses", "entrance")

    drive_to(sim, scheduler, "entrance")
    for _ in range(20):  # settle: two seconds in the entrance
        sim.step(0.1)
        scheduler.tick(sim.time)

    truth = sim.ground_truth_facts()
    for fact in (("robot_at", "r2d2", "entrance"), ("object_at", "glasses", "entrance")):
        assert fact in truth
        assert kb.holds(*fact)
    assert ("object_on", "glasses", "entrance_shelf") in truth and kb.holds(
        "object_on", "glasses", "entrance_shelf"
    )
    assert kb.holds("found", "glasses") and not kb.facts("possibly_at", "glasses")
    why = kb.why(Fact("object_at", ("glasses", "entrance")))
    assert why is not None and why.status is BeliefStatus.OBSERVED and why.source == "kp'.object_at"
    # provenance chain: the fact cites the CKU, the CKU cites the camera LLKU
    cku = units[why.support[0]]
    assert isinstance(cku, CKU) and cku.symbol == "glasses"
    llku = units[cku.support[0]]
    assert isinstance(llku, LLKU) and llku.source == "kp.camera_objects" and llku.label == "glasses"
    # nothing believed observed contradicts the ground truth
    observed = {
        (f.predicate, *f.args)
        for f in kb.facts()
        if f.predicate in ("robot_at", "object_at", "object_on", "person_at")
        and (w := kb.why(f)) is not None
        and w.status is BeliefStatus.OBSERVED
    }
    assert observed <= truth
