"""KP' for searching: what has been explored, and where an entity of unknown location may be.

:class:`ExploredKP` asserts ``(explored ?room)`` once the object camera has covered enough of the room: each
room carries sample points on its floor and at table height (away from walls and furniture); a sample is
covered when a frame taken from inside the room could see it (:class:`~knic.kgm1.sources.FrameView`: in the
image, within the miss range, not hidden). The room is explored when the camera has looked in
``look_around_bins`` of 8 headings from inside it and ``min_look_coverage`` of the samples is covered (a
search: sweeps and a half turn), or when ``min_coverage`` is covered from at least ``min_headings`` headings.
Driving through a room looks one or two ways and covers part of it, so it rarely counts as exploring it.
Every ``explored`` fact (whoever wrote it) expires ``ttl_s`` seconds after it was made, and the room's
coverage starts again, so a place can be searched again for an object that moved.

:class:`CandidatesKP` keeps ``(possibly_at ?e ?room)`` as ASSUMED facts for entities whose place is unknown
(no ``object_at`` / ``person_at``, not held, not handed over). A room stops being a candidate for an entity
once the robot searched it *for that entity* (``(searched ?e ?room)``, the search actions' own record, kept
until the entity is located) or, for an item, while the room counts as explored by the camera (people walk,
so for a person only explorations made after they were lost count). The candidates are the
``max_candidates`` likeliest such rooms by the priors (for a person, the room where they were last seen
first); when no prior room is left, every room not searched for it (the planner then goes to the nearest
first). When no room is left at all, the entity has no candidate: a goal that needs it is unreachable and
dropped, so a search over the whole home ends. Once the entity is located anywhere, its candidates and its
``searched`` facts go. A ``searched`` mark is no permanent truth, since people carry things about: the marks
made before the entity's place was last asserted (seen somewhere, held, handed over, even if that belief is
gone again) are retracted, and a mark older than ``searched_ttl_s`` is retracted once per room (the room is
searched again, but only after every room never searched for the entity: the search still ends). For an
item asked for from a piece of furniture (a goal ``(taken_from ?o ?f)``) the furniture is an ASSUMED
``(possibly_on ?o ?f)`` candidate while the item is not located and that room was not searched for it. A
person some goal wants somewhere (``(person_at ?p ?room)``) is ``(to_accompany ?p)`` (the robot may meet
and guide only them). Entities considered: those with priors, those named in a goal,
those that already have candidates, and those that were located once.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, ClassVar

import numpy as np
import numpy.typing as npt

from knic.bus import Bus
from knic.kgm3.base import KPPrime
from knic.spatial import points_in_polygon
from knic.units import Scan
from knowledge_base import BeliefStatus, Change, ChangeKind, Fact, KnowledgeBase

if TYPE_CHECKING:
    from worlds.model import World

#: entity -> ((room, probability), ...), likeliest first
Priors = Mapping[str, Sequence[tuple[str, float]]]


def room_samples(
    polygon: npt.NDArray[np.float64],
    obstacles: Sequence[npt.NDArray[np.float64]],
    *,
    spacing: float = 0.4,
    inset: float = 0.2,
    heights: Sequence[float] = (0.1, 0.75),
) -> npt.NDArray[np.float64]:
    """Sample points (N, 3) of a room: a grid at ``spacing`` metres inside the polygon, at least ``inset``
    from
    its bounding box edges and outside every obstacle footprint, at each height."""
    lo, hi = polygon.min(axis=0) + inset, polygon.max(axis=0) - inset
    xs = np.arange(lo[0], hi[0] + 1e-9, spacing)
    ys = np.arange(lo[1], hi[1] + 1e-9, spacing)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    xy = np.stack([gx.ravel(), gy.ravel()], axis=1)
    keep = points_in_polygon(xy, polygon)
    for footprint in obstacles:
        keep &= ~points_in_polygon(xy, footprint)
    xy = xy[keep]
    return np.concatenate([np.column_stack([xy, np.full(len(xy), h)]) for h in heights], axis=0)


class ExploredKP(KPPrime):
    """``(explored ?room)`` from camera coverage, with a time to live (see the module docstring).

    Consumes the object camera's scan markers and the location CKUs (each room's outline, every furniture
    footprint as an obstacle); the rooms' sample points are laid out when the places have arrived.
    """

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        min_coverage: float = 0.9,
        min_headings: int = 4,
        look_around_bins: int = 7,
        min_look_coverage: float = 0.25,
        ttl_s: float = 120.0,
        spacing: float = 0.4,
        frequency: float = 5.0,
        name: str = "kp'.explored",
    ) -> None:
        super().__init__(name, frequency, bus, kb, "percept.vision.scan.object", places=True)
        self.min_coverage, self.look_around_bins, self.min_look_coverage = (
            min_coverage,
            look_around_bins,
            min_look_coverage,
        )
        self.min_headings = min_headings
        self.ttl_s = ttl_s
        self.spacing = spacing
        #: room -> sample points (N, 3) on its floor and at table height
        self.samples: dict[str, npt.NDArray[np.float64]] = {}
        self._seen: dict[str, npt.NDArray[np.float64]] = {}
        self._headings: dict[str, npt.NDArray[np.float64]] = {}
        self._epoch: dict[str, float] = {}
        self._places_version = -1

    def _lay_out(self) -> None:
        """(Re)compute the rooms' samples when the places changed (a room whose samples changed starts
        over)."""
        if self._places_version == self.locations.version:
            return
        self._places_version = self.locations.version
        obstacles = list(self.locations.footprints.values())
        for name, prism in self.locations.rooms.prisms.items():
            samples = room_samples(prism.polygon, obstacles, spacing=self.spacing)
            old = self.samples.get(name)
            self.samples[name] = samples
            if old is None or len(old) != len(samples) or not np.array_equal(old, samples):
                self._seen[name] = np.full(len(samples), -math.inf)
            self._headings.setdefault(name, np.full(8, -math.inf))
            self._epoch.setdefault(name, -math.inf)

    def coverage(self, room: str) -> float:
        """Share of the room's samples covered since its coverage last started."""
        self._lay_out()
        seen = self._seen[room]
        return float((seen > self._epoch[room]).mean()) if len(seen) else 0.0

    def headings(self, room: str) -> int:
        """How many of 8 heading sectors the camera has looked in from inside the room since then."""
        self._lay_out()
        return int((self._headings[room] > self._epoch[room]).sum())

    def step(self, now: float) -> None:
        """Accumulate coverage from the scans received; assert explored rooms; expire old explored facts."""
        assert self.inbox is not None
        self._lay_out()
        for message in self.inbox.drain():
            scan: Scan = message.payload
            pos = scan.view.position
            room = self.locations.room_at(float(pos[0]), float(pos[1]))
            if room is None:
                continue
            visible = scan.view.visible(self.samples[room])
            self._seen[room][visible] = scan.stamp
            axis = scan.view.optical_axis()
            # eight sectors centred on the axes and diagonals
            heading = (math.atan2(axis[1], axis[0]) + math.pi / 8) % (2 * math.pi)
            sector = int(heading / (2 * math.pi) * 8) % 8
            self._headings[room][sector] = scan.stamp
            if not self.kb.holds("explored", room) and self._covered(room):
                self.assert_fact("explored", room, at=scan.stamp, confidence=self.coverage(room))
        for fact in self.kb.facts("explored"):
            prov = self.kb.why(fact)
            if prov is not None and now - prov.since > self.ttl_s:
                room = fact.args[0]
                self.retract_fact("explored", room, at=now)
                if room in self._epoch:
                    self._epoch[room] = now

    def _covered(self, room: str) -> bool:
        cov = self.coverage(room)
        headings = self.headings(room)
        if cov >= self.min_coverage and headings >= self.min_headings:
            return True
        return headings >= self.look_around_bins and cov >= self.min_look_coverage


class CandidatesKP(KPPrime):
    """``(possibly_at ?e ?room)`` search candidates, ASSUMED (see the module docstring).

    Args:
        priors: entity -> (room, probability) pairs.
        rooms: every room, in the order fallback candidates are taken.
        max_candidates: most candidate rooms asserted per entity at a time.
        searched_ttl_s: simulated seconds after which a ``(searched ?e ?room)`` mark is retracted, once per
            entity and room until the entity is located again (infinite: never).
    """

    #: predicates whose assertion places an entity (its argument position): evidence of where it is now
    PLACING: ClassVar[Mapping[str, int]] = {"object_at": 0, "person_at": 0, "holding": 1, "has": 1}

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        priors: Priors,
        rooms: Sequence[str],
        *,
        max_candidates: int = 3,
        searched_ttl_s: float = 180.0,
        frequency: float = 2.0,
        name: str = "kp'.candidates",
    ) -> None:
        super().__init__(name, frequency, bus, kb, None)
        self.priors = {e: sorted(p, key=lambda rp: -rp[1]) for e, p in priors.items()}
        self.rooms = list(rooms)
        self.max_candidates = max_candidates
        self.searched_ttl_s = searched_ttl_s
        #: entity -> when its place was last asserted (perception or an action's effect)
        self.placed_at: dict[str, float] = {}
        #: (entity, room) whose searched mark aged out: searched again only after the never-searched rooms
        self.reopened: set[tuple[str, str]] = set()
        kb.subscribe(self._placed)
        self.last_room: dict[str, str] = {}
        self.lost_at: dict[str, float] = {}
        self._tracked: set[str] = set()
        self._now = 0.0

    def wanted(self, entity: str) -> list[tuple[str, float]]:
        """The candidate rooms an entity should have now, with their probabilities (empty when located)."""
        if self.located(entity):
            return []
        ranked: list[tuple[str, float]] = []
        last = self.last_room.get(entity)
        if last is not None and self.is_a(entity, "person"):
            ranked.append((last, 1.0))
        ranked += list(self.priors.get(entity, ()))
        seen: set[str] = set()
        excluded = self.explored_for(entity) | self.searched_for(entity)
        again = {room for e, room in self.reopened if e == entity} - excluded
        result: list[tuple[str, float]] = []
        for room, p in ranked:
            if room not in seen and room not in excluded | again and self.is_a(room, "room"):
                seen.add(room)
                result.append((room, p))
        if result:
            return result[: self.max_candidates]
        rest = [(r, 0.0) for r in self.rooms if r not in excluded | again and self.is_a(r, "room")]
        return rest or [(r, 0.0) for r in self.rooms if r in again]

    def _placed(self, change: Change) -> None:
        """Note when an entity's place is asserted (a sighting, a pick, a hand-over)."""
        where = self.PLACING.get(change.name) if change.kind == ChangeKind.ADD_FACT else None
        if where is not None and where < len(change.args):
            self.placed_at[change.args[where]] = change.time

    def stale_searches(self, entity: str, now: float) -> list[Fact]:
        """The entity's ``searched`` marks that no longer rule its room out: all of them once it is located;
        else those made before its place was last asserted, and those older than ``searched_ttl_s`` (once
        per room: noted in :attr:`reopened`)."""
        marks = self.kb.facts("searched", entity)
        if self.located(entity):
            self.reopened = {(e, r) for e, r in self.reopened if e != entity}
            return marks
        placed = self.placed_at.get(entity, -math.inf)
        stale = []
        for fact in marks:
            prov = self.kb.why(fact)
            since = prov.since if prov is not None else now
            if since < placed:
                self.reopened = {(e, r) for e, r in self.reopened if e != entity}
                stale.append(fact)
            elif now - since > self.searched_ttl_s and (entity, fact.args[1]) not in self.reopened:
                self.reopened.add((entity, fact.args[1]))
                stale.append(fact)
        return stale

    def searched_for(self, entity: str) -> set[str]:
        """Rooms the robot searched for the entity since it was last located (``(searched ?e ?room)``)."""
        return {f.args[1] for f in self.kb.facts("searched", entity)}

    def wanted_on(self, entity: str) -> list[str]:
        """The furniture an item is sought on (goals ``(taken_from ?o ?f)``) whose room was not searched for
        it; empty when the item is located or for a person."""
        if not self.is_a(entity, "item") or self.located(entity):
            return []
        searched = self.searched_for(entity)
        out = []
        for goal in self.kb.goals():
            if goal.predicate != "taken_from" or goal.args[0] != entity:
                continue
            rooms = {f.args[1] for f in self.kb.facts("furniture_in", goal.args[1])}
            if not rooms & searched:
                out.append(goal.args[1])
        return sorted(set(out))

    def explored_for(self, entity: str) -> set[str]:
        """Rooms whose camera exploration rules them out for the entity.

        For a person, only explorations made after they were lost count: people walk about, so a room
        explored before the person went out of sight (often the room they were last seen in) may hold them
        again.
        """
        rooms: set[str] = set()
        since = self.lost_at.get(entity) if self.is_a(entity, "person") else None
        for fact in self.kb.facts("explored"):
            if since is not None:
                prov = self.kb.why(fact)
                if prov is not None and prov.since < since:
                    continue
            rooms.add(fact.args[0])
        return rooms

    def located(self, entity: str) -> bool:
        """Whether the knowledge base knows where the entity is (or who holds it)."""
        place = self.kb.facts("person_at", entity) if self.is_a(entity, "person") else []
        if self.is_a(entity, "item"):
            place = self.kb.facts("object_at", entity)
            if not place and (self.kb.facts("holding", None, entity) or self.kb.facts("has", None, entity)):
                return True
        if place:
            self.last_room[entity] = place[0].args[1]
            self._tracked.add(entity)
            self.lost_at.pop(entity, None)
            return True
        if entity in self.last_room:
            self.lost_at.setdefault(entity, self._now)
        return False

    def entities(self) -> list[str]:
        """Entities whose candidates this KP' maintains."""
        names = set(self.priors) | self._tracked | {f.args[0] for f in self.kb.facts("possibly_at")}
        for goal in self.kb.goals():
            names |= {a for a in goal.args if self.is_a(a, "item") or self.is_a(a, "person")}
        return sorted(n for n in names if self.is_a(n, "entity"))

    def step(self, now: float) -> None:
        """Bring every tracked entity's possibly_at / possibly_on facts in line with :meth:`wanted` and
        :meth:`wanted_on`; forget the searches for located entities; keep the accompany requests."""
        self._now = now
        if "to_accompany" in self.kb.domain.predicates:
            self.requests(now)
        for entity in self.entities():
            stale = self.stale_searches(entity, now)
            if stale:
                with self.kb.batch():
                    for fact in stale:
                        self.retract_fact("searched", *fact.args, at=now)
            if self.kb.holds("found", entity) and not self.located(entity):
                # found means "its place is known": with the place gone (the belief aged out, an action
                # moved it out of sight) a search for it must be possible again
                self.retract_fact("found", entity, at=now)
            wanted = dict(self.wanted(entity))
            on = set(self.wanted_on(entity))
            current = {f.args[1] for f in self.kb.facts("possibly_at", entity)}
            current_on = {f.args[1] for f in self.kb.facts("possibly_on", entity)}
            if current == set(wanted) and current_on == on and all(self._assumed(entity, r) for r in wanted):
                continue
            with self.kb.batch():
                for room in sorted(current - set(wanted)):
                    self.retract_fact("possibly_at", entity, room, at=now)
                for furniture in sorted(current_on - on):
                    self.retract_fact("possibly_on", entity, furniture, at=now)
                for room, p in wanted.items():
                    self.assert_fact(
                        "possibly_at",
                        entity,
                        room,
                        at=now,
                        confidence=p,
                        assumed=True,
                        support=(f"prior:{entity}",),
                    )
                for furniture in sorted(on - current_on):
                    self.assert_fact(
                        "possibly_on", entity, furniture, at=now, assumed=True, support=(f"request:{entity}",)
                    )

    def requests(self, now: float) -> None:
        """``(to_accompany ?p)`` exactly for the people a goal wants somewhere."""
        wanted = {g.args[0] for g in self.kb.goals() if g.predicate == "person_at"}
        have = {f.args[0] for f in self.kb.facts("to_accompany")}
        if wanted == have:
            return
        with self.kb.batch():
            for person in sorted(have - wanted):
                self.retract_fact("to_accompany", person, at=now)
            for person in sorted(wanted - have):
                self.assert_fact("to_accompany", person, at=now, support=("request",))

    def _assumed(self, entity: str, room: str) -> bool:
        prov = self.kb.why(Fact("possibly_at", (entity, room)))
        return prov is not None and prov.status == BeliefStatus.ASSUMED


def priors_from_world(world: World) -> dict[str, list[tuple[str, float]]]:
    """Entity -> (room, probability) pairs from the world's item and person priors."""
    out: dict[str, list[tuple[str, float]]] = {}
    for name, item in world.items.items():
        if item.priors:
            out[name] = [(p.room, float(p.probability)) for p in item.priors]
    for name, person in world.people.items():
        if person.priors:
            out[name] = [(p.room, float(p.probability)) for p in person.priors]
    return out
