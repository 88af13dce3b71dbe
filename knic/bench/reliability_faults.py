"""Fault injection in the closed loop, for ``knic bench reliability``: faults at the robot seam and a planner
whose subprocess is killed, with the goals still reached.

The faults are injected from outside, never by patching internals:

* :class:`FaultyRobot` wraps the simulator behind the :class:`~core.robot.Robot` protocol (handed to the
  run through ``RunConfig.robot_wrapper``) and, once armed, makes one command misbehave as a real robot's
  driver would: ``action_raises`` (a base command raises), ``action_hangs`` (a base goal is accepted and then
  never progresses: the base stays put and the goal stays ACTIVE until the robot is stopped),
  ``action_false`` (a grasp reports failure), ``camera_dropout`` or ``localisation_dropout`` (the sensor
  keeps returning its last reading, stale stamp included, for ``dropout_s`` simulated seconds, as a driver
  that stopped publishing does).
* :class:`KillingPlanner` wraps the dispatcher's planner (its public ``planner`` attribute) and, once,
  answers a planning request by running Fast Downward on the task in a subprocess and killing that
  subprocess (SIGKILL, its children included) while it runs; the dispatcher gets what a dead planner gives.

:func:`fault_runs` runs one closed-loop episode per fault in the simulated apartment and counts ``injected``
(faults that really fired), ``recovered`` (fired in a run whose goals the referee then found holding in
the ground truth) and ``crashed`` (the run itself raised: the loop did not survive the fault).
"""

from __future__ import annotations

import os
import signal
import threading
import time
from typing import Any

from core.robot import (
    CameraFrame,
    CommandResult,
    DeviceReading,
    NavState,
    NavStatus,
    Pose2D,
    Robot,
    SoundEvent,
    Utterance,
    Vec3,
)

__all__ = ["FAULTS", "FaultyRobot", "KillingPlanner", "fault_runs"]

#: the faults, each in its own episode
FAULTS = (
    "action_raises",
    "action_hangs",
    "action_false",
    "camera_dropout",
    "localisation_dropout",
    "planner_dies",
)
#: the errand every fault episode runs (search, pick, carry, place: every kind of action)
GOAL = "(object_at glasses bedroom)"
WORLD = "erl_home_paper"


class InjectedFault(RuntimeError):
    """What an ``action_raises`` fault raises from a robot command."""


class FaultyRobot:
    """A :class:`~core.robot.Robot` that forwards everything to ``robot`` except one injected fault.

    Args:
        robot: the robot behind the seam (the simulator).
        fault: one of :data:`FAULTS` other than ``planner_dies`` (None: a clean robot).
        after_s: the fault fires at the first matching command at or after this robot time (seconds).
        dropout_s: how long a sensor dropout lasts (seconds of robot time).
    """

    def __init__(
        self, robot: Robot, fault: str | None, *, after_s: float = 2.0, dropout_s: float = 20.0
    ) -> None:
        self._robot = robot
        self.fault = fault
        self.after_s = after_s
        self.dropout_s = dropout_s
        #: robot time at which the fault fired (None: not yet)
        self.fired_at: float | None = None
        self._hung: NavStatus | None = None
        self._dropout: tuple[float, CameraFrame | None, Pose2D | None] | None = None
        self._last_frame: CameraFrame | None = None
        self._last_pose: Pose2D | None = None

    # -------------------------------------------------------------------- arming
    def _fires(self, kind: str) -> bool:
        if self.fault != kind or self.fired_at is not None or self._robot.time < self.after_s:
            return False
        self.fired_at = self._robot.time
        return True

    def _navigate(self, start: Any, *args: Any) -> int:
        self._hung = None
        if self._fires("action_raises"):
            raise InjectedFault("injected fault: the base driver raised on a navigation goal")
        if self._fires("action_hangs"):
            last = self._robot.nav_status()
            self._hung = NavStatus(NavState.ACTIVE, last.goal_id + 1000, "injected hang")
            return self._hung.goal_id
        return int(start(*args))

    def _in_dropout(self, sensor: str) -> bool:
        if self.fault != sensor:
            return False
        if self._dropout is None and self._fires(sensor):
            self._dropout = (self._robot.time, None, None)
        if self._dropout is None:
            return False
        if self._robot.time - self._dropout[0] >= self.dropout_s:
            self.fault = None  # over: the sensors come back
            self._dropout = None
            return False
        return True

    # -------------------------------------------------------------------- readings
    @property
    def time(self) -> float:
        return self._robot.time

    @property
    def robot_name(self) -> str:
        return self._robot.robot_name

    def camera_frame(self) -> CameraFrame:
        if self._in_dropout("camera_dropout") and self._dropout is not None:
            start, frame, pose = self._dropout
            if frame is None:
                frame = self._last_frame if self._last_frame is not None else self._robot.camera_frame()
                self._dropout = (start, frame, pose)
            return frame
        self._last_frame = frame = self._robot.camera_frame()
        return frame

    def robot_pose(self) -> Pose2D:
        if self._in_dropout("localisation_dropout") and self._dropout is not None:
            start, frame, pose = self._dropout
            if pose is None:
                pose = self._last_pose if self._last_pose is not None else self._robot.robot_pose()
                self._dropout = (start, frame, pose)
            return pose
        self._last_pose = pose = self._robot.robot_pose()
        return pose

    def poll_sounds(self) -> list[SoundEvent]:
        return self._robot.poll_sounds()

    def poll_utterances(self) -> list[Utterance]:
        return self._robot.poll_utterances()

    def device_states(self) -> dict[str, DeviceReading]:
        return self._robot.device_states()

    def held_item(self) -> str | None:
        return self._robot.held_item()

    def nav_status(self) -> NavStatus:
        return self._hung if self._hung is not None else self._robot.nav_status()

    # -------------------------------------------------------------------- commands
    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        return self._navigate(self._robot.navigate_to_point, x, y, yaw)

    def navigate_to_room(self, room: str) -> int:
        return self._navigate(self._robot.navigate_to_room, room)

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        return self._navigate(self._robot.navigate_to_furniture, furniture, near)

    def navigate_to_person(self, person: str) -> int:
        return self._navigate(self._robot.navigate_to_person, person)

    def set_base_velocity(self, linear: float, angular: float) -> None:
        self._hung = None
        self._robot.set_base_velocity(linear, angular)

    def stop(self) -> None:
        self._hung = None
        self._robot.stop()

    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        if self._fires("action_false"):
            return CommandResult(False, "injected fault: the grasp slipped")
        return self._robot.pick(item, at)

    def place(self, furniture: str) -> CommandResult:
        return self._robot.place(furniture)

    def release(self) -> CommandResult:
        return self._robot.release()

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        return self._robot.give(person, at)

    def pan_camera(self, angle: float) -> None:
        self._robot.pan_camera(angle)

    def set_light(self, device: str, on: bool) -> CommandResult:
        return self._robot.set_light(device, on)

    def set_level(self, device: str, percent: float) -> CommandResult:
        return self._robot.set_level(device, percent)

    def say(self, text: str) -> None:
        self._robot.say(text)

    def escort(self, person: str, at: Vec3 | None = None) -> CommandResult:
        return self._robot.escort(person, at)

    def stop_escort(self) -> None:
        self._robot.stop_escort()


class KillingPlanner:
    """The dispatcher's planner, except that its first planning request runs Fast Downward in a subprocess
    and kills it (SIGKILL, with its children) while it runs; every later request goes to ``planner``.

    Args:
        planner: the dispatcher's planner (a :class:`planner.engines.TaskPlanner`).
        up_domain: the unified-planning domain (for the Fast Downward run).
    """

    def __init__(self, planner: Any, up_domain: Any) -> None:
        self._planner = planner
        self._up_domain = up_domain
        #: process ids killed (empty: the fault has not fired)
        self.killed: list[int] = []
        self.armed = True

    def __getattr__(self, name: str) -> Any:
        return getattr(self._planner, name)

    def solve(self, task: Any, *, timeout: float | None = None) -> Any:
        if not self.armed:
            return self._planner.solve(task, timeout=timeout)
        from planner.engines import TaskPlanner

        self.armed = False
        done = threading.Event()
        killer = threading.Thread(target=self._kill_children, args=(done,), daemon=True)
        killer.start()
        try:
            return TaskPlanner(self._up_domain, engine="fast-downward").solve(task, timeout=timeout)
        finally:
            done.set()
            killer.join()

    def _kill_children(self, done: threading.Event) -> None:
        while not done.is_set() and not self.killed:
            for pid in _descendants(os.getpid()):
                try:
                    os.kill(pid, signal.SIGKILL)
                    self.killed.append(pid)
                except ProcessLookupError:
                    pass
            time.sleep(0.002)


def _descendants(root: int) -> list[int]:
    """Process ids of every descendant of ``root`` (from ``/proc``; empty where there is none)."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="ascii", errors="replace") as handle:
                ppid = int(handle.read().rsplit(")", 1)[1].split()[1])
        except (OSError, ValueError, IndexError):
            continue
        children.setdefault(ppid, []).append(int(entry))
    out: list[int] = []
    todo = [root]
    while todo:
        found = children.get(todo.pop(), [])
        out += found
        todo += found
    return out


def fault_runs(
    faults: tuple[str, ...] = FAULTS, *, seed: int = 0, max_sim_time: float = 900.0
) -> dict[str, Any]:
    """One closed-loop episode per fault (see the module docstring); the counts and each episode's outcome."""
    from knic.system import KnicSystem, RunConfig

    episodes: dict[str, Any] = {}
    for fault in faults:
        robots: list[FaultyRobot] = []

        def wrap(robot: Robot, fault: str = fault, robots: list[FaultyRobot] = robots) -> Robot:
            faulty = FaultyRobot(robot, None if fault == "planner_dies" else fault)
            robots.append(faulty)
            return faulty

        config = RunConfig(world=WORLD, seed=seed, max_sim_time=max_sim_time, robot_wrapper=wrap)
        wall = time.perf_counter()
        killing: KillingPlanner | None = None
        with KnicSystem(config) as system:
            if fault == "planner_dies":
                killing = KillingPlanner(system.dispatcher.planner, system.kb.domain.up_domain)
                system.dispatcher.planner = killing
            system.add_goal(GOAL)
            try:
                result = system.run()
            except Exception as exc:  # the loop must survive every fault: a crash is what this counts
                episodes[fault] = {"injected": True, "recovered": False, "goal_reached": False,
                                   "crashed": f"{type(exc).__name__}: {exc}"}  # fmt: skip
                continue
        fired = bool(killing.killed) if killing is not None else robots[0].fired_at is not None
        episodes[fault] = {
            "injected": fired,
            "recovered": fired and result.success,
            "goal_reached": result.success,
            "crashed": "",
            "reason": result.reason,
            "sim_s": round(result.sim_time, 1),
            "wall_s": round(time.perf_counter() - wall, 1),
            "replans": result.replans,
        }
    return {
        "injected": sum(e["injected"] for e in episodes.values()),
        "recovered": sum(e["recovered"] for e in episodes.values()),
        "crashed": sum(bool(e["crashed"]) for e in episodes.values()),
        "episodes": episodes,
    }
