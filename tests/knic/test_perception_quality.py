"""Perception quality: sighting gates, depth outliers, track loss hysteresis, explored coverage, re-seeding.

Each test pins one behaviour behind the grounding figures (precision, recall, flapping facts).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from knic.bus import Bus, Message
from knic.kgm1.camera import CameraObjectsKP
from knic.kgm1.sources import FrameView
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import load_role
from knic.kgm2.tracking import Tracker
from knic.kgm3.people import PersonPlaceKP
from knic.kgm3.places import ObjectPlaceKP
from knic.kgm3.search import CandidatesKP, ExploredKP
from knic.spatial import LocationModel
from knic.units import LLKU, Kind, Scan
from knowledge_base import BeliefStatus, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus, publish_place_percepts
from tests.knic.synthetic import FakeSensors, frame, percept
from worlds.model import World

CAMERA = (5.0, 2.0, 1.2, 0.0)


def objects_seen(kb: KnowledgeBase, camera_frame: object, **gates: object) -> list[LLKU]:
    sensors = FakeSensors()
    sensors.next_frame = camera_frame  # type: ignore[assignment]
    bus = Bus()
    got: list[Message] = []
    bus.subscribe("percept.vision.object", got.append)
    kp = CameraObjectsKP(sensors, bus, kb, {"glasses": "glasses", "mug": "mug"}, **gates)  # type: ignore[arg-type]
    kp.step(1.0)
    return [m.payload for m in got]


def test_tiny_and_far_detections_are_not_sightings(paper_kb: KnowledgeBase) -> None:
    boxes = [
        ("glasses", (36, 26, 44, 34), 2.0, None),  # 64 pixels at 2 m: a sighting
        ("mug", (10, 10, 12, 12), 2.0, None),  # 4 pixels: too small
        ("cup", (60, 40, 70, 50), 5.8, None),  # 100 pixels but 5.8 m away: beyond the range
    ]
    units = objects_seen(paper_kb, frame(1.0, CAMERA, boxes=boxes), min_pixels=6, detect_range=4.0)
    assert [u.label for u in units] == ["glasses"]


def test_background_points_through_the_mask_do_not_move_the_position(paper_kb: KnowledgeBase) -> None:
    f = frame(1.0, CAMERA, boxes=[("glasses", (36, 26, 44, 34), 2.0, None)])
    depth = np.array(f.depth)
    depth[26:34, 36:39] = 5.0  # three of eight mask columns see the wall 3 m behind the glasses
    f = dataclasses.replace(f, depth=depth)
    (unit,) = objects_seen(paper_kb, f, max_points=64)
    ranges = np.linalg.norm(unit.points - np.array(CAMERA[:3]), axis=1)
    assert len(unit.points) == 40 and np.all(np.abs(ranges - 2.0) < 0.2)
    assert math.dist(unit.position[:2], (7.0, 2.0)) < 0.1


def test_a_briefly_missed_track_is_kept_and_a_long_missed_one_dropped() -> None:
    tracker = Tracker("mug", radius=0.4, max_misses=2, min_lost_s=2.0)
    tracker.associate([percept(Kind.OBJECT, "mug", (2.0, 1.0, 0.8), 0.0)], 0.0)
    shown = lambda pts: np.ones(len(pts), dtype=bool)  # noqa: E731
    for t in (0.2, 0.4, 0.6, 0.8, 1.0, 1.8):
        assert tracker.miss_scan(shown, t) == []  # occluded for under two seconds: still tracked
    dropped = tracker.miss_scan(shown, 2.2)
    assert [t.cls for t in dropped] == ["mug"] and tracker.tracks == {}


def test_a_frame_edge_does_not_count_as_seeing() -> None:
    # a point 2 m ahead, projecting one pixel inside the left image border
    f = frame(0.0, CAMERA, depth=math.inf)
    k = f.intrinsics
    x_left = (0.5 - k.cx) * 2.0 / k.fx
    point = np.array([[7.0, 2.0 - x_left, 1.2]])
    assert FrameView(f, 4.0).visible(point).tolist() == [True]
    assert FrameView(f, 4.0, edge_px=3).visible(point).tolist() == [False]


def scan_from(bus: Bus, at: tuple[float, float], yaw: float, t: float) -> None:
    view = FrameView(frame(t, (at[0], at[1], 1.2, yaw)), max_range=4.0)
    bus.publish("percept.vision.scan.object", Scan(Kind.OBJECT, t, view, "cam"), source="kp", stamp=t)


def test_driving_through_a_room_does_not_explore_it(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    explored = ExploredKP(bus, paper_kb)
    x, y = paper_locations.waypoints["kitchen"]
    t = 0.0
    for dx in (-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5):  # straight across, looking ahead
        scan_from(bus, (x + dx, y), 0.0, t)
        scan_from(bus, (x + dx, y), math.pi, t + 0.1)
        t += 0.5
    explored.step(t)
    assert explored.headings("kitchen") == 2 and explored.coverage("kitchen") > 0.2
    assert not paper_kb.holds("explored", "kitchen")
    for i in range(8):  # then it stops and looks around
        scan_from(bus, (x, y), i * math.pi / 4, t)
        t += 0.5
    explored.step(t)
    assert paper_kb.holds("explored", "kitchen")


def test_a_person_lost_in_an_explored_room_is_searched_there_at_once(
    paper_kb: KnowledgeBase, paper_world: World
) -> None:
    cands = CandidatesKP(Bus(), paper_kb, {"annie": [("living_room", 0.5)]}, list(paper_world.rooms))
    paper_kb.add_fact("explored", "kitchen", source="kp'.explored", at=5.0)
    paper_kb.add_fact("person_at", "annie", "kitchen", source="kp'.person_at", at=10.0)
    cands.step(10.0)
    paper_kb.remove_fact("person_at", "annie", "kitchen", source="kp'.person_at", at=12.0)
    cands.step(12.0)
    assert {f.args[1] for f in paper_kb.facts("possibly_at", "annie")} == {"kitchen", "living_room"}
    # a search of the kitchen after she was lost rules it out
    paper_kb.remove_fact("explored", "kitchen", source="kp'.explored", at=20.0)
    paper_kb.add_fact("explored", "kitchen", source="kp'.explored", at=20.0)
    cands.step(20.0)
    assert {f.args[1] for f in paper_kb.facts("possibly_at", "annie")} == {"living_room"}


def test_a_first_sighting_never_moves_the_anchor(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    places = ObjectPlaceKP(bus, paper_kb, needed=2)
    shelf = (7.75, 1.5, 0.92)
    for i, t in enumerate((1.0, 1.2)):
        send(bus, cku("glasses", Kind.OBJECT, shelf, t, hits=5 + i))
    places.step(1.2)
    why = paper_kb.why(paper_kb.facts("object_at", "glasses")[0])
    assert why is not None and why.status is BeliefStatus.OBSERVED
    elsewhere = (7.3, 1.0, 0.3)
    assert (
        paper_locations.room_at(elsewhere[0], elsewhere[1])
        == paper_kb.facts("object_at", "glasses")[0].args[1]
    )
    send(bus, cku("glasses", Kind.OBJECT, elsewhere, 1.4, hits=1))  # a new track: a false positive
    places.step(1.4)
    anchor = paper_kb.anchor("glasses")
    assert anchor is not None and math.dist(anchor["pose"]["position"], shelf) < 0.05


def test_a_confused_label_on_another_settled_object_moves_nothing(paper_locations: LocationModel) -> None:
    bus = Bus()
    layer = CognitiveLayer(bus, load_role("all_top_rate"))
    publish_place_percepts(bus, paper_locations)
    view = FrameView(frame(0.0, (5.0, 2.0, 1.2, 0.0)), max_range=4.0)
    soap, sponge = (7.7, 2.0, 0.92), (7.7, 2.25, 0.92)  # 0.25 m apart: within the soap track radius

    def scan(t: float, *units: LLKU) -> None:
        for unit in units:
            bus.publish(f"percept.vision.object.{unit.label}", unit, source="kp", stamp=t)
        bus.publish("percept.vision.scan.object", Scan(Kind.OBJECT, t, view, "cam"), source="kp", stamp=t)
        layer.step(t)

    t = 0.0
    for _ in range(4):  # both settle where they are
        scan(t, percept(Kind.OBJECT, "soap", soap, t, identity="soap"))
        scan(t + 0.1, percept(Kind.OBJECT, "sponge", (2.0, 1.0, 0.9), t + 0.1, identity="sponge"))
        t += 0.2
    for _ in range(3):  # the soap is read as "sponge" in consecutive frames
        scan(t, percept(Kind.OBJECT, "sponge", soap, t, identity="sponge"))
        t += 0.2
    track = layer.trackers["sponge"].by_symbol("sponge")
    assert track is not None and math.dist(track.centroid, (2.0, 1.0, 0.9)) < 0.05
    assert layer.stats.confusions == 3
    # a real sponge put beside the soap, both detected: the sponge's track follows it
    for _ in range(2):
        scan(
            t,
            percept(Kind.OBJECT, "soap", soap, t, identity="soap"),
            percept(Kind.OBJECT, "sponge", sponge, t, identity="sponge"),
        )
        t += 0.2
    track = layer.trackers["sponge"].by_symbol("sponge")
    assert track is not None and math.dist(track.centroid, sponge) < 0.1


def glasses_on_the_shelf(kb: KnowledgeBase, locations: LocationModel) -> tuple[Bus, ObjectPlaceKP]:
    """The object place KP' after two sightings of the glasses on the entrance shelf (t = 1.0 and 1.2)."""
    bus = Bus()
    publish_place_ckus(bus, locations)
    places = ObjectPlaceKP(bus, kb, needed=2)
    for t in (1.0, 1.2):
        send(bus, cku("glasses", Kind.OBJECT, (7.75, 1.5, 0.92), t, hits=3))
    places.step(1.2)
    assert kb.holds("object_on", "glasses", "entrance_shelf")
    return bus, places


def test_a_partial_view_does_not_take_an_item_off_its_surface(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus, places = glasses_on_the_shelf(paper_kb, paper_locations)
    # seen low over the shelf's footprint (voxels under its top) in several frames: still on the shelf
    for t in (1.4, 1.6, 1.8):
        send(bus, cku("glasses", Kind.OBJECT, (7.75, 1.5, 0.4), t, hits=4))
    places.step(1.8)
    assert paper_kb.holds("object_on", "glasses", "entrance_shelf") and places.writes.retracted == 0


def test_an_item_picked_up_is_on_no_furniture_any_more(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    _, places = glasses_on_the_shelf(paper_kb, paper_locations)
    # the pick's effects as the dispatcher writes them: holding, and no object_at (it cannot name the shelf)
    paper_kb.remove_fact("hand_empty", "r2d2", source="dispatcher", at=2.0)
    paper_kb.add_fact("holding", "r2d2", "glasses", source="dispatcher", at=2.0)
    paper_kb.remove_fact("object_at", "glasses", "entrance", source="dispatcher", at=2.0)
    places.step(2.1)
    assert not paper_kb.facts("object_on", "glasses") and paper_kb.holds("holding", "r2d2", "glasses")


def test_a_person_last_seen_walking_ages_sooner(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    bus = Bus()
    publish_place_ckus(bus, paper_locations)
    paper_kb.add_instance("person", "tracy")
    kp = PersonPlaceKP(bus, paper_kb, ttl_s=30.0, moving_ttl_s=8.0, needed=2)
    for i in range(6):  # annie sits still; tracy walks along the bedroom at 1 m/s
        t = 1.0 + 0.4 * i
        send(bus, cku("annie", Kind.PERSON, (1.1, 6.6, 0.8), t, cls="person"))
        send(bus, cku("tracy", Kind.PERSON, (0.5 + 0.4 * i, 7.5, 0.9), t, cls="person"))
    kp.step(3.0)
    assert kp.walking("tracy") and not kp.walking("annie")
    assert {f.args[0] for f in paper_kb.facts("person_at")} == {"annie", "tracy"}
    kp.step(12.0)

    def aged() -> set[str]:
        return {
            f.args[0]
            for f in paper_kb.facts("person_at")
            if (p := paper_kb.why(f)) is not None and p.status == BeliefStatus.ASSUMED
        }

    # neither is forgotten for want of news (no view of their places); tracy's belief ages first
    assert {f.args[0] for f in paper_kb.facts("person_at")} == {"annie", "tracy"} and aged() == {"tracy"}
    kp.step(33.5)
    assert {f.args[0] for f in paper_kb.facts("person_at")} == {"annie", "tracy"}
    assert aged() == {"annie", "tracy"}
