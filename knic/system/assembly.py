"""Assembly: the closed loop's parts built from a :class:`~knic.system.config.RunConfig`.

:func:`assemble` builds, in order:

1. the world (``load_world``) and its :class:`~worlds.simulation.Simulation` (seeded, optional scenario): the
   robot behind the seam, and the oracle a referee may read;
2. the :class:`~knowledge_base.KnowledgeBase` of ``worlds/erl_home/domain.pddl`` (optionally journalled to
   SQLite) on the simulated clock, seeded with what the robot knows before the run
   (:func:`knic.seed.seed_kb_from_world`: map, anchors, priors as assumed ``possibly_at`` facts);
3. the inference pipeline (:func:`knic.pipeline.build_pipeline`: KGM-1, KGM-2 under the role, KGM-3) reading
   the robot's sensors, and the perception the actions steer by (:class:`knic.kgm3.sightings.BusPerception`);
4. the ERL actions (:func:`actions.erl.build_erl_registry`) commanding the robot, and the steppable
   :class:`~planner.dispatch.Dispatcher` with its recovery policy and trace (unless ``dispatch`` is off);
5. under a role with revisit data (the companion), the :class:`~knic.system.revisits.RevisitDriver`: while
   the robot has nothing to do it goes back to look where the role says (beliefs only);
6. one :class:`~knic.scheduler.Scheduler` stepping, in this order at each instant: the simulator
   (:class:`SimulationComponent`), the pipeline's components, the dispatcher (:class:`DispatcherComponent`),
   the revisit driver.

Steps 2-5 do not depend on the robot behind the seam: :func:`build_agent` builds them on any
:class:`~core.robot.Robot` (the ROS 2 split run builds its KnIC with it). Nothing runs here;
:class:`~knic.system.loop.RunLoop` runs a scheduler.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from actions.base import ActionRegistry
from actions.erl import ErlContext, build_erl_registry
from knic.kgm3.sightings import BusPerception
from knic.pipeline import Pipeline, build_pipeline
from knic.scheduler import Component, Scheduler
from knic.seed import seed_kb_from_world
from knic.system.config import ACTION_TIME_LIMITS, DOMAIN, RunConfig
from knic.system.revisits import RevisitDriver, dispatcher_free
from knowledge_base import KnowledgeBase
from planner.dispatch import Dispatcher
from planner.engines import TaskPlanner, silence_up
from planner.recovery import GoalRetry, RecoveryPolicy
from planner.trace import Trace

if TYPE_CHECKING:
    from core.robot import Robot
    from worlds.model import World
    from worlds.oracle import Oracle
    from worlds.simulation import Simulation


class Steppable(Protocol):
    """A simulator the loop advances: its clock and one step to a later time."""

    @property
    def time(self) -> float:
        """Simulated seconds since the start of the episode."""
        ...

    def step(self, dt: float = 0.1) -> None:
        """Advance simulated time by ``dt`` seconds."""
        ...


class SimulationComponent(Component):
    """Advances the simulator to the scheduler's time; registered first, so perception reads the present.

    Args:
        sim: the simulation.
        frequency: Hz of simulated time (the simulator integrates in its own control periods in between).
    """

    name = "sim"

    def __init__(self, sim: Steppable, frequency: float = 20.0) -> None:
        self.sim = sim
        self.frequency = frequency

    def step(self, now: float) -> None:
        """Step the simulator from its time to ``now`` (simulated seconds); nothing when already there."""
        dt = now - self.sim.time
        if dt > 1e-9:
            self.sim.step(dt)


class DispatcherComponent(Component):
    """Steps the plan dispatcher once per period (after perception at the same instant).

    An idle dispatcher's step costs nothing until the goals change or a goal stops holding (see
    :mod:`planner.dispatch`), so it is stepped unconditionally.
    """

    name = "dispatcher"

    def __init__(self, dispatcher: Dispatcher, frequency: float = 10.0) -> None:
        self.dispatcher = dispatcher
        self.frequency = frequency

    def step(self, now: float) -> None:
        """One bounded unit of dispatch work (plan, start, advance or finish an action)."""
        self.dispatcher.step()


@dataclass
class Assembly:
    """The built parts of one run (see the module docstring); :meth:`close` releases them.

    ``sim`` is the whole simulator (for the loop's clock and :meth:`close`); the parts that steer or perceive
    see it only as :attr:`robot`, a referee only as :attr:`oracle`.
    """

    config: RunConfig
    world: World
    sim: Simulation
    kb: KnowledgeBase
    pipeline: Pipeline
    perception: BusPerception
    context: ErlContext
    registry: ActionRegistry
    trace: Trace
    dispatcher: Dispatcher | None
    scheduler: Scheduler
    revisits: RevisitDriver | None = None

    @property
    def robot(self) -> Robot:
        """The robot seam of the simulator: what perception reads and actions command."""
        return self.sim

    @property
    def oracle(self) -> Oracle:
        """The simulator's ground truth, for referees and benchmarks only."""
        return self.sim

    def close(self) -> None:
        """Stop listening, close the journal and the simulator (idempotent)."""
        if self.dispatcher is not None:
            self.dispatcher.close()
        self.perception.close()
        self.kb.close()
        self.sim.close()


def assemble(config: RunConfig) -> Assembly:
    """Build every part of a run from ``config``; nothing runs yet.

    Raises:
        core.errors.WorldError: unknown world or scenario.
        core.errors.InferenceError: unknown role.
        core.errors.JournalError: the journal file cannot be written.
    """
    from worlds.api import load_world
    from worlds.simulation import Simulation

    silence_up()
    world = load_world(config.world)
    sim = Simulation(world, seed=config.seed, scenario=config.scenario, gui=config.gui)
    try:
        robot = sim if config.robot_wrapper is None else config.robot_wrapper(sim)
        agent = build_agent(config, world, robot, lambda: sim.time)
        scheduler = Scheduler(real_time_factor=config.real_time_factor)
        scheduler.add(SimulationComponent(sim))
        for component in agent.components():
            scheduler.add(component)
    except BaseException:
        sim.close()
        raise
    return Assembly(
        config,
        world,
        sim,
        agent.kb,
        agent.pipeline,
        agent.perception,
        agent.context,
        agent.registry,
        agent.trace,
        agent.dispatcher,
        scheduler,
        agent.revisits,
    )


@dataclass
class Agent:
    """KnIC's side of a run on any robot (steps 2-5 of the module docstring): what :func:`assemble` builds
    on the simulator in process and :class:`knic.ros.split.RosRun` on a robot reached over ROS 2, so both
    share one recovery policy, one set of action time limits and one planning-time model."""

    kb: KnowledgeBase
    pipeline: Pipeline
    perception: BusPerception
    context: ErlContext
    registry: ActionRegistry
    trace: Trace
    dispatcher: Dispatcher | None
    revisits: RevisitDriver | None = None

    def components(self) -> list[Component]:
        """The pipeline's components, then the dispatcher's, then the revisit driver, in the order a
        scheduler steps them."""
        out: list[Component] = list(self.pipeline)
        if self.dispatcher is not None:
            out.append(DispatcherComponent(self.dispatcher))
        if self.revisits is not None:
            out.append(self.revisits)
        return out


def build_agent(config: RunConfig, world: World, robot: Robot, clock: Callable[[], float]) -> Agent:
    """KnIC on ``robot`` (the seam: the simulator or a remote robot) in ``world`` (its map and what the
    robot knows before the run), the knowledge base on ``clock`` (the robot's seconds).

    Raises:
        core.errors.InferenceError: unknown role.
        core.errors.JournalError: the journal file cannot be written.
    """
    kb = open_kb(config.journal, clock)
    seed_kb_from_world(kb, world)
    pipeline = build_pipeline(kb, robot, world, config.role)
    perception = BusPerception(kb, pipeline.bus)
    context = ErlContext(robot, kb, perception, robot_name=world.robot.name)
    registry = build_erl_registry(robot, kb, context=context, confirm_devices=True)
    trace = Trace(config.trace_stream)
    dispatcher = None
    if config.dispatch:
        dispatcher = Dispatcher(
            kb,
            TaskPlanner(kb.domain.up_domain),
            registry,
            policy=RecoveryPolicy(
                max_replans_per_goal=config.max_replans_per_goal,
                goal_retry=GoalRetry(config.goal_retries, config.retry_after_s),
            ),
            trace=trace,
            time_limits=ACTION_TIME_LIMITS,
            planning_time=config.planning_time,
            replan_settle_s=config.replan_settle_s,
        )
    revisits = None
    revisit = pipeline.role.revisit
    if dispatcher is not None and config.revisits and (revisit.people or revisit.rooms):
        from knic.kgm2.attention import Revisits, rooms_from_kb

        policy = Revisits(kb, revisit, rooms_from_kb(kb))
        revisits = RevisitDriver(robot, policy, dispatcher_free(kb, dispatcher), trace)
    return Agent(kb, pipeline, perception, context, registry, trace, dispatcher, revisits)


def open_kb(journal: Path | None, clock: Callable[[], float]) -> KnowledgeBase:
    """The ERL knowledge base on ``clock`` (simulated seconds), journalled to ``journal`` when given (an
    existing file and its ``-wal``/``-shm`` companions are replaced)."""
    if journal is not None:
        for suffix in ("", "-wal", "-shm"):
            Path(str(journal) + suffix).unlink(missing_ok=True)
    kb = KnowledgeBase.from_pddl(DOMAIN, journal=journal)
    kb.set_clock(clock)
    return kb
