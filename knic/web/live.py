"""The running system's side of the web view (``knic run --serve``).

The closed loop is single-threaded (see :mod:`knic.system`); the web server runs on its own thread. They meet
in a :class:`LiveLink`, and nothing else crosses:

* the link registers a :class:`WebBridge` component with the run's scheduler. On the run thread, at each of
  its steps, the bridge takes the goals the page submitted (a thread-safe queue) through the goal intake
  (:class:`knic.intake.GoalIntake`: understood, validated, confirmed when the role asks, all or nothing), and
  every ``1 / snapshot_hz`` wall seconds it copies what the journal does not hold into a fresh
  JSON-able :attr:`LiveLink.snapshot` (components, the bus's recent messages, KGM-2's tracks and their voxels,
  the navigation path, the ground truth); the server only reads that dictionary, which is replaced whole.
* the facts themselves reach the page through the journal file (:class:`knic.web.view.JournalView`).

Pacing: with ``pace`` the bridge holds the loop back so that simulated time runs at most ``pace`` times wall
time (``1``: real time), so a person can watch; without it the run goes as fast as the machine allows.
"""

from __future__ import annotations

import math
import queue
import threading
import time
from collections.abc import Callable
from concurrent.futures import Future
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from knic.intake import GoalIntake
from knic.scheduler import Component, SchedulerEvent
from knic.units import CKU, LLKU

if TYPE_CHECKING:
    from knic.system import KnicSystem

#: most voxels drawn per track, most messages shown per topic, most topics
MAX_VOXELS, MAX_MESSAGES, MAX_TOPICS = 600, 5, 300


@dataclass
class _Request:
    text: str
    source: str
    future: Future[dict[str, Any]]


class LinkClosed(Exception):
    """The run is over: the link takes no more goals."""


class LiveLink:
    """What the web server may ask of a running system (see the module docstring).

    Lifecycle: construct on the run thread after the system is built (it registers its bridge with the
    scheduler and takes a first snapshot); :meth:`submit` from any thread; :meth:`close` when the run is over
    (pending and later submissions fail with :class:`LinkClosed`).

    Args:
        system: the assembled run.
        pace: simulated seconds per wall second at most (None: as fast as possible).
        speaker: the person "me" refers to in typed commands.
        snapshot_hz: wall-clock rate of snapshots.
    """

    def __init__(
        self,
        system: KnicSystem,
        *,
        pace: float | None = None,
        speaker: str = "annie",
        snapshot_hz: float = 5.0,
    ) -> None:
        from knic.system.names import run_vocabulary

        self.system = system
        self.pace = pace
        self.speaker = speaker
        self.snapshot_period = 1.0 / snapshot_hz
        self.vocabulary = run_vocabulary(system)
        self.intake = GoalIntake(
            system.kb,
            self.vocabulary,
            say=system.context.say,
            confirm=system.pipeline.role.confirm_actions,
        )
        self._requests: queue.SimpleQueue[_Request] = queue.SimpleQueue()
        self._trace: list[dict[str, Any]] = []
        self._unsubscribe = system.trace.subscribe(lambda event: self._trace.append(event.to_dict()))
        self._closed = threading.Event()
        self._last_snapshot = -math.inf
        self._pace_origin: tuple[float, float] | None = None
        self.version = 0
        self.snapshot: dict[str, Any] = {}
        self.bridge = WebBridge(self)
        system.scheduler.add(self.bridge)
        self.take_snapshot(system.sim.time)

    # ------------------------------------------------------------------ any thread
    def events(self, after: int = 0) -> list[dict[str, Any]]:
        """The run's trace events after the first ``after`` (a :class:`knic.web.view.TraceSource`)."""
        return self._trace[after:]

    @property
    def closed(self) -> bool:
        """The run is over."""
        return self._closed.is_set()

    def submit(self, text: str, *, source: str = "web") -> Future[dict[str, Any]]:
        """Queue a command, a PDDL goal or a yes/no answer for the intake; the future gets its reply dict.

        The future fails with :class:`LinkClosed` when the run is over.
        """
        future: Future[dict[str, Any]] = Future()
        if self.closed:
            future.set_exception(LinkClosed("the run is over; it takes no more goals"))
            return future
        self._requests.put(_Request(text, source, future))
        return future

    def close(self) -> None:
        """The run is over: fail the pending submissions, stop following the trace."""
        self._closed.set()
        self._unsubscribe()
        self._drain(lambda r: r.future.set_exception(LinkClosed("the run is over; it takes no more goals")))
        self.snapshot = {**self.snapshot, "state": "ended"}
        self.version += 1

    # ------------------------------------------------------------------ run thread
    def step(self, now: float) -> None:
        """The bridge's step: goals in, a snapshot out when due, then pacing (run thread only)."""
        self._drain(self._take)
        wall = time.perf_counter()
        if wall - self._last_snapshot >= self.snapshot_period:
            self.take_snapshot(now)
        if self.pace is not None:
            if self._pace_origin is None:
                self._pace_origin = (now, wall)
            delay = self._pace_origin[1] + (now - self._pace_origin[0]) / self.pace - time.perf_counter()
            if delay > 0:
                time.sleep(min(delay, 1.0))

    def _drain(self, handle: Callable[[_Request], None]) -> None:
        while True:
            try:
                request = self._requests.get_nowait()
            except queue.Empty:
                return
            handle(request)

    def _take(self, request: _Request) -> None:
        if not request.future.set_running_or_notify_cancel():
            return
        try:
            intake = self.intake
            if intake.awaiting_answer is not None and not request.text.strip().startswith("("):
                reply = intake.hear(request.text)
            else:
                reply = intake.submit(request.text, speaker=self.speaker, source=request.source)
            request.future.set_result(reply.to_dict())
        except Exception as exc:  # a bug in the intake must not stop the run; the page gets the reason
            request.future.set_exception(exc)

    def take_snapshot(self, now: float) -> None:
        """Copy the live state the journal does not hold into :attr:`snapshot` (run thread only)."""
        system = self.system
        self._last_snapshot = time.perf_counter()
        pending = self.intake.awaiting_answer
        self.snapshot = {
            "state": "ended" if self.closed else "running",
            "sim_time": now,
            "pace": self.pace,
            "role": role_record(system),
            "components": component_records(system, now),
            "overruns": [overrun_record(e) for e in list(system.scheduler.events)[-20:]],
            "bus": bus_records(system),
            "tracks": track_records(system),
            "believed_pose": believed_pose(system),
            "nav_path": [list(p) for p in system.sim.nav_status().path],
            "truth": truth_record(system),
            "devices": device_records(system),
            "intake": {
                "awaiting_answer": pending.said if pending is not None else None,
                "history": [
                    {
                        "text": r.submission.text,
                        "outcome": r.outcome.value,
                        "time": r.time,
                        "reason": r.reason,
                    }
                    for r in self.intake.history[-10:]
                ],
            },
            "trace_events": len(self._trace),
        }
        self.version += 1


class WebBridge(Component):
    """The scheduler component of a :class:`LiveLink` (stepped after every other part, 20 Hz of sim time)."""

    name = "web"
    frequency = 20.0

    def __init__(self, link: LiveLink) -> None:
        self.link = link

    def step(self, now: float) -> None:
        """Goals in, snapshot out, pacing (see :meth:`LiveLink.step`)."""
        self.link.step(now)


# ---------------------------------------------------------------------- snapshot parts (run thread)
def role_record(system: KnicSystem) -> dict[str, Any]:
    """The role: name, description, flags and the rate and priority per class and room."""
    role = system.pipeline.role
    return {
        "name": role.name,
        "description": role.description,
        "confirm_actions": role.confirm_actions,
        "operator_only": role.operator_only,
        "person_ttl_s": role.person_ttl_s,
        "default": {"rate_hz": role.default.rate_hz, "priority": role.default.priority},
        "classes": {c: {"rate_hz": p.rate_hz, "priority": p.priority} for c, p in role.classes.items()},
        "rooms": {r: {"rate_hz": p.rate_hz, "priority": p.priority} for r, p in role.rooms.items()},
    }


def component_records(system: KnicSystem, now: float) -> list[dict[str, Any]]:
    """Per scheduled component: nominal and measured rate, mean and worst step time, overruns
    (:meth:`knic.scheduler.Scheduler.report`)."""
    return list(system.scheduler.report(now))


def overrun_record(event: SchedulerEvent) -> dict[str, Any]:
    """One overrun report (JSON)."""
    return {
        "kind": event.kind,
        "component": event.component,
        "time": event.now,
        "wall_ms": 1000.0 * event.wall_s,
        "budget_ms": 1000.0 * event.budget_s,
        "missed": event.missed,
    }


def summarize(payload: Any) -> str:
    """A one-line description of a bus payload (an LLKU, a CKU, or anything else)."""
    if isinstance(payload, LLKU):
        x, y, z = payload.position
        return (
            f"LLKU {payload.kind.value} {payload.symbol} conf {payload.confidence:.2f} at "
            f"({x:.2f}, {y:.2f}, {z:.2f}), {len(payload.points)} points"
        )
    if isinstance(payload, CKU):
        x, y, z = payload.position
        return (
            f"CKU {payload.kind.value} {payload.symbol} conf {payload.confidence:.2f} at "
            f"({x:.2f}, {y:.2f}, {z:.2f}), {len(payload.keys)} voxels, priority {payload.role_priority}"
        )
    text = repr(payload)
    return text if len(text) <= 120 else text[:117] + "..."


def bus_records(system: KnicSystem) -> list[dict[str, Any]]:
    """The bus's recent messages per topic (newest last), the topics most recently used first."""
    recent = system.pipeline.bus.recent()
    topics = sorted(recent.items(), key=lambda kv: -kv[1][-1].seq if kv[1] else 0)[:MAX_TOPICS]
    return [
        {
            "topic": topic,
            "messages": [
                {"stamp": m.stamp, "source": m.source, "seq": m.seq, "summary": summarize(m.payload)}
                for m in messages[-MAX_MESSAGES:]
            ],
        }
        for topic, messages in topics
    ]


def track_records(system: KnicSystem) -> list[dict[str, Any]]:
    """KGM-2's tracks: symbol, class, centroid, and the voxels of the latest observation inserted into the
    track's octomap (the keys KP' intersect with rooms and furniture) projected on the floor, one cell per
    distinct ``(x, y)``, with the radius they span around the centroid.

    The keys rather than the whole tree: reading every occupied leaf out of pyoctomap costs about 0.1 s per
    track, too much for a snapshot taken on the run thread several times a second.
    """
    import numpy as np

    from knic.spatial.keys import key_centers

    out = []
    for track in system.pipeline.cognition.tracks():
        resolution = float(track.octomap.resolution)
        keys = np.asarray(track.keys)
        occupied = key_centers(keys, resolution) if len(keys) else np.empty((0, 3))
        cx, cy, _ = track.centroid
        voxels: list[list[float]] = []
        radius = 0.0
        if len(occupied):
            cells = np.unique(np.floor(occupied[:, :2] / resolution).astype(np.int64), axis=0)[:MAX_VOXELS]
            xy = (cells.astype(np.float64) + 0.5) * resolution
            radius = float(np.max(np.hypot(xy[:, 0] - cx, xy[:, 1] - cy))) + resolution / 2
            voxels = [[round(float(a), 3), round(float(b), 3)] for a, b in xy]
        out.append(
            {
                "symbol": track.symbol,
                "cls": track.cls,
                "x": cx,
                "y": cy,
                "radius": radius,
                "resolution": resolution,
                "confidence": track.confidence,
                "last_seen": track.last_seen,
                "voxels": voxels,
            }
        )
    return out


def believed_pose(system: KnicSystem) -> dict[str, Any] | None:
    """The robot's pose as its localisation reports it (the latest ``percept.pose`` message)."""
    latest = system.pipeline.bus.latest("percept.pose")
    if not latest or not isinstance(latest[-1].payload, LLKU):
        return None
    unit = latest[-1].payload
    return {
        "name": unit.symbol,
        "x": unit.position[0],
        "y": unit.position[1],
        "yaw": float(unit.attributes.get("yaw", 0.0)),
        "stamp": unit.stamp,
    }


def truth_record(system: KnicSystem) -> dict[str, Any]:
    """Where the simulator says things are (the referee's view; the robot never reads it)."""
    sim, world = system.sim, system.world
    pose = sim.true_robot_pose()
    items = []
    for name in world.items:
        p = sim.true_pose(name).position
        items.append({"name": name, "x": p[0], "y": p[1], "z": p[2]})
    people = []
    for name in world.people:
        if sim.person_present(name):
            p = sim.true_pose(name).position
            people.append({"name": name, "x": p[0], "y": p[1]})
    return {
        "robot": {"name": world.robot.name, "x": pose.x, "y": pose.y, "yaw": pose.yaw},
        "items": items,
        "people": people,
        "held": sim.held_item(),
    }


def device_records(system: KnicSystem) -> list[dict[str, Any]]:
    """The devices with their true state (the believed state is in the facts)."""
    states = system.sim.device_states()
    return [
        {"name": d.name, "kind": d.kind, "room": d.room, "truth": states.get(d.name)}
        for d in system.world.devices.values()
    ]
