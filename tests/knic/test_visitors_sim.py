"""A person the robot does not know beforehand is met in the simulator and becomes a new instance."""

from __future__ import annotations

from dataclasses import replace

from core.robot import NavState
from knic.pipeline import build_pipeline
from knic.scheduler import Scheduler
from knic.seed import seed_kb_from_world
from knic.units import LLKU, Kind
from knowledge_base import KnowledgeBase
from tests.knic.synthetic import DOMAIN
from worlds.api import NoiseConfig
from worlds.model import World
from worlds.simulation import Simulation


def test_a_stranger_met_in_the_bedroom_becomes_visitor_1(paper_world: World) -> None:
    annie = replace(paper_world.people["annie"], known=False)
    world = replace(paper_world, people={**paper_world.people, "annie": annie})
    sim = Simulation(world, seed=3, noise=NoiseConfig())
    try:
        kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: sim.time)
        seed_kb_from_world(kb, world)
        assert kb.type_of("annie") is None  # not preloaded: the robot has never met her
        pipeline = build_pipeline(kb, sim, world, role="companion")
        people: list[LLKU] = []
        pipeline.bus.subscribe(
            "percept.vision",
            lambda m: (
                people.append(m.payload)
                if isinstance(m.payload, LLKU) and m.payload.kind is Kind.PERSON
                else None
            ),
        )
        scheduler = Scheduler(real_time_factor=1.0)
        for component in pipeline:
            scheduler.add(component)
        sim.navigate_to_room("bedroom")
        end = sim.time + 60.0
        while sim.nav_status().state is NavState.ACTIVE and sim.time < end:
            sim.step(0.1)
            scheduler.tick(sim.time)
        for _ in range(60):  # six seconds looking at her
            sim.step(0.1)
            scheduler.tick(sim.time)
        assert kb.type_of("visitor_1") == "person"
        assert kb.holds("person_at", "visitor_1", "bedroom")
        assert kb.type_of("annie") is None and kb.type_of("visitor_2") is None
        # the recogniser saw her and never named her
        assert people and all(unit.identity is None for unit in people)
    finally:
        sim.close()
