"""The simulator as its own ROS 2 node (``knic sim --ros``): its sensors out, the robot's commands in.

The node owns a :class:`worlds.simulation.Simulation` and is the only thing that steps it. It publishes what
the robot's sensors read (:mod:`knic.ros.topics`: pose estimate, camera image, depth, detections with
camera info and pose, sounds, speech heard, device readings, navigation state, the map) and simulated time
on ``/clock``; it executes the commands of the :class:`core.robot.Robot` protocol that arrive on
``/robot/command`` and answers each on ``/robot/command_result`` with the same ``id``. Nothing of the
oracle goes out, except at the end: :meth:`SimNode.referee` judges the goals KnIC published on
``/knic/facts`` against ground truth, for whoever started the simulator.

Time, two modes:

* **lockstep** (default): simulated time advances only when KnIC grants it on ``/knic/step_until``: the
  node steps to the granted time, publishes the sensors for that instant, then ``/clock`` and a ``/sim/tick``
  manifest (what it published, so a subscriber can wait until everything for that instant arrived). KnIC
  then reads, thinks and commands, and grants the next instant. The split run does the same work, in the
  same order, as one process.
* **free running** (``rate``): simulated time follows the wall clock times ``rate``, as a robot would; KnIC
  keeps up or falls behind.

Lifecycle: construct (creates the node in the given rclpy context), :meth:`run` on one thread until the
time limit or ``stop`` is set, :meth:`close`. Commands are executed inside :meth:`run`'s spinning, on the
same thread as the stepping, so the simulator is never touched from two threads.
"""

from __future__ import annotations

import contextlib
import math
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from core.errors import KnicError
from core.robot import CommandResult, NavStatus
from knic.ros import topics as tp
from knic.ros.camera import frame_to_ros
from knic.ros.convert import (
    MessageError,
    grid_to_ros,
    json_object,
    json_to_ros,
    nav_status_to_json,
    pose_to_ros,
    result_to_json,
    sound_to_json,
    time_from_ros,
    time_to_ros,
    utterance_to_json,
)

if TYPE_CHECKING:
    from worlds.simulation import Simulation

#: command name -> (argument names, whether the answer is a CommandResult)
COMMANDS: dict[str, tuple[tuple[str, ...], str]] = {
    "navigate_to_point": (("x", "y", "yaw"), "goal"),
    "navigate_to_room": (("room",), "goal"),
    "navigate_to_furniture": (("furniture", "near"), "goal"),
    "navigate_to_person": (("person",), "goal"),
    "set_base_velocity": (("linear", "angular"), "none"),
    "stop": ((), "none"),
    "pick": (("item", "at"), "result"),
    "place": (("furniture",), "result"),
    "release": ((), "result"),
    "give": (("person", "at"), "result"),
    "pan_camera": (("angle",), "none"),
    "set_light": (("device", "on"), "result"),
    "set_level": (("device", "percent"), "result"),
    "say": (("text",), "none"),
    "escort": (("person", "at"), "result"),
    "stop_escort": ((), "none"),
}


class SimNode:
    """The simulator's node (see the module docstring).

    Args:
        sim: the simulation (the node steps it; nobody else may).
        context: an initialised rclpy context (:func:`knic.ros.env.ros_context`).
        rate: None for lockstep; else the real-time factor of free running.
        dt: simulated seconds per step when free running.
    """

    def __init__(self, sim: Simulation, context: Any, *, rate: float | None = None, dt: float = 0.05) -> None:
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import CameraInfo, Image
        from std_msgs.msg import String

        from knic.ros.env import make_executor, make_node

        if rate is not None and rate <= 0:
            raise KnicError(f"knic sim: --rate must be positive, got {rate}")
        self.sim = sim
        self.rate = rate
        self.dt = dt
        self.node = make_node("knic_sim", context)
        self.executor = make_executor(context)
        self.executor.add_node(self.node)
        n, q = self.node, tp.reliable
        self.pub_clock = n.create_publisher(Clock, tp.CLOCK, q(10))
        self.pub_tick = n.create_publisher(String, tp.TICK, q(10))
        self.pub_pose = n.create_publisher(_pose_type(), tp.POSE_ESTIMATE, q(10, latched=True))
        self.pub_state = n.create_publisher(String, tp.ROBOT_STATE, q(10, latched=True))
        self.pub_devices = n.create_publisher(String, tp.DEVICES, q(10, latched=True))
        self.pub_sounds = n.create_publisher(String, tp.SOUNDS, q(100, latched=True))
        self.pub_heard = n.create_publisher(String, tp.HEARD, q(100, latched=True))
        self.pub_camera = {
            "image": n.create_publisher(Image, tp.CAMERA_IMAGE, q(5, latched=True)),
            "depth": n.create_publisher(Image, tp.CAMERA_DEPTH, q(5, latched=True)),
            "masks": n.create_publisher(Image, tp.CAMERA_MASKS, q(5, latched=True)),
            "labels": n.create_publisher(String, tp.CAMERA_LABELS, q(5, latched=True)),
            "info": n.create_publisher(CameraInfo, tp.CAMERA_INFO, q(5, latched=True)),
            "pose": n.create_publisher(_pose_type(), tp.CAMERA_POSE, q(5, latched=True)),
        }
        self.pub_map = n.create_publisher(_grid_type(), tp.ROBOT_MAP, q(1, latched=True))
        self.pub_result = n.create_publisher(String, tp.COMMAND_RESULT, q(50))
        n.create_subscription(String, tp.COMMAND, self._on_command, q(50))
        n.create_subscription(Clock, tp.STEP_UNTIL, self._on_grant, q(10))
        n.create_subscription(String, tp.FACTS, self._on_facts, q(1, latched=True))
        self.granted: float | None = None
        self.goals: list[str] = []
        self.commands = 0
        self.steps = 0
        self._seq = 0
        self._sounds = 0
        self._heard = 0
        self._frame_stamp = -1.0
        self._published_at: float | None = None
        self._replies: dict[Any, dict[str, Any]] = {}
        self._devices: dict[str, Any] | None = None
        self._state_content: tuple[Any, ...] | None = None
        grid = sim.grid
        self.pub_map.publish(grid_to_ros(grid.occupied, grid.origin, grid.resolution, sim.time))

    # ------------------------------------------------------------------ running

    def run(self, max_sim_time: float = math.inf, stop: threading.Event | None = None) -> float:
        """Step and publish until ``max_sim_time`` simulated seconds or ``stop`` is set; returns the
        simulated time reached."""
        stop = stop or threading.Event()
        wall0, sim0 = time.perf_counter(), self.sim.time
        while not stop.is_set() and self.node.context.ok():
            self.executor.spin_once(timeout_sec=0.01 if self.rate is None else 0.0)
            if self.rate is None:
                target = self.granted
            else:
                target = sim0 + (time.perf_counter() - wall0) * self.rate
                target = math.floor(target / self.dt + 1e-9) * self.dt
            if target is None:
                continue
            target = min(target, max_sim_time)
            if target > self.sim.time + 1e-9:
                self.sim.step(target - self.sim.time)
                self.steps += 1
                self.publish_sensors()
            elif self._published_at is None:
                self.publish_sensors()
            if self.sim.time >= max_sim_time - 1e-9:
                break
            if self.rate is not None:
                time.sleep(min(0.005, self.dt / self.rate))
        return self.sim.time

    def publish_sensors(self) -> None:
        """Publish every sensor reading for the simulator's present instant, then ``/clock`` and the tick."""
        from rosgraph_msgs.msg import Clock

        sim, t = self.sim, self.sim.time
        self.pub_pose.publish(pose_to_ros(sim.robot_pose()))
        for sound in sim.poll_sounds():
            self._sounds += 1
            self.pub_sounds.publish(json_to_ros({"seq": self._sounds, **sound_to_json(sound)}))
        for heard in sim.poll_utterances():
            self._heard += 1
            self.pub_heard.publish(json_to_ros({"seq": self._heard, **utterance_to_json(heard)}))
        devices = sim.device_states()
        if devices != self._devices:  # latched: the latest readings stay available
            self._devices = devices
            self.pub_devices.publish(json_to_ros({"t": t, "states": devices}))
        frame = sim.camera_frame()
        if frame.stamp != self._frame_stamp:
            self._frame_stamp = frame.stamp
            messages = frame_to_ros(frame)
            for key, pub in self.pub_camera.items():
                pub.publish(getattr(messages, key))
        now_state = (nav_status_to_json(sim.nav_status()), sim.held_item(), sim.camera_pan)
        if now_state != self._state_content:  # latched: the latest state stays available
            self._state_content = now_state
            self.pub_state.publish(json_to_ros(self.robot_state()))
        self.pub_clock.publish(Clock(clock=time_to_ros(t)))
        manifest = {
            "t": t,
            "state": self._seq,
            "frame": self._frame_stamp,
            "sounds": self._sounds,
            "heard": self._heard,
        }
        self.pub_tick.publish(json_to_ros(manifest))
        self._published_at = t

    def robot_state(self) -> dict[str, Any]:
        """The small state a command may change: navigation status, held item, camera pan (numbered)."""
        self._seq += 1
        sim = self.sim
        return {
            "seq": self._seq,
            "t": sim.time,
            "nav": nav_status_to_json(sim.nav_status()),
            "held": sim.held_item(),
            "pan": sim.camera_pan,
        }

    # ------------------------------------------------------------------ callbacks

    def _on_grant(self, msg: Any) -> None:
        t = time_from_ros(msg.clock)
        if self.granted is None or t > self.granted:
            self.granted = t
        elif self._published_at is not None and abs(t - self._published_at) < 1e-9:
            self.publish_sensors()  # the grant was repeated: the tick may have been missed (discovery)

    def _on_facts(self, msg: Any) -> None:
        with contextlib.suppress(MessageError):
            self.goals = [str(g) for g in json_object(msg, "facts snapshot", "goals")["goals"]]

    def _on_command(self, msg: Any) -> None:
        reply: dict[str, Any]
        request_id = _request_id(msg)
        if request_id is not None and request_id in self._replies:  # a repeat: answer again, do not redo
            self.pub_result.publish(json_to_ros(self._replies[request_id]))
            return
        try:
            request = json_object(msg, "command", "id", "op")
            reply = {"id": request["id"], **self.execute(str(request["op"]), request.get("args") or {})}
        except KnicError as exc:
            reply = {"id": request_id, "ok": False, "error": str(exc), "kind": type(exc).__name__}
        reply["state"] = self.robot_state()
        if request_id is not None:
            self._replies[request_id] = reply
            while len(self._replies) > 256:
                self._replies.pop(next(iter(self._replies)))
        self.pub_result.publish(json_to_ros(reply))

    def execute(self, op: str, args: dict[str, Any]) -> dict[str, Any]:
        """Execute one command of the robot protocol on the simulator.

        Returns:
            ``{"ok": True, "value": goal id | None}`` or a command result's ``ok`` and ``reason``.

        Raises:
            MessageError: unknown command or arguments; WorldError: a name the world does not know.
        """
        if op not in COMMANDS:
            raise MessageError(f"command {op!r} unknown; known: {', '.join(sorted(COMMANDS))}")
        names, answer = COMMANDS[op]
        extra = set(args) - set(names)
        if extra:
            raise MessageError(f"command {op}: unexpected argument {sorted(extra)[0]!r}")
        method: Callable[..., Any] = getattr(self.sim, op)
        kwargs = {k: (tuple(v) if k in ("near", "at") and v is not None else v) for k, v in args.items()}
        try:
            value = method(**kwargs)
        except TypeError as exc:
            raise MessageError(f"command {op}: {exc}") from None
        self.commands += 1
        if answer == "result":
            assert isinstance(value, CommandResult)
            return result_to_json(value)
        return {"ok": True, "value": value if answer == "goal" else None}

    # ------------------------------------------------------------------ referee

    def referee(self) -> dict[str, Any]:
        """The goals KnIC last published and which of them do not hold in ground truth (for referees)."""
        from knowledge_base import Fact

        truth = self.sim.ground_truth_facts()
        unmet = [g for g in self.goals if tuple((Fact.parse(g).predicate, *Fact.parse(g).args)) not in truth]
        return {
            "sim_time": round(self.sim.time, 3),
            "goals": self.goals,
            "unmet_in_truth": unmet,
            "success": bool(self.goals) and not unmet,
            "commands": self.commands,
            "steps": self.steps,
        }

    def nav_status(self) -> NavStatus:
        """The simulator's navigation status (for tests)."""
        return self.sim.nav_status()

    def close(self) -> None:
        """Destroy the node (the context is its owner's to shut down)."""
        self.executor.remove_node(self.node)
        self.node.destroy_node()
        self.executor.shutdown(timeout_sec=0.5)


def _request_id(msg: Any) -> Any:
    try:
        value = json_object(msg, "command").get("id")
        return value if isinstance(value, int | str) else None
    except MessageError:
        return None


def _pose_type() -> Any:
    from geometry_msgs.msg import PoseStamped

    return PoseStamped


def _grid_type() -> Any:
    from nav_msgs.msg import OccupancyGrid

    return OccupancyGrid
