"""Where the robot should look next when it has nothing else to do: the role's revisits (belief in time).

Seed 004's motivational principles decide which units the cognitive layer processes; the same role data says
which places and people the robot keeps fresh by going to look at them again (``revisit`` in the role file,
:class:`~knic.kgm2.roles.Revisit`). :class:`Revisits` turns that data and the beliefs into the
next room to visit:

1. a room where a person is believed with an aged belief (``person_at`` ASSUMED: not seen for the role's
   time to live), the oldest first, when the robot has not looked at the room since the belief aged: the
   visit either sees them (the belief is observed again) or views the place without them (KGM-2 drops the
   track and KGM-3 retracts the fact);
2. otherwise the room whose last look is the oldest, weighted: a room in ``revisit.rooms`` or holding a
   believed ``revisit.items`` item counts ``revisit.priority_weight`` times its age, other rooms once.

A room counts as looked at when the caller says so (:meth:`Revisits.looked`, after a camera sweep in it). The
policy reads beliefs only, never the simulator's truth. Times are simulated seconds. Two callers drive the
robot by it: a run (:mod:`knic.system.revisits`, while the robot has nothing else to do) and the grounding
bench's patrol (:mod:`knic.bench.patrol`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from knic.kgm2.roles import Revisit
from knowledge_base import BeliefStatus, KnowledgeBase


class Revisits:
    """The role's revisit policy over the knowledge base.

    Args:
        kb: the knowledge base (read only).
        revisit: the role's revisit data.
        rooms: the rooms the robot can go to, with where to look at each from (:func:`rooms_from_kb`).
    """

    def __init__(self, kb: KnowledgeBase, revisit: Revisit, rooms: Mapping[str, RoomView]) -> None:
        self.kb = kb
        self.revisit = revisit
        self.rooms = dict(rooms)
        #: room -> simulated time the robot last looked at it
        self.last_look: dict[str, float] = {}

    def looked(self, room: str, now: float) -> None:
        """The robot has just looked around ``room`` (a sweep from inside it)."""
        self.last_look[room] = now

    def aged_people(self) -> list[tuple[float, str, str]]:
        """(aged since, person, room) of every aged person_at belief, oldest first."""
        out = []
        for fact in self.kb.facts("person_at"):
            prov = self.kb.why(fact)
            if prov is not None and prov.status is BeliefStatus.ASSUMED and fact.args[1] in self.rooms:
                out.append((prov.since, fact.args[0], fact.args[1]))
        return sorted(out)

    def priority_rooms(self) -> set[str]:
        """The role's rooms and the rooms where one of the role's items is believed."""
        rooms = set(self.revisit.rooms)
        for item in self.revisit.items:
            rooms.update(f.args[1] for f in self.kb.facts("object_at", item, None))
        return rooms & set(self.rooms)

    def next_room(self, now: float, here: str | None = None) -> str | None:
        """The room to visit next (None when there is no room at all); ``here`` is where the robot is."""
        if not self.rooms:
            return None
        room = self.person_room(now)
        if room is not None:
            return room
        priority = self.priority_rooms()

        def score(room: str) -> float:
            age = now - self.last_look.get(room, -1e6)
            weight = self.revisit.priority_weight if room in priority else 1.0
            return age * weight - (1e-3 if room == here else 0.0)

        return max(sorted(self.rooms), key=score)

    def person_room(self, now: float) -> str | None:
        """The room of the oldest aged person belief not looked at since it aged (None: none, or the role
        does not revisit people)."""
        if not self.revisit.people:
            return None
        for since, _person, room in self.aged_people():
            if self.last_look.get(room, -math.inf) < since:
                return room
        return None

    def view_of(self, room: str) -> RoomView:
        """Where to go to look at ``room``, and which way to face."""
        return self.rooms[room]


@dataclass(frozen=True)
class RoomView:
    """Where to stand to look at a room: ``point`` (the room's first waypoint) and the room's ``centre`` (the
    mean of its outline), world frame, metres."""

    point: tuple[float, float]
    centre: tuple[float, float]

    def heading(self, min_distance: float = 0.5) -> float | None:
        """Radians from the point towards the centre (None when they are closer than ``min_distance``)."""
        dx, dy = self.centre[0] - self.point[0], self.centre[1] - self.point[1]
        return math.atan2(dy, dx) if math.hypot(dx, dy) >= min_distance else None


def rooms_from_kb(kb: KnowledgeBase, names: Sequence[str] | None = None) -> dict[str, RoomView]:
    """Each anchored room's view: its first waypoint (else the outline's mean) and the outline's mean.

    Args:
        names: the rooms to take (default every instance of type ``room``); rooms without an anchor are
            left out.
    """
    if names is None:
        names = kb.instances("room")
    out: dict[str, RoomView] = {}
    for room in names:
        geometry = kb.anchor(room) or {}
        waypoints = geometry.get("waypoints") or []
        region = geometry.get("region") or []
        if not region and not waypoints:
            continue
        if region:
            centre = (
                sum(float(p[0]) for p in region) / len(region),
                sum(float(p[1]) for p in region) / len(region),
            )
        else:
            centre = (float(waypoints[0][0]), float(waypoints[0][1]))
        point = (float(waypoints[0][0]), float(waypoints[0][1])) if waypoints else centre
        out[room] = RoomView(point, centre)
    return out
