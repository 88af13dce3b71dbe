"""What one run leaves behind: the referee's ground-truth timeline and the robot's ERL recording (a bag).

:class:`Recorder` attaches to an assembled run (its scheduler, knowledge base, bus and simulator) before it
starts and watches it in simulated time:

* for the referee, every :data:`TRUTH_PERIOD_S` the oracle's true dynamic facts and the robot's true pose,
  what the robot said, and when the oracle's penalty counters went up (:class:`~.referee.Timeline`); at
  10 Hz the true base speed of every contact (:class:`~.damage.ImpactProbe`, for the damage model);
* for the ERL recording, the robot's own data: its localisation pose (the KGM-1 pose LLKU, 10 Hz), the path of
  every navigation goal it planned, the command it understood and every change of its fact base
  (:class:`Recording`).

:func:`write_bag` writes the recording as a ROS 2 bag in MCAP format without ROS (the ``rosbags`` library):
``/erlc/robot_pose`` geometry_msgs/msg/PoseStamped, ``/erlc/trajectory`` nav_msgs/msg/Path,
``/erlc/command`` std_msgs/msg/String, ``/knic/facts`` std_msgs/msg/String (one JSON object per change).
Stamps are simulated time. :func:`read_bag` reads one back.

The referee's data come from the oracle (:class:`worlds.oracle.Oracle`), whose readings are pure (no random
draw): watching changes nothing in the run. The recording comes from what the robot itself has: the pose
LLKU on the bus, its navigation status, its knowledge base.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from core.robot import NavState, NavStatus
from knic.bench.granny_annie.referee import Sample, Timeline
from knic.system.loop import Probe
from worlds.oracle import Oracle

if TYPE_CHECKING:
    from knic.bus import Bus, Message
    from knic.scheduler import Scheduler
    from knowledge_base import Change, KnowledgeBase
    from worlds.model import World

#: seconds between two ground-truth samples
TRUTH_PERIOD_S = 0.5
#: the bus topic of the robot's localisation LLKU (KGM-1 ``RobotPoseKP``)
POSE_TOPIC = "percept.pose.robot.robot"
FRAME = "map"
TOPICS = {
    "/erlc/robot_pose": "geometry_msgs/msg/PoseStamped",
    "/erlc/trajectory": "nav_msgs/msg/Path",
    "/erlc/command": "std_msgs/msg/String",
    "/knic/facts": "std_msgs/msg/String",
}


class NavReading(Protocol):
    """The robot reading the recorder takes for the trajectory (:meth:`core.robot.Robot.nav_status`)."""

    def nav_status(self) -> NavStatus:
        """The latest navigation goal (``goal_id``, ``state``, ``path``, ``goal``)."""
        ...


class WorldOracle(Oracle, Protocol):
    """The oracle with the world it simulates (:class:`worlds.simulation.Simulation` satisfies it)."""

    @property
    def world(self) -> World:
        """The world's model (its furniture and walls are what the base may bump into)."""
        ...


@dataclass
class Recording:
    """The robot's own data of one run, in simulated seconds.

    Attributes:
        poses: (t, x, y, yaw) of the localisation estimate.
        paths: (t, [(x, y), ...]) of every planned navigation path.
        commands: (t, text) of the commands understood.
        facts: (t, JSON text) of every change of the fact base.
    """

    poses: list[tuple[float, float, float, float]] = field(default_factory=list)
    paths: list[tuple[float, list[tuple[float, float]]]] = field(default_factory=list)
    commands: list[tuple[float, str]] = field(default_factory=list)
    facts: list[tuple[float, str]] = field(default_factory=list)


class Recorder:
    """Watches one run (see the module docstring). Construct, :meth:`attach` before the run, :meth:`finish`
    after it, :meth:`close` to stop listening."""

    def __init__(
        self,
        oracle: WorldOracle,
        robot: NavReading,
        kb: KnowledgeBase,
        bus: Bus,
        impact_window_s: float = 0.3,
    ) -> None:
        from knic.bench.granny_annie.damage import ImpactProbe

        self.oracle = oracle
        self.impacts = ImpactProbe(oracle, oracle.world, impact_window_s)
        self.robot = robot
        self.timeline = Timeline(impacts=self.impacts.impacts)  # the probe's list: live scores see it too
        self.recording = Recording()
        self._counters = {"bumps": 0, "drops": 0, "person_hits": 0, "testbed_damage": 0}
        self._said = 0
        self._nav_goal = 0
        self._sub = bus.subscribe(POSE_TOPIC, self._on_pose)
        self._unsubscribe = kb.subscribe(self._on_change)

    def attach(self, scheduler: Scheduler) -> None:
        """Add the recorder's probes (stepped after the run's parts at the same instant)."""
        scheduler.add(Probe("bench.truth", 1.0 / TRUTH_PERIOD_S, self.sample))
        scheduler.add(Probe("bench.nav", 10.0, self._nav))
        scheduler.add(Probe("bench.contacts", 10.0, self.impacts.step))

    def command(self, t: float, text: str) -> None:
        """Record a command the robot understood (published on ``/erlc/command``)."""
        self.recording.commands.append((t, text))

    def sample(self, now: float) -> None:
        """Take one ground-truth sample at simulated time ``now``."""
        pose = self.oracle.true_robot_pose()
        facts = frozenset(self.oracle.ground_truth_facts())
        self.timeline.samples.append(Sample(now, facts, (pose.x, pose.y, pose.yaw)))
        counters = self.oracle.counters()
        for name, stamps in (
            ("bumps", self.timeline.bumps),
            ("drops", self.timeline.drops),
            ("person_hits", self.timeline.person_hits),
            ("testbed_damage", self.timeline.testbed_damage),
        ):
            value = int(getattr(counters, name, 0))
            stamps.extend([now] * max(0, value - self._counters[name]))
            self._counters[name] = value
        said = self.oracle.spoken()
        for u in said[self._said :]:
            self.timeline.said.append((float(u.stamp), str(u.text)))
        self._said = len(said)

    def finish(self, end: float, *, finished: bool, understood: tuple[str, ...] | None) -> Timeline:
        """Close the timeline at simulated time ``end`` (a last sample there) and return it."""
        if not self.timeline.samples or self.timeline.samples[-1].t < end - 1e-9:
            self.sample(end)
        self.timeline.end = end
        self.timeline.finished = finished
        self.timeline.understood = understood
        return self.timeline

    def close(self) -> None:
        """Stop listening to the bus and the knowledge base (idempotent)."""
        self._sub.cancel()
        self._unsubscribe()

    def _on_pose(self, message: Message) -> None:
        unit = message.payload
        x, y, _z = unit.position
        self.recording.poses.append((message.stamp, x, y, float(unit.attributes.get("yaw", 0.0))))

    def _nav(self, now: float) -> None:
        """Record the path of each new navigation goal once the robot has planned it (the step after the goal
        was sent), or when the goal ended without one."""
        status = self.robot.nav_status()
        if status.goal_id == self._nav_goal:
            return
        path = [(float(x), float(y)) for x, y in status.path]
        if not path and status.state is NavState.ACTIVE:
            return  # not planned yet
        if not path and status.goal is not None:  # a turn on the spot: the goal pose alone
            path = [(float(status.goal.x), float(status.goal.y))]
        self._nav_goal = status.goal_id
        self.recording.paths.append((now, path))

    def _on_change(self, change: Change) -> None:
        if change.kind.value not in ("add_fact", "remove_fact"):
            return
        entry = {
            "t": round(change.time, 3),
            "op": "add" if change.kind.value == "add_fact" else "remove",
            "fact": "(" + " ".join((change.name, *change.args)) + ")",
            "source": change.provenance.source,
        }
        self.recording.facts.append((change.time, json.dumps(entry, sort_keys=True)))


# --------------------------------------------------------------------------------------------------- bags


def _typestore() -> Any:
    from rosbags.typesys import Stores, get_typestore

    return get_typestore(Stores.ROS2_JAZZY)


def _stamp(store: Any, t: float) -> Any:
    sec = int(t)
    return store.types["builtin_interfaces/msg/Time"](sec=sec, nanosec=round((t - sec) * 1e9) % 1_000_000_000)


def write_bag(path: Path, recording: Recording) -> None:
    """Write ``recording`` as a ROS 2 bag (MCAP storage) in the directory ``path`` (replaced if it
    exists)."""
    import shutil

    from rosbags.rosbag2 import StoragePlugin, Writer

    store = _typestore()
    types = store.types
    header = types["std_msgs/msg/Header"]
    pose_stamped, pose_t = types["geometry_msgs/msg/PoseStamped"], types["geometry_msgs/msg/Pose"]
    point, quat = types["geometry_msgs/msg/Point"], types["geometry_msgs/msg/Quaternion"]
    string, path_t = types["std_msgs/msg/String"], types["nav_msgs/msg/Path"]

    def pose_msg(t: float, x: float, y: float, yaw: float) -> Any:
        import math

        q = quat(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))
        return pose_stamped(
            header=header(stamp=_stamp(store, t), frame_id=FRAME),
            pose=pose_t(position=point(x=x, y=y, z=0.0), orientation=q),
        )

    messages: list[tuple[float, str, Any]] = []
    messages += [(t, "/erlc/robot_pose", pose_msg(t, x, y, yaw)) for t, x, y, yaw in recording.poses]
    for t, points in recording.paths:
        poses = [pose_msg(t, x, y, 0.0) for x, y in points]
        messages.append(
            (
                t,
                "/erlc/trajectory",
                path_t(header=header(stamp=_stamp(store, t), frame_id=FRAME), poses=poses),
            )
        )
    messages += [(t, "/erlc/command", string(data=text)) for t, text in recording.commands]
    messages += [(t, "/knic/facts", string(data=text)) for t, text in recording.facts]
    messages.sort(key=lambda m: m[0])
    if path.exists():
        shutil.rmtree(path)
    with Writer(path, version=9, storage_plugin=StoragePlugin.MCAP) as writer:
        connections = {
            topic: writer.add_connection(topic, msgtype, typestore=store) for topic, msgtype in TOPICS.items()
        }
        for t, topic, msg in messages:
            data = store.serialize_cdr(msg, TOPICS[topic])
            writer.write(connections[topic], round(t * 1e9), data)


def read_bag(path: Path) -> dict[str, list[tuple[float, str, Any]]]:
    """Every message of a bag by topic: (time in seconds, message type, decoded message)."""
    from rosbags.rosbag2 import Reader

    store = _typestore()
    out: dict[str, list[tuple[float, str, Any]]] = {}
    with Reader(path) as reader:
        for connection in reader.connections:
            out.setdefault(connection.topic, [])
        for connection, timestamp, raw in reader.messages():
            msg = store.deserialize_cdr(raw, connection.msgtype)
            out[connection.topic].append((timestamp / 1e9, connection.msgtype, msg))
    return out
