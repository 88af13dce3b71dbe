"""A person's stale track lost (KGM-2 dropped it after a long time unseen): the belief is retracted a moment
later unless the person is seen again meanwhile (they had moved a step within the room)."""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm3.people import PersonPlaceKP
from knic.spatial import LocationModel
from knic.units import Kind
from knowledge_base import Fact, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus

BEDROOM = Fact("person_at", ("annie", "bedroom"))


def _believed_in_the_bedroom(bus: Bus, kb: KnowledgeBase, locations: LocationModel) -> PersonPlaceKP:
    publish_place_ckus(bus, locations)
    kp = PersonPlaceKP(bus, kb, needed=2, lost_grace_s=3.0, stale_s=10.0)
    for t in (0.2, 0.4):
        send(bus, cku("annie", Kind.PERSON, (2.0, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert kb.facts("person_at") == [BEDROOM]
    return kp


def test_a_stale_track_lost_retracts_the_belief_after_the_grace(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    kp = _believed_in_the_bedroom(bus, paper_kb, paper_locations)
    send(bus, cku("annie", Kind.PERSON, (2.0, 6.0, 1.0), 30.0, cls="person", lost=True, last_seen=0.4))
    kp.step(30.0)
    assert paper_kb.facts("person_at") == [BEDROOM]
    kp.step(31.0)
    assert paper_kb.facts("person_at") == [BEDROOM]
    kp.step(33.0)
    assert paper_kb.facts("person_at") == []


def test_a_stale_track_lost_and_the_person_seen_a_step_away_keeps_the_belief(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    kp = _believed_in_the_bedroom(bus, paper_kb, paper_locations)
    send(bus, cku("annie", Kind.PERSON, (2.0, 6.0, 1.0), 30.0, cls="person", lost=True, last_seen=0.4))
    kp.step(30.0)
    send(bus, cku("annie", Kind.PERSON, (2.8, 6.3, 1.0), 30.4, cls="person"))  # her new track
    kp.step(30.4)
    for t in (31.0, 34.0, 40.0):
        kp.step(t)
        assert paper_kb.facts("person_at") == [BEDROOM]


def test_a_track_lost_soon_after_a_sighting_retracts_at_once(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    kp = _believed_in_the_bedroom(bus, paper_kb, paper_locations)
    send(bus, cku("annie", Kind.PERSON, (2.0, 6.0, 1.0), 3.0, cls="person", lost=True, last_seen=0.4))
    kp.step(3.0)
    assert paper_kb.facts("person_at") == []
