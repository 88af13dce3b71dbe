"""The sensing actions ``search_object`` and ``search_person``: explore a room with the camera.

The robot goes through the room's viewpoints -- its anchored waypoints (where it looks all around: a camera
sweep, a half turn, another sweep) and then the furniture standing in it (a short sweep facing each) -- and
stops early once perception has located the entity. The actions never write what they sense: the dispatcher
checks after deactivation that a KP' asserted the sensed effects (``found``, ``object_at`` / ``person_at``),
else the action ends with a postcondition failure and the system replans (see ``sensing:`` in
``worlds/erl_home/domain.meta.yaml``).

Step returns SUCCEEDED when (a) the entity is believed found in this room, (b) it is believed found in
another room (the search is over; the dispatcher's check then fails and the planner uses the new knowledge),
or (c) every viewpoint has been looked at plus a short grace for pending confirmations. Execution failures:
the room has no anchor (activation), or no viewpoint of the room could be reached at all.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from actions.base import ActionStatus
from actions.erl.common import ErlAction, NavGoal, to_furniture, to_point
from actions.erl.context import ErlContext, furniture_map, room_map, wrap

#: seconds to wait after the last viewpoint for perception to confirm a sighting
CONFIRM_GRACE_S = 1.5
#: camera pans (radians) when facing a piece of furniture
FURNITURE_PANS = (-0.5, 0.0, 0.5)


@dataclass
class _Task:
    """One step of the search route: drive somewhere, or rest the camera at a pan angle."""

    kind: str  # "nav" or "pan"
    start: Callable[[], int] | None = None
    what: str = ""
    pan: float = 0.0
    turn: bool = False


class SearchAction(ErlAction):
    """``(search_object ?r ?o ?l)`` or ``(search_person ?r ?p ?l)`` (see the module docstring).

    Args:
        name: ``search_object`` or ``search_person``.
        args: ``(robot, entity, room)``.
        ctx: the action context.
    """

    def __init__(self, name: str, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__(name, args, ctx)
        _robot, self.entity, self.room = args
        self.place_predicate = "object_at" if name == "search_object" else "person_at"
        self.tasks: list[_Task] = []
        self.nav: NavGoal | None = None
        self.reached = 0
        self.unreachable: list[str] = []
        self.started = ctx.now

    # ------------------------------------------------------------------ lifecycle

    def activation(self) -> bool:
        """Plan the route through the room's viewpoints and start on it."""
        room = room_map(self.ctx.kb, self.room)
        if room is None:
            return self.refuse(f"room {self.room} has no anchor (region, waypoints) in the knowledge base")
        self.started = self.ctx.now
        for wp in room.waypoints:
            self.tasks.append(_Task("nav", to_point(self.ctx, wp), f"a viewpoint of {self.room}"))
            self.tasks += [_Task("pan", pan=a) for a in self.ctx.search_pans]
            self.tasks.append(_Task("nav", None, "half turn", turn=True))
            self.tasks += [_Task("pan", pan=a) for a in self.ctx.search_pans]
        for name in self._furniture_route(room.waypoints[0]):
            self.tasks.append(_Task("nav", to_furniture(self.ctx, name), name))
            self.tasks += [_Task("pan", pan=a) for a in FURNITURE_PANS]
        self.enter("route")
        return True

    def step(self) -> ActionStatus:
        """Advance along the route; finish early once the entity is located (see the module docstring)."""
        if self.ctx.kb.holds("found", self.entity) and self.ctx.kb.facts(self.place_predicate, self.entity):
            return ActionStatus.SUCCEEDED
        if self.phase == "grace":
            pending = self.ctx.perceived.seen_since(self.entity, self.started) is not None
            if self.in_phase_for() < (CONFIRM_GRACE_S * (2 if pending else 1)):
                return ActionStatus.RUNNING
            if self.reached == 0:
                return self.fail(f"no viewpoint of {self.room} reachable ({'; '.join(self.unreachable)})")
            return ActionStatus.SUCCEEDED
        if self.phase == "nav":
            assert self.nav is not None
            status = self.nav.poll()
            if status is ActionStatus.RUNNING:
                return status
            if status is ActionStatus.FAILED:
                self.unreachable.append(self.nav.reason)
                self._skip_pans()
            else:
                self.reached += 1
            self.enter("route")
        elif self.phase == "pan":
            if self.in_phase_for() < self.ctx.dwell_s:
                return ActionStatus.RUNNING
            self.enter("route")
        return self._next_task()

    # ------------------------------------------------------------------ route

    def _next_task(self) -> ActionStatus:
        if not self.tasks:
            self.ctx.robot.pan_camera(0.0)
            self.enter("grace")
            return ActionStatus.RUNNING
        task = self.tasks.pop(0)
        if task.kind == "pan":
            self.ctx.robot.pan_camera(task.pan)
            self.enter("pan")
            return ActionStatus.RUNNING
        self.ctx.robot.pan_camera(0.0)
        start = task.start
        if task.turn:
            pose = self.ctx.robot.robot_pose()
            start = to_point(self.ctx, (pose.x, pose.y), wrap(pose.yaw + math.pi))
        assert start is not None
        self.nav = NavGoal(self.ctx, [start], task.what)
        if not self.nav.start():
            self.unreachable.append(self.nav.reason)
            self._skip_pans()
            return self._next_task()
        self.enter("nav")
        return ActionStatus.RUNNING

    def _skip_pans(self) -> None:
        while self.tasks and self.tasks[0].kind == "pan":
            self.tasks.pop(0)

    def _furniture_route(self, origin: tuple[float, float]) -> list[str]:
        """The room's anchored furniture (``furniture_in``), greedy nearest-first from ``origin``."""
        pieces = {}
        for fact in self.ctx.kb.facts("furniture_in", None, self.room):
            known = furniture_map(self.ctx.kb, fact.args[0])
            if known is not None:
                pieces[known.name] = known.position
        route: list[str] = []
        here = origin
        while pieces:
            name = min(sorted(pieces), key=lambda n: math.dist(pieces[n], here))
            here = pieces.pop(name)
            route.append(name)
        return route
