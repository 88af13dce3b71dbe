"""The role's revisits: where the robot goes to look next, from the beliefs and the role data."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import InferenceError
from knic.kgm2.attention import Revisits, rooms_from_kb
from knic.kgm2.roles import Revisit, load_role, load_roles
from knowledge_base import BeliefStatus, KnowledgeBase


def test_companion_revisits_people_and_its_rooms() -> None:
    revisit = load_role("companion").revisit
    assert revisit.people and "living_room" in revisit.rooms and "glasses" in revisit.items
    assert revisit.priority_weight > 1
    assert not load_role("all_top_rate").revisit.people


def test_bad_revisit_data(tmp_path: Path) -> None:
    bad = tmp_path / "roles.yaml"
    bad.write_text("roles:\n  x: {default: {rate_hz: 1}, revisit: {people: true, rooms: kitchen}}\n")
    with pytest.raises(InferenceError, match=r"x\.revisit\.rooms"):
        load_roles(bad)
    bad.write_text("roles:\n  x: {default: {rate_hz: 1}, revisit: {priority_weight: 0.5}}\n")
    with pytest.raises(InferenceError, match="priority_weight"):
        load_roles(bad)
    bad.write_text("roles:\n  x: {default: {rate_hz: 1}, revisit: {often: true}}\n")
    with pytest.raises(InferenceError, match="revisit"):
        load_roles(bad)


def test_rooms_from_kb_take_the_anchors(home_kb: KnowledgeBase) -> None:
    rooms = rooms_from_kb(home_kb)
    assert {"kitchen", "living_room", "bedroom"} <= set(rooms)
    geometry = home_kb.anchor("kitchen") or {}
    assert rooms["kitchen"].point == tuple(float(v) for v in geometry["waypoints"][0])
    region = geometry["region"]
    assert rooms["kitchen"].centre == pytest.approx(
        (sum(p[0] for p in region) / len(region), sum(p[1] for p in region) / len(region))
    )


def test_an_aged_person_belief_is_visited_first(home_kb: KnowledgeBase, clock: list[float]) -> None:
    rooms = rooms_from_kb(home_kb, ["kitchen", "living_room", "bedroom", "bathroom"])
    policy = Revisits(home_kb, Revisit(people=True, rooms=("living_room",), priority_weight=2.0), rooms)
    for room in rooms:
        policy.looked(room, 0.0)
    clock[0] = 10.0
    home_kb.add_fact("person_at", "tracy", "bathroom", source="test", status=BeliefStatus.OBSERVED)
    # nothing aged: the priority room, whose last look counts twice, before the others
    assert policy.next_room(now=20.0) == "living_room"
    clock[0] = 30.0
    home_kb.add_fact("person_at", "tracy", "bathroom", source="test", status=BeliefStatus.ASSUMED)
    assert policy.person_room(now=31.0) == "bathroom"
    assert policy.next_room(now=31.0) == "bathroom"
    # once looked at after the belief aged, the room is not chosen again for it
    policy.looked("bathroom", 40.0)
    assert policy.person_room(now=41.0) is None
    assert policy.next_room(now=41.0) == "living_room"


def test_a_priority_item_makes_its_room_a_priority(home_kb: KnowledgeBase) -> None:
    rooms = rooms_from_kb(home_kb, ["kitchen", "bedroom"])
    policy = Revisits(home_kb, Revisit(items=("glasses",), priority_weight=3.0), rooms)
    policy.looked("kitchen", 0.0)
    policy.looked("bedroom", 5.0)
    assert policy.next_room(now=20.0) == "kitchen"
    home_kb.add_fact("object_at", "glasses", "bedroom", source="test")
    assert policy.priority_rooms() == {"bedroom"}
    assert policy.next_room(now=20.0) == "bedroom"
