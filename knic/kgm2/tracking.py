"""Association of percepts over time: seed 002's tracking component (Algorithm 2.1) per entity class.

For every scan (one camera frame) the detections of one class are matched to the class's tracks:

1. a detection that carries an identity (a recognised person, an object whose class names one item) updates
   the track of that symbol wherever it is (a recognised entity that jumped has moved; its octomap restarts);
   a symbol has at most one track, so only one detection per identity and scan is kept: the one nearest the
   track; a sighting far from the track moves it only once seen again there (``jump_confirm``);
2. the others are matched greedily by increasing centroid distance, a pair counting only within the radius
   ``radius`` (metres) and each track and detection used once (lines 2.1.2-2.1.15);
3. an unmatched detection starts a new track;
4. a track not updated by the scan gets a miss when the scan could have seen it (``visible``; every scan when
   no visibility test is given): a miss update on its octomap's occupied voxels (log-odds down, clamped), and
   it is dropped after more than ``max_misses`` consecutive misses (2.1.16-2.1.19) or once its octomap holds
   no occupied voxel, either only when at least ``min_lost_s`` simulated seconds passed since it was last
   seen (a brief occlusion or a fast approach never drops a track: the retraction it causes needs evidence
   as strong as the assertion did; an entity seen many times takes more misses to empty than a one-off).

The centroid of a matched track moves to the weighted average of old and new (weight ``gain`` on the new one).
Time stamps are simulated seconds.
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from core.errors import InferenceError
from knic.spatial import DEFAULT_RESOLUTION, EntityOctomap
from knic.units import LLKU, Keys

#: Visibility test for a scan: world-frame points (N, 3) -> which of them the sensor could see.
Visibility = Callable[[npt.NDArray[np.float64]], npt.NDArray[np.bool_]]

_track_ids = itertools.count(1)


@dataclass(eq=False)
class Track:
    """One tracked entity: its symbol, centroid (world frame, metres), octomap and counters."""

    track_id: int
    cls: str
    symbol: str
    centroid: tuple[float, float, float]
    octomap: EntityOctomap
    first_seen: float
    last_seen: float
    confidence: float
    hits: int = 1
    misses: int = 0
    support: deque[str] = field(default_factory=lambda: deque(maxlen=4))
    #: an unconfirmed far sighting of this identity: (position, sightings, last stamp)
    jump: tuple[tuple[float, float, float], int, float] | None = None
    #: sightings behind the latest update: 1, or the sightings that confirmed a jump to a far spot
    sightings: int = 1
    #: unnamed sightings large enough for the face recogniser (see ``Tracker.face_pixels``)
    face_views: int = 0
    #: scans that could see the track at its spot (since it started or last jumped) and did not detect it
    #: (a real item is detected in most; a spot where the detector once fired spuriously, in few)
    missed: int = 0

    @property
    def keys(self) -> Keys:
        """Voxel keys the track's octomap holds occupied (a query of the tree, see :class:`EntityOctomap`)."""
        return self.octomap.keys


@dataclass
class Association:
    """What one scan did: tracks updated (with their detection), created and dropped."""

    updated: list[tuple[Track, LLKU]] = field(default_factory=list)
    created: list[tuple[Track, LLKU]] = field(default_factory=list)
    dropped: list[Track] = field(default_factory=list)


class Tracker:
    """Tracks of one entity class.

    Args:
        cls: the class tracked (``"glasses"``, ``"person"``).
        radius: association radius e_R, metres.
        max_misses: threshold eta: a track is dropped after more than this many consecutive missed scans.
        gain: weight of the new centroid in the weighted average.
        resolution: octomap resolution of new tracks, metres.
        ray_length: metres of each ray cast into a track's octomap (see :class:`EntityOctomap`).
        jump_confirm: sightings near one far spot needed before an identified track jumps there (1: at once).
        jump_window_s: most simulated seconds between two of those sightings.
        min_lost_s: least simulated seconds since the last sighting before a missed track is dropped.
        face_pixels: a sighting without identity whose mask has at least this many pixels (LLKU attribute
            ``pixels``) counts as a face view: the recogniser saw the person well and did not know them
            (0: nothing counted; for classes without faces).
        probe_up_m: metres above a track's centroid where the entity's body still is (a person's upper body
            above the hip-high centroid); a scan that could see that point could see the entity, so it counts
            a miss too (a robot passing close by a person sees the torso while the centroid is below the
            view). 0: the centroid only.
        gate_growth: metres per second the association radius of a track grows with the time since it
            was last seen, up to ``max_gate`` metres (None: twice the radius): an entity unseen for a while
            may have moved (a person who walked on while the camera looked away), so an unnamed detection a
            little beyond the radius of a stale track is that track's entity rather than someone new. 0: a
            fixed radius (items do not move by themselves).
        stale_s: simulated seconds unseen after which a track is stale (None: never): a stale track is dropped
            after more than ``stale_misses`` consecutive misses instead of ``max_misses``. ``max_misses`` and
            ``min_lost_s`` guard a track just seen against a brief occlusion (someone passing in front, the
            detector missing a frame); a person not seen for a while whose spot the camera looks at again
            without seeing them has most likely walked away while the camera looked elsewhere (a robot
            sweeping a room may have the spot in view for a few frames only, fewer than ``max_misses``).
        stale_misses: the misses a stale track tolerates (see ``stale_s``).
        reset_distance: metres the track's centroid may move from where its octomap was started before the
            octomap restarts (None: the radius). A person's octomap restarts after a smaller move than the
            association radius: the voxels of where they stood before would otherwise outvote where they
            stand now (a person who stepped from the dining room to just inside the living room was still
            believed in the dining room).
    """

    def __init__(
        self,
        cls: str,
        *,
        radius: float = 0.5,
        max_misses: int = 5,
        gain: float = 0.8,
        resolution: float = DEFAULT_RESOLUTION,
        ray_length: float = 1.0,
        jump_confirm: int = 2,
        jump_window_s: float = 2.0,
        min_lost_s: float = 0.0,
        face_pixels: int = 0,
        probe_up_m: float = 0.0,
        gate_growth: float = 0.0,
        max_gate: float | None = None,
        reset_distance: float | None = None,
        stale_s: float | None = None,
        stale_misses: int = 1,
    ) -> None:
        if radius <= 0 or max_misses < 0 or not 0 < gain <= 1:
            raise InferenceError(f"tracker {cls}: radius > 0, max_misses >= 0 and 0 < gain <= 1 required")
        self.cls = cls
        self.radius = radius
        self.max_misses = max_misses
        self.gain = gain
        self.resolution = resolution
        self.ray_length = ray_length
        self.jump_confirm = max(1, jump_confirm)
        self.jump_window_s = jump_window_s
        self.min_lost_s = min_lost_s
        self.face_pixels = face_pixels
        self.probe_up_m = max(0.0, probe_up_m)
        self.gate_growth = max(0.0, gate_growth)
        self.reset_distance = radius if reset_distance is None else reset_distance
        self.max_gate = max(radius, max_gate if max_gate is not None else 2.0 * radius)
        self.stale_s = stale_s
        self.stale_misses = max(0, min(stale_misses, max_misses))
        self.tracks: dict[int, Track] = {}
        self._by_symbol: dict[str, Track] = {}
        self.duplicates = 0
        self.jumps_set_aside = 0

    def by_symbol(self, symbol: str) -> Track | None:
        """The live track of a symbol, if any."""
        return self._by_symbol.get(symbol)

    def associate(
        self, detections: Sequence[LLKU], now: float, visible: Visibility | None = None
    ) -> Association:
        """Match one scan's detections of this class to the tracks, update octomaps and miss counters."""
        result = Association()
        used: set[int] = set()
        pending: list[LLKU] = []
        for det in detections if len(detections) == 1 else self._one_per_identity(detections):
            track = self._by_symbol.get(det.identity) if det.identity else None
            if track is None:
                pending.append(det)
                continue
            distance = math.dist(det.position, track.centroid)  # the centroid's move, asked twice below
            if self._jump_confirmed(track, det, now, distance):
                self._update(track, det, now, distance)
                used.add(track.track_id)
                result.updated.append((track, det))
        if pending:
            self._match_pending(pending, used, result, now)
        if len(used) < len(self.tracks):  # some track was not updated by this scan
            self._count_misses(used, visible, result, now)
        return result

    def _match_pending(self, pending: list[LLKU], used: set[int], result: Association, now: float) -> None:
        """Lines 2.1.2-2.1.15 for detections no identity placed: greedy nearest matching, then new tracks."""
        matched: set[int] = set()
        free = [t for t in self.tracks.values() if t.track_id not in used and not self._claimed(t, pending)]
        if free:
            det_pos = np.array([d.position for d in pending])
            trk_pos = np.array([t.centroid for t in free])
            dist = np.linalg.norm(det_pos[:, None, :] - trk_pos[None, :, :], axis=2)
            gates = [self.gate(t, now) for t in free]
            widest = max(gates)
            for flat in np.argsort(dist, axis=None):
                i, j = divmod(int(flat), len(free))
                if dist[i, j] >= widest:
                    break
                if dist[i, j] >= gates[j]:
                    continue
                det = pending[i]
                if i in matched or free[j].track_id in used:
                    continue
                if det.identity and det.identity != free[j].symbol:
                    continue
                self._update(free[j], det, now)
                used.add(free[j].track_id)
                matched.add(i)
                result.updated.append((free[j], det))
        for i, det in enumerate(pending):
            if i not in matched:
                track = self._create(det, now)
                used.add(track.track_id)
                result.created.append((track, det))

    def gate(self, track: Track, now: float) -> float:
        """The association radius of ``track`` at simulated time ``now`` (see ``gate_growth``)."""
        if self.gate_growth <= 0:
            return self.radius
        return min(self.max_gate, self.radius + self.gate_growth * max(0.0, now - track.last_seen))

    def _jump_confirmed(self, track: Track, det: LLKU, now: float, distance: float | None = None) -> bool:
        """Whether an identified detection may update its track: near it, or a far sighting seen again.

        A recognised entity far from its track (beyond the radius) has either moved or is a false positive or
        a label confusion; the track moves only after ``jump_confirm`` sightings near the same far spot, each
        within ``jump_window_s`` of the previous one. Until then the detection is set aside. ``distance``: the
        detection's from the track's centroid, when the caller has it.
        """
        track.sightings = 1
        if distance is None:
            distance = math.dist(det.position, track.centroid)
        if distance < self.radius:
            track.jump = None
            return True
        if self.jump_confirm <= 1:
            return True
        seen = 1
        if track.jump is not None:
            where, count, last = track.jump
            if math.dist(det.position, where) < self.radius and now - last <= self.jump_window_s:
                seen = count + 1
        if seen >= self.jump_confirm:
            track.jump = None
            track.sightings = seen
            return True
        track.jump = (det.position, seen, now)
        self.jumps_set_aside += 1
        return False

    def _one_per_identity(self, detections: Sequence[LLKU]) -> list[LLKU]:
        """Keep one detection per identity: the one nearest the symbol's track (else the most confident).

        A symbol names one individual, so it has at most one track; a second detection with the same identity
        in one scan is a false positive or a confusion and is discarded (counted in :attr:`duplicates`).
        """
        best: dict[str, LLKU] = {}
        out: list[LLKU] = []
        for det in detections:
            if det.identity is None:
                out.append(det)
                continue
            other = best.get(det.identity)
            if other is None:
                best[det.identity] = det
                continue
            self.duplicates += 1
            track = self._by_symbol.get(det.identity)
            if track is not None:
                closer = math.dist(det.position, track.centroid) < math.dist(other.position, track.centroid)
            else:
                closer = det.confidence > other.confidence
            if closer:
                best[det.identity] = det
        return out + list(best.values())

    def miss_scan(self, visible: Visibility | None, now: float | None = None) -> list[Track]:
        """A scan (at simulated time ``now``; None: no time condition) that saw nothing of this class: count
        misses; return the tracks dropped."""
        result = Association()
        self._count_misses(set(), visible, result, now)
        return result.dropped

    def _claimed(self, track: Track, pending: Sequence[LLKU]) -> bool:
        # a track whose symbol is an identity of this scan belongs to that detection, not to a nearby
        # anonymous one
        return any(d.identity == track.symbol for d in pending)

    def _count_misses(
        self, used: set[int], visible: Visibility | None, result: Association, now: float | None = None
    ) -> None:
        if len(used) >= len(self.tracks):  # every track was updated by this scan
            return
        stale = [t for t in self.tracks.values() if t.track_id not in used]
        if not stale:
            return
        if visible is None:
            seen = np.ones(len(stale), dtype=bool)
        elif self.probe_up_m > 0:
            centroids = np.array([t.centroid for t in stale])
            upper = centroids + np.array([0.0, 0.0, self.probe_up_m])
            both = visible(np.concatenate([centroids, upper]))
            seen = both[: len(stale)] | both[len(stale) :]
        else:
            seen = visible(np.array([t.centroid for t in stale]))
        for track, could_see in zip(stale, seen, strict=True):
            if not could_see:
                continue
            track.misses += 1
            track.missed += 1
            left = track.octomap.miss()  # the view without the entity is evidence in its octomap
            long_enough = now is None or now - track.last_seen >= self.min_lost_s
            if (track.misses > self.misses_allowed(track, now) or left == 0) and long_enough:
                del self.tracks[track.track_id]
                self._by_symbol.pop(track.symbol, None)
                result.dropped.append(track)

    def misses_allowed(self, track: Track, now: float | None) -> int:
        """Consecutive misses ``track`` tolerates at simulated time ``now``: ``max_misses``, or
        ``stale_misses`` once it has not been seen for ``stale_s`` seconds."""
        if self.stale_s is not None and now is not None and now - track.last_seen >= self.stale_s:
            return self.stale_misses
        return self.max_misses

    def _create(self, det: LLKU, now: float) -> Track:
        tid = next(_track_ids)
        octomap = EntityOctomap(
            self.resolution, reset_distance=self.reset_distance, ray_length=self.ray_length
        )
        centroid = det.position
        octomap.update(det.points, centroid, det.sensor_origin)
        track = Track(
            tid, self.cls, det.identity or f"{self.cls}_{tid}", centroid, octomap, now, now, det.confidence
        )
        track.support.append(det.uid)
        self._count_face(track, det)
        self.tracks[tid] = track
        self._by_symbol[track.symbol] = track
        return track

    def _update(self, track: Track, det: LLKU, now: float, distance: float | None = None) -> None:
        """``det`` updates ``track``; ``distance``: ``math.dist`` of its position from the track's centroid,
        when the caller has it."""
        new = det.position
        if distance is None:
            distance = math.dist(new, track.centroid)
        if distance >= self.radius:
            track.centroid = new
            track.missed = 0  # a new spot: the views of the old one say nothing of it
        else:
            g, old = self.gain, track.centroid
            track.centroid = (
                g * new[0] + (1.0 - g) * old[0],
                g * new[1] + (1.0 - g) * old[1],
                g * new[2] + (1.0 - g) * old[2],
            )
        track.octomap.update(det.points, track.centroid, det.sensor_origin)
        track.last_seen = now
        track.hits += 1
        track.misses = 0
        track.confidence = 0.5 * track.confidence + 0.5 * det.confidence
        track.support.append(det.uid)
        if self.face_pixels:
            self._count_face(track, det)

    def _count_face(self, track: Track, det: LLKU) -> None:
        if not self.face_pixels or det.identity is not None:
            return
        pixels = det.attributes.get("pixels", 0)
        if not isinstance(pixels, int | np.integer):
            return
        if pixels >= self.face_pixels:
            track.face_views += 1
