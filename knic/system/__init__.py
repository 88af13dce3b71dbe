"""One run of the whole closed loop: simulated apartment, KnIC pipeline, knowledge base, planner, actions.

The run is three things kept apart:

* :mod:`knic.system.assembly` builds the parts from a :class:`RunConfig` (the robot behind the seam, the
  knowledge base, the pipeline, the actions, the dispatcher, the scheduler);
* :mod:`knic.system.loop` runs the scheduler in simulated time until a stop condition fires, with hooks and
  probes for tests and benchmarks;
* :mod:`knic.system.verdict` judges: the robot's own "done" from its beliefs (the run stops on it) and the
  referee's judgement from ground truth (reported, never acted on).

:class:`KnicSystem` ties them for the common case (``knic run``, tests). Everything runs on one thread in
simulated time, as fast as the machine allows, deterministic under the seed.
"""

from __future__ import annotations

import time
from abc import abstractmethod
from collections.abc import Callable, Sequence

from actions.erl.devices import spoken
from core.errors import KnicError, KnowledgeBaseError
from knic.scheduler import Component
from knic.system.assembly import Assembly, assemble
from knic.system.config import RunConfig, RunResult
from knic.system.loop import RunLoop
from knic.system.verdict import BeliefVerdict, Referee, Stop
from knowledge_base import Fact, KnowledgeBase
from planner.dispatch import DispatcherState
from planner.trace import EventKind, TraceEvent


class TaskFlow(Component):
    """A scheduled task flow (the Granny Annie dialogue): stepped like any component; busy while it runs."""

    @abstractmethod
    def busy(self) -> bool:
        """Whether the flow still has something to do (the run does not stop meanwhile)."""

    def holds_robot(self) -> bool:
        """Whether the flow needs the robot to stay where it is (a dialogue): no revisit starts meanwhile
        (:mod:`knic.system.revisits`). Default: never."""
        return False


def drop_sentence(kb: KnowledgeBase, goal: Fact, reason: str) -> str:
    """What the robot says when it drops ``goal``: that it looked everywhere for an entity it has no
    candidate place left for, else the goal and the reason."""
    for entity in goal.args:
        kind = kb.type_of(entity)
        if kind not in ("item", "person") or not reason.startswith("unreachable"):
            continue
        located = kb.facts("object_at" if kind == "item" else "person_at", entity)
        if not located and not kb.facts("possibly_at", entity) and not kb.facts("holding", None, entity):
            return f"I looked everywhere and could not find the {spoken(entity)}, so I give up on {goal}."
    return f"I cannot achieve {goal}: {reason}."


__all__ = ["KnicSystem", "RunConfig", "RunResult", "build_system", "parse_goal"]


class KnicSystem:
    """The assembled closed loop with the robot's stop condition and a referee (see the module docstring).

    Lifecycle: construct (builds everything, nothing runs), :meth:`add_goal` one or more goals, :meth:`run`,
    :meth:`close` (closes the journal and the simulator). Usable as a context manager. The parts are
    attributes (``sim``, ``kb``, ``pipeline``, ``perceived``, ``context``, ``registry``, ``trace``,
    ``dispatcher``, ``scheduler``, ``world``).

    Raises:
        core.errors.WorldError: unknown world or scenario.
        core.errors.InferenceError: unknown role.
        core.errors.JournalError: the journal file cannot be written.
    """

    def __init__(self, config: RunConfig | None = None) -> None:
        self.config = cfg = config or RunConfig()
        self.parts: Assembly = assemble(cfg)
        parts = self.parts
        self.world, self.sim, self.kb = parts.world, parts.sim, parts.kb
        self.pipeline, self.perceived, self.context = parts.pipeline, parts.perception, parts.context
        self.registry, self.trace, self.scheduler = parts.registry, parts.trace, parts.scheduler
        if parts.dispatcher is None:
            raise KnicError("KnicSystem needs the dispatcher (RunConfig.dispatch=True)")
        self.dispatcher = parts.dispatcher
        #: task flows (e.g. the Granny Annie dialogue) that keep the run going while busy
        self.flows: list[TaskFlow] = []
        self.beliefs = BeliefVerdict(
            self.kb,
            self._dropped,
            self._idle,
            settle_s=cfg.settle_s,
            give_up_s=cfg.give_up_s,
            busy=[lambda: any(f.busy() for f in self.flows)],
        )
        self.referee = Referee(self.sim, lambda: [u.text for u in self.sim.spoken()], spoken)
        self._told: set[str] = set()
        self._observed = False
        self.trace.subscribe(self._tell_dropped)

    # ------------------------------------------------------------------ goals

    def add_goal(self, goal: Fact | str, *, source: str = "user") -> Fact:
        """Add a PDDL goal (``Fact`` or ``"(object_at glasses bedroom)"``) to the knowledge base.

        Raises:
            KnowledgeBaseError: malformed goal, unknown predicate or symbol, wrong type (nothing added).
        """
        fact = goal if isinstance(goal, Fact) else parse_goal(goal)
        self.kb.add_goal(fact.predicate, *fact.args, source=source)
        return fact

    def add_flow(self, flow: TaskFlow) -> None:
        """Schedule a task flow (a scheduler component with ``busy()``) after the dispatcher; the run does
        not stop while it is busy, and it may add goals while the robot runs."""
        self.flows.append(flow)
        self.scheduler.add(flow)
        if self.parts.revisits is not None:
            self.parts.revisits.holds.append(flow.holds_robot)

    # ------------------------------------------------------------------ running

    def run(
        self, max_sim_time: float | None = None, *, on_check: Callable[[KnicSystem], None] | None = None
    ) -> RunResult:
        """Run until the robot believes every goal achieved (and settled) or dropped, or ``max_sim_time``;
        then the referee judges the goals from ground truth.

        Args:
            max_sim_time: simulated seconds (default from the config).
            on_check: called at every stop-condition check (tests and benchmarks sample the state there).

        Raises:
            KnicError: no goal was given.
        """
        limit = self.config.max_sim_time if max_sim_time is None else max_sim_time
        if not self.kb.goals() and not self.flows:
            raise KnicError("knic run: no goal given (use --goal or --speech)")
        loop: RunLoop[Stop] = RunLoop(self.scheduler, self.config.check_period_s)
        if not self._observed:
            loop.add_probe("referee", 10.0, self.referee.observe)
            self._observed = True
        if on_check is not None:
            loop.add_hook(lambda now: on_check(self))
        loop.add_stop(self.beliefs)
        wall0 = time.perf_counter()
        end = loop.run(limit)
        stop = end.stop
        goals = self.kb.goals()
        unmet = self.referee.unmet(goals)
        if stop is None:
            self.dispatcher.cancel("run ended")
            reason = f"goals not reached within {limit:g} s of simulated time"
        elif not stop.done:
            self.dispatcher.cancel("run ended")
            reason = stop.reason
        elif unmet:
            reason = f"{stop.reason}, but the referee finds {unmet[0]} not holding"
        else:
            reason = "every goal holds in the knowledge base and in the ground truth"
        counters = self.sim.counters()
        return RunResult(
            success=stop is not None and stop.done and not unmet,
            reason=reason,
            sim_time=self.sim.time,
            wall_s=time.perf_counter() - wall0,
            goals=[str(g) for g in goals],
            believed_done=stop is not None and stop.done,
            unmet_in_truth=[str(g) for g in unmet],
            unconfirmed=[str(f) for f in self.beliefs.unconfirmed()],
            plans=self.dispatcher.plans,
            replans=self.dispatcher.replans,
            counters={"bumps": counters.bumps, "person_hits": counters.person_hits, "drops": counters.drops},
        )

    def _idle(self) -> bool:
        return self.dispatcher.state == DispatcherState.IDLE

    def _dropped(self) -> dict[str, str]:
        return self.dispatcher.report().dropped

    def _tell_dropped(self, event: TraceEvent) -> None:
        """Say once per goal why it was dropped (the robot tells the people it works for)."""
        if event.kind != EventKind.GOAL_DROPPED or not event.goal or event.goal in self._told:
            return
        self._told.add(event.goal)
        self.context.say(drop_sentence(self.kb, parse_goal(event.goal), event.reason or ""))

    # ------------------------------------------------------------------ teardown

    def close(self) -> None:
        """Stop listening, close the journal and the simulator (idempotent)."""
        self.parts.close()

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
