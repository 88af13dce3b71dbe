"""KnIC on ROS 2: assembled on a :class:`~knic.ros.robot.RosRobot` (``knic ros``), or attached to a
single-process run (``knic run --ros``).

:class:`RosRun` builds KnIC with the single-process run's own code (:func:`knic.system.assembly.build_agent`
from a :class:`~knic.system.config.RunConfig`: knowledge base seeded from the world's map, the inference
pipeline, the ERL actions, the dispatcher with the same recovery policy) on a robot reached over ROS 2 topics
instead of the simulator in process, and schedules first the :class:`~knic.ros.robot.RosClock` (KnIC
runs on the robot's ``/clock``; a lockstep simulator advances as KnIC grants) and last the
:class:`~knic.ros.knic_node.KnicBridge`. It holds no oracle: its verdict is the robot's own
(:class:`knic.system.verdict.BeliefVerdict`); the simulator's node referees (:meth:`SimNode.referee`).

:func:`attach` adds the KnIC node to an assembled single-process :class:`knic.system.KnicSystem`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from core.errors import KnicError
from knic.ros.knic_node import HeardSpeech, KnicBridge, KnicNode
from knic.ros.robot import RosClock, RosLink, RosRobot
from knic.scheduler import Scheduler
from knic.system.assembly import build_agent
from knic.system.config import RunConfig
from knic.system.loop import RunLoop
from knic.system.verdict import BeliefVerdict, Stop
from planner.dispatch import DispatcherState
from planner.engines import silence_up

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
        config: what the run is made of, as for a single-process run (world: the robot's map and what it
            knows before the run, no ground truth; role; journal; trace stream; recovery policy, planning
            time, settle and give-up times, a robot wrapper); ``seed``, ``scenario`` and ``gui`` are the
            simulator's and ignored here.
        listen: speech the robot hears goes to the goal intake (:class:`~knic.ros.knic_node.HeardSpeech`:
            commands, and answers to the open question).
    """

    def __init__(self, link: RosLink, config: RunConfig | None = None, *, listen: bool = False) -> None:
        from worlds.api import load_world

        silence_up()
        self.config = cfg = config or RunConfig()
        if not cfg.dispatch:
            raise KnicError("knic ros: the run needs the dispatcher (RunConfig.dispatch=True)")
        self.link = link
        self.world = load_world(cfg.world)
        self.robot = RosRobot(link, self.world.robot.name)
        seam = self.robot if cfg.robot_wrapper is None else cfg.robot_wrapper(self.robot)  # fault injection
        agent = build_agent(cfg, self.world, seam, lambda: self.robot.time)
        assert agent.dispatcher is not None
        self.kb, self.pipeline, self.perception = agent.kb, agent.pipeline, agent.perception
        self.context, self.trace, self.dispatcher = agent.context, agent.trace, agent.dispatcher
        self.clock = RosClock(self.robot)
        self.node = KnicNode(
            link,
            self.kb,
            self.trace,
            self.robot,
            self.world,
            cognition=self.pipeline.cognition,
            confirm=self.pipeline.role.confirm_actions,
        )
        self.scheduler = Scheduler(real_time_factor=cfg.real_time_factor)
        self.scheduler.add(self.clock)
        for component in agent.components():
            self.scheduler.add(component)
        self.scheduler.add(KnicBridge(self.node))
        self.speech = HeardSpeech(self.node) if listen else None
        if self.speech is not None:
            self.scheduler.add(self.speech)
        self.beliefs = BeliefVerdict(
            self.kb,
            self.dispatcher.dropped_for_good,
            lambda: self.dispatcher.state == DispatcherState.IDLE,
            settle_s=cfg.settle_s,
            give_up_s=cfg.give_up_s,
        )

    def add_goal(self, text: str) -> dict[str, Any]:
        """Submit a goal through the intake (as ``/knic/goal`` would); returns the intake's reply."""
        reply = self.node.submit(text, source="user")
        out = dict(reply.to_dict())
        if reply.outcome.value == "asked":
            out["question"] = self.node.questions.open_id
        return out

    def run(self, max_sim_time: float, *, until_done: bool = True) -> RosRunResult:
        """Run until the robot believes its goals achieved or dropped (``until_done`` and some goal given),
        or ``max_sim_time`` simulated seconds."""
        loop: RunLoop[Stop] = RunLoop(self.scheduler, self.config.check_period_s)
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
