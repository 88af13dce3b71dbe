"""One run of the whole closed loop: simulated apartment, KnIC pipeline, knowledge base, planner, actions.

:class:`KnicSystem` assembles a run from a :class:`RunConfig`:

1. the world (``load_world``) and its :class:`~worlds.simulation.Simulation` (seeded, optional scenario);
2. the :class:`~knowledge_base.KnowledgeBase` of ``worlds/erl_home/domain.pddl`` (optionally journalled to
   SQLite) on the simulated clock, seeded with what the robot knows before the run
   (:func:`knic.seed.seed_kb_from_world`: map, anchors, priors as assumed ``possibly_at`` facts);
3. the inference pipeline (:func:`knic.pipeline.build_pipeline`: KGM-1, KGM-2 under the role, KGM-3);
4. the ERL actions (:func:`actions.erl.build_erl_registry`) and the steppable
   :class:`~planner.dispatch.Dispatcher` with its trace;
5. one :class:`~knic.scheduler.Scheduler` stepping, in this order at each instant: the simulator
   (:class:`SimulationComponent`), the pipeline's components, the dispatcher (:class:`DispatcherComponent`).

Everything runs on one thread in simulated time, as fast as the machine allows (no sleeping), and is
deterministic under the seed. :meth:`KnicSystem.run` stops when every goal holds both in the knowledge base
and in the simulator's ground truth (then waits up to ``settle_s`` for perception to confirm the perceivable
goal facts as observed), when every remaining goal was dropped, or at ``max_sim_time``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from actions.erl import ErlContext, PerceivedEntities, build_erl_registry
from actions.erl.devices import spoken
from core.errors import KnicError, KnowledgeBaseError
from knic.pipeline import Pipeline, build_pipeline
from knic.scheduler import Component, Scheduler
from knic.seed import seed_kb_from_world
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from planner.dispatch import Dispatcher, DispatcherState
from planner.engines import Planner, TaskPlanner, silence_up
from planner.model import PlanningTask
from planner.plan import PlanResult
from planner.recovery import RecoveryPolicy
from planner.trace import EventKind, Trace, TraceEvent

if TYPE_CHECKING:
    from worlds.scenario import Scenario
    from worlds.simulation import Simulation

DOMAIN = Path(__file__).resolve().parent.parent / "worlds" / "erl_home" / "domain.pddl"

#: goal predicates the simulator's ground truth decides
TRUTH_PREDICATES = frozenset(
    {
        "robot_at",
        "person_at",
        "object_at",
        "object_on",
        "holding",
        "hand_empty",
        "has",
        "light_on",
        "light_off",
        "device_level",
        "person_near",
    }
)
#: goal predicates a KP' can confirm (status OBSERVED) once an action made them true
PERCEIVED_PREDICATES = frozenset(
    {"robot_at", "person_at", "object_at", "object_on", "light_on", "light_off", "device_level"}
)
#: simulated seconds each action may run before the dispatcher times it out
ACTION_TIME_LIMITS = {
    "move": 120.0,
    "search_object": 240.0,
    "search_person": 240.0,
    "pick": 90.0,
    "place": 90.0,
    "give": 90.0,
    "meet": 90.0,
    "guide": 150.0,
}


class SurfaceAwarePlanner:
    """The planner, told which furniture can carry items (map knowledge the PDDL domain does not express).

    ``place`` only needs ``(furniture_in ?f ?l)``, so a planner would happily put the glasses "on" the bin.
    Before each call the ``furniture_in`` facts of furniture without a surface are left out of the *planning
    task* (the knowledge base keeps them: the bin is in the kitchen); plans are otherwise the wrapped
    planner's.

    Args:
        planner: the wrapped planner (:class:`planner.engines.TaskPlanner`).
        no_surface: furniture symbols that items cannot be put on.
    """

    def __init__(self, planner: Planner, no_surface: frozenset[str]) -> None:
        self.planner = planner
        self.no_surface = no_surface

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        """Plan for ``task`` without the surfaceless furniture as places."""
        facts = frozenset(a for a in task.facts if not (a[0] == "furniture_in" and a[1] in self.no_surface))
        return self.planner.solve(replace(task, facts=facts), timeout=timeout)


class SimulationComponent(Component):
    """Advances the simulator to the scheduler's time; registered first, so perception reads the present.

    Args:
        sim: the simulation.
        frequency: Hz of simulated time (the simulator integrates in its own control periods in between).
    """

    name = "sim"

    def __init__(self, sim: Simulation, frequency: float = 20.0) -> None:
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
class RunConfig:
    """What one run is made of.

    Attributes:
        world: world name (``erl_home``, ``erl_home_paper``) or world file.
        scenario: scenario name, file or :class:`~worlds.scenario.Scenario`, or None.
        seed: seed of the simulator's random draws.
        role: robot role name (``knic/roles.yaml``).
        max_sim_time: simulated seconds after which the run stops unfinished.
        settle_s: simulated seconds to wait, once the goals hold, for perception to confirm them.
        journal: SQLite journal file of the knowledge base's history (replaced if it exists), or None.
        trace_stream: text stream receiving the trace as JSON lines, or None.
        gui: open the pybullet GUI.
        check_period_s: simulated seconds between checks of the stop condition.
        goal_retries: times a goal the dispatcher dropped is handed back to it (perception may have learnt
            something since), each ``retry_after_s`` simulated seconds after the drop.
        retry_after_s: see ``goal_retries``.
        real_time_factor: the scheduler's overrun budget is period / factor (wall seconds per step).
    """

    world: str | Path = "erl_home"
    scenario: str | Path | Scenario | None = None
    seed: int = 0
    role: str = "companion"
    max_sim_time: float = 600.0
    settle_s: float = 8.0
    journal: Path | None = None
    trace_stream: TextIO | None = None
    gui: bool = False
    check_period_s: float = 0.5
    goal_retries: int = 20
    real_time_factor: float = 1.0
    retry_after_s: float = 10.0


@dataclass
class RunResult:
    """How a run ended.

    Attributes:
        success: every goal held in the knowledge base and in the ground truth.
        reason: one line: why it ended.
        sim_time: simulated seconds at the end.
        wall_s: wall-clock seconds the run took.
        goals: the goals, as PDDL strings.
        unconfirmed: perceivable goal facts perception had not confirmed (status not OBSERVED) at the end.
        plans, replans: counts from the dispatcher.
        counters: the simulator's penalty counters (bumps, person_hits, drops).
    """

    success: bool
    reason: str
    sim_time: float
    wall_s: float
    goals: list[str] = field(default_factory=list)
    unconfirmed: list[str] = field(default_factory=list)
    plans: int = 0
    replans: int = 0
    counters: dict[str, int] = field(default_factory=dict)


class KnicSystem:
    """The assembled closed loop (see the module docstring).

    Lifecycle: construct (builds everything, nothing runs), :meth:`add_goal` one or more goals, :meth:`run`,
    :meth:`close` (closes the journal and the simulator). Usable as a context manager.

    Raises:
        core.errors.WorldError: unknown world or scenario.
        core.errors.InferenceError: unknown role.
        core.errors.JournalError: the journal file cannot be written.
    """

    def __init__(self, config: RunConfig | None = None) -> None:
        from worlds.api import load_world
        from worlds.simulation import Simulation

        self.config = cfg = config or RunConfig()
        silence_up()
        self.world = load_world(cfg.world)
        self.sim = Simulation(self.world, seed=cfg.seed, scenario=cfg.scenario, gui=cfg.gui)
        try:
            self.kb = self._open_kb(cfg.journal)
            seed_kb_from_world(self.kb, self.world)
            self.pipeline: Pipeline = build_pipeline(self.kb, self.sim, self.world, cfg.role)
            self.perceived = PerceivedEntities(self.kb, self.pipeline.bus)
            self.context = ErlContext(self.sim, self.kb, self.perceived, robot_name=self.world.robot.name)
            self.registry = build_erl_registry(
                self.sim, self.kb, bus=self.pipeline.bus, robot=self.world.robot.name, context=self.context
            )
            self.trace = Trace(cfg.trace_stream)
            self.dispatcher = Dispatcher(
                self.kb,
                SurfaceAwarePlanner(
                    TaskPlanner(self.kb.domain.up_domain),
                    frozenset(f.name for f in self.world.furniture.values() if not f.surface),
                ),
                self.registry,
                policy=RecoveryPolicy(max_replans_per_goal=12),
                trace=self.trace,
                time_limits=ACTION_TIME_LIMITS,
            )
            self._retries: dict[str, int] = {}
            self._dropped_at: dict[str, float] = {}
            self.scheduler = Scheduler(real_time_factor=cfg.real_time_factor)
            self.scheduler.add(SimulationComponent(self.sim))
            for component in self.pipeline:
                self.scheduler.add(component)
            self.scheduler.add(DispatcherComponent(self.dispatcher))
        except BaseException:
            self.sim.close()
            raise

    def _open_kb(self, journal: Path | None) -> KnowledgeBase:
        if journal is not None:
            for suffix in ("", "-wal", "-shm"):
                Path(str(journal) + suffix).unlink(missing_ok=True)
        kb = KnowledgeBase.from_pddl(DOMAIN, journal=journal)
        kb.set_clock(lambda: self.sim.time)
        return kb

    # ------------------------------------------------------------------ goals

    def add_goal(self, goal: Fact | str, *, source: str = "user") -> Fact:
        """Add a PDDL goal (``Fact`` or ``"(object_at glasses bedroom)"``) to the knowledge base.

        Raises:
            KnowledgeBaseError: malformed goal, unknown predicate or symbol, wrong type (nothing added).
        """
        fact = goal if isinstance(goal, Fact) else parse_goal(goal)
        self.kb.add_goal(fact.predicate, *fact.args, source=source)
        return fact

    # ------------------------------------------------------------------ running

    def run(
        self, max_sim_time: float | None = None, *, on_check: Callable[[KnicSystem], None] | None = None
    ) -> RunResult:
        """Run the loop until the goals hold (and settled), all are dropped, or ``max_sim_time``.

        Args:
            max_sim_time: simulated seconds (default from the config).
            on_check: called at every stop-condition check (tests and benchmarks sample the state there).

        Raises:
            KnicError: no goal was given.
        """
        limit = self.config.max_sim_time if max_sim_time is None else max_sim_time
        if not self.kb.goals():
            raise KnicError("knic run: no goal given (use --goal or --speech)")
        wall0 = time.perf_counter()
        next_check = 0.0
        settle_from: float | None = None
        reason = f"goals not reached within {limit:g} s of simulated time"
        success = False
        while True:
            due = self.scheduler.next_due()
            if due is None or due > limit + 1e-9:
                break
            self.scheduler.tick(due)
            if due + 1e-9 < next_check:
                continue
            next_check = due + self.config.check_period_s
            if on_check is not None:
                on_check(self)
            verdict = self.verdict()
            if verdict is None:
                settle_from = None
            elif verdict:
                reason = verdict
                break
            else:
                settle_from = due if settle_from is None else settle_from
                if not self.unconfirmed() or due - settle_from >= self.config.settle_s:
                    success = True
                    reason = "every goal holds in the knowledge base and in the ground truth"
                    break
        if not success:
            self.dispatcher.cancel("run ended")
        counters = self.sim.counters()
        return RunResult(
            success,
            reason,
            self.sim.time,
            time.perf_counter() - wall0,
            [str(g) for g in self.kb.goals()],
            [str(f) for f in self.unconfirmed()],
            self.dispatcher.plans,
            self.dispatcher.replans,
            {"bumps": counters.bumps, "person_hits": counters.person_hits, "drops": counters.drops},
        )

    def verdict(self) -> str | None:
        """``""`` when every goal holds in the knowledge base and the ground truth; a failure reason when the
        dispatcher gave up on the goals that do not hold; None while the run should go on."""
        goals = self.kb.goals()
        missing = [g for g in goals if not self.kb.holds(g)]
        if not missing and all(self.holds_in_truth(g) for g in goals):
            return ""
        self._retry_dropped()
        report = self.dispatcher.report()
        dropped = {g: why for g, why in report.dropped.items() if g in {str(m) for m in missing}}
        exhausted = [g for g in dropped if self._retries.get(g, 0) >= self.config.goal_retries]
        if missing and self.dispatcher.state == DispatcherState.IDLE and len(exhausted) == len(missing):
            goal = sorted(exhausted)[0]
            return f"goal {goal} dropped: {dropped[goal]}"
        return None

    def _retry_dropped(self) -> None:
        """Hand goals the dispatcher dropped back to it, ``retry_after_s`` after the drop, at most
        ``goal_retries`` times each (a REPLAN trace event says so)."""
        now = self.sim.time
        for atom, why in list(self.dispatcher.dropped.items()):
            goal = "(" + " ".join(atom) + ")"
            since = self._dropped_at.setdefault(goal, now)
            count = self._retries.get(goal, 0)
            if count >= self.config.goal_retries or now - since < self.config.retry_after_s:
                continue
            self._retries[goal] = count + 1
            del self._dropped_at[goal]
            self.dispatcher.retry(atom)
            reason = f"retrying goal {goal} ({count + 1}/{self.config.goal_retries}) dropped for: {why}"
            self.trace.emit(TraceEvent(EventKind.REPLAN, now, reason=reason, goal=goal))

    def holds_in_truth(self, goal: Fact) -> bool:
        """Whether the simulator's ground truth agrees with ``goal`` (goals it cannot judge count as true).

        ``reported`` is judged from what the robot said: a report ("I found the ...") naming the entity and
        the room where it truly is, or the gripper when the robot holds it.
        """
        truth = self.sim.ground_truth_facts()
        if goal.predicate in TRUTH_PREDICATES:
            return (goal.predicate, *goal.args) in truth
        if goal.predicate == "reported":
            entity = goal.args[0]
            places = [
                f"in the {spoken(f[2])}"
                for f in truth
                if f[0] in ("object_at", "person_at") and f[1] == entity
            ]
            if any(f[0] == "holding" and f[2] == entity for f in truth):
                places.append("in my gripper")
            claim = f"i found the {spoken(entity)}"
            return any(
                u.text.lower().startswith(claim) and any(p in u.text.lower() for p in places)
                for u in self.sim.spoken()
            )
        return True

    def unconfirmed(self) -> list[Fact]:
        """Goal facts of perceivable predicates that hold but not (yet) as OBSERVED."""
        out = []
        for goal in self.kb.goals():
            if goal.predicate not in PERCEIVED_PREDICATES:
                continue
            prov = self.kb.why(goal)
            if prov is None or prov.status != BeliefStatus.OBSERVED:
                out.append(goal)
        return out

    # ------------------------------------------------------------------ teardown

    def close(self) -> None:
        """Stop listening, close the journal and the simulator (idempotent)."""
        self.dispatcher.close()
        self.perceived.close()
        self.kb.close()
        self.sim.close()

    def __enter__(self) -> KnicSystem:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def parse_goal(text: str) -> Fact:
    """A PDDL atom ``"(object_at glasses bedroom)"`` as a :class:`Fact`.

    Raises:
        KnowledgeBaseError: the text is not a PDDL atom.
    """
    try:
        return Fact.parse(text)
    except (ValueError, KnicError) as exc:
        raise KnowledgeBaseError(
            f"goal {text!r} is not a PDDL atom like (object_at glasses bedroom): {exc}"
        ) from None


def build_system(goals: Sequence[str] = (), **config: object) -> KnicSystem:
    """A :class:`KnicSystem` from keyword configuration (``RunConfig`` fields) with the given PDDL goals."""
    system = KnicSystem(RunConfig(**config))  # type: ignore[arg-type]
    try:
        for goal in goals:
            system.add_goal(goal)
    except BaseException:
        system.close()
        raise
    return system
