"""KGM-2, the cognitive model layer: LLKUs in, CKUs out, under the robot's role (seed 004, II.B and III.B).

One :class:`CognitiveLayer` component drains every percept (``percept.#``) at each step and:

* groups camera units by scan (a :class:`~knic.units.Scan` marker closes a frame) and, per entity
  class, runs the class's :class:`~knic.kgm2.tracking.Tracker` when the role says the class is due (its
  ``rate_hz`` for the room the camera is in; rate 0: not processed at all) in decreasing role priority;
  matched and new tracks update their octomap and are published as CKUs on ``cognition.<kind>.<symbol>``
  (their keys are a query of the track's octomap, run when a KP' first reads them);
  tracks dropped after their misses are published once with ``attributes["lost"] = True`` and no keys;
* passes robot pose, sound and device units through as CKUs (rate-limited by the role for their class);
* turns each location unit into a location CKU carrying the place's octomap (``cognition.location.<name>``).

The rooms the role's policies name come from the same location units: the layer adds each one to its own
:class:`~knic.spatial.LocationModel` the moment it is published (a subscription, so a camera KP asking
:meth:`CognitiveLayer.admits` in the same instant already finds the rooms).

Everything runs inside the component's ``step`` in simulated time: no threads, no wall clock.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from knic.bus import Bus, Message, topic_level
from knic.kgm2.roles import Policy, Role
from knic.kgm2.tracking import Track, Tracker
from knic.scheduler import Component
from knic.spatial import DEFAULT_RESOLUTION, ROOM, Location, LocationModel, keys_of
from knic.units import CKU, LLKU, Kind, Scan, make_cku

#: where KGM-1 publishes the places of the map
LOCATION_PERCEPTS = "percept.map.location"

#: tracker class of a person percept (people are one class; identity tells them apart)
PERSON_CLASS = "person"

#: the kinds KGM-2 tracks (camera units, grouped by scan); the others pass through
_TRACKED_KINDS = frozenset({Kind.OBJECT, Kind.PERSON})


@dataclass
class TrackingConfig:
    """Association parameters per kind.

    Radius (metres), misses tolerated, octomap resolution (metres), length of the rays cast into entity
    octomaps (metres, 0: from the sensor), least simulated seconds unseen before a missed track is dropped,
    and sightings near one far spot before a recognised entity's track jumps there.
    """

    object_radius: float = 0.4
    person_radius: float = 0.8
    object_max_misses: int = 5
    person_max_misses: int = 4
    resolution: float = DEFAULT_RESOLUTION
    ray_length: float = 1.0
    object_min_lost_s: float = 2.5
    person_min_lost_s: float = 2.5
    object_jump_confirm: int = 2
    person_jump_confirm: int = 2
    #: least mask pixels of a person's sighting in which the face recogniser could have named a known person
    #: (the robot's recogniser's own limit); an unnamed track counts such sightings (``face_views``)
    face_pixels: int = 40
    #: metres above a person track's centroid also tested for visibility (the upper body, see ``Tracker``)
    person_probe_up_m: float = 0.5
    #: metres per second a person track's association radius grows while unseen (see ``Tracker``)
    person_gate_growth: float = 0.2
    #: metres a person track's centroid moves before its octomap restarts (see ``Tracker``)
    person_reset_m: float = 0.3
    #: simulated seconds unseen after which a person track is stale, and the misses a stale track tolerates
    #: (see ``Tracker``): a person unseen for a while who is missed where the camera looks has walked away
    person_stale_s: float | None = 10.0
    person_stale_misses: int = 1


@dataclass
class CognitionStats:
    """Counters: units processed, units skipped by the role's rates, CKUs published, tracks dropped,
    detections set aside as label confusions."""

    processed: int = 0
    skipped: int = 0
    published: int = 0
    dropped: int = 0
    confusions: int = 0
    by_class: dict[str, int] = field(default_factory=lambda: defaultdict(int))


class CognitiveLayer(Component):
    """The KGM-2 component (see the module docstring).

    Args:
        bus: input (``percept``) and output (``cognition``) bus.
        role: the active role.
        config: association parameters (their ``resolution`` is the entity octomaps' and the CKU keys').
        frequency: Hz of simulated time; should be at least the role's top rate.
        name: component name (``source`` of the CKUs).
    """

    def __init__(
        self,
        bus: Bus,
        role: Role,
        *,
        config: TrackingConfig | None = None,
        frequency: float = 10.0,
        name: str = "kgm2.cognition",
    ) -> None:
        self.name = name
        self.frequency = frequency
        self.bus = bus
        self.role = role
        self.config = config or TrackingConfig()
        #: the rooms and furniture received from KGM-1's location units
        self.locations = LocationModel(self.config.resolution)
        for message in bus.latest(LOCATION_PERCEPTS):  # places published before this layer was built
            self._on_location(message)
        self._places = bus.subscribe(LOCATION_PERCEPTS, self._on_location)
        self.trackers: dict[str, Tracker] = {}
        self.stats = CognitionStats()
        self._inbox = bus.inbox("percept", capacity=20000)
        self._last_run: dict[tuple[str, str], float] = {}
        #: class -> stamp of the latest frame :meth:`admits` let through (the scan then processes it)
        self._admitted: dict[str, float] = {}
        #: hits after which a track counts as settled (see :meth:`_unsettled`)
        self.settled_hits = 3
        #: a label confusion is suspected only on a track seen this recently (simulated seconds): an object
        #: misread while the camera looks at it; a stale track of an object since moved away blocks nothing
        self.confusion_recent_s = 3.0
        self._topics: dict[tuple[Kind, str], str] = {}  # (kind, symbol) -> CKU topic
        self._policies: dict[tuple[str, str | None], Policy] = {}  # (class, room) -> policy of _policies_of
        self._policies_of = role

    # ------------------------------------------------------------------ lifecycle

    def _on_location(self, message: Message) -> None:
        unit = message.payload
        location = unit.attributes.get("location") if isinstance(unit, LLKU) else None
        if isinstance(location, Location):
            self.locations.add(location)

    def step(self, now: float) -> None:
        """Process every percept received since the previous step, in arrival order, scan by scan."""
        pending: dict[Kind, list[LLKU]] = defaultdict(list)
        for message in self._inbox.drain():
            payload = message.payload
            if isinstance(payload, Scan):
                self._scan(payload, pending.pop(payload.kind, []))
            elif isinstance(payload, LLKU):
                if payload.kind in _TRACKED_KINDS:
                    pending[payload.kind].append(payload)
                else:
                    self._passthrough(payload, message)
        for units in pending.values():  # units whose scan marker has not arrived: associate without misses
            if units:
                self._associate_scan(units, units[0].stamp, None, units[0].kind)

    def tracker(self, cls: str, kind: Kind) -> Tracker:
        """The tracker of a class (created on first use)."""
        found = self.trackers.get(cls)
        if found is None:
            cfg = self.config
            person = kind is Kind.PERSON
            found = Tracker(
                cls,
                radius=cfg.person_radius if person else cfg.object_radius,
                max_misses=cfg.person_max_misses if person else cfg.object_max_misses,
                resolution=cfg.resolution,
                ray_length=cfg.ray_length,
                min_lost_s=cfg.person_min_lost_s if person else cfg.object_min_lost_s,
                jump_confirm=cfg.person_jump_confirm if person else cfg.object_jump_confirm,
                face_pixels=cfg.face_pixels if person else 0,
                probe_up_m=cfg.person_probe_up_m if person else 0.0,
                gate_growth=cfg.person_gate_growth if person else 0.0,
                reset_distance=cfg.person_reset_m if person else None,
                stale_s=cfg.person_stale_s if person else None,
                stale_misses=cfg.person_stale_misses,
            )
            self.trackers[cls] = found
        return found

    def tracks(self) -> Iterable[Track]:
        """Every live track of every class."""
        for tracker in self.trackers.values():
            yield from tracker.tracks.values()

    # ------------------------------------------------------------------ camera scans

    def admits(self, cls: str, camera_position: tuple[float, float, float], stamp: float) -> bool:
        """The role's early filter, asked by a camera KP before it deprojects a frame's detections of ``cls``.

        True when the class is due under the role for the room the camera is in (its ``rate_hz``), or when
        its knowledge is unsettled (a first sighting, a young, missed or jumping track: evidence is processed
        at the camera's rate until it settles); always True when the camera is outside every room (the
        detection's own room then decides, in :meth:`step`); False for a class the role does not process.
        A frame let through is processed by the scan whatever the rate says; a class withheld is neither
        associated nor missed for that frame. ``camera_position``: world frame, metres; ``stamp``: the
        frame's simulated time.
        """
        room = self.locations.room_at(camera_position[0], camera_position[1])
        if room is None:
            return True
        policy = self.role.policy(cls, room)
        if policy.rate_hz <= 0:
            return False
        tracker = self.trackers.get(cls)
        admitted = (
            self._due(cls, "scan", policy, stamp)
            or tracker is None
            or not tracker.tracks
            or any(
                t.misses > 0 or t.jump is not None or t.hits < self.settled_hits
                for t in tracker.tracks.values()
            )
        )
        if admitted:
            self._admitted[cls] = stamp
        return admitted

    def _scan(self, scan: Scan, units: list[LLKU]) -> None:
        self._associate_scan(units, scan.stamp, scan, scan.kind)

    def _associate_scan(self, units: list[LLKU], stamp: float, scan: Scan | None, kind: Kind) -> None:
        person = kind is Kind.PERSON
        by_class: dict[str, list[LLKU]] = defaultdict(list)
        for unit in units:
            by_class[PERSON_CLASS if person else unit.label].append(unit)
        withheld = scan.withheld if scan is not None else frozenset()
        if kind is Kind.OBJECT:
            self._set_aside_confusions(by_class, withheld)
        classes = set(by_class)
        if scan is not None:
            classes.update(c for c, t in self.trackers.items() if t.tracks and (c == PERSON_CLASS) is person)
        if withheld:
            classes -= withheld
        camera_room = None
        if scan is not None:
            pos = scan.view.position
            camera_room = self.locations.room_at(float(pos[0]), float(pos[1]))
        # classes in decreasing role priority, then by name (unique: the policies are never compared)
        plans: list[tuple[int, str, Policy, list[LLKU]]] = []
        for cls in classes:
            dets = by_class.get(cls) or []
            room = camera_room
            if room is None and dets:
                p = dets[0].position
                room = self.locations.room_at(p[0], p[1])
            policy = self._policy(cls, room)
            plans.append((-policy.priority, cls, policy, dets))
        plans.sort()
        visible = scan.view.visible if scan is not None else None
        stats = self.stats
        for _, cls, policy, dets in plans:
            tracker = self.trackers.get(cls) or self.tracker(cls, kind)
            if (
                self._admitted.get(cls) != stamp
                and not self._due(cls, "scan", policy, stamp)
                and not (policy.rate_hz > 0 and self._unsettled(tracker, dets))
            ):
                stats.skipped += len(dets)
                continue
            if dets:
                result = tracker.associate(dets, stamp, visible)
                for track, det in result.updated:
                    self._publish_track(track, det, policy, stamp)
                for track, det in result.created:
                    self._publish_track(track, det, policy, stamp)
                dropped = result.dropped
            else:
                dropped = tracker.miss_scan(visible, stamp) if scan is not None else []
            stats.processed += len(dets)
            stats.by_class[cls] += len(dets)
            for track in dropped:
                self._publish_lost(track, kind, stamp)

    def _set_aside_confusions(
        self, by_class: dict[str, list[LLKU]], withheld: frozenset[str] = frozenset()
    ) -> None:
        """Drop the object detections that are most likely another object under a confused label.

        A detection of class X lying on a settled track of another class Y (within Y's radius), seen in the
        last ``confusion_recent_s``, away from X's own tracks, while no detection of Y explains Y's track in
        this scan, is Y seen under the wrong label: it must neither start an X track nor move X's track
        there. When both X and Y are detected at the spot (two objects side by side) the detection stands; so
        does it when Y's detections were ``withheld`` by the camera's role filter (nothing is known of Y).
        Counted in ``stats.confusions``.
        """
        trackers = self.trackers
        for cls, dets in list(by_class.items()):
            own = trackers.get(cls)
            kept = []
            for det in dets:
                if own is not None and det.identity:  # the common case, asked first (see _confused)
                    mine = own.by_symbol(det.identity)
                    if mine is not None and math.dist(det.position, mine.centroid) < own.radius:
                        kept.append(det)
                        continue
                if not self._confused(cls, det, by_class, withheld, own):
                    kept.append(det)
            if len(kept) < len(dets):
                self.stats.confusions += len(dets) - len(kept)
                by_class[cls] = kept

    def _confused(
        self,
        cls: str,
        det: LLKU,
        by_class: dict[str, list[LLKU]],
        withheld: frozenset[str],
        own: Tracker | None,
    ) -> bool:
        if own is not None:
            mine = own.by_symbol(det.identity) if det.identity else None
            if mine is not None and math.dist(det.position, mine.centroid) < own.radius:
                return False  # the common case: a recognised entity where its track is
            if any(math.dist(det.position, t.centroid) < own.radius for t in own.tracks.values()):
                return False
        for other_cls, tracker in self.trackers.items():
            if other_cls in (cls, PERSON_CLASS) or other_cls in withheld:
                continue
            for track in tracker.tracks.values():
                if (
                    track.hits < self.settled_hits
                    or det.stamp - track.last_seen > self.confusion_recent_s
                    or math.dist(det.position, track.centroid) >= tracker.radius
                ):
                    continue
                explained = any(
                    math.dist(d.position, track.centroid) < tracker.radius
                    for d in by_class.get(other_cls, [])
                )
                if not explained:
                    return True
        return False

    def _unsettled(self, tracker: Tracker, dets: list[LLKU]) -> bool:
        """Whether a class needs this scan although its role rate says it is not due.

        The role's rate keeps settled knowledge fresh; evidence that would change it is processed at the
        camera's rate until it settles, so confirming a sighting or a loss takes as few frames at a low rate
        as at the top one: a detection that no settled track (``settled_hits`` hits) explains, a pending
        far sighting of a recognised entity, a track being missed where the camera could see it, or a young
        track (fewer than ``settled_hits`` hits): every frame that could see it and did not is counted
        (``Track.missed``), so a spurious detection is not taken for an item seen twice.
        """
        radius = tracker.radius
        for track in tracker.tracks.values():
            if track.misses > 0 or track.jump is not None or track.hits < self.settled_hits:
                return True
        for det in dets:
            explained = False
            for track in tracker.tracks.values():
                if track.hits >= self.settled_hits and math.dist(det.position, track.centroid) < radius:
                    explained = det.identity is None or det.identity == track.symbol
                    if explained:
                        break
            if not explained:
                return True
        return False

    def _policy(self, cls: str, room: str | None) -> Policy:
        """The role's policy for ``cls`` in ``room``, remembered per role (roles are immutable data)."""
        if self._policies_of is not self.role:
            self._policies.clear()
            self._policies_of = self.role
        key = (cls, room)
        found = self._policies.get(key)
        if found is None:
            found = self._policies[key] = self.role.policy(cls, room)
        return found

    def _due(self, cls: str, stream: str, policy: Policy, stamp: float) -> bool:
        if policy.rate_hz <= 0:
            return False
        key = (cls, stream)
        last = self._last_run.get(key)
        if last is not None and stamp - last < 1.0 / policy.rate_hz - 1e-6:  # policy.period, rate_hz > 0
            return False
        self._last_run[key] = stamp
        return True

    def _publish_track(self, track: Track, det: LLKU, policy: Policy, stamp: float) -> None:
        octomap = track.octomap
        cku = make_cku(  # CKU(symbol, cls, kind, octomap, position, role_priority, stamp, ...), by position
            track.symbol,
            track.cls,
            det.kind,
            octomap.tree,
            track.centroid,
            policy.priority,
            stamp,
            track.confidence,
            octomap.read_keys,  # keys: a query the KP' run when they read them, not now
            (det.uid,),
            track.track_id,
            {
                "identified": det.identity is not None,
                "hits": track.hits,
                "missed": track.missed,
                "face_views": track.face_views,
                "sightings": track.sightings,
                "sensor_origin": det.sensor_origin,
            },
        )
        self._emit(cku)

    def _publish_lost(self, track: Track, kind: Kind, stamp: float) -> None:
        x, y, z = (float(v) for v in track.centroid)
        self.stats.dropped += 1
        cku = CKU(
            symbol=track.symbol,
            cls=track.cls,
            kind=kind,
            octomap=track.octomap.tree,
            keys=np.zeros((0, 3), dtype=np.int64),
            position=(x, y, z),
            role_priority=0,
            stamp=stamp,
            confidence=track.confidence,
            support=tuple(track.support),
            track_id=track.track_id,
            attributes={"lost": True, "last_keys": track.keys, "last_seen": track.last_seen},
        )
        self._emit(cku)

    # ------------------------------------------------------------------ other units

    def _passthrough(self, unit: LLKU, message: Message) -> None:
        if unit.kind is Kind.LOCATION:
            self._publish_location(unit)
            return
        cls = unit.label
        room = self.locations.room_at(unit.position[0], unit.position[1])
        policy = self.role.policy(cls, room)
        # sounds are events: never rate-limited away
        if unit.kind is not Kind.SOUND and not self._due(cls, unit.symbol, policy, unit.stamp):
            self.stats.skipped += 1
            return
        self.stats.processed += 1
        self.stats.by_class[cls] += 1
        cku = CKU(
            symbol=unit.symbol,
            cls=cls,
            kind=unit.kind,
            octomap=None,
            keys=keys_of(np.asarray([unit.position], dtype=np.float64), self.config.resolution),
            position=unit.position,
            role_priority=policy.priority,
            stamp=unit.stamp,
            confidence=unit.confidence,
            support=(unit.uid,),
            attributes=dict(unit.attributes),
        )
        self._emit(cku)

    def _publish_location(self, unit: LLKU) -> None:
        """A place of the map as a CKU carrying its octomap; a location unit without a place is skipped."""
        location = unit.attributes.get("location")
        if not isinstance(location, Location):
            self.stats.skipped += 1
            return
        volume = location.volume
        room = location.name if location.cls == ROOM else location.room
        cku = CKU(
            symbol=location.name,
            cls=location.cls,
            kind=Kind.LOCATION,
            octomap=volume.octree() if volume is not None else None,
            keys=np.zeros((0, 3), dtype=np.int64),
            position=unit.position,
            role_priority=self.role.policy(location.cls, room).priority,
            stamp=unit.stamp,
            confidence=1.0,
            support=(unit.uid,),
            attributes=dict(unit.attributes),
        )
        self._emit(cku)

    def _emit(self, cku: CKU) -> None:
        key = (cku.kind, cku.symbol)
        topic = self._topics.get(key)
        if topic is None:
            topic = self._topics[key] = f"cognition.{cku.kind.value}.{topic_level(cku.symbol)}"
        self.bus.publish(topic, cku, source=self.name, stamp=cku.stamp)
        self.stats.published += 1
