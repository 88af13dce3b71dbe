"""The perception the actions steer by: a belief an action refuted is retracted by the place KP'."""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm3.people import PersonPlaceKP
from knic.kgm3.places import ObjectPlaceKP
from knic.kgm3.sightings import REFUTED_SOURCE, BusPerception
from knic.spatial import LocationModel
from knic.units import Kind
from knowledge_base import Fact, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus

SHELF_TOP = (7.7, 1.5, 0.92)


def test_refuted_item_loses_its_place_and_sighting(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = ObjectPlaceKP(bus, paper_kb, needed=2)
    perception = BusPerception(paper_kb, bus)
    for t in (1.0, 1.2):
        send(bus, cku("glasses", Kind.OBJECT, SHELF_TOP, t))
    kp.step(1.2)
    assert paper_kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "entrance"))]
    assert perception.position("glasses") == SHELF_TOP
    perception.refute("glasses", SHELF_TOP, 5.0, "the gripper closed on nothing")
    kp.step(5.0)
    assert not paper_kb.facts("object_at", "glasses") and not paper_kb.holds("found", "glasses")
    assert perception.lost_since("glasses", 5.0)
    history = [c for c in paper_kb.changes() if c.name == "object_at"]
    assert history[-1].kind.value == "remove_fact"
    perception.close()


def test_refuted_person_loses_person_at(paper_kb: KnowledgeBase, paper_locations: LocationModel) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)
    perception = BusPerception(paper_kb, bus)
    seen: list[str] = []
    bus.subscribe("cognition.person", lambda m: seen.append(m.source))
    for t in (1.0, 1.2):
        send(bus, cku("annie", Kind.PERSON, (1.1, 6.6, 0.8), t, cls="person"))
    kp.step(1.2)
    assert paper_kb.holds("person_at", "annie", "bedroom")
    perception.refute("annie", (1.1, 6.6, 0.8), 3.0, "nobody took the item")
    kp.step(3.0)
    assert not paper_kb.facts("person_at", "annie")
    assert seen[-1] == REFUTED_SOURCE
    perception.close()
