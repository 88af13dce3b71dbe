"""Building blocks of the ERL actions: a base class with failure bookkeeping and a navigation-goal follower.

Both are driven by the dispatcher's ticks (see :mod:`actions.base` for the lifecycle): nothing here blocks or
sleeps; every call does a bounded amount of work and reads the simulated clock of the robot interface.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from actions.base import Action, ActionStatus
from actions.erl.context import ErlContext, Point
from core.robot import NavState


class ErlAction(Action):
    """An ERL action: an :class:`~actions.base.Action` bound to an :class:`ErlContext`.

    Subclasses implement :meth:`step` as a small phase machine. :meth:`fail` records the one-line reason the
    dispatcher puts in the trace. The default :meth:`deactivation` stops the base unless the action
    succeeded, so a failed, timed-out or cancelled action never leaves the robot driving.
    """

    def __init__(self, name: str, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__(name, args)
        self.ctx = ctx
        self.phase = "start"
        self.phase_since = ctx.now

    def fail(self, reason: str) -> ActionStatus:
        """Record ``reason`` and return FAILED."""
        self.failure_reason = reason
        return ActionStatus.FAILED

    def refuse(self, reason: str) -> bool:
        """Record ``reason`` and return False (for :meth:`activation`)."""
        self.failure_reason = reason
        return False

    def drive(self, nav: NavGoal) -> ActionStatus | None:
        """Poll ``nav``: None once the base has arrived, else what :meth:`step` returns now (RUNNING, or
        FAILED with the navigation's reason)."""
        status = nav.poll()
        if status is ActionStatus.FAILED:
            return self.fail(nav.reason)
        return None if status is ActionStatus.SUCCEEDED else status

    def holds_or_refuse(self, item: str) -> bool:
        """True when the gripper holds ``item``; else record why and return False (for :meth:`activation`)."""
        held = self.ctx.robot.held_item()
        if held != item:
            return self.refuse(f"the gripper holds {held or 'nothing'}, not {item}")
        return True

    def enter(self, phase: str) -> None:
        """Switch to ``phase`` and note when (simulated seconds)."""
        self.phase = phase
        self.phase_since = self.ctx.now

    def in_phase_for(self) -> float:
        """Simulated seconds spent in the current phase."""
        return self.ctx.now - self.phase_since

    def deactivation(self) -> bool:
        """Stop the base (and centre the camera) unless the action succeeded; always True."""
        if self.ending != "succeeded":
            self.ctx.robot.stop()
        self.ctx.robot.pan_camera(0.0)
        return True


class NavGoal:
    """Follows one navigation goal, trying alternative targets when the base refuses one at once.

    Args:
        ctx: the action context.
        starts: callables that each send one goal to the base and return its id, best first. The next one is
            tried when a goal fails before the base moved (its target is not free, no path to it).
        what: words for failure messages (``"kitchen"``).
        retry_blocked: also try the next alternative when the base reports the path blocked (a person
            standing where the robot wants to be), not only when a target is unreachable.
    """

    def __init__(
        self, ctx: ErlContext, starts: Sequence[Callable[[], int]], what: str, *, retry_blocked: bool = False
    ) -> None:
        self.ctx = ctx
        self.starts = list(starts)
        self.what = what
        self.retry_blocked = retry_blocked
        self.goal_id = -1
        self.reason = ""
        self._tried = 0
        self._first_reason = ""

    def start(self) -> bool:
        """Send the first goal the base accepts; False (with :attr:`reason`) when every one fails at once."""
        while self._tried < len(self.starts):
            self.goal_id = self.starts[self._tried]()
            self._tried += 1
            status = self.ctx.robot.nav_status()
            if status.goal_id == self.goal_id and status.state is NavState.FAILED:
                self._first_reason = self._first_reason or status.reason
                continue
            return True
        self.reason = f"cannot navigate to {self.what}: {self._first_reason or 'no target'}"
        return False

    def poll(self) -> ActionStatus:
        """RUNNING while the goal is active; SUCCEEDED on arrival; FAILED (see :attr:`reason`) otherwise.

        A goal that fails with "no path" or an unfree target is replaced by the next alternative; "path
        blocked" (a person or an obstacle in the way for too long) is a failure of the action unless
        ``retry_blocked``.
        """
        status = self.ctx.robot.nav_status()
        if status.goal_id != self.goal_id:
            self.reason = f"navigation to {self.what} was preempted"
            return ActionStatus.FAILED
        if status.state is NavState.SUCCEEDED:
            return ActionStatus.SUCCEEDED
        if status.state in (NavState.ACTIVE, NavState.IDLE):
            return ActionStatus.RUNNING
        blocked = "blocked" in status.reason and not self.retry_blocked
        if status.state is NavState.FAILED and not blocked and self.start():
            return ActionStatus.RUNNING
        self.reason = f"navigation to {self.what} {status.state.value}: {status.reason or 'no reason given'}"
        return ActionStatus.FAILED


def to_point(ctx: ErlContext, point: Point, yaw: float | None = None) -> Callable[[], int]:
    """A start callable for :class:`NavGoal`: go to ``point`` (final heading ``yaw`` when given)."""
    return lambda: ctx.robot.navigate_to_point(point[0], point[1], yaw)


def to_furniture(ctx: ErlContext, furniture: str, near: Point | None = None) -> Callable[[], int]:
    """A start callable for :class:`NavGoal`: go within reach of ``furniture`` (near ``near`` on it)."""
    return lambda: ctx.robot.navigate_to_furniture(furniture, near)
