"""person_at across a doorway: the camera sees a body's near side, so a person standing in a doorway looks a
little inside the next room; they stay believed where they were until seen clearly through."""

from __future__ import annotations

import pytest

from knic.bus import Bus
from knic.kgm3.people import PersonPlaceKP
from knic.spatial import LocationModel
from knic.units import Kind
from knowledge_base import Fact, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus


def test_a_person_in_the_doorway_stays_in_the_room_they_were_in(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)  # the paper's bedroom | kitchen wall is x = 4, door at y = 6
    t = 0.0
    for x in (3.0, 3.0):
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    for x in (4.1, 4.15, 4.2, 4.1):  # seen 10-20 cm into the kitchen: in the doorway
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person"))
        kp.step(t)
        assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    for x in (4.5, 4.6):  # clearly through
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "kitchen"))]


def test_seen_from_the_room_believed_a_person_just_beyond_its_door_is_in_the_next_room(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    # the camera sees a body's near side: the room behind the seen centroid along the line of sight is what
    # the doorway margin keeps, not the room in front of it
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)
    t = 0.0
    for x in (3.0, 3.0):
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person", sensor_origin=(1.0, 6.0, 1.2)))
        kp.step(t)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    # seen from the kitchen side 15 cm into the kitchen: in the doorway, still the bedroom
    for _ in range(3):
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (4.15, 6.0, 1.0), t, cls="person", sensor_origin=(6.5, 6.0, 1.2)))
        kp.step(t)
        assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    # the same spot seen from the bedroom: the body's far side is farther into the kitchen
    for _ in range(2):
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (4.15, 6.0, 1.0), t, cls="person", sensor_origin=(1.0, 6.0, 1.2)))
        kp.step(t)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "kitchen"))]


def test_a_person_last_seen_walking_to_the_door_and_unseen_since_has_walked_out_of_the_room(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    # the paper's bedroom | kitchen wall is x = 4, door at y = 6: annie walks east towards it at 0.8 m/s and
    # the camera turns away; carried on along her walk she is through the door: her bedroom belief goes
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)
    t, x = 0.0, 1.6
    while t < 1.9:
        t, x = t + 0.2, x + 0.16
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    assert kp.walking("annie")
    kp.step(t + 0.6)  # a moment unseen: as between sightings
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
    kp.step(t + 2.0)  # x 3.2 + 0.8 m/s * 2 s: 0.8 m into the kitchen
    assert paper_kb.facts("person_at") == []


@pytest.mark.parametrize(
    ("x0", "y", "step"),
    [
        (1.6, 6.0, -0.16),  # west, towards the bedroom's outer wall (nothing beyond)
        (1.6, 7.5, 0.16),  # east, towards the kitchen wall 1.5 m beside the door: through the wall
    ],
)
def test_a_person_walking_towards_a_wall_is_not_taken_out_of_the_room(
    paper_kb: KnowledgeBase, paper_locations: LocationModel, x0: float, y: float, step: float
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)
    t = 0.0
    for k in range(10):  # annie walks at 0.8 m/s, then is not seen for long
        t += 0.2
        send(bus, cku("annie", Kind.PERSON, (x0 + step * k, y, 1.0), t, cls="person"))
        kp.step(t)
    assert kp.walking("annie")
    for dt in (1.0, 3.0, 10.0):
        kp.step(t + dt)
        assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]


def test_a_person_seen_again_after_a_gap_is_not_walking_for_the_way_they_went_unseen(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    kp = PersonPlaceKP(bus, paper_kb, needed=2)
    for t, x in ((0.0, 1.0), (0.2, 1.0), (3.5, 3.0), (3.7, 3.0)):  # 2 m further after 3.3 s out of sight
        send(bus, cku("annie", Kind.PERSON, (x, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert not kp.walking("annie")
    kp.step(6.0)
    assert paper_kb.facts("person_at") == [Fact("person_at", ("annie", "bedroom"))]
