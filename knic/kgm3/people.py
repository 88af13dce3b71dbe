"""KP' for where people are: ``person_at`` (+ ``found``), retracted on evidence only, aged in time.

The shared place logic (sightings confirmed into a room, retraction by a lost track or an explored room) is
:class:`knic.kgm3.places._EntityPlaceKP`'s. People add: belief in time (a person not seen for their time to
live is kept ASSUMED at half confidence; the time to live is shorter when last seen walking and longer after
a long stay in the room), a person seen leaving, and visitors: people met for the first time become
``visitor_<n>`` instances.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import replace

from knic.bus import Bus
from knic.kgm3.places import _EntityPlaceKP
from knic.spatial import DEFAULT_RESOLUTION
from knic.units import CKU
from knowledge_base import BeliefStatus, Fact, KnowledgeBase


class PersonPlaceKP(_EntityPlaceKP):
    """``(person_at ?p ?room)`` and ``(found ?p)`` for recognised people and visitors, retracted only on
    evidence.

    Args:
        ttl_s: simulated seconds after the last sighting at which the person_at this KP' wrote ages (written
            ASSUMED at half confidence; the role's ``person_ttl_s``), for a person who stood still when last
            seen. The fact is never retracted for age: only a view of the place without them (KGM-2's lost
            track, an explored room) retracts it.
        moving_ttl_s: the same for a person who was walking when last seen (faster than ``walking_speed``
            m/s over the last ``speed_window_s`` seconds of sightings): they are likely elsewhere soon.
        dwell_share: a person standing still who has been seen in the same room for a while is likely to stay:
            their time to live is at least this share of how long they have been seen there (from the first
            sighting that put them in the room to the last), at most ``max_ttl_s``.
        visitor_views: face views without recognition after which an unnamed person becomes a visitor
            instance (see :meth:`instance_of`).
        resolution: metres, of the CKUs' voxel keys (KGM-2's tracking resolution).
        doorway_m: a person believed in one room and seen in the next stays believed where they were while
            their seen centroid is within this many metres of the believed room: the camera sees a body's
            near side, so someone stopping in a doorway looks up to a body radius inside the robot's room.
        walk_on_s: a person last seen walking and not seen for at least ``min_unseen_s`` seconds is
            predicted on along their last velocity for up to this many seconds (0: no prediction); when that
            walk leads at least ``doorway_m`` into another room through one of the believed room's doors
            (the map's doors, from the room's anchor; without them, into a room ``connected`` to it), they
            are taken to have walked out of view and out of the room: the belief is retracted (see
            :meth:`walked_out`).
        min_unseen_s: see ``walk_on_s``; longer than the gaps between sightings of a person in view.
        lost_grace_s: a track KGM-2 dropped when the person had not been seen for ``stale_s`` seconds
            retracts the belief only this many seconds later, unless the person is seen again meanwhile: a
            person unseen for a while may have moved a little within the room, so the spot where they were
            is empty while they are a step away, seen a moment later (0: at once).
        stale_s: see ``lost_grace_s`` (KGM-2's ``person_stale_s``).
    """

    pddl_type = "person"
    place_predicate = "person_at"

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        ttl_s: float = 30.0,
        needed: int = 2,
        min_confidence: float = 0.5,
        explored_grace_s: float = 15.0,
        moving_ttl_s: float = 10.0,
        dwell_share: float = 0.5,
        max_ttl_s: float = 120.0,
        visitor_views: int = 5,
        walking_speed: float = 0.3,
        speed_window_s: float = 1.5,
        frequency: float = 5.0,
        name: str = "kp'.person_at",
        resolution: float = DEFAULT_RESOLUTION,
        doorway_m: float = 0.3,
        walk_on_s: float = 4.0,
        min_unseen_s: float = 1.0,
        lost_grace_s: float = 3.0,
        stale_s: float = 10.0,
    ) -> None:
        super().__init__(
            name, frequency, bus, kb, "cognition.person", needed, min_confidence, explored_grace_s, resolution
        )
        self.ttl_s = ttl_s
        self.doorway_m = doorway_m
        self.walk_on_s = walk_on_s
        self.min_unseen_s = min_unseen_s
        #: metres beyond a door's half width where a walk still goes through it (the centroid's noise)
        self.door_margin_m = 0.3
        self._doors: dict[str, list[tuple[tuple[float, float], float, str | None]] | None] = {}
        self.lost_grace_s = lost_grace_s
        self.stale_s = stale_s
        #: person -> the lost CKU of their stale track, awaiting ``lost_grace_s``
        self._losing: dict[str, CKU] = {}
        self.anonymous_classes = frozenset({"person"})
        self.visitor_prefix = "visitor"
        self.visitor_views = visitor_views
        self.visitor_clearance = 1.0
        self.visitor_window_s = 3.0
        #: face views without recognition after which an unnamed person may be a visitor met before
        self.rebind_views = min(3, visitor_views)
        #: metres per second a person may walk: a visitor unseen for ``visitor_window_s`` who could have
        #: walked to where an unnamed person is seen well is out of sight (see :meth:`visitor_out_of_sight`)
        self.person_speed = 1.5
        #: seconds an unnamed person's sighting stays a candidate for a visitor whose track is lost later
        self.rebind_window_s = 15.0
        #: KGM-2 track id -> the latest CKU of an unnamed person seen well, not yet an instance
        self._unbound: dict[int, CKU] = {}
        #: tracks just bound to a visitor met before: their next sighting stands for all the track's hits
        self._just_bound: set[int] = set()
        self.moving_ttl_s = min(moving_ttl_s, ttl_s)
        self.dwell_share = dwell_share
        self.max_ttl_s = max(max_ttl_s, ttl_s)
        #: person -> (room, simulated time of the first sighting that put them there)
        self._in_room_since: dict[str, tuple[str, float]] = {}
        self.walking_speed = walking_speed
        self.speed_window_s = speed_window_s
        self._trail: dict[str, deque[tuple[float, tuple[float, float, float]]]] = {}
        #: KGM-2 track id -> the recent sightings of an unnamed person's track, not yet an instance: a visitor
        #: met again takes their track's trail (they were walking before they were known to be them)
        self._track_trails: dict[int, deque[tuple[float, tuple[float, float, float]]]] = {}

    def instance_of(self, cku: CKU) -> str | None:
        """As for every entity, and: a person met for the first time becomes a visitor.

        An unnamed person's track becomes the instance ``visitor_<n>`` once the face recogniser saw them well
        ``visitor_views`` times without knowing them (KGM-2's ``face_views``) and no known person was seen
        within ``visitor_clearance`` metres in the last ``visitor_window_s`` seconds (a known person whose
        face was missed in a few frames has a named track nearby); when a visitor met before is out of sight
        (:meth:`visitor_out_of_sight`) the track is that visitor met again. The track keeps the instance from
        then on.
        """
        anonymous = bool(cku.track_id) and cku.symbol == f"{cku.cls}_{cku.track_id}"
        if not anonymous:
            return super().instance_of(cku)
        found = self.discovered.get(cku.track_id)
        if found is not None or cku.attributes.get("lost"):
            self._unbound.pop(cku.track_id, None)
            self._track_trails.pop(cku.track_id, None)
            return found
        self._remember(self._track_trails.setdefault(cku.track_id, deque()), cku)
        views = int(cku.attributes.get("face_views", 0))
        if views < self.rebind_views or self.known_near(cku.position, cku.stamp):
            return None
        again = self.visitor_out_of_sight(cku.position, cku.stamp)
        if again is not None:
            self.bind(cku.track_id, again)
            return again
        if views < self.visitor_views:
            self._unbound[cku.track_id] = cku  # maybe the visitor, once their old track is gone
            return None
        self._unbound.pop(cku.track_id, None)
        return self.discover(self.visitor_prefix, cku)

    def rebind_pending(self, now: float) -> None:
        """A visitor's track was lost while an unnamed person, seen well ``rebind_views`` times in the last
        ``rebind_window_s`` seconds, was somewhere else: that person is the visitor, who had walked on (the
        robot looked away before the new track had ``visitor_views`` face views). Their latest sighting is
        processed as the visitor's, standing for as many sightings as the track had hits."""
        for tid, cku in list(self._unbound.items()):
            if now - cku.stamp > self.rebind_window_s:
                del self._unbound[tid]
        if not self._unbound:
            return
        tid, cku = max(self._unbound.items(), key=lambda item: item[1].stamp)
        again = self.visitor_out_of_sight(cku.position, cku.stamp)
        if again is None:
            return
        self.bind(tid, again)
        self.seen(replace(cku, symbol=again))

    def visitor_out_of_sight(
        self, where: tuple[float, float, float] | None = None, at: float | None = None
    ) -> str | None:
        """The visitor met before who is out of sight (KGM-2 lost their track, their place aged unseen, or
        they could have walked to ``where`` since last seen), last seen latest; None when every visitor met
        is in sight.

        A stranger met again after their track was lost is far likelier the visitor already met than a new
        one (visitors come one at a time): the new track takes that visitor's instance instead of making a
        ``visitor_<n+1>`` for the same person. So is an unnamed person seen well at ``where`` (at simulated
        time ``at``) while the visitor's own track has not been seen for ``visitor_window_s`` seconds and is
        near enough to have walked there at ``person_speed`` since: a track the camera no longer looks at
        does not speak for where the visitor is. A second stranger seen while the first is in view, or too
        far from them to be them, is a new visitor.
        """
        gone = [v for v in dict.fromkeys(self.discovered.values()) if not self._in_sight(v, where, at)]
        if not gone:
            return None
        return max(gone, key=lambda v: self.last_seen.get(v, -math.inf))

    def _in_sight(
        self, visitor: str, where: tuple[float, float, float] | None = None, at: float | None = None
    ) -> bool:
        """Whether KGM-2 tracks the visitor and their place is believed as observed (not aged: a visitor
        unseen for their time to live may well have walked on), and, given an unnamed person seen at
        ``where`` at ``at``, the visitor was seen lately or could not have walked there since."""
        if visitor not in self.tracked:
            return False
        if any(
            (prov := self.kb.why(fact)) is not None and prov.status is BeliefStatus.ASSUMED
            for fact in self.kb.facts(self.place_predicate, visitor)
        ):
            return False
        if where is None or at is None:
            return True
        seen, last = self.last_seen.get(visitor), self.last_position.get(visitor)
        if seen is None or last is None or at - seen < self.visitor_window_s:
            return True
        return math.dist(last[:2], where[:2]) > self.person_speed * (at - seen)

    def bind(self, track_id: int, visitor: str) -> None:
        """The track is ``visitor`` from now on; their older tracks are not (a lost CKU of an old track, where
        the visitor no longer is, must not retract where they are now)."""
        for tid in [t for t, v in self.discovered.items() if v == visitor]:
            del self.discovered[tid]
        self.discovered[track_id] = visitor
        self._unbound.pop(track_id, None)
        self._just_bound.add(track_id)
        trail = self._track_trails.pop(track_id, None)
        if trail:
            self._trail[visitor] = trail

    def known_near(self, position: tuple[float, float, float], stamp: float) -> bool:
        """Whether a known (not discovered) person was seen near ``position`` lately."""
        visitors = set(self.discovered.values())
        for symbol, seen in self.last_seen.items():
            if symbol in visitors or seen < stamp - self.visitor_window_s:
                continue
            where = self.last_position.get(symbol)
            if where is not None and math.dist(where[:2], position[:2]) < self.visitor_clearance:
                return True
        return False

    def seen(self, cku: CKU) -> None:
        """One sighting: remember the recent trail (for the walking test), then as for every entity.

        The first sighting of a track just bound to a visitor met before stands for as many sightings as the
        track had hits (the track saw them there that often before it was known to be them)."""
        if cku.track_id in self._just_bound:
            self._just_bound.discard(cku.track_id)
            hits = int(cku.attributes.get("hits", 1))
            if hits > int(cku.attributes.get("sightings", 1)):
                cku = replace(cku, attributes={**cku.attributes, "sightings": hits})
        trail = self._trail.setdefault(cku.symbol, deque())
        if not trail or trail[-1][0] < cku.stamp:
            self._remember(trail, cku)
        super().seen(cku)

    def _remember(self, trail: deque[tuple[float, tuple[float, float, float]]], cku: CKU) -> None:
        """Append the sighting to a trail, keeping the last ``speed_window_s`` seconds (and two sightings);
        a sighting from before a gap of more than twice that is dropped: the person was out of sight, and the
        way from there to here says nothing of their walking speed."""
        trail.append((cku.stamp, cku.position))
        while len(trail) > 2 and cku.stamp - trail[1][0] >= self.speed_window_s:
            trail.popleft()
        while len(trail) > 1 and cku.stamp - trail[0][0] > 2.0 * self.speed_window_s:
            trail.popleft()

    def place_of(self, cku: CKU) -> tuple[str | None, str | None]:
        """As for every entity, but the believed room while the seen centroid is within :attr:`doorway_m` of
        it on the far side from the camera (the camera sees a body's near side: someone in a doorway is not
        yet in the robot's room). When the CKU names the camera (``attributes["sensor_origin"]``) only the
        point :attr:`doorway_m` beyond the centroid along the line of sight counts: a person seen from the
        believed room, standing just beyond its doorway, is in the next room (kept there while seen, they
        were believed in the room they had left for as long as they stood by the door)."""
        room, furniture = super().place_of(cku)
        current = self.value_of(self.place_predicate, cku.symbol)
        if room is None or current is None or room == current or self.doorway_m <= 0:
            return room, furniture
        x, y, _ = cku.position
        m = self.doorway_m
        origin = cku.attributes.get("sensor_origin")
        near: tuple[tuple[float, float], ...]
        if isinstance(origin, tuple) and len(origin) >= 2:
            dx, dy = x - float(origin[0]), y - float(origin[1])
            norm = math.hypot(dx, dy)
            near = ((x + m * dx / norm, y + m * dy / norm),) if norm > 1e-6 else ()
        else:
            near = ((x + m, y), (x - m, y), (x, y + m), (x, y - m))
        if any(self.locations.room_at(px, py) == current for px, py in near):
            return current, furniture
        return room, furniture

    def velocity(self, symbol: str) -> tuple[float, float] | None:
        """The person's planar velocity (m/s) over their last sightings, None when too few."""
        trail = self._trail.get(symbol)
        if not trail or len(trail) < 2:
            return None
        (t0, p0), (t1, p1) = trail[0], trail[-1]
        if t1 - t0 < 0.5 * self.speed_window_s:
            return None
        return ((p1[0] - p0[0]) / (t1 - t0), (p1[1] - p0[1]) / (t1 - t0))

    def walking(self, symbol: str) -> bool:
        """Whether the person moved faster than ``walking_speed`` over their last sightings."""
        v = self.velocity(symbol)
        return v is not None and math.hypot(*v) > self.walking_speed

    def walked_out(self, symbol: str, believed: str, now: float) -> bool:
        """Whether the person, last seen walking and unseen since, has walked out of the believed room.

        Their last sighting is carried on along their velocity for the time unseen, at most ``walk_on_s``
        seconds: when that point and the point ``doorway_m`` short of it (clearly through, not in a doorway)
        lie in another room, and the walk leaves the believed room through one of its doors to that room
        (within ``door_margin_m`` of the opening), the person walked on out of view (the camera turned away
        as they left). A walk that leads into a wall counts for nothing. Without a map of the doors, a walk
        into a room ``connected`` to the believed one counts."""
        seen = self.last_seen.get(symbol)
        trail = self._trail.get(symbol)
        if self.walk_on_s <= 0 or seen is None or not trail or now - seen < self.min_unseen_s:
            return False
        v = self.velocity(symbol)
        speed = math.hypot(*v) if v is not None else 0.0
        if v is None or speed <= self.walking_speed:
            return False
        x, y, _ = trail[-1][1]
        dt = min(now - seen, self.walk_on_s)
        px, py = x + v[0] * dt, y + v[1] * dt
        room = self.locations.room_at(px, py)
        if room is None or room == believed:
            return False
        back = self.doorway_m / speed
        if self.locations.room_at(px - v[0] * back, py - v[1] * back) != room:
            return False
        doors = self.doors_of(believed)
        if doors is None:  # no map of the doors: the rooms must at least be connected
            return not self.kb.facts("connected") or bool(self.kb.facts("connected", believed, room))
        # where the walk leaves the believed room must be one of its doors to that room
        steps = max(1, math.ceil(math.hypot(px - x, py - y) / 0.05))
        for k in range(1, steps + 1):
            cx, cy = x + (px - x) * k / steps, y + (py - y) * k / steps
            if self.locations.room_at(cx, cy) != believed:
                return any(
                    to == room and math.dist(at, (cx, cy)) <= 0.5 * width + self.door_margin_m
                    for at, width, to in doors
                )
        return False

    def doors_of(self, room: str) -> list[tuple[tuple[float, float], float, str | None]] | None:
        """The room's doors from its anchor in the knowledge base (the map the robot was given): (centre,
        width, the room beyond); None when the anchor names no doors."""
        found = self._doors.get(room)
        if found is None and room not in self._doors:
            geometry = self.kb.anchor(room) or {}
            raw = geometry.get("doors") if isinstance(geometry, dict) else None
            if isinstance(raw, list):
                found = [
                    ((float(d["position"][0]), float(d["position"][1])), float(d["width"]), d.get("to"))
                    for d in raw
                    if isinstance(d, dict)
                ]
            self._doors[room] = found
        return found

    def lost(self, cku: CKU) -> None:
        """As for every entity, but a stale track's loss (the person unseen for ``stale_s`` before KGM-2
        dropped it) is held back ``lost_grace_s`` seconds (see :meth:`settle_losses`)."""
        last = cku.attributes.get("last_seen")
        stale = isinstance(last, int | float) and cku.stamp - float(last) >= self.stale_s
        if self.lost_grace_s <= 0 or not stale:
            self._losing.pop(cku.symbol, None)
            super().lost(cku)
            return
        self.tracked.discard(cku.symbol)
        self._losing[cku.symbol] = cku

    def settle_losses(self, now: float) -> None:
        """The stale losses held back: cancelled by a sighting of the person since, carried out (the
        belief retracted as for any lost track) once ``lost_grace_s`` passed."""
        for symbol, cku in list(self._losing.items()):
            if self.last_seen.get(symbol, -math.inf) > cku.stamp:
                del self._losing[symbol]
            elif now - cku.stamp >= self.lost_grace_s:
                del self._losing[symbol]
                super().lost(replace(cku, stamp=now))

    def left_belief(self, symbol: str, believed: str, room: str | None) -> bool:
        """A person whose track was last seen outside the believed room, after the belief was made, and is
        not there either, was seen leaving: where they are is unknown (the belief is retracted)."""
        prov = self.kb.why(Fact(self.place_predicate, (symbol, believed)))
        return prov is not None and room != believed and self.last_seen.get(symbol, -math.inf) >= prov.since

    def write_place(
        self, symbol: str, room: str, furniture: str | None, at: float, support: tuple[str, ...], conf: float
    ) -> None:
        """As for every entity; a new room starts the person's dwell there."""
        held = self._in_room_since.get(symbol)
        if held is None or held[0] != room:
            self._in_room_since[symbol] = (room, at)
        super().write_place(symbol, room, furniture, at, support, conf)

    def forget_place(self, symbol: str, at: float, support: tuple[str, ...]) -> None:
        """As for every entity; the dwell ends."""
        self._in_room_since.pop(symbol, None)
        super().forget_place(symbol, at, support)

    def ttl_of(self, symbol: str) -> float:
        """Seconds the person's place lives after their last sighting: ``moving_ttl_s`` when last seen
        walking, else ``ttl_s`` or, when longer, ``dwell_share`` of their dwell in the room (capped)."""
        if self.walking(symbol):
            return self.moving_ttl_s
        held = self._in_room_since.get(symbol)
        if held is None:
            return self.ttl_s
        dwell = self.last_seen.get(symbol, held[1]) - held[1]
        return min(self.max_ttl_s, max(self.ttl_s, self.dwell_share * dwell))

    def step(self, now: float) -> None:
        """Process sightings and explored rooms, bind a visitor met again (:meth:`rebind_pending`), settle
        the stale losses held back (:meth:`settle_losses`), retract the place of a person who walked on out of
        view and out of the room (:meth:`walked_out`), then age the beliefs of people unseen for their TTL."""
        super().step(now)
        self.rebind_pending(now)
        self.settle_losses(now)
        for fact in self.kb.facts("person_at"):
            symbol = fact.args[0]
            prov = self.kb.why(fact)
            if prov is None or prov.source != self.name:
                continue
            if self.walked_out(symbol, fact.args[1], now):
                self.forget_place(symbol, now, ())
                continue
            if prov.status is not BeliefStatus.OBSERVED:
                continue
            if now - self.last_seen.get(symbol, prov.since) > self.ttl_of(symbol):
                self.assert_fact(
                    "person_at", *fact.args, at=now, confidence=0.5 * prov.confidence, assumed=True
                )
