"""Search KP': explored from camera coverage (with a TTL) and the possibly_at candidates (ASSUMED)."""

from __future__ import annotations

import math

from knic.bus import Bus
from knic.kgm1.sources import FrameView
from knic.kgm3.places import ObjectPlaceKP
from knic.kgm3.search import CandidatesKP, ExploredKP, priors_from_world
from knic.spatial import LocationModel
from knic.units import Kind, Scan
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus
from tests.knic.synthetic import frame
from worlds.model import World


def look_around(bus: Bus, at: tuple[float, float], start: float, depth: float = math.inf) -> float:
    """Scans of a camera turning on the spot in 8 steps; returns the time after the last one."""
    t = start
    for i in range(8):
        view = FrameView(frame(t, (at[0], at[1], 1.2, i * math.pi / 4), depth=depth), max_range=4.0)
        bus.publish("percept.vision.scan.object", Scan(Kind.OBJECT, t, view, "cam"), source="kp", stamp=t)
        t += 0.5
    return t


def candidates(kb: KnowledgeBase, entity: str) -> set[str]:
    return {f.args[1] for f in kb.facts("possibly_at", entity)}


def test_seeded_candidates_are_assumed(paper_kb: KnowledgeBase) -> None:
    assert candidates(paper_kb, "glasses") == {"kitchen", "entrance", "living_room"}
    why = paper_kb.why(Fact("possibly_at", ("glasses", "kitchen")))
    assert why is not None and why.status is BeliefStatus.ASSUMED and why.confidence == 0.4


def test_the_paper_search_sequence(
    paper_kb: KnowledgeBase, paper_world: World, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    explored = ExploredKP(bus, paper_kb, ttl_s=120.0)
    places = ObjectPlaceKP(bus, paper_kb, needed=2)
    cands = CandidatesKP(bus, paper_kb, priors_from_world(paper_world), list(paper_world.rooms))
    cands.step(0.0)
    assert candidates(paper_kb, "glasses") == {"kitchen", "entrance", "living_room"}
    # the robot looks around the kitchen: nothing there
    t = look_around(bus, paper_locations.waypoints["kitchen"], 10.0)
    explored.step(t)
    assert paper_kb.holds("explored", "kitchen") and explored.headings("kitchen") == 8
    assert explored.coverage("kitchen") >= 0.25
    assert not paper_kb.holds("explored", "entrance")
    cands.step(t)
    assert candidates(paper_kb, "glasses") == {"entrance", "living_room"}
    # the glasses are seen on the entrance shelf
    for dt in (0.0, 0.2):
        send(bus, cku("glasses", Kind.OBJECT, (7.75, 1.5, 0.92), t + 5 + dt))
    places.step(t + 5.2)
    cands.step(t + 5.2)
    why = paper_kb.why(Fact("object_at", ("glasses", "entrance")))
    assert why is not None and why.status is BeliefStatus.OBSERVED
    assert candidates(paper_kb, "glasses") == set()


def test_explored_expires_and_a_lost_object_is_searched_again(
    paper_kb: KnowledgeBase, paper_world: World, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    explored = ExploredKP(bus, paper_kb, ttl_s=60.0)
    cands = CandidatesKP(bus, paper_kb, priors_from_world(paper_world), list(paper_world.rooms))
    t = look_around(bus, paper_locations.waypoints["kitchen"], 0.0)
    explored.step(t)
    cands.step(t)
    assert "kitchen" not in candidates(paper_kb, "glasses")
    explored.step(t + 59.0)
    assert paper_kb.holds("explored", "kitchen")
    explored.step(t + 61.0)
    assert not paper_kb.holds("explored", "kitchen") and explored.coverage("kitchen") == 0.0
    cands.step(t + 61.0)
    assert "kitchen" in candidates(paper_kb, "glasses")


def test_a_wall_in_front_of_the_camera_explores_nothing(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    explored = ExploredKP(bus, paper_kb)
    t = look_around(bus, paper_locations.waypoints["kitchen"], 0.0, depth=0.3)
    explored.step(t)
    assert explored.coverage("kitchen") < 0.1 and not paper_kb.holds("explored", "kitchen")


def test_when_every_prior_room_is_explored_other_rooms_become_candidates(
    paper_kb: KnowledgeBase, paper_world: World
) -> None:
    cands = CandidatesKP(Bus(), paper_kb, priors_from_world(paper_world), list(paper_world.rooms))
    for room in ("kitchen", "entrance", "living_room"):
        paper_kb.add_fact("explored", room, source="dispatcher", at=1.0, status=EFFECT)
    cands.step(2.0)
    assert candidates(paper_kb, "glasses") == {"bedroom"}
    why = paper_kb.why(Fact("possibly_at", ("glasses", "bedroom")))
    assert why is not None and why.status is BeliefStatus.ASSUMED and why.source == "kp'.candidates"


def test_a_person_unseen_for_long_is_searched_where_last_seen_first(
    paper_kb: KnowledgeBase, paper_world: World
) -> None:
    cands = CandidatesKP(Bus(), paper_kb, {}, list(paper_world.rooms), max_candidates=1)
    paper_kb.add_fact("person_at", "annie", "kitchen", source="kp'.person_at", at=1.0)
    cands.step(1.0)
    assert candidates(paper_kb, "annie") == set()
    paper_kb.remove_fact("person_at", "annie", "kitchen", source="kp'.person_at", at=40.0)
    cands.step(40.0)
    assert candidates(paper_kb, "annie") == {"kitchen"}


EFFECT = BeliefStatus.EFFECT


def test_a_room_searched_for_one_entity_is_still_a_candidate_for_another(
    home_kb: KnowledgeBase, home_world: World
) -> None:
    cands = CandidatesKP(Bus(), home_kb, priors_from_world(home_world), list(home_world.rooms))
    cands.step(0.0)
    assert "living_room" in candidates(home_kb, "tablet")
    # the robot searched the living room for the tablet; annie (never located) may still be there
    home_kb.add_fact(
        "searched", "tablet", "living_room", source="dispatcher", at=1.0, status=BeliefStatus.EFFECT
    )
    cands.step(2.0)
    assert "living_room" not in candidates(home_kb, "tablet")
    assert "living_room" in candidates(home_kb, "annie")


def test_a_search_covers_every_room_and_ends(home_kb: KnowledgeBase, home_world: World) -> None:
    rooms = sorted(home_world.rooms)
    cands = CandidatesKP(Bus(), home_kb, {}, rooms)  # no priors: every room not searched yet
    home_kb.add_goal("has", "annie", "candle")
    cands.step(0.0)
    assert candidates(home_kb, "candle") == set(rooms)
    for i, room in enumerate(rooms[:-1]):
        home_kb.add_fact(
            "searched", "candle", room, source="dispatcher", at=float(i), status=BeliefStatus.EFFECT
        )
    cands.step(10.0)
    assert candidates(home_kb, "candle") == {rooms[-1]}
    home_kb.add_fact(
        "searched", "candle", rooms[-1], source="dispatcher", at=11.0, status=BeliefStatus.EFFECT
    )
    cands.step(12.0)
    assert candidates(home_kb, "candle") == set()  # nothing left: a goal needing it is unreachable
    # once located, the searches are forgotten (it may be moved and searched for again later)
    home_kb.add_fact("object_at", "candle", "kitchen", source="kp'.object_at", at=13.0)
    cands.step(13.0)
    assert home_kb.facts("searched", "candle") == []


def test_an_item_asked_for_from_a_furniture_is_assumed_on_it(
    home_kb: KnowledgeBase, home_world: World
) -> None:
    cands = CandidatesKP(Bus(), home_kb, priors_from_world(home_world), list(home_world.rooms))
    home_kb.add_goal("taken_from", "apple", "kitchen_cabinet")
    cands.step(0.0)
    why = home_kb.why(Fact("possibly_on", ("apple", "kitchen_cabinet")))
    assert why is not None and why.status is BeliefStatus.ASSUMED
    home_kb.add_fact("searched", "apple", "kitchen", source="dispatcher", at=1.0, status=EFFECT)
    cands.step(2.0)
    assert not home_kb.holds("possibly_on", "apple", "kitchen_cabinet")
