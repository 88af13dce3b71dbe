"""Association over time with a radius and a miss counter (seed 002, Algorithm 2.1)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from knic.kgm2.tracking import Tracker
from knic.units import Kind
from tests.knic.synthetic import percept


def test_same_object_across_frames_and_a_new_one_beyond_the_radius() -> None:
    tracker = Tracker("mug", radius=0.4)
    first = tracker.associate([percept(Kind.OBJECT, "mug", (2.0, 1.0, 0.8), 0.0)], 0.0)
    ((track, _),) = first.created
    again = tracker.associate([percept(Kind.OBJECT, "mug", (2.1, 1.05, 0.8), 0.2)], 0.2)
    assert [t.track_id for t, _ in again.updated] == [track.track_id] and not again.created
    assert np.allclose(track.centroid, [2.08, 1.04, 0.8])  # weighted average, gain 0.8
    other = tracker.associate(
        [
            percept(Kind.OBJECT, "mug", (2.1, 1.0, 0.8), 0.4),
            percept(Kind.OBJECT, "mug", (3.5, 1.0, 0.8), 0.4),
        ],
        0.4,
    )
    assert [t.track_id for t, _ in other.updated] == [track.track_id]
    assert len(other.created) == 1 and len(tracker.tracks) == 2
    assert track.hits == 3 and track.misses == 0


def test_dropped_after_more_than_max_misses_only_when_visible() -> None:
    tracker = Tracker("mug", radius=0.4, max_misses=2)
    tracker.associate([percept(Kind.OBJECT, "mug", (2.0, 1.0, 0.8), 0.0)], 0.0)
    hidden = lambda pts: np.zeros(len(pts), dtype=bool)  # noqa: E731
    shown = lambda pts: np.ones(len(pts), dtype=bool)  # noqa: E731
    for _ in range(5):
        assert tracker.miss_scan(hidden) == []
    assert tracker.miss_scan(shown) == [] and tracker.miss_scan(shown) == []
    dropped = tracker.miss_scan(shown)
    assert [t.cls for t in dropped] == ["mug"] and tracker.tracks == {}


def test_recognised_identity_follows_the_person_and_anonymous_detections_join_nearby_tracks() -> None:
    tracker = Tracker("person", radius=0.8)
    tracker.associate([percept(Kind.PERSON, "person", (1.0, 1.0, 1.0), 0.0, identity="jack")], 0.0)
    far = tracker.associate([percept(Kind.PERSON, "person", (5.0, 5.0, 1.0), 0.8, identity="jack")], 0.8)
    assert not far.updated and not far.created  # one far sighting is set aside (could be a false positive)
    jump = tracker.associate([percept(Kind.PERSON, "person", (5.0, 5.0, 1.0), 1.0, identity="jack")], 1.0)
    ((track, _),) = jump.updated
    assert track.symbol == "jack" and np.allclose(track.centroid, [5.0, 5.0, 1.0])
    assert track.octomap.resets == 1
    anon = tracker.associate([percept(Kind.PERSON, "person", (5.2, 5.0, 1.0), 1.2)], 1.2)
    assert [t.symbol for t, _ in anon.updated] == ["jack"]
    stranger = tracker.associate([percept(Kind.PERSON, "person", (0.0, 0.0, 1.0), 1.4)], 1.4)
    assert [t.symbol for t, _ in stranger.created] == [f"person_{stranger.created[0][0].track_id}"]


def test_one_track_per_identity_even_with_a_false_positive_of_the_same_class() -> None:
    tracker = Tracker("glasses", radius=0.4, max_misses=1)
    tracker.associate([percept(Kind.OBJECT, "glasses", (7.7, 1.5, 0.9), 0.0, identity="glasses")], 0.0)
    for i in range(1, 6):  # the real glasses and a spurious "glasses" elsewhere in every frame
        scan = tracker.associate(
            [
                percept(Kind.OBJECT, "glasses", (7.5, 1.1, 0.7), i, identity="glasses"),
                percept(Kind.OBJECT, "glasses", (7.7, 1.5, 0.9), i, identity="glasses"),
            ],
            float(i),
            lambda pts: np.ones(len(pts), dtype=bool),
        )
        assert not scan.created and not scan.dropped
    (track,) = tracker.tracks.values()
    assert np.allclose(track.centroid, (7.7, 1.5, 0.9), atol=0.05) and tracker.duplicates == 5


def test_a_single_far_false_positive_does_not_move_an_identified_track() -> None:
    tracker = Tracker("remote", radius=0.4)
    tracker.associate([percept(Kind.OBJECT, "remote", (8.5, 1.6, 0.5), 0.0, identity="remote")], 0.0)
    tracker.associate([percept(Kind.OBJECT, "remote", (10.1, 0.4, 0.6), 5.0, identity="remote")], 5.0)
    tracker.associate([percept(Kind.OBJECT, "remote", (10.1, 0.4, 0.6), 9.0, identity="remote")], 9.0)
    (track,) = tracker.tracks.values()
    assert np.allclose(track.centroid, (8.5, 1.6, 0.5), atol=0.05) and tracker.jumps_set_aside == 2


def test_unnamed_person_tracks_count_the_views_the_face_recogniser_had() -> None:
    tracker = Tracker("person", radius=0.8, face_pixels=40)

    def seen(pixels: int, t: float, identity: str | None = None) -> None:
        unit = percept(Kind.PERSON, "person", (2.0, 1.0, 1.0), t, identity=identity)
        tracker.associate([replace(unit, attributes={"pixels": pixels})], t)

    seen(500, 0.0)
    seen(12, 0.2)  # too small for a face: not a face view
    seen(np.int64(80), 0.4)  # type: ignore[arg-type]
    (track,) = tracker.tracks.values()
    assert track.symbol.startswith("person_") and track.hits == 3 and track.face_views == 2
    seen(500, 0.6, identity="jack")  # a named sighting goes to jack's own track and counts nothing
    assert tracker.by_symbol("jack") is not None and tracker.by_symbol("jack").face_views == 0  # type: ignore[union-attr]
    assert Tracker("mug").face_pixels == 0


def test_a_person_whose_upper_body_is_in_view_is_missed_though_the_centroid_is_below_the_view() -> None:
    # a robot passing close by: the hip-high centroid is under the camera's view, the torso above it is not
    above_1m = lambda pts: np.asarray(pts)[:, 2] > 1.0  # noqa: E731
    person = Tracker("person", radius=0.8, max_misses=1, probe_up_m=0.5)
    centroid_only = Tracker("person", radius=0.8, max_misses=1)
    for tracker in (person, centroid_only):
        tracker.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.7), 0.0)], 0.0)
    assert person.miss_scan(above_1m) == [] and centroid_only.miss_scan(above_1m) == []
    assert [t.misses for t in person.tracks.values()] == [1]
    assert [t.misses for t in centroid_only.tracks.values()] == [0]
    assert [t.cls for t in person.miss_scan(above_1m)] == ["person"] and person.tracks == {}
    assert centroid_only.miss_scan(above_1m) == [] and len(centroid_only.tracks) == 1


def test_an_unnamed_person_beyond_the_radius_of_a_track_unseen_for_a_while_is_that_track() -> None:
    # the person walked on while the camera looked away: the stale track's gate has grown
    growing = Tracker("person", radius=0.8, gate_growth=0.2)
    fixed = Tracker("person", radius=0.8)
    for tracker in (growing, fixed):
        tracker.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.9), 0.0)], 0.0)
    assert growing.gate(next(iter(growing.tracks.values())), 5.0) == 1.6  # 0.8 + 0.2 m/s * 5 s, at most 2x
    late = percept(Kind.PERSON, "person", (4.1, 2.0, 0.9), 5.0)  # 1.1 m away, 5 s later
    moved = growing.associate([late], 5.0)
    assert len(moved.updated) == 1 and not moved.created and len(growing.tracks) == 1
    ((track, _),) = moved.updated
    assert track.centroid == (4.1, 2.0, 0.9)  # beyond the radius: the track jumps there
    assert len(fixed.associate([late], 5.0).created) == 1 and len(fixed.tracks) == 2
    # seen a moment ago, the gate is the radius: someone 1.1 m away is someone else
    fresh = growing.associate([percept(Kind.PERSON, "person", (5.2, 2.0, 0.9), 5.2)], 5.2)
    assert len(fresh.created) == 1


def test_a_person_octomap_restarts_after_a_step_smaller_than_the_association_radius() -> None:
    person = Tracker("person", radius=0.8, reset_distance=0.3)
    item_like = Tracker("person", radius=0.8)
    for tracker in (person, item_like):
        tracker.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.9), 0.0)], 0.0)
        tracker.associate([percept(Kind.PERSON, "person", (3.45, 2.0, 0.9), 0.2)], 0.2)
    ((track,),) = [list(person.tracks.values())]
    ((other,),) = [list(item_like.tracks.values())]
    assert track.octomap.resets == 1 and other.octomap.resets == 0
    # the restarted map holds only voxels of where the person stands now
    assert min(track.keys[:, 0]) > min(other.keys[:, 0])


def test_a_person_unseen_for_a_while_and_missed_in_view_is_dropped_after_fewer_misses() -> None:
    # the robot sweeping a room has the spot where the person was in view for a few frames only: a person
    # unseen for a while (stale) who is not there is dropped after stale_misses misses, not max_misses
    shown = lambda pts: np.ones(len(pts), dtype=bool)  # noqa: E731
    stale = Tracker("person", radius=0.8, max_misses=4, min_lost_s=2.5, stale_s=10.0, stale_misses=1)
    for tracker in (stale, Tracker("person", radius=0.8, max_misses=4, min_lost_s=2.5)):
        tracker.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.9), 0.0)], 0.0)
        # just seen: a brief occlusion never drops the track, however many frames it lasts within 2.5 s
        assert all(tracker.miss_scan(shown, 0.2 * k) == [] for k in range(1, 5))
    assert [t.misses for t in stale.tracks.values()] == [4]
    assert stale.misses_allowed(next(iter(stale.tracks.values())), 5.0) == 4
    # looked at again 20 s later: dropped at the next miss
    assert [t.cls for t in stale.miss_scan(shown, 20.0)] == ["person"] and stale.tracks == {}
    # a track seen lately is kept through stale_misses + 1 misses
    fresh = Tracker("person", radius=0.8, max_misses=4, min_lost_s=2.5, stale_s=10.0, stale_misses=1)
    fresh.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.9), 0.0)], 0.0)
    assert fresh.miss_scan(shown, 3.0) == [] and fresh.miss_scan(shown, 3.2) == [] and len(fresh.tracks) == 1
    # unseen for stale_s: two misses in view drop it
    late = Tracker("person", radius=0.8, max_misses=4, min_lost_s=2.5, stale_s=10.0, stale_misses=1)
    late.associate([percept(Kind.PERSON, "person", (3.0, 2.0, 0.9), 0.0)], 0.0)
    assert late.miss_scan(shown, 12.0) == []
    assert [t.cls for t in late.miss_scan(shown, 12.2)] == ["person"]
