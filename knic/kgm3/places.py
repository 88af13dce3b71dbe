"""KP' for where things are: ``robot_at``, ``object_at`` / ``object_on`` (+ ``found``), and the place logic
``person_at`` shares (its KP', :class:`knic.kgm3.people.PersonPlaceKP`, adds belief in time and visitors).

Each consumes one CKU stream and intersects the entity's occupied voxel keys with the room prisms (the
locations' octomaps) and the furniture support prisms (seed 004, III.C: "check the spatial intersection of
each octomap of people with each octomap of locations"); the places come from the location CKU stream. The
room holding most of an entity's voxels is where it is; an item whose voxels fall at least
``min_support_share`` into a surface's support prism is on that furniture. Once an item is believed on a
surface, a view that puts too few of its voxels on it (the item at the frame edge or half hidden) keeps it
there while the item's centre stays over the surface's footprint.

Retraction:

* a confirmed new place retracts the old one (the predicates are single-valued);
* a track KGM-2 dropped after repeated misses where the camera could see it (``attributes["lost"]``; KGM-2
  drops a track only after several misses over seconds, so a brief occlusion retracts nothing) retracts
  the place it was believed at, and ``found``: the entity is not where we thought;
* a room explored after the belief was made, without the entity being seen since, retracts it as well.

Nothing is retracted for want of news: a person sitting still out of view keeps ``person_at``. A person not
seen for the role's ``person_ttl_s`` (sooner, ``moving_ttl_s``, when last seen walking) keeps the fact with
its belief aged: it is re-written ASSUMED at half its confidence (belief in time), and the next sighting
makes it OBSERVED again.

Items the robot holds or has given to someone are left to the actions that moved them. An item seen in a
person's hands (off every surface, at hand height next to a recognised person,
:class:`knic.kgm3.carried.PeopleHands`) is confirmed like a place and written ``(has ?p ?o)`` by this KP',
its ``object_at`` / ``object_on`` retracted; seen at a place again, or its track lost, that ``has`` goes.
"""

from __future__ import annotations

import logging
from dataclasses import replace

import numpy as np

from core.errors import KnowledgeBaseError
from knic.bus import Bus
from knic.kgm3.base import Confirmer, KPPrime
from knic.kgm3.carried import PeopleHands
from knic.spatial import DEFAULT_RESOLUTION, points_in_polygon
from knic.units import CKU
from knowledge_base import BeliefStatus, Fact, KnowledgeBase

log = logging.getLogger(__name__)

#: the place value of an item believed in a person's hands: ``(HAND, person)``
HAND = "@hand"


class RobotAtKP(KPPrime):
    """``(robot_at ?r ?room)`` from the localisation CKU and the room octomaps.

    The hysteresis is in space, not in time: a pose within ``boundary_m`` of the believed room keeps it (the
    localisation's noise scatters a robot standing in a doorway across the boundary), and a pose farther
    inside another room is that room at once (``needed`` 1: a second reading only adds a pose period of
    delay to every room change). ``boundary_m`` is about 2.5 standard deviations of the localisation's
    position noise (2 cm per axis on the default robot, ``worlds/noise.yaml``): a standing robot's noise
    crosses it about once in a hundred readings, and a reading that does is undone by the next.
    """

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        needed: int = 1,
        frequency: float = 10.0,
        name: str = "kp'.robot_at",
        boundary_m: float = 0.05,
    ) -> None:
        super().__init__(name, frequency, bus, kb, "cognition.robot", places=True)
        self.confirmer: Confirmer[str] = Confirmer(needed)
        self.boundary_m = boundary_m

    def room_of(self, x: float, y: float, current: str | None) -> str | None:
        """The room at ``(x, y)``, but the believed one while the pose is within ``boundary_m`` of it: a
        robot standing in a doorway, its localisation noise scattering the pose across the boundary, stays
        where it was believed until it is clearly through."""
        room = self.locations.room_at(x, y)
        if room is None or current is None or room == current or self.boundary_m <= 0:
            return room
        m = self.boundary_m
        near = ((x + m, y), (x - m, y), (x, y + m), (x, y - m))
        return current if any(self.locations.room_at(px, py) == current for px, py in near) else room

    def step(self, now: float) -> None:
        """Confirm the room of every pose received; write robot_at when it changes."""
        assert self.inbox is not None
        for message in self.inbox.drain():
            cku: CKU = message.payload
            x, y, _ = cku.position
            if not self.is_a(cku.symbol, "robot"):
                continue
            current = self.value_of("robot_at", cku.symbol)
            room = self.room_of(x, y, current)
            if room is None:
                continue
            if self.confirmer.observe(cku.symbol, room, cku.confidence, current, cku.stamp):
                support = (cku.uid, *cku.support)
                with self.kb.batch():
                    self.assert_fact("robot_at", cku.symbol, room, at=cku.stamp, support=support)
                    self.retract_all(
                        "robot_at", cku.symbol, None, at=cku.stamp, keep=_fact("robot_at", cku.symbol, room)
                    )
            elif room == current:
                self.assert_fact("robot_at", cku.symbol, room, at=cku.stamp, support=(cku.uid, *cku.support))


def _fact(predicate: str, *args: str) -> Fact:
    return Fact(predicate, tuple(args))


class _EntityPlaceKP(KPPrime):
    """Shared logic of the object and person place KP'."""

    pddl_type = "entity"
    place_predicate = "object_at"
    #: least track hits of a sighting whose position becomes the entity's last known position
    min_hits_for_position = 2
    #: least hits of the track behind a sighting that confirms a new place (see :meth:`established`; 0: any)
    min_track_hits = 0

    def __init__(
        self,
        name: str,
        frequency: float,
        bus: Bus,
        kb: KnowledgeBase,
        pattern: str,
        needed: int,
        min_confidence: float,
        explored_grace_s: float,
        resolution: float,
        window_s: float = 2.0,
    ) -> None:
        super().__init__(name, frequency, bus, kb, pattern, places=True, resolution=resolution)
        self.confirmer: Confirmer[tuple[str | None, str | None]] = Confirmer(needed, min_confidence, window_s)
        self.last_seen: dict[str, float] = {}
        #: entities KGM-2 tracks now (a CKU came, no lost CKU since): their absence is KGM-2's to judge
        self.tracked: set[str] = set()
        self.last_position: dict[str, tuple[float, float, float]] = {}
        self.explored_grace_s = explored_grace_s
        #: simulated seconds after a room becomes explored before beliefs in it are checked against it (the
        #: look-around that made it explored may not have reached the entity's spot yet)
        self.explored_settle_s = 6.0
        #: KGM-2 track id -> the instance discovered for it (see :meth:`instance_of`)
        self.discovered: dict[int, str] = {}
        #: least hits of an anonymous track before it becomes an instance
        self.discover_hits = 3
        #: classes whose anonymous tracks never become instances
        self.anonymous_classes: frozenset[str] = frozenset()

    def step(self, now: float) -> None:
        """Process the CKUs received, then retract beliefs contradicted by explored rooms (and TTLs)."""
        assert self.inbox is not None
        for message in self.inbox.drain():
            cku: CKU = message.payload
            symbol = self.instance_of(cku)
            if symbol is None or self.moved_by_action(symbol):
                continue
            if symbol != cku.symbol:
                cku = replace(cku, symbol=symbol)
            if cku.attributes.get("lost"):
                self.lost(cku)
            else:
                self.seen(cku)
        self.check_explored(now)

    def moved_by_action(self, symbol: str) -> bool:
        """True when an action, not perception, owns where the entity is (held or handed over)."""
        return False

    def instance_of(self, cku: CKU) -> str | None:
        """The knowledge base's instance a CKU is about, discovering a new one when due; None: ignore it.

        A CKU of a known instance is about that instance. A settled anonymous track (at least
        ``discover_hits`` hits) of an entity KGM-1 could not name -- a second mug, when the class no longer
        names one item -- becomes a new instance ``<class>_<n>`` (the first free ``n`` from 1), added OBSERVED
        with the CKU as support; its track keeps that instance from then on. Discovery is off for classes in
        :attr:`anonymous_classes` (an unrecognised person stays "someone": the same person recognised later
        would be counted twice).
        """
        anonymous = bool(cku.track_id) and cku.symbol == f"{cku.cls}_{cku.track_id}"  # KGM-2's track name
        if not anonymous:
            return cku.symbol if self.is_a(cku.symbol, self.pddl_type) else None
        found = self.discovered.get(cku.track_id)
        if found is not None or cku.attributes.get("lost"):
            return found
        if cku.cls in self.anonymous_classes or int(cku.attributes.get("hits", 1)) < self.discover_hits:
            return None
        return self.discover(cku.cls, cku)

    def discover(self, prefix: str, cku: CKU) -> str | None:
        """Add the instance ``<prefix>_<n>`` (the first free ``n`` from 1) for the CKU's track; None when the
        knowledge base refuses it."""
        n = 1
        while self.kb.type_of(f"{prefix}_{n}") is not None:
            n += 1
        name = f"{prefix}_{n}"
        try:
            self.kb.add_instance(
                self.pddl_type,
                name,
                source=self.name,
                at=cku.stamp,
                status=BeliefStatus.OBSERVED,
                support=(cku.uid, *cku.support),
            )
        except KnowledgeBaseError as exc:
            self.writes.rejected += 1
            log.warning("%s: cannot add the discovered instance %s: %s", self.name, name, exc)
            return None
        self.discovered[cku.track_id] = name
        return name

    def place_of(self, cku: CKU) -> tuple[str | None, str | None]:
        """(room, furniture or None) from the entity's voxels."""
        room, _ = self.locations.rooms.best(cku.keys)
        return room, None

    def seen(self, cku: CKU) -> None:
        """One observation of the entity."""
        self.last_seen[cku.symbol] = cku.stamp
        self.tracked.add(cku.symbol)
        if int(cku.attributes.get("hits", self.min_hits_for_position)) >= self.min_hits_for_position:
            # a track's first sighting (a false positive or a label confusion more often than not) never
            # moves the entity's anchored position
            self.last_position[cku.symbol] = cku.position
        room, furniture = self.place_of(cku)
        if room is None:
            return
        current = self.current_value(cku.symbol)
        support = (cku.uid, *cku.support)
        weight = int(cku.attributes.get("sightings", 1))
        if self.confirmer.observe(
            cku.symbol, (room, furniture), cku.confidence, current, cku.stamp, weight, self.established(cku)
        ):
            with self.kb.batch():
                self.write_place(cku.symbol, room, furniture, cku.stamp, support, cku.confidence)
        elif current == (room, furniture):
            # the belief already holds (maybe as an action's effect): mark it observed, once
            self.write_place(cku.symbol, room, furniture, cku.stamp, support, cku.confidence)

    def established(self, cku: CKU) -> bool:
        """Whether the track behind ``cku`` has been seen consistently enough for its sighting to confirm a
        new place: at least ``min_track_hits`` hits, and missed in fewer of the scans that could see it at
        its spot (KGM-2's ``missed``, counted in every frame while the track is young) than detected.

        A real item in view is detected in most frames; a false positive or a label confusion is a one-off
        whose spot the camera then sees empty, frame after frame: two of them landing near each other (a
        patch of a table read as "soap" twice in two seconds) make a track of two hits and several misses,
        which confirms no place however many sightings the confirmer has counted. Its sightings still count
        toward the place, so a real item is confirmed as soon as its track is consistent. CKUs without these
        counts (not from KGM-2's tracker) are established.
        """
        if self.min_track_hits <= 0:
            return True
        hits = int(cku.attributes.get("hits", self.min_track_hits))
        missed = int(cku.attributes.get("missed", 0))
        return hits >= self.min_track_hits and missed < hits

    def current_value(self, symbol: str) -> tuple[str | None, str | None]:
        """What the knowledge base holds of the entity's place, as the confirmer compares it:
        ``(room, furniture)``."""
        return (self.value_of(self.place_predicate, symbol), self.current_support(symbol))

    def current_support(self, symbol: str) -> str | None:
        """The furniture the entity is believed on (None for people)."""
        return None

    def write_place(
        self, symbol: str, room: str, furniture: str | None, at: float, support: tuple[str, ...], conf: float
    ) -> None:
        """Assert the entity's room (and furniture) and ``found``; retract the other places."""
        self.assert_fact(self.place_predicate, symbol, room, at=at, support=support, confidence=conf)
        keep = _fact(self.place_predicate, symbol, room)
        self.retract_all(self.place_predicate, symbol, None, at=at, keep=keep, support=support)
        self.assert_fact("found", symbol, at=at, support=support, confidence=conf)

    def forget_place(self, symbol: str, at: float, support: tuple[str, ...]) -> None:
        """The entity is no longer known to be where it was: retract its place and ``found``."""
        with self.kb.batch():
            self.retract_all(self.place_predicate, symbol, None, at=at, support=support)
            self.retract_fact("found", symbol, at=at, support=support)
        self.confirmer.forget(symbol)

    def lost(self, cku: CKU) -> None:
        """KGM-2 dropped the entity's track although the camera could see where it was."""
        self.tracked.discard(cku.symbol)
        believed = self.value_of(self.place_predicate, cku.symbol)
        last_keys = cku.attributes.get("last_keys")
        keys = last_keys if isinstance(last_keys, np.ndarray) else cku.keys
        room, _ = self.locations.rooms.best(keys)
        if room is None:
            room = self.locations.room_at(cku.position[0], cku.position[1])
        if believed is not None and (believed == room or self.left_belief(cku.symbol, believed, room)):
            self.forget_place(cku.symbol, cku.stamp, (cku.uid, *cku.support))

    def left_belief(self, symbol: str, believed: str, room: str | None) -> bool:
        """Whether a track lost outside the believed room also refutes the belief (default: no; an item's
        track may have wandered off on a confusion)."""
        return False

    def check_explored(self, now: float) -> None:
        """Retract beliefs about rooms explored since, when the entity was not seen during the exploration.

        Only for entities KGM-2 does not track (a belief from an action's effect, from before a restart, or
        whose track was dropped): a tracked entity's absence is judged by KGM-2's misses where the camera
        could see its voxels (a lost track), not by the room's coverage, which says nothing of the entity's
        own spot and meets CKUs thinned by the role's rates (an item seen at 1 Hz in a room swept in a few
        seconds was retracted and re-asserted within a second: a flap)."""
        for fact in self.kb.facts(self.place_predicate):
            symbol, room = fact.args
            if self.moved_by_action(symbol) or symbol in self.tracked:
                continue
            explored = self.kb.why(Fact("explored", (room,)))
            belief = self.kb.why(fact)
            if explored is None or belief is None or belief.since >= explored.since:
                continue
            if now - explored.since < self.explored_settle_s:
                continue  # the camera is still in the room: let the sightings of this instant come in
            seen = self.last_seen.get(symbol, float("-inf"))
            if belief.status is BeliefStatus.EFFECT:  # the robot put it there itself: as good as a sighting
                seen = max(seen, belief.since)
            if seen < explored.since - self.explored_grace_s:
                self.forget_place(symbol, now, ())


class ObjectPlaceKP(_EntityPlaceKP):
    """``(object_at ?o ?room)``, ``(object_on ?o ?furniture)`` and ``(found ?o)`` for items.

    Args:
        min_support_share: least share of the item's voxels inside a surface's support prism for object_on.
        window_s: most simulated seconds between two sightings that confirm a new place together. Items stand
            still and are seen at the role's class rate (1 Hz for most), often in glimpses (a small glass
            behind a bottle: two sightings 3 s apart); a false sighting far from the item's track is held back
            by KGM-2 until seen again there, so a longer window than for people costs no precision.
        anchors: also anchor the item's last known position in the knowledge base (``set_anchor``) when it
            moved more than ``anchor_step`` metres.
        min_track_hits: least hits of an item's track before its sightings confirm a new place (see
            :meth:`established`, which also asks the track to have been detected in more of the frames that
            could see it than not): two spurious detections that happened to land together confirm nothing.
        resolution: metres, of the CKUs' voxel keys (KGM-2's tracking resolution).
    """

    pddl_type = "item"
    place_predicate = "object_at"

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        needed: int = 2,
        min_confidence: float = 0.5,
        min_support_share: float = 0.2,
        explored_grace_s: float = 15.0,
        window_s: float = 10.0,
        anchors: bool = True,
        anchor_step: float = 0.2,
        frequency: float = 5.0,
        name: str = "kp'.object_at",
        resolution: float = DEFAULT_RESOLUTION,
        min_track_hits: int = 1,
    ) -> None:
        super().__init__(
            name,
            frequency,
            bus,
            kb,
            "cognition.object",
            needed,
            min_confidence,
            explored_grace_s,
            resolution,
            window_s,
        )
        self.min_support_share = min_support_share
        self.min_track_hits = min_track_hits
        #: the recognised people's places, for items seen in someone's hands
        self.hands = PeopleHands(bus, lambda symbol: self.is_a(symbol, "person"))
        self.anchors = anchors
        self.anchor_step = anchor_step
        self._anchored: dict[str, tuple[float, float, float]] = {}

    def moved_by_action(self, symbol: str) -> bool:
        """Held by the robot or handed to a person by it: the actions own its place (a ``has`` this KP'
        wrote, an item seen in someone's hands, stays perception's)."""
        if self.kb.facts("holding", None, symbol):
            return True
        return any(self._source(f) != self.name for f in self.kb.facts("has", None, symbol))

    def _source(self, fact: Fact) -> str | None:
        prov = self.kb.why(fact)
        return prov.source if prov is not None else None

    def holder_of(self, symbol: str) -> str | None:
        """The person this KP' believes holds the item (its own ``has``), or None."""
        for fact in self.kb.facts("has", None, symbol):
            if self._source(fact) == self.name:
                return fact.args[0]
        return None

    def current_value(self, symbol: str) -> tuple[str | None, str | None]:
        """``(HAND, person)`` while the item is believed in someone's hands, else its room and surface."""
        holder = self.holder_of(symbol)
        return (HAND, holder) if holder is not None else super().current_value(symbol)

    def seen(self, cku: CKU) -> None:
        """One sighting: in a person's hands (off every surface, at hand height next to them) it confirms
        ``(has ?p ?o)``; elsewhere, as for every entity."""
        room, furniture = self.place_of(cku)
        holder = self.hands.holder(cku) if room is not None and furniture is None else None
        if holder is None:
            super().seen(cku)
            return
        self.last_seen[cku.symbol] = cku.stamp
        self.tracked.add(cku.symbol)
        current = self.current_value(cku.symbol)
        support = (cku.uid, *cku.support)
        weight = int(cku.attributes.get("sightings", 1))
        decisive = self.established(cku)
        if self.confirmer.observe(
            cku.symbol, (HAND, holder), cku.confidence, current, cku.stamp, weight, decisive
        ):
            self.write_holder(cku.symbol, holder, cku.stamp, support, cku.confidence)

    def write_holder(
        self, symbol: str, person: str, at: float, support: tuple[str, ...], conf: float
    ) -> None:
        """The item is in ``person``'s hands: assert ``has`` and ``found``, retract its places."""
        with self.kb.batch():
            self.assert_fact("has", person, symbol, at=at, support=support, confidence=conf)
            self._retract_held(symbol, at, support, keep=person)
            self.retract_all("object_at", symbol, None, at=at, support=support)
            self.retract_all("object_on", symbol, None, at=at, support=support)
            self.assert_fact("found", symbol, at=at, support=support, confidence=conf)

    def _retract_held(
        self, symbol: str, at: float, support: tuple[str, ...], keep: str | None = None
    ) -> None:
        """Retract this KP''s own ``has`` facts about the item (but ``keep``'s)."""
        for fact in self.kb.facts("has", None, symbol):
            if fact.args[0] != keep and self._source(fact) == self.name:
                self.retract_fact("has", *fact.args, at=at, support=support)

    def lost(self, cku: CKU) -> None:
        """As for every entity; an item believed in someone's hands whose track KGM-2 dropped where the
        camera could see it is no longer known to be with them."""
        # the spot seen empty, frame after frame, refutes the sightings still pending there: a later spurious
        # detection at the same spot starts afresh instead of completing them
        self.confirmer.forget(cku.symbol)
        if self.holder_of(cku.symbol) is not None:
            self.tracked.discard(cku.symbol)
            self.forget_place(cku.symbol, cku.stamp, (cku.uid, *cku.support))
            return
        super().lost(cku)

    def step(self, now: float) -> None:
        """As for every entity, then: an item held or handed over is on no furniture any more."""
        super().step(now)
        for predicate in ("holding", "has"):
            for fact in self.kb.facts(predicate):
                # the pick's PDDL effects cannot name the furniture the item left, so its object_on stays
                self.retract_all("object_on", fact.args[1], None, at=now)

    def place_of(self, cku: CKU) -> tuple[str | None, str | None]:
        """(room, surface) from the item's voxels; the surface only if it stands in that room."""
        room, _ = self.locations.rooms.best(cku.keys)
        furniture, share = self.locations.furniture.best(cku.keys)
        if furniture is not None and (
            share < self.min_support_share or self.locations.furniture_room.get(furniture) != room
        ):
            furniture = None
        if furniture is None and room is not None:
            # hysteresis: a partial view (the item at the frame edge, half hidden) that puts few voxels on the
            # surface it is believed on does not take it off while its centre stays over that surface
            believed = self.current_support(cku.symbol)
            footprint = self.locations.footprints.get(believed) if believed else None
            if (
                believed is not None
                and footprint is not None
                and self.locations.furniture_room.get(believed) == room
                and bool(points_in_polygon(np.array([cku.position[:2]]), footprint)[0])
            ):
                furniture = believed
        return room, furniture

    def current_support(self, symbol: str) -> str | None:
        """The surface the item is believed on."""
        return self.value_of("object_on", symbol)

    def write_place(
        self, symbol: str, room: str, furniture: str | None, at: float, support: tuple[str, ...], conf: float
    ) -> None:
        """Assert object_at, object_on (or retract it when on no surface) and found; anchor the position.
        An item seen at a place is in nobody's hands (this KP''s ``has`` goes)."""
        self._retract_held(symbol, at, support)
        super().write_place(symbol, room, furniture, at, support, conf)
        if furniture is not None:
            self.assert_fact("object_on", symbol, furniture, at=at, support=support, confidence=conf)
            keep = _fact("object_on", symbol, furniture)
            self.retract_all("object_on", symbol, None, at=at, keep=keep, support=support)
        else:
            self.retract_all("object_on", symbol, None, at=at, support=support)
        self._anchor(symbol, at, support)

    def forget_place(self, symbol: str, at: float, support: tuple[str, ...]) -> None:
        """Retract object_at, object_on, found and this KP''s ``has``."""
        with self.kb.batch():
            self._retract_held(symbol, at, support)
            super().forget_place(symbol, at, support)
            self.retract_all("object_on", symbol, None, at=at, support=support)

    def _anchor(self, symbol: str, at: float, support: tuple[str, ...]) -> None:
        position = self.last_position.get(symbol)
        if not self.anchors or position is None:
            return
        previous = self._anchored.get(symbol)
        if previous is not None and float(np.linalg.norm(np.subtract(position, previous))) < self.anchor_step:
            return
        self._anchored[symbol] = position
        self.kb.set_anchor(
            symbol,
            {"pose": {"position": list(position)}, "frame": "world"},
            source=self.name,
            at=at,
            status=BeliefStatus.OBSERVED,
            support=support,
        )
