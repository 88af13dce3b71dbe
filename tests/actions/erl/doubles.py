"""A scripted robot for the ERL action tests; it satisfies the robot seam, :class:`core.robot.Robot`.

Navigation goals succeed after ``nav_ticks`` calls of :meth:`FakeRobot.tick` (or fail at once with
``nav_failure``); the gripper and devices answer from simple state. Time advances by ``dt`` per tick. The
camera sees nothing (an empty frame): the action tests feed perception through the perception seam instead.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from core.robot import (
    CAUSE_NOT_AT_BELIEF,
    CameraFrame,
    CameraIntrinsics,
    CommandResult,
    DeviceReading,
    NavState,
    NavStatus,
    Pose2D,
    Pose3D,
    Robot,
    SoundEvent,
    Utterance,
    Vec3,
)
from knic.seed import seed_kb_from_world
from knowledge_base import KnowledgeBase
from worlds.api import load_world

#: metres between the believed and the true item position within which the double's gripper closes on it
GRASP_TOLERANCE = 0.12

DOMAIN = Path(__file__).resolve().parents[3] / "worlds" / "erl_home" / "domain.pddl"
INTRINSICS = CameraIntrinsics(8, 6, 6.0, 6.0, 4.0, 3.0, 0.1, 8.0)


class FakeRobot:
    """A robot whose base teleports to its goal after a few ticks (see the module docstring)."""

    def __init__(self, *, nav_ticks: int = 3, dt: float = 0.1) -> None:
        self.now = 0.0
        self.dt = dt
        self.x, self.y, self.yaw = 2.8, 5.0, 0.0
        self.nav_ticks = nav_ticks
        self.nav_failure = ""
        self.fail_goal_ids: set[int] = set()
        self._goal: tuple[float, float, float | None] | None = None
        self._left = 0
        self._status = NavStatus(NavState.IDLE)
        self._next = 1
        self.held: str | None = None
        self.items: dict[str, tuple[float, float]] = {}
        self.people: dict[str, tuple[float, float]] = {}
        self.lights: dict[str, bool] = {}
        self.levels: dict[str, float] = {}
        self.said: list[str] = []
        self.pan = 0.0
        self.pans: list[float] = []
        self.escorting: str | None = None
        self.goals: list[str] = []
        self.placed: dict[str, str] = {}

    # clock
    @property
    def time(self) -> float:
        return self.now

    @property
    def robot_name(self) -> str:
        return "r2d2"

    def tick(self) -> None:
        """Advance time; arrive when the goal's ticks are used up."""
        self.now = round(self.now + self.dt, 9)
        if self._goal is not None and self._status.state is NavState.ACTIVE:
            self._left -= 1
            if self._left <= 0:
                x, y, yaw = self._goal
                self.x, self.y = x, y
                if yaw is not None:
                    self.yaw = yaw
                self._status = NavStatus(NavState.SUCCEEDED, self._status.goal_id, self._status.target)

    # sensing
    def robot_pose(self) -> Pose2D:
        return Pose2D(self.x, self.y, self.yaw, self.now)

    def camera_frame(self) -> CameraFrame:
        k = INTRINSICS
        return CameraFrame(
            stamp=self.now,
            width=k.width,
            height=k.height,
            rgb=np.zeros((k.height, k.width, 3), dtype=np.uint8),
            depth=np.full((k.height, k.width), np.inf, dtype=np.float32),
            intrinsics=k,
            camera_pose=Pose3D((self.x, self.y, 1.2), stamp=self.now),
        )

    def poll_sounds(self) -> list[SoundEvent]:
        return []

    def poll_utterances(self) -> list[Utterance]:
        return []

    def device_states(self) -> dict[str, DeviceReading]:
        return {**self.lights, **self.levels}

    # navigation
    def _start(self, target: str, x: float, y: float, yaw: float | None) -> int:
        gid = self._next
        self._next += 1
        self.goals.append(target)
        if self.nav_failure or gid in self.fail_goal_ids:
            self._status = NavStatus(NavState.FAILED, gid, target, self.nav_failure or "no path")
            return gid
        self._goal = (x, y, yaw)
        self._left = self.nav_ticks
        self._status = NavStatus(NavState.ACTIVE, gid, target)
        return gid

    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        return self._start(f"point ({x:.2f}, {y:.2f})", x, y, yaw)

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        x, y = near if near is not None else (0.0, 0.0)
        return self._start(f"furniture {furniture}", x - 0.5, y, 0.0)

    def navigate_to_room(self, room: str) -> int:
        return self._start(f"room {room}", 0.0, 0.0, None)

    def navigate_to_person(self, person: str) -> int:
        px, py = self.people[person]
        return self._start(f"person {person}", px - 0.9, py, 0.0)

    def set_base_velocity(self, linear: float, angular: float) -> None:
        self.stop()

    def nav_status(self) -> NavStatus:
        return self._status

    def stop(self) -> None:
        if self._status.state is NavState.ACTIVE:
            self._status = NavStatus(NavState.CANCELLED, self._status.goal_id, self._status.target, "stopped")

    # gripper
    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        if self.held is not None:
            return CommandResult(False, f"hand is not empty: holding {self.held}")
        if item not in self.items:
            return CommandResult(False, f"{item} is not here", CAUSE_NOT_AT_BELIEF if at else "")
        ix, iy = self.items[item]
        if at is not None and math.hypot(ix - at[0], iy - at[1]) > GRASP_TOLERANCE:
            return CommandResult(False, f"the gripper closed on nothing at {at}", CAUSE_NOT_AT_BELIEF)
        d = math.hypot(ix - self.x, iy - self.y)
        if d > 0.9:
            return CommandResult(False, f"{item} is {d:.2f} m away, reach is 0.90 m")
        del self.items[item]
        self.held = item
        return CommandResult(True)

    def place(self, furniture: str) -> CommandResult:
        if self.held is None:
            return CommandResult(False, "hand is empty")
        self.placed[self.held] = furniture
        self.held = None
        return CommandResult(True)

    def release(self) -> CommandResult:
        if self.held is None:
            return CommandResult(False, "hand is empty")
        self.held = None
        return CommandResult(True)

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        if self.held is None:
            return CommandResult(False, "hand is empty")
        px, py = self.people[person]
        d = math.hypot(px - self.x, py - self.y)
        if d > 1.25:
            return CommandResult(False, f"{person} is {d:.2f} m away, reach is 1.25 m")
        self.held = None
        return CommandResult(True)

    def held_item(self) -> str | None:
        return self.held

    def pan_camera(self, angle: float) -> None:
        self.pan = angle
        self.pans.append(angle)

    # devices, speech, escort
    def set_light(self, device: str, on: bool) -> CommandResult:
        if not device.endswith("light"):
            return CommandResult(False, f"{device} is not a light")
        self.lights[device] = on
        return CommandResult(True)

    def set_level(self, device: str, percent: float) -> CommandResult:
        self.levels[device] = percent
        return CommandResult(True)

    def say(self, text: str) -> None:
        self.said.append(text)

    def escort(self, person: str, at: Vec3 | None = None) -> CommandResult:
        px, py = self.people[person]
        if at is not None and math.hypot(px - at[0], py - at[1]) > 1.0:
            return CommandResult(
                False, f"nobody answered: {person} is not at the believed position", CAUSE_NOT_AT_BELIEF
            )
        d = math.hypot(px - self.x, py - self.y)
        if d > 2.0:
            return CommandResult(False, f"{person} is {d:.2f} m away, must be within 2.00 m")
        self.escorting = person
        return CommandResult(True)

    def stop_escort(self) -> None:
        self.escorting = None


def paper_kb() -> KnowledgeBase:
    """A knowledge base of the paper's apartment seeded with what the robot knows (on wall-clock time 0)."""
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: 0.0)
    seed_kb_from_world(kb, load_world("erl_home_paper"))
    return kb


def _check(robot: FakeRobot) -> Robot:
    return robot  # mypy checks the double against the protocol here
