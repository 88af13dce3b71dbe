"""``(searched ?e ?room)`` is no permanent truth: evidence that the entity moved, or age, lets the search
cover a room again, and a search over the whole home still ends."""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm3.search import CandidatesKP, priors_from_world
from knowledge_base import BeliefStatus, KnowledgeBase
from worlds.model import World

EFFECT = BeliefStatus.EFFECT


def candidates(kb: KnowledgeBase, entity: str) -> set[str]:
    return {f.args[1] for f in kb.facts("possibly_at", entity)}


def searched(kb: KnowledgeBase, entity: str) -> set[str]:
    return {f.args[1] for f in kb.facts("searched", entity)}


def test_a_room_searched_before_the_item_was_seen_carried_is_a_candidate_again(
    home_kb: KnowledgeBase, home_world: World, clock: list[float]
) -> None:
    cands = CandidatesKP(Bus(), home_kb, priors_from_world(home_world), list(home_world.rooms))
    home_kb.add_goal("has", "annie", "tablet")
    cands.step(0.0)
    assert "living_room" in candidates(home_kb, "tablet")
    clock[0] = 1.0
    home_kb.add_fact("searched", "tablet", "living_room", source="dispatcher", status=EFFECT)
    cands.step(2.0)
    assert "living_room" not in candidates(home_kb, "tablet")
    # Tracy is seen holding the tablet for a moment, then walks out of view: the belief goes before the KP'
    # steps, but the tablet moved after the living room was searched
    clock[0] = 5.0
    home_kb.add_fact("has", "tracy", "tablet", source="kp'.carried")
    clock[0] = 5.2
    home_kb.remove_fact("has", "tracy", "tablet", source="kp'.carried")
    cands.step(6.0)
    assert searched(home_kb, "tablet") == set()
    assert "living_room" in candidates(home_kb, "tablet")
    # a search made after the sighting counts again
    clock[0] = 20.0
    home_kb.add_fact("searched", "tablet", "living_room", source="dispatcher", status=EFFECT)
    cands.step(21.0)
    assert searched(home_kb, "tablet") == {"living_room"}
    assert "living_room" not in candidates(home_kb, "tablet")


def test_an_item_seen_somewhere_and_then_not_there_reopens_the_rooms_searched_before(
    home_kb: KnowledgeBase, home_world: World, clock: list[float]
) -> None:
    cands = CandidatesKP(Bus(), home_kb, {}, sorted(home_world.rooms))
    home_kb.add_goal("has", "annie", "candle")
    clock[0] = 1.0
    home_kb.add_fact("searched", "candle", "kitchen", source="dispatcher", status=EFFECT)
    cands.step(1.0)
    assert "kitchen" not in candidates(home_kb, "candle")
    clock[0] = 3.0
    home_kb.add_fact("object_at", "candle", "dining_room", source="kp'.object_at")
    clock[0] = 3.4  # the place was in view and it was not there: someone took it
    home_kb.remove_fact("object_at", "candle", "dining_room", source="kp'.object_at")
    cands.step(4.0)
    assert "kitchen" in candidates(home_kb, "candle") and searched(home_kb, "candle") == set()


def test_old_marks_reopen_their_room_once_after_the_rooms_never_searched_and_the_search_ends(
    home_kb: KnowledgeBase, home_world: World, clock: list[float]
) -> None:
    rooms = sorted(home_world.rooms)
    cands = CandidatesKP(Bus(), home_kb, {}, rooms, searched_ttl_s=100.0)  # no priors
    home_kb.add_goal("has", "annie", "candle")
    first, *middle, last = rooms
    for i, room in enumerate([first, *middle]):
        clock[0] = float(i)
        home_kb.add_fact("searched", "candle", room, source="dispatcher", status=EFFECT)
    cands.step(10.0)
    assert candidates(home_kb, "candle") == {last}
    # long after: the first rooms' marks aged out, but the room never searched comes first
    cands.step(103.5)
    assert not home_kb.holds("searched", "candle", first)
    assert candidates(home_kb, "candle") == {last}
    clock[0] = 104.0
    home_kb.add_fact("searched", "candle", last, source="dispatcher", status=EFFECT)
    cands.step(120.0)
    # then the rooms whose marks aged out are searched again (the candle may have been carried there)
    reopened = set(rooms) - searched(home_kb, "candle")
    assert first in reopened and last not in reopened
    assert candidates(home_kb, "candle") == reopened
    for room in sorted(reopened):
        clock[0] = 130.0
        home_kb.add_fact("searched", "candle", room, source="dispatcher", status=EFFECT)
    cands.step(131.0)
    assert candidates(home_kb, "candle") == set()
    # once per room: far later only the room never reopened yet ages out; after that nothing does
    cands.step(1000.0)
    assert candidates(home_kb, "candle") == {last}
    clock[0] = 1001.0
    home_kb.add_fact("searched", "candle", last, source="dispatcher", status=EFFECT)
    cands.step(5000.0)
    assert candidates(home_kb, "candle") == set() and searched(home_kb, "candle") == set(rooms)


def test_an_item_whose_place_is_no_longer_known_is_not_found_and_can_be_searched_for(
    home_kb: KnowledgeBase, home_world: World, clock: list[float]
) -> None:
    cands = CandidatesKP(Bus(), home_kb, priors_from_world(home_world), list(home_world.rooms))
    home_kb.add_goal("has", "annie", "glasses")
    clock[0] = 1.0
    with home_kb.batch():
        home_kb.add_fact("object_at", "glasses", "kitchen", source="kp'.object_at")
        home_kb.add_fact("found", "glasses", source="kp'.object_at")
    cands.step(1.0)
    assert home_kb.holds("found", "glasses") and candidates(home_kb, "glasses") == set()
    # the belief goes by a path that leaves found behind (an effect, an aged belief): found must follow it
    clock[0] = 5.0
    home_kb.remove_fact("object_at", "glasses", "kitchen", source="kp'.object_at")
    cands.step(5.0)
    assert not home_kb.holds("found", "glasses")
    assert candidates(home_kb, "glasses")
    # held by the robot: located, found stays
    clock[0] = 8.0
    with home_kb.batch():
        home_kb.add_fact("holding", "r2d2", "glasses", source="dispatcher", status=EFFECT)
        home_kb.add_fact("found", "glasses", source="dispatcher", status=EFFECT)
    cands.step(8.0)
    assert home_kb.holds("found", "glasses")
