"""The grounding bench's robot behaviour: a patrol of the rooms, or the role's revisits.

No goals are given in the grounding bench, so this component drives the robot: from room to room (knowledge-
base anchors), sweeping the camera on arrival. Under a role with revisit data it asks
:class:`knic.kgm2.attention.Revisits` where to go next; otherwise it follows a fixed tour.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from knic.scheduler import Component

if TYPE_CHECKING:
    from knic.system.assembly import Assembly


class Patrol(Component):
    """Drives the robot from room waypoint to room waypoint (knowledge-base anchors), sweeping the camera
    for ``sweep_s`` on arrival.

    Under a role with revisit data (the companion) the next room is the role's choice
    (:class:`knic.kgm2.attention.Revisits`: aged beliefs about people first, then the rooms not looked at for
    longest, priority rooms weighted); otherwise a fixed tour of the rooms.
    """

    name = "bench.patrol"
    frequency = 5.0

    def __init__(self, parts: Assembly, sweep_s: float = 5.0) -> None:
        from knic.kgm2.attention import Revisits, rooms_from_kb

        self.robot = parts.robot
        tour = (
            "living_room",
            "dining_room",
            "kitchen",
            "hallway",
            "bedroom",
            "bathroom",
            "hallway",
            "entrance_hall",
        )
        points = rooms_from_kb(parts.kb, tour)
        self.tour = [r for r in tour if r in points]
        self.points = points
        revisit = parts.pipeline.role.revisit
        self.revisits = Revisits(parts.kb, revisit, points) if revisit.people or revisit.rooms else None
        self.index = 0
        self.sweep_s = sweep_s
        self.arrived: float | None = None
        self.goal = -1
        self.room: str | None = None
        self.for_person = False

    def _next_room(self, now: float) -> str:
        if self.revisits is not None:
            room = self.revisits.next_room(now, self.room)
            if room is not None:
                return room
        room = self.tour[self.index % len(self.tour)]
        self.index += 1
        return room

    def step(self, now: float) -> None:
        from core.robot import NavState

        status = self.robot.nav_status()
        if self.revisits is not None and self.goal >= 0 and self.arrived is None and not self.for_person:
            # a person's belief aged on the way to a room chosen for its age alone: go to them first
            urgent = self.revisits.person_room(now)
            if urgent is not None and urgent != self.room:
                self._go(urgent, now)
                return
        if self.goal < 0 or (status.goal_id == self.goal and status.state is not NavState.ACTIVE):
            if self.arrived is None and self.goal >= 0:
                self.arrived = now
            if self.arrived is not None and now - self.arrived < self.sweep_s:
                self.robot.pan_camera(1.3 * math.sin(2 * math.pi * (now - self.arrived) / self.sweep_s))
                return
            if self.arrived is not None and self.revisits is not None and self.room is not None:
                self.revisits.looked(self.room, now)
            self.robot.pan_camera(0.0)
            self._go(self._next_room(now), now)

    def _go(self, room: str, now: float) -> None:
        self.room = room
        self.for_person = self.revisits is not None and room == self.revisits.person_room(now)
        view = self.points[room]
        # a revisit faces the room (the sweep covers it), the fixed tour keeps its arrival heading
        yaw = view.heading() if self.revisits is not None else None
        self.goal = self.robot.navigate_to_point(*view.point, yaw)
        self.arrived = None
