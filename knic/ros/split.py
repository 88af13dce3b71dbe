"""KnIC on ROS 2: assembled on a :class:`~knic.ros.robot.RosRobot` (``knic ros``), or attached to a
single-process run (``knic run --ros``).

:class:`RosRun` builds the same parts as :func:`knic.system.assembly.assemble` -- knowledge base seeded from
the world's map, the inference pipeline, the ERL actions, the dispatcher -- on a robot reached over ROS 2
topics instead of the simulator in process, and schedules first the :class:`~knic.ros.robot.RosClock` (KnIC
runs on the robot's ``/clock``; a lockstep simulator advances as KnIC grants) and last the
:class:`~knic.ros.knic_node.KnicBridge`. It holds no oracle: its verdict is the robot's own
(:class:`knic.system.verdict.BeliefVerdict`); the simulator's node referees (:meth:`SimNode.referee`).

:func:`attach` adds the KnIC node to an assembled single-process :class:`knic.system.KnicSystem`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from actions.erl import ErlContext, build_erl_registry
from knic.kgm3.sightings import BusPerception
from knic.pipeline import build_pipeline
from knic.ros.knic_node import KnicBridge, KnicNode
from knic.ros.robot import RosClock, RosLink, RosRobot
from knic.scheduler import Scheduler
from knic.seed import seed_kb_from_world
from knic.system.assembly import DispatcherComponent, open_kb
from knic.system.config import ACTION_TIME_LIMITS
from knic.system.loop import RunLoop
from knic.system.verdict import BeliefVerdict, Stop
from planner.dispatch import Dispatcher, DispatcherState
from planner.engines import TaskPlanner, silence_up
from planner.recovery import GoalRetry, RecoveryPolicy
from planner.trace import Trace

if TYPE_CHECKING:
    from knic.system import KnicSystem


@dataclass
class RosRunResult:
    """How a ``knic ros`` run ended (the robot's own verdict; no ground truth here)."""

    done: bool
    reason: str
    sim_time: float
    wall_s: float
    goals: list[str] = field(default_factory=list)
    plans: int = 0
    replans: int = 0
    commands: int = 0
    fact_events: int = 0

    def to_dict(self) -> dict[str, Any]:
        """JSON form."""
        return dict(self.__dict__)


class RosRun:
    """KnIC on a ROS 2 robot (see the module docstring). Construct, :meth:`run`, :meth:`close`.

    Args:
        link: the process's executor (its context sets the DDS domain).
        world: world name or file: the robot's map and what it knows before the run (no ground truth).
        role: robot role.
        journal: SQLite history file, or None.
        trace_stream: JSON-lines trace stream, or None.
        settle_s: see :class:`knic.system.verdict.BeliefVerdict`.
    """

    def __init__(
        self,
        link: RosLink,
        world: str | Path = "erl_home",
        *,
        role: str = "companion",
        journal: Path | None = None,
        trace_stream: Any = None,
        settle_s: float = 8.0,
    ) -> None:
        from knic.kgm2.roles import load_role
        from worlds.api import load_world

        silence_up()
        self.link = link
        self.world = load_world(world)
        the_role = load_role(role)
        self.robot = RosRobot(link, self.world.robot.name)
        self.kb = open_kb(journal, lambda: self.robot.time)
        seed_kb_from_world(self.kb, self.world)
        self.pipeline = build_pipeline(self.kb, self.robot, self.world, the_role)
        self.perception = BusPerception(self.kb, self.pipeline.bus)
        self.context = ErlContext(self.robot, self.kb, self.perception, robot_name=self.world.robot.name)
        registry = build_erl_registry(self.robot, self.kb, context=self.context, confirm_devices=True)
        self.trace = Trace(trace_stream)
        self.dispatcher = Dispatcher(
            self.kb,
            TaskPlanner(self.kb.domain.up_domain),
            registry,
            policy=RecoveryPolicy(goal_retry=GoalRetry(20, 10.0)),
            trace=self.trace,
            time_limits=ACTION_TIME_LIMITS,
        )
        self.clock = RosClock(self.robot)
        self.node = KnicNode(
            link,
            self.kb,
            self.trace,
            self.robot,
            self.world,
            cognition=self.pipeline.cognition,
            confirm=the_role.confirm_actions,
        )
        self.scheduler = Scheduler()
        self.scheduler.add(self.clock)
        for component in self.pipeline:
            self.scheduler.add(component)
        self.scheduler.add(DispatcherComponent(self.dispatcher))
        self.scheduler.add(KnicBridge(self.node))
        self.beliefs = BeliefVerdict(
            self.kb,
            self.dispatcher.dropped_for_good,
            lambda: self.dispatcher.state == DispatcherState.IDLE,
            settle_s=settle_s,
        )

    def add_goal(self, text: str) -> dict[str, Any]:
        """Submit a goal through the intake (as ``/knic/goal`` would); returns the intake's reply."""
        return dict(self.node.intake.submit(text, source="user").to_dict())

    def run(self, max_sim_time: float, *, until_done: bool = True) -> RosRunResult:
        """Run until the robot believes its goals achieved or dropped (``until_done`` and some goal given),
        or ``max_sim_time`` simulated seconds."""
        loop: RunLoop[Stop] = RunLoop(self.scheduler, 0.5)
        if until_done:
            loop.add_stop(lambda now: self.beliefs(now) if self.kb.goals() else None)
        wall0 = time.perf_counter()
        end = loop.run(max_sim_time)
        stop = end.stop
        if stop is None:
            self.dispatcher.cancel("run ended")
            reason = f"stopped at {max_sim_time:g} s of simulated time"
        else:
            reason = stop.reason
        return RosRunResult(
            done=stop is not None and stop.done,
            reason=reason,
            sim_time=self.robot.time,
            wall_s=time.perf_counter() - wall0,
            goals=[str(g) for g in self.kb.goals()],
            plans=self.dispatcher.plans,
            replans=self.dispatcher.replans,
            commands=self.robot.commands_sent,
            fact_events=self.node.events_published,
        )

    def close(self) -> None:
        """Stop listening and close the knowledge base (the link's owner closes the link)."""
        self.node.publish_snapshot()
        self.node.close()
        self.dispatcher.close()
        self.perception.close()
        self.kb.close()


def attach(system: KnicSystem, link: RosLink) -> KnicNode:
    """Add the KnIC node to a single-process run: its bridge is stepped by the run's scheduler."""
    node = KnicNode(
        link,
        system.kb,
        system.trace,
        system.sim,
        system.world,
        cognition=system.pipeline.cognition,
        confirm=system.pipeline.role.confirm_actions,
    )
    system.scheduler.add(KnicBridge(node))
    return node
