"""The places of the map travel as units: locations KP (LLKU) -> KGM-2 (CKU with the octomap) -> the KP'.

Nothing hands the map to KGM-2 or to the KP': what they know of rooms and furniture is what the location
stream brought them, and every location CKU published has readers.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from knic.bus import Message
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm3.base import KPPrime
from knic.pipeline import build_pipeline
from knic.scheduler import Scheduler
from knic.seed import seed_kb_from_world
from knic.spatial import FURNITURE, ROOM, Location
from knic.units import CKU, Kind
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from tests.knic.synthetic import DOMAIN
from worlds.api import NoiseConfig
from worlds.model import World
from worlds.simulation import Simulation

#: the KP' that place things in rooms or on furniture
PLACE_READERS = ("kp'.robot_at", "kp'.object_at", "kp'.person_at", "kp'.sound_at", "kp'.explored")


@pytest.fixture()
def sim(paper_world: World) -> Iterator[Simulation]:
    simulation = Simulation(paper_world, seed=3, noise=NoiseConfig())
    yield simulation
    simulation.close()


def test_rooms_and_furniture_reach_the_kp_prime_through_the_location_ckus(
    sim: Simulation, paper_world: World
) -> None:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: sim.time)
    seed_kb_from_world(kb, paper_world)
    pipeline = build_pipeline(kb, sim, paper_world, role="companion")
    ckus: list[CKU] = []

    def record(message: Message) -> None:
        ckus.append(message.payload)

    pipeline.bus.subscribe("cognition.location", record)
    readers = [kp for kp in pipeline if isinstance(kp, KPPrime) and kp.name in PLACE_READERS]
    assert len(readers) == len(PLACE_READERS) and all(len(kp.locations) == 0 for kp in readers)
    assert len(pipeline.cognition.locations) == 0

    scheduler = Scheduler(real_time_factor=1.0)
    for component in pipeline:
        scheduler.add(component)
    scheduler.tick(0.0)

    # one location CKU per room and piece of furniture, carrying its place and (with a volume) its octomap
    names = [c.symbol for c in ckus]
    assert names == [*paper_world.rooms, *paper_world.furniture]
    for cku in ckus:
        place = cku.attributes["location"]
        assert isinstance(place, Location) and cku.kind is Kind.LOCATION and cku.cls == place.cls
        assert (cku.octomap is None) == (place.volume is None)
    rooms = [c for c in ckus if c.cls == ROOM]
    assert all(c.octomap is not None and c.octomap.getNumLeafNodes() > 0 for c in rooms)
    surfaces = {c.symbol for c in ckus if c.cls == FURNITURE and c.octomap is not None}
    assert surfaces == {f.name for f in paper_world.furniture.values() if f.surface}

    # every reader learnt the same places from the stream, none was handed the map KGM-1 read
    holders: list[CognitiveLayer | KPPrime] = [pipeline.cognition, *readers]
    for kp in holders:
        model = kp.locations
        assert model is not pipeline.locations
        assert model.rooms.names() == list(paper_world.rooms)
        assert model.furniture.names() == pipeline.locations.furniture.names()
        assert model.furniture_room == pipeline.locations.furniture_room
        for cku in rooms:
            assert model.rooms.prisms[cku.symbol] is cku.attributes["location"].volume
    # and they use it: the robot's start room is believed from the pose CKU and the room octomaps
    why = kb.why(Fact("robot_at", (paper_world.robot.name, "bedroom")))
    assert why is not None and why.source == "kp'.robot_at" and why.status is BeliefStatus.OBSERVED
