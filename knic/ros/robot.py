"""KnIC's side of the robot seam across processes: a :class:`core.robot.Robot` backed by ROS 2 topics.

:class:`RosRobot` subscribes to what a robot (or ``knic sim --ros``) publishes -- :mod:`knic.ros.topics`:
pose estimate, camera frames, sounds, speech heard, device readings, navigation state -- and keeps the
latest of each; the readings of the protocol return those at once. A command is a request on
``/robot/command`` with a fresh ``id``; the call spins until the reply with that ``id`` arrives (or
``command_timeout`` wall seconds pass: :class:`RobotLinkError`) and returns its value. Each reply carries the
robot's state after the command (navigation status, held item), so a goal id is followed by its status at
once, as with the simulator in process.

Threading: every callback runs inside :meth:`RosLink.spin`, which only the run loop's thread calls (from
:class:`RosClock`, from a command waiting for its reply, from the KnIC node's bridge); the caches need no
lock.

:class:`RosClock` is the scheduler component that keeps KnIC on the robot's time: at each instant it grants
the simulator that instant (``/knic/step_until``) and waits until ``/clock`` reached it and, in lockstep,
until every message of the instant's ``/sim/tick`` manifest arrived.
"""

from __future__ import annotations

import itertools
import time
from typing import Any

import numpy as np

from core.errors import KnicError, WorldError
from core.robot import (
    CameraFrame,
    CameraIntrinsics,
    CommandResult,
    DeviceReading,
    NavState,
    NavStatus,
    Pose2D,
    Pose3D,
    SoundEvent,
    Utterance,
    Vec3,
)
from knic.ros import topics as tp
from knic.ros.camera import CameraMessages, frame_from_ros
from knic.ros.convert import (
    MessageError,
    json_object,
    json_to_ros,
    nav_status_from_json,
    pose_from_ros,
    result_from_json,
    sound_from_json,
    time_from_ros,
    time_to_ros,
    utterance_from_json,
)
from knic.scheduler import Component


class RobotLinkError(KnicError):
    """The robot does not answer over ROS 2 (no reply to a command, no clock) within the time limit."""

    exit_code = 1


class RosLink:
    """One rclpy executor for the nodes of a process, spun by the run loop's thread only.

    Args:
        context: an initialised rclpy context (:func:`knic.ros.env.ros_context`).
    """

    def __init__(self, context: Any) -> None:
        from knic.ros.env import make_executor

        self.context = context
        self.executor = make_executor(context)
        self.nodes: list[Any] = []

    def node(self, name: str, **kwargs: Any) -> Any:
        """A new node in this link's context, spun by :meth:`spin`."""
        from knic.ros.env import make_node

        node = make_node(name, self.context, **kwargs)  # fewer entities in every wait
        self.executor.add_node(node)
        self.nodes.append(node)
        return node

    def spin(self, timeout: float = 0.0) -> None:
        """Run the callbacks that are ready (waiting at most ``timeout`` wall seconds for the first)."""
        self.executor.spin_once(timeout_sec=timeout)

    def drain(self, limit: int = 1000) -> None:
        """Run every ready callback, without waiting."""
        for _ in range(limit):
            before = self._count
            self.executor.spin_once(timeout_sec=0.0)
            if self._count == before:
                break

    _count = 0

    def count(self) -> None:
        """Note that a callback ran (subscriptions call it, so :meth:`drain` knows when nothing is left)."""
        self._count += 1

    def close(self) -> None:
        """Destroy the nodes and the executor."""
        for node in self.nodes:
            self.executor.remove_node(node)
            node.destroy_node()
        self.nodes.clear()
        self.executor.shutdown(timeout_sec=0.5)


def _blank_frame() -> CameraFrame:
    """What the camera shows before its first frame arrived: nothing (no detection, depth inf)."""
    return CameraFrame(
        stamp=-1.0,
        width=1,
        height=1,
        rgb=np.zeros((1, 1, 3), dtype=np.uint8),
        depth=np.full((1, 1), np.inf, dtype=np.float32),
        intrinsics=CameraIntrinsics(1, 1, 1.0, 1.0, 0.5, 0.5, 0.05, 8.0),
        camera_pose=Pose3D((0.0, 0.0, 0.0)),
    )


class RosRobot:
    """A :class:`core.robot.Robot` over ROS 2 topics (see the module docstring).

    Args:
        link: the process's executor; the robot adds its node ``knic_robot``.
        robot_name: the robot's PDDL symbol.
        command_timeout: wall seconds a command waits for its reply.
    """

    def __init__(self, link: RosLink, robot_name: str, *, command_timeout: float = 20.0) -> None:
        from geometry_msgs.msg import PoseStamped
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import CameraInfo, Image
        from std_msgs.msg import String

        self.link = link
        self._name = robot_name
        self.command_timeout = command_timeout
        n, q = link.node("knic_robot"), tp.reliable
        self.node = n
        self._time = 0.0
        self._clock_seen = False
        self._tick: dict[str, Any] | None = None
        self._pose = Pose2D(0.0, 0.0, 0.0, -1.0)
        self._state_seq = 0
        self._nav = NavStatus(NavState.IDLE)
        self._held: str | None = None
        self._devices: dict[str, DeviceReading] = {}
        self._sounds: list[SoundEvent] = []
        self._sound_seq = 0
        self._heard: list[Utterance] = []
        self._heard_seq = 0
        self._parts: dict[float, CameraMessages] = {}
        self._frame = _blank_frame()
        self._frame_done = -1.0  # stamp of the latest frame received whole (converted or dropped)
        self._results: dict[int, dict[str, Any]] = {}
        self._pending: set[int] = set()
        self._ids = itertools.count(1)
        self.commands_sent = 0
        self.pub_command = n.create_publisher(String, tp.COMMAND, q(50))
        self.pub_grant = n.create_publisher(Clock, tp.STEP_UNTIL, q(10))
        n.create_subscription(Clock, tp.CLOCK, self._on_clock, q(10))
        n.create_subscription(String, tp.TICK, self._on_tick, q(10))
        n.create_subscription(PoseStamped, tp.POSE_ESTIMATE, self._on_pose, q(10, latched=True))
        n.create_subscription(String, tp.ROBOT_STATE, self._on_state, q(10, latched=True))
        n.create_subscription(String, tp.DEVICES, self._on_devices, q(10, latched=True))
        n.create_subscription(String, tp.SOUNDS, self._on_sound, q(100, latched=True))
        n.create_subscription(String, tp.HEARD, self._on_heard, q(100, latched=True))
        n.create_subscription(String, tp.COMMAND_RESULT, self._on_result, q(50))
        for key, msg_type, topic in (
            ("image", Image, tp.CAMERA_IMAGE),
            ("depth", Image, tp.CAMERA_DEPTH),
            ("masks", Image, tp.CAMERA_MASKS),
            ("labels", String, tp.CAMERA_LABELS),
            ("info", CameraInfo, tp.CAMERA_INFO),
            ("pose", PoseStamped, tp.CAMERA_POSE),
        ):
            n.create_subscription(msg_type, topic, self._camera_part(key), q(5, latched=True))

    # ------------------------------------------------------------------ callbacks

    def _on_clock(self, msg: Any) -> None:
        self.link.count()
        self._time = max(self._time, time_from_ros(msg.clock))
        self._clock_seen = True

    def _on_tick(self, msg: Any) -> None:
        self.link.count()
        try:
            tick = json_object(msg, "tick", "t", "state", "frame", "sounds", "heard")
        except MessageError:
            return
        if self._tick is None or tick["t"] >= self._tick["t"]:
            self._tick = tick

    def _on_pose(self, msg: Any) -> None:
        self.link.count()
        pose = pose_from_ros(msg)
        if pose.stamp >= self._pose.stamp:
            self._pose = pose

    def _on_state(self, msg: Any) -> None:
        self.link.count()
        try:
            self._take_state(json_object(msg, "robot state", "seq", "nav", "held"))
        except MessageError:
            return

    def _take_state(self, state: dict[str, Any]) -> None:
        if int(state["seq"]) <= self._state_seq:
            return
        self._state_seq = int(state["seq"])
        self._nav = nav_status_from_json(state["nav"])
        held = state.get("held")
        self._held = None if held is None else str(held)

    def _on_devices(self, msg: Any) -> None:
        self.link.count()
        try:
            states = json_object(msg, "device readings", "states")["states"]
        except MessageError:
            return
        self._devices = {str(k): (v if isinstance(v, bool) else float(v)) for k, v in states.items()}

    def _on_sound(self, msg: Any) -> None:
        self.link.count()
        try:
            data = json_object(msg, "sound", "seq")
            if int(data["seq"]) > self._sound_seq:
                self._sounds.append(sound_from_json(data))
                self._sound_seq = int(data["seq"])
        except MessageError:
            return

    def _on_heard(self, msg: Any) -> None:
        self.link.count()
        try:
            data = json_object(msg, "utterance", "seq")
            if int(data["seq"]) > self._heard_seq:
                self._heard.append(utterance_from_json(data))
                self._heard_seq = int(data["seq"])
        except MessageError:
            return

    def _camera_part(self, key: str) -> Any:
        def take(msg: Any) -> None:
            self.link.count()
            raw = time_from_ros(msg.header.stamp) if key != "labels" else self._labels_stamp(msg)
            if raw is None:
                return
            stamp = round(raw, 6)  # the parts meet on the stamp to the microsecond (JSON and ns stamps)
            if stamp <= self._frame_done:
                return
            parts = self._parts.setdefault(stamp, CameraMessages())
            setattr(parts, key, msg)
            if parts.complete():
                self._frame_done = max(self._frame_done, stamp)
                try:
                    self._frame = frame_from_ros(parts)
                except MessageError as exc:  # a broken frame is skipped (and said), the run goes on
                    self.node.get_logger().warning(f"camera frame at t={stamp:.2f} dropped: {exc}")
                self._parts = {s: p for s, p in self._parts.items() if s > stamp}

        return take

    @staticmethod
    def _labels_stamp(msg: Any) -> float | None:
        try:
            return float(json_object(msg, "detection labels", "stamp")["stamp"])
        except (MessageError, TypeError, ValueError):
            return None

    def _on_result(self, msg: Any) -> None:
        self.link.count()
        try:
            reply = json_object(msg, "command result", "id")
        except MessageError:
            return
        if isinstance(reply.get("state"), dict):
            self._take_state(reply["state"])
        if reply["id"] in self._pending:
            self._results[reply["id"]] = reply

    # ------------------------------------------------------------------ synchronisation (RosClock)

    def caught_up(self, now: float) -> bool:
        """Whether the robot's clock reached ``now`` and, with a lockstep manifest for it, every message it
        lists arrived."""
        if self._time < now - 1e-9:
            return False
        tick = self._tick
        if tick is None or tick["t"] < now - 1e-9:
            return self._clock_seen and self._tick is None
        return (
            self._state_seq >= int(tick["state"])
            and self._frame_done >= float(tick["frame"]) - 1e-9
            and self._sound_seq >= int(tick["sounds"])
            and self._heard_seq >= int(tick["heard"])
            and self._pose.stamp >= tick["t"] - 1e-9
        )

    def grant(self, now: float) -> None:
        """Tell a lockstep simulator it may advance to ``now`` (``/knic/step_until``)."""
        from rosgraph_msgs.msg import Clock

        self.pub_grant.publish(Clock(clock=time_to_ros(now)))

    # ------------------------------------------------------------------ commands

    def call(self, op: str, **args: Any) -> dict[str, Any]:
        """Send one command and wait for its reply.

        Raises:
            WorldError: the robot does not know a name in the command (nothing changed).
            RobotLinkError: no reply within ``command_timeout`` wall seconds, or the robot refused the
                command as malformed.
        """
        request_id = next(self._ids)
        request = json_to_ros({"id": request_id, "op": op, "args": args})
        deadline = time.monotonic() + self.command_timeout
        while self.pub_command.get_subscription_count() == 0:  # nobody would hear it yet (discovery)
            if time.monotonic() > deadline:
                raise RobotLinkError(f"robot: nobody subscribes to {tp.COMMAND} (command {op})")
            self.link.spin(0.05)
        self._pending.add(request_id)
        self.pub_command.publish(request)
        self.commands_sent += 1
        sent = time.monotonic()
        while request_id not in self._results:
            now = time.monotonic()
            if now > deadline:
                self._pending.discard(request_id)
                raise RobotLinkError(f"robot: no reply to command {op} within {self.command_timeout:g} s")
            if now - sent > 1.0:  # the request or its reply was lost: the robot answers a repeat once
                self.pub_command.publish(request)
                sent = now
            self.link.spin(0.05)
        self._pending.discard(request_id)
        reply = self._results.pop(request_id)
        if "error" in reply:
            if reply.get("kind") == "WorldError":
                raise WorldError(str(reply["error"]))
            raise RobotLinkError(f"robot refused command {op}: {reply['error']}")
        return reply

    def _result(self, op: str, **args: Any) -> CommandResult:
        return result_from_json(self.call(op, **args))

    def _goal(self, op: str, **args: Any) -> int:
        return int(self.call(op, **args)["value"])

    # ------------------------------------------------------------------ the Robot protocol: readings

    @property
    def time(self) -> float:
        """The robot's clock (``/clock``): simulated seconds in simulation."""
        return self._time

    @property
    def robot_name(self) -> str:
        """The robot's PDDL symbol."""
        return self._name

    def camera_frame(self) -> CameraFrame:
        """The latest complete camera frame (an empty one before the first arrived)."""
        return self._frame

    def robot_pose(self) -> Pose2D:
        """The latest pose estimate."""
        return self._pose

    def poll_sounds(self) -> list[SoundEvent]:
        """Sounds received since the previous call."""
        out, self._sounds = self._sounds, []
        return out

    def poll_utterances(self) -> list[Utterance]:
        """Speech received since the previous call."""
        out, self._heard = self._heard, []
        return out

    def device_states(self) -> dict[str, DeviceReading]:
        """The latest device readings."""
        return dict(self._devices)

    def held_item(self) -> str | None:
        """The gripper's item, as of the latest state or command reply."""
        return self._held

    def nav_status(self) -> NavStatus:
        """The latest navigation status."""
        return self._nav

    # ------------------------------------------------------------------ the Robot protocol: commands

    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        """Start a base goal to a world point; returns the goal id."""
        return self._goal("navigate_to_point", x=x, y=y, yaw=yaw)

    def navigate_to_room(self, room: str) -> int:
        """Start a base goal to a room; returns the goal id."""
        return self._goal("navigate_to_room", room=room)

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        """Start a base goal within reach of a piece of furniture; returns the goal id."""
        return self._goal(
            "navigate_to_furniture", furniture=furniture, near=None if near is None else list(near)
        )

    def navigate_to_person(self, person: str) -> int:
        """Start a base goal near a person; returns the goal id."""
        return self._goal("navigate_to_person", person=person)

    def set_base_velocity(self, linear: float, angular: float) -> None:
        """Drive the base directly."""
        self.call("set_base_velocity", linear=linear, angular=angular)

    def stop(self) -> None:
        """Stop the base and cancel any goal."""
        self.call("stop")

    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        """Grasp an item (at the believed position ``at``, world frame, when given)."""
        return self._result("pick", item=item, **_at(at))

    def place(self, furniture: str) -> CommandResult:
        """Put the held item on a piece of furniture."""
        return self._result("place", furniture=furniture)

    def release(self) -> CommandResult:
        """Open the gripper."""
        return self._result("release")

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Hand the held item to a person (believed at ``at`` when given)."""
        return self._result("give", person=person, **_at(at))

    def pan_camera(self, angle: float) -> None:
        """Set the camera pan (radians)."""
        self.call("pan_camera", angle=angle)

    def set_light(self, device: str, on: bool) -> CommandResult:
        """Switch a light."""
        return self._result("set_light", device=device, on=on)

    def set_level(self, device: str, percent: float) -> CommandResult:
        """Set a dimmer or blinds."""
        return self._result("set_level", device=device, percent=percent)

    def say(self, text: str) -> None:
        """Speak through the robot's loudspeaker."""
        self.call("say", text=text)

    def escort(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Ask a person to follow (believed at ``at`` when given)."""
        return self._result("escort", person=person, **_at(at))

    def stop_escort(self) -> None:
        """Stop escorting."""
        self.call("stop_escort")


def _at(at: Vec3 | None) -> dict[str, Any]:
    """The optional believed position of a gripper or hand-over command, only when given."""
    return {} if at is None else {"at": [float(v) for v in at]}


class RosClock(Component):
    """Keeps the scheduler on the robot's clock (see the module docstring); registered first.

    Args:
        robot: the ROS robot.
        frequency: Hz of simulated time (the lockstep simulator advances in these steps).
        timeout: wall seconds without reaching an instant before :class:`RobotLinkError`.
    """

    name = "ros_clock"

    def __init__(self, robot: RosRobot, frequency: float = 10.0, timeout: float = 60.0) -> None:
        self.robot = robot
        self.frequency = frequency
        self.timeout = timeout
        self.waits = 0

    def step(self, now: float) -> None:
        """Grant ``now`` and wait until the robot's messages for it arrived.

        Raises:
            RobotLinkError: nothing reached ``now`` within ``timeout`` wall seconds.
        """
        robot = self.robot
        robot.link.drain()
        start = last_grant = time.monotonic()
        robot.grant(now)
        while not robot.caught_up(now):
            robot.link.spin(0.05)
            self.waits += 1
            wall = time.monotonic()
            if wall - last_grant > 1.0:  # a grant or a tick lost while the peers discover each other
                robot.grant(now)
                last_grant = wall
            if wall - start > self.timeout:
                raise RobotLinkError(f"robot: no clock reaching t={now:.2f} s within {self.timeout:g} s")
