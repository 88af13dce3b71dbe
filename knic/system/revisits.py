"""The role's revisits in a run: when the robot has nothing to do, it goes back to look where the role says.

:class:`~knic.kgm2.attention.Revisits` (KGM-2) decides *where* from the role data and the beliefs (people
whose belief aged first, then the rooms not looked at for longest, the role's rooms weighted);
:class:`RevisitDriver` decides *when* and drives the base there:

* only while the robot is free: the dispatcher is idle with nothing to work on (no goal, or every open goal
  dropped and waiting for news) and no task flow holds the robot where it is (Annie's dialogue). When every
  goal holds the robot stays put (perception is confirming them, the run is about to end);
* only after ``idle_before_s`` of being free (a goal given a moment later does not find the robot leaving);
* a revisit is a trip to the room's view point facing the room, then a camera sweep of ``sweep_s``; the room
  then counts as looked at (:meth:`~knic.kgm2.attention.Revisits.looked`);
* the moment the robot is not free any more (a goal arrived, a dropped goal came back, a dialogue started),
  the driver stops the base if its own trip is still under way, recentres the camera and leaves the robot to
  the dispatcher; a later free moment starts a new choice.

It reads beliefs only (the knowledge base, the dispatcher's book), never the simulator's truth. Every trip is
a ``task`` trace event ``revisit`` (``data``: the room and why: ``person`` with the person whose belief aged,
or ``room``), every completed sweep a ``revisited`` event, a trip given up because the robot is needed a
``revisit interrupted`` event, a trip that failed a ``revisit failed`` event (that room then waits its turn
again, and the robot pauses ``idle_before_s``). Times are simulated seconds.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from core.robot import NavState, Robot
from knic.kgm2.attention import Revisits
from knic.scheduler import Component
from knowledge_base import KnowledgeBase
from planner.dispatch import Dispatcher, DispatcherState
from planner.trace import EventKind, Trace, TraceEvent

#: camera pan amplitude of the sweep on arrival, radians either side of the base heading
SWEEP_PAN = 1.3


class RevisitDriver(Component):
    """Drives the robot on the role's revisits while it is free (see the module docstring).

    Args:
        robot: the robot seam (base goals, camera pan).
        revisits: the role's revisit policy over the knowledge base.
        free: whether the robot has nothing to do (called at each step; see :func:`dispatcher_free`).
        trace: where the ``revisit`` and ``revisited`` events go.
        idle_before_s: simulated seconds the robot must have been free before a revisit starts.
        sweep_s: simulated seconds of the camera sweep on arrival.
    """

    name = "attention.revisits"
    frequency = 5.0

    def __init__(
        self,
        robot: Robot,
        revisits: Revisits,
        free: Callable[[], bool],
        trace: Trace,
        *,
        idle_before_s: float = 3.0,
        sweep_s: float = 5.0,
    ) -> None:
        self.robot = robot
        self.revisits = revisits
        self.free = free
        self.trace = trace
        self.idle_before_s = idle_before_s
        self.sweep_s = sweep_s
        #: callables telling whether something else holds the robot where it is (a task flow's dialogue)
        self.holds: list[Callable[[], bool]] = []
        self.room: str | None = None  # the room of the trip under way (None: no trip)
        self.goal = -1
        self.arrived: float | None = None
        self.for_person: str | None = None
        self.here: str | None = None  # the room last looked at
        self._free_since: float | None = None
        #: completed revisits: (room, why, simulated time the sweep ended)
        self.done: list[tuple[str, str, float]] = []

    def step(self, now: float) -> None:
        """Start, advance or abandon a revisit (see the module docstring)."""
        if not self.free() or any(hold() for hold in self.holds):
            self._free_since = None
            self._yield(now)
            return
        if self._free_since is None:
            self._free_since = now
        if now - self._free_since < self.idle_before_s:
            return
        if self.room is None:
            self._start(now)
            return
        status = self.robot.nav_status()
        if self.arrived is None:
            if status.goal_id != self.goal:
                if status.goal_id > self.goal:
                    self.room = None  # something else took the base: choose again when free
                return  # else the robot has not reported the trip yet (a remote robot's status lags)
            if status.state is NavState.ACTIVE:
                urgent = self.revisits.person_room(now)
                if self.for_person is None and urgent is not None and urgent != self.room:
                    self._start(now)  # a person's belief aged on the way: go to them first
                return
            if status.state is not NavState.SUCCEEDED:
                # the trip failed: the room goes to the back of the queue, and a pause before the next choice
                self._event("revisit failed", now, self.room, "person" if self.for_person else "room")
                self.revisits.looked(self.room, now)
                self.room, self._free_since = None, now
                return
            self.arrived = now
        if now - self.arrived < self.sweep_s:
            self.robot.pan_camera(SWEEP_PAN * math.sin(2 * math.pi * (now - self.arrived) / self.sweep_s))
            return
        self.robot.pan_camera(0.0)
        self.revisits.looked(self.room, now)
        why = "person" if self.for_person else "room"
        self.done.append((self.room, why, now))
        self._event("revisited", now, self.room, why)
        self.here, self.room = self.room, None

    def _start(self, now: float) -> None:
        room = self.revisits.next_room(now, self.here)
        if room is None:
            return
        person_room = self.revisits.person_room(now)
        self.for_person = None
        if room == person_room:
            self.for_person = next((p for _since, p, r in self.revisits.aged_people() if r == room), None)
        view = self.revisits.view_of(room)
        self.robot.pan_camera(0.0)
        self.goal = self.robot.navigate_to_point(*view.point, view.heading())
        self.room, self.arrived = room, None
        self._event("revisit", now, room, "person" if self.for_person else "room")

    def _yield(self, now: float) -> None:
        """Leave the robot to whoever needs it: stop the driver's own trip if it is still under way."""
        if self.room is None:
            return
        status = self.robot.nav_status()
        if status.goal_id == self.goal and status.state is NavState.ACTIVE:
            self.robot.stop()
        if self.arrived is not None:
            self.robot.pan_camera(0.0)
        self._event("revisit interrupted", now, self.room, "person" if self.for_person else "room")
        self.room, self.arrived = None, None

    def _event(self, what: str, now: float, room: str, why: str) -> None:
        data = {"room": room, "why": why}
        reason = f"{room}: looking again for {self.for_person}" if self.for_person else f"{room}: oldest look"
        if self.for_person:
            data["person"] = self.for_person
        self.trace.emit(TraceEvent(EventKind.TASK, now, action=what, reason=reason, data=data))


def dispatcher_free(kb: KnowledgeBase, dispatcher: Dispatcher) -> Callable[[], bool]:
    """Whether the robot has nothing to do, from the dispatcher's book and the knowledge base's goals: the
    dispatcher is idle and either there is no goal or every goal that does not hold was dropped (waiting for
    news). Every goal holding is not free: the robot stays while perception confirms them."""

    def free() -> bool:
        if dispatcher.state != DispatcherState.IDLE:
            return False
        goals = kb.goals()
        missing = [g for g in goals if not kb.holds(g)]
        if goals and not missing:
            return False
        dropped = dispatcher.dropped
        return all((g.predicate, *g.args) in dropped for g in missing)

    return free
