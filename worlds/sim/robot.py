"""The robot's mobile base: a kinematic unicycle with velocity limits, a goal follower and contact tracking.

The base is kinematic: every control period its pose is set from the commanded velocities (no dynamics), which
keeps runs fast and exactly reproducible. Navigation goals are planned on the :class:`GridMap` and followed
with a rotate-then-drive controller. A standing person in the way (a doorway, a corridor) is handled as a
social navigation stack does: the robot stops short of them and waits :data:`WAIT_BEFORE_REPLAN`, then plans
around them; when no way around exists it asks them to make way (:attr:`BaseController.ask_way`: the robot
says so and the person may step off its path) and keeps waiting, trying the way around again every
:data:`WAIT_BEFORE_REPLAN`; after :data:`GIVE_UP_AFTER` seconds blocked in all the goal fails with
``"path blocked by <person>"`` (it never pushes through). A goal fails with ``"no path"`` when it is
unreachable.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from core.robot import NavState, NavStatus, Pose2D
from worlds.geometry import Point, segment_distance, wrap_angle
from worlds.model import RobotSpec
from worlds.sim.navigation import GridMap

WAIT_BEFORE_REPLAN = 2.0  # seconds blocked by a person before planning around them
GIVE_UP_AFTER = 20.0  # seconds blocked in total before the goal fails


@dataclass
class _Goal:
    goal_id: int
    target: str
    goals: list[Point]
    final_yaw: Callable[[float, float], float | None]
    path: list[Point] = field(default_factory=list)
    index: int = 1
    blocked_for: float = 0.0
    blocked_total: float = 0.0
    planned: bool = False
    asked: set[str] = field(default_factory=set)


class BaseController:
    """Pose, velocity commands and navigation goals of the robot base (world frame, simulated time).

    Lifecycle: created by the simulation; :meth:`update` is called once per control period; commands
    (:meth:`start_goal`, :meth:`set_velocity`, :meth:`stop`) may come at any time between updates.

    Attributes:
        ask_way: called once per goal and blocking person, with the person's name and the rest of the
            robot's path (from the base), when no way around them exists: the robot asks them to make way
            (the simulation says it aloud and lets the person step aside). Default: nobody is asked.
    """

    def __init__(self, spec: RobotSpec, grid: GridMap) -> None:
        self.spec = spec
        self.grid = grid
        self.x, self.y, self.yaw = spec.start
        self.v_cmd = 0.0
        self.w_cmd = 0.0
        self._goal: _Goal | None = None
        self._status = NavStatus(state=NavState.IDLE)
        self._next_id = 1
        self.ask_way: Callable[[str, list[Point]], None] = lambda _person, _path: None

    # ------------------------------------------------------------------------------------------ commands

    def pose(self, stamp: float) -> Pose2D:
        """The true pose."""
        return Pose2D(self.x, self.y, self.yaw, stamp)

    def status(self) -> NavStatus:
        """Status of the latest goal."""
        return self._status

    def start_goal(
        self, target: str, goals: Sequence[Point], final_yaw: Callable[[float, float], float | None]
    ) -> int:
        """Start a goal to the nearest reachable of ``goals``; preempts an active goal. Returns its id."""
        self._cancel("preempted")
        self.v_cmd = self.w_cmd = 0.0
        gid = self._next_id
        self._next_id += 1
        self._goal = _Goal(goal_id=gid, target=target, goals=list(goals), final_yaw=final_yaw)
        if not goals:
            self._finish(NavState.FAILED, "no free pose near the target")
        else:
            self._status = NavStatus(state=NavState.ACTIVE, goal_id=gid, target=target)
        return gid

    def fail_now(self, target: str, reason: str) -> int:
        """Register a goal that fails at once with ``reason`` (e.g. nothing reachable); returns its id."""
        gid = self.start_goal(target, [(self.x, self.y)], lambda x, y: None)
        self._finish(NavState.FAILED, reason)
        return gid

    def set_velocity(self, linear: float, angular: float) -> None:
        """Velocity mode: cancel any goal and hold ``(linear, angular)`` clipped to the limits."""
        self._cancel("preempted by a velocity command")
        self.v_cmd = max(-self.spec.max_linear, min(self.spec.max_linear, linear))
        self.w_cmd = max(-self.spec.max_angular, min(self.spec.max_angular, angular))

    def stop(self) -> None:
        """Zero velocity, cancel any goal (reason ``"stopped"``)."""
        self._cancel("stopped")
        self.v_cmd = self.w_cmd = 0.0

    def _cancel(self, reason: str) -> None:
        if self._goal is not None and self._status.state is NavState.ACTIVE:
            self._finish(NavState.CANCELLED, reason)
        self._goal = None

    def _finish(self, state: NavState, reason: str = "") -> None:
        g = self._goal
        if g is None:
            return
        goal_pose = Pose2D(g.path[-1][0], g.path[-1][1], self.yaw) if g.path else None
        self._status = NavStatus(
            state=state, goal_id=g.goal_id, target=g.target, reason=reason, goal=goal_pose, path=tuple(g.path)
        )
        self._goal = None
        self.v_cmd = self.w_cmd = 0.0

    # ------------------------------------------------------------------------------------------ control

    def update(
        self,
        dt: float,
        people: Sequence[tuple[str, float, float, float]],
        is_free: Callable[[float, float], bool],
    ) -> None:
        """Advance one control period of ``dt`` seconds.

        Args:
            dt: period in seconds.
            people: ``(name, x, y, radius)`` of people present, to wait for or plan around.
            is_free: True when the base may stand at a point (used in velocity mode: the base stops at
            contact).
        """
        if self._goal is not None:
            self._follow(dt, people)
            return
        if self.v_cmd == 0.0 and self.w_cmd == 0.0:
            return
        self.yaw = wrap_angle(self.yaw + self.w_cmd * dt)
        nx = self.x + self.v_cmd * math.cos(self.yaw) * dt
        ny = self.y + self.v_cmd * math.sin(self.yaw) * dt
        if is_free(nx, ny):
            self.x, self.y = nx, ny
            return
        lo, hi = 0.0, 1.0  # move as far as the bumper allows
        for _ in range(8):
            mid = (lo + hi) / 2
            if is_free(self.x + (nx - self.x) * mid, self.y + (ny - self.y) * mid):
                lo = mid
            else:
                hi = mid
        self.x, self.y = self.x + (nx - self.x) * lo, self.y + (ny - self.y) * lo

    def _plan(self, g: _Goal, people: Sequence[tuple[str, float, float, float]], around_people: bool) -> bool:
        blocked = None
        if around_people:
            discs = [(x, y, r + self.spec.radius + 0.1) for _, x, y, r in people]
            blocked = self.grid.with_discs(discs)
        path = self.grid.plan((self.x, self.y), g.goals, blocked)
        if path is None or (around_people and not self._clear_of(path, people)):
            return False
        g.path, g.index, g.planned = path, 1, True
        self._status = NavStatus(
            state=NavState.ACTIVE,
            goal_id=g.goal_id,
            target=g.target,
            goal=Pose2D(path[-1][0], path[-1][1], 0.0),
            path=tuple(path),
        )
        return True

    def _clear_of(self, path: list[Point], people: Sequence[tuple[str, float, float, float]]) -> bool:
        """Whether ``path`` (from the base on) never gets closer to a person than touching them, or than the
        base is now (a base already close to someone may only move away). A path planned around people from
        a start inside a person's inflated disc may lead straight through them."""
        for _, px, py, r in people:
            limit = min(r + self.spec.radius + 0.05, math.hypot(px - self.x, py - self.y)) - 1e-3
            if any(segment_distance(px, py, a, b) < limit for a, b in itertools.pairwise(path)):
                return False
        return True

    def _follow(self, dt: float, people: Sequence[tuple[str, float, float, float]]) -> None:
        g = self._goal
        assert g is not None
        if not g.planned and not self._plan(g, people, around_people=False):
            self._finish(NavState.FAILED, "no path")
            return
        s = self.spec
        if g.index >= len(g.path):
            yaw = g.final_yaw(self.x, self.y)
            if yaw is None or abs(wrap_angle(yaw - self.yaw)) < 0.03:
                self._finish(NavState.SUCCEEDED)
                return
            err = wrap_angle(yaw - self.yaw)
            self.yaw = wrap_angle(self.yaw + max(-s.max_angular * dt, min(s.max_angular * dt, err)))
            return
        tx, ty = g.path[g.index]
        dist = math.hypot(tx - self.x, ty - self.y)
        if dist < 0.02:
            g.index += 1
            return
        err = wrap_angle(math.atan2(ty - self.y, tx - self.x) - self.yaw)
        turn = max(-s.max_angular * dt, min(s.max_angular * dt, err))
        if abs(err) > 0.5:
            self.yaw = wrap_angle(self.yaw + turn)
            return
        step = min(s.max_linear * dt, dist)
        nyaw = wrap_angle(self.yaw + turn)
        nx = self.x + step * math.cos(nyaw)
        ny = self.y + step * math.sin(nyaw)
        if abs(err) < 0.05:  # stay on the straight segment
            nx, ny = self.x + step * (tx - self.x) / dist, self.y + step * (ty - self.y) / dist
        blocker = next(
            (
                n
                for n, px, py, r in people
                if math.hypot(nx - px, ny - py) < r + s.radius + 0.05
                and math.hypot(nx - px, ny - py) < math.hypot(self.x - px, self.y - py)
            ),
            None,
        )
        if blocker is not None:
            g.blocked_for += dt
            g.blocked_total += dt
            if g.blocked_total > GIVE_UP_AFTER:
                self._finish(NavState.FAILED, f"path blocked by {blocker}")
            elif g.blocked_for > WAIT_BEFORE_REPLAN:
                g.blocked_for = 0.0
                replanned = self._plan(g, people, around_people=True)
                if not replanned and blocker not in g.asked and g.target != f"person {blocker}":
                    g.asked.add(blocker)  # no way around: ask them to make way (not whom it goes to), wait
                    self.ask_way(blocker, [(self.x, self.y), *g.path[g.index :]])
            return
        g.blocked_for = 0.0
        self.x, self.y, self.yaw = nx, ny, nyaw
