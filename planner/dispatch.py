"""The dispatch loop (seed 004, Algorithm 1), steppable from a single-threaded scheduler.

:class:`Dispatcher` keeps the knowledge base's goals true: it plans, runs the plan action by action through
the activation / step / deactivation interface (:mod:`actions.base`), writes effects, and replans when an
action fails or when a knowledge-base change breaks the rest of the plan. See :mod:`planner` for the API.

Each :meth:`Dispatcher.step` does a bounded amount of work, in this order:

0. while IDLE (every goal achieved or dropped), nothing at all unless something that matters changed: the
   goals (added, removed, a dropped goal handed back with :meth:`Dispatcher.retry`) or a fact that is a goal
   (a goal stopped holding); other knowledge-base changes are not even looked at, so an idle dispatcher
   costs nothing per tick and never plans when there is nothing to do;
1. if the knowledge base changed since the last step: replan when the goals changed, or when the rest of the
   plan (with the running action's effects assumed) no longer reaches the goals from the current facts;
   a running action is then cancelled (``deactivation`` with ending "cancelled");
2. when no action is running and every goal holds: go IDLE (no plan is made, even after a failure);
   otherwise plan when there is no plan (the plan is validated against the current facts before it runs;
   goals the planner proves unreachable are dropped and reported by name);
3. either start the next action -- check its at-start conditions, ``activation()`` -- or advance the running
   one -- check the time limit and the over-all conditions, ``step()``; when it finishes: ``deactivation()``,
   at-end conditions, write the effects (belief status "effect", source "dispatcher"), check the sensed
   effects of sensing actions (asserted by perception, never written here).

Time is the dispatcher's clock (default ``kb.now``: simulated seconds in the closed loop).
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from actions.base import Action, ActionRegistry, ActionStatus, Outcome
from core.errors import KnicError
from knowledge_base import BeliefStatus, Change, ChangeKind, KnowledgeBase
from planner.engines import Planner
from planner.model import ActionSchema, Atom, PlanningTask, atom_str, ground
from planner.plan import PlanResult, PlanStatus, PlanStep
from planner.problem import task_from_kb
from planner.recovery import Recovery, RecoveryPolicy
from planner.trace import EventKind, Trace, TraceEvent
from planner.validate import apply, check_plan, unmet_conditions

SOURCE = "dispatcher"
_GOAL_CHANGES = (ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL)
_FACT_CHANGES = (ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT)


class DispatcherState(enum.StrEnum):
    """IDLE: no goal left to work on (all achieved or dropped, or none). EXECUTING: a plan is being run."""

    IDLE = "idle"
    EXECUTING = "executing"
    STOPPED = "stopped"


@dataclass
class DispatchReport:
    """What :meth:`Dispatcher.run` returns: goals achieved and dropped (with reasons), counts, final state."""

    state: DispatcherState
    achieved: list[str] = field(default_factory=list)
    dropped: dict[str, str] = field(default_factory=dict)
    ticks: int = 0
    plans: int = 0
    replans: int = 0


@dataclass
class _Running:
    step: PlanStep
    schema: ActionSchema
    action: Action
    started: float


class Dispatcher:
    """Runs plans for the knowledge base's goals; call :meth:`step` once per tick (see the module docstring).

    Args:
        kb: the knowledge base (goals are read from it, effects written to it).
        planner: anything satisfying :class:`planner.engines.Planner`.
        registry: PDDL action name -> implementation factory.
        policy: recovery per outcome and the replan bound per goal.
        trace: where events go (a new :class:`Trace` when None).
        time_limit: seconds an action may run on the dispatcher's clock; per action name via ``time_limits``.
        time_limits: action name -> time limit, overriding ``time_limit``.
        planning_timeout: wall-clock seconds per planner call.
        clock: time source; ``kb.now`` when None.

    Lifecycle: construct, then call :meth:`step` (or :meth:`run`) repeatedly; :meth:`close` unsubscribes from
    the knowledge base. Errors in action code become execution failures; the dispatcher itself raises only for
    misuse (e.g. a plan step with no registered implementation is an activation failure, not an exception).
    """

    def __init__(
        self,
        kb: KnowledgeBase,
        planner: Planner,
        registry: ActionRegistry,
        *,
        policy: RecoveryPolicy | None = None,
        trace: Trace | None = None,
        time_limit: float = 120.0,
        time_limits: Mapping[str, float] | None = None,
        planning_timeout: float = 30.0,
        clock: Callable[[], float] | None = None,
    ) -> None:
        self.kb = kb
        self.planner = planner
        self.registry = registry
        self.policy = policy or RecoveryPolicy()
        self.trace = trace if trace is not None else Trace()
        self.time_limit = time_limit
        self.time_limits = dict(time_limits or {})
        self.planning_timeout = planning_timeout
        self.clock = clock or kb.now
        self.sensing = {name: frozenset(preds) for name, preds in kb.domain.sensing.items()}
        self.state = DispatcherState.IDLE
        self.plan: tuple[PlanStep, ...] = ()
        self.index = 0
        self.current: _Running | None = None
        self.last_result: PlanResult | None = None
        self.dropped: dict[Atom, str] = {}
        self.achieved: set[Atom] = set()
        self.plans = 0
        self.replans = 0
        self._domain: Any = None
        self._planned_goals: frozenset[Atom] | None = None
        self._need_plan: str | None = None
        self._dirty = True  # look at the knowledge base on the first step
        self._wake = True  # while IDLE: something that matters changed (goals, or a fact that is a goal)
        self._writing = False
        self._step_failures = 0
        self._replans_of: dict[Atom, int] = {}
        self._goals: list[Atom] | None = None  # the knowledge base's goals, refreshed on goal changes
        self._goal_set: frozenset[Atom] = frozenset()  # the same, as a set
        self._unsubscribe = kb.subscribe(self._on_change)

    # -- public ---------------------------------------------------------------------------------------
    def step(self) -> DispatcherState:
        """Do one bounded unit of work (see the module docstring) and return the resulting state."""
        if self.state == DispatcherState.STOPPED:
            return self.state
        if self._asleep():
            return self.state  # nothing that matters changed since every goal was achieved or dropped
        self._wake = False
        goals = self._active_goals()
        if not goals:
            self._dirty = False
            self._finish_idle()
            return self.state
        if self._dirty:
            self._dirty = False
            self._check_after_change(goals)
        if self.current is None:
            facts = self._facts()
            if all(g in facts for g in goals):  # nothing to do, whatever was pending: no (empty) plan
                self._announce_achieved(goals, facts)
                self._finish_idle()
                return self.state
        self.state = DispatcherState.EXECUTING
        if self._need_plan is not None or self._planned_goals is None:
            if self.current is not None:
                self._cancel_current(self._need_plan or "replanning")
            self._make_plan(goals)
            goals = self._active_goals()
            if not goals:
                self._finish_idle()
                return self.state
            if self._need_plan is not None:  # planning failed or the plan was rejected: next tick
                return self.state
        if self.current is None:
            self._start_next(goals)
        else:
            self._advance()
        return self.state

    def tick(self, now: float | None = None) -> DispatcherState:
        """Alias of :meth:`step` for schedulers that pass the time (``now`` is ignored: the clock is used)."""
        return self.step()

    def run(self, max_ticks: int = 10_000, on_tick: Callable[[int], None] | None = None) -> DispatchReport:
        """Step until IDLE or STOPPED or ``max_ticks`` steps; call ``on_tick(i)`` after each step.

        Tests use ``on_tick`` to advance simulated time or to change the knowledge base under a running plan.
        """
        ticks = 0
        while ticks < max_ticks:
            state = self.step()
            ticks += 1
            if on_tick is not None:
                on_tick(ticks)
            if state == DispatcherState.STOPPED or self._asleep():
                break
        return self.report(ticks)

    def report(self, ticks: int = 0) -> DispatchReport:
        """The goals achieved and dropped so far."""
        return DispatchReport(
            self.state,
            sorted(atom_str(g) for g in self.achieved),
            {atom_str(g): why for g, why in self.dropped.items()},
            ticks,
            self.plans,
            self.replans,
        )

    def cancel(self, reason: str = "cancelled by the caller") -> None:
        """Cancel the running action (outcome "cancelled") and stop; later steps do nothing."""
        if self.current is not None:
            self._cancel_current(reason)
        self.state = DispatcherState.STOPPED

    def retry(self, goal: Atom) -> bool:
        """Hand a dropped goal back: forget why it was dropped, so the next step plans for it again.

        Args:
            goal: the goal as an atom, ``("object_at", "glasses", "bedroom")``.

        Returns:
            False (and nothing changes) when the goal was not dropped.
        """
        if self.dropped.pop(goal, None) is None:
            return False
        self._replans_of.pop(goal, None)
        self._wake = self._dirty = True  # the active goals changed: an idle or running dispatcher must look
        return True

    def close(self) -> None:
        """Stop listening to the knowledge base."""
        self._unsubscribe()

    # -- knowledge-base changes ----------------------------------------------------------------------
    def _asleep(self) -> bool:
        """IDLE and nothing that matters happened since: the step has nothing to do."""
        return self.state == DispatcherState.IDLE and not self._wake and self._need_plan is None

    def _on_change(self, change: Change) -> None:
        if change.kind in _GOAL_CHANGES:
            self._goals = None
            self._wake = True
        if self._writing:
            return
        self._dirty = True
        if change.kind in _FACT_CHANGES and (
            self._goals is None or (change.name, *change.args) in self._goal_set
        ):
            self._wake = True  # a goal started or stopped holding

    def _check_after_change(self, goals: list[Atom]) -> None:
        if self._planned_goals is None or self._need_plan is not None:
            return
        if frozenset(goals) != self._planned_goals:
            self._need_plan = "goals changed"
            return
        facts = set(self._facts())
        rest = self.plan[self.index :]
        if self.current is not None:
            apply(self.current.schema, self.current.step.args, facts)
            rest = self.plan[self.index + 1 :]
        check = check_plan(self._strips(), facts, rest, goals)
        if not check.valid:
            self._need_plan = f"knowledge change breaks the plan: {check.reason}"

    # -- planning ------------------------------------------------------------------------------------
    def _make_plan(self, goals: list[Atom]) -> None:
        reason = self._need_plan
        self._need_plan = None
        now = self.clock()
        if reason is not None and self._planned_goals is not None:
            self.replans += 1
            self.trace.emit(TraceEvent(EventKind.REPLAN, now, reason=reason))
            self._count_replan(goals, now)
            goals = self._active_goals()
            if not goals:
                return
        task = task_from_kb(self.kb, goals)
        self.achieved.difference_update(g for g in goals if g not in task.facts)  # to be achieved again
        result = self.planner.solve(task, timeout=self.planning_timeout)
        self.last_result = result
        self.plans += 1
        self._planned_goals = frozenset(goals)
        self.plan, self.index, self._step_failures = (), 0, 0
        if result.status in (PlanStatus.TIMEOUT, PlanStatus.ERROR):
            self._need_plan = f"planning {result.status.value}: {result.message}"
            return
        for goal in result.unreachable_goals:
            self._drop(goal, "unreachable: no plan reaches it from what the robot knows", now)
        self._planned_goals = frozenset(self._active_goals())
        if not result.has_plan:
            return
        check = check_plan(task.domain, task.facts, result.plan, result.reachable_goals, task.objects)
        if not check.valid:
            self._need_plan = f"plan rejected by validation: {check.reason}"
            return
        self.plan = result.plan
        self.trace.emit(
            TraceEvent(
                EventKind.PLAN,
                now,
                plan=tuple(str(s) for s in self.plan),
                data={
                    "planning_ms": round(result.planning_ms, 3),
                    "engine": result.engine,
                    "goals": [atom_str(g) for g in goals],
                },
            )
        )

    def _count_replan(self, goals: list[Atom], now: float) -> None:
        facts = self._facts()
        for goal in goals:
            if goal in facts:
                continue
            count = self._replans_of.get(goal, 0) + 1
            self._replans_of[goal] = count
            if count > self.policy.max_replans_per_goal:
                self._drop(goal, f"gave up after {count - 1} replans", now)

    # -- execution -----------------------------------------------------------------------------------
    def _start_next(self, goals: list[Atom]) -> None:
        if self.index >= len(self.plan):
            facts = self._facts()
            unmet = [g for g in goals if g not in facts]
            if unmet:
                self._need_plan = "plan finished but goals do not hold: " + " ".join(
                    atom_str(g) for g in unmet
                )
            return
        step = self.plan[self.index]
        now = self.clock()
        schema = self._strips().schemas[step.name]
        self.trace.emit(TraceEvent(EventKind.DISPATCH, now, action=str(step)))
        missing = unmet_conditions(schema, step.args, self._facts(), "start")
        if missing:
            self._failed(step, Outcome.PRECONDITION_FAILURE, f"at-start condition {missing[0]} does not hold")
            return
        try:
            action = self.registry.create(step.name, step.args)
            ok = action.activation()
            why = action.failure_reason
        except Exception as exc:  # action code must not stop the loop
            ok, why = False, _describe(exc)
        if not ok:
            self._failed(step, Outcome.ACTIVATION_FAILURE, why or "activation() returned False")
            return
        self.trace.emit(TraceEvent(EventKind.ACTIVATION, now, action=str(step)))
        self.current = _Running(step, schema, action, now)
        if schema.start_add or schema.start_delete:
            self._write(schema.start_add, schema.start_delete, step, frozenset())

    def _advance(self) -> None:
        run = self.current
        assert run is not None
        now = self.clock()
        limit = self.time_limits.get(run.step.name, self.time_limit)
        if now - run.started > limit:
            self._end(run, "timeout")
            self._failed(run.step, Outcome.TIMEOUT, f"still running after {limit:g} s")
            return
        if run.schema.durative:
            missing = unmet_conditions(run.schema, run.step.args, self._facts(), "overall")
            if missing:
                self._end(run, "failed")
                self._failed(run.step, Outcome.EXECUTION_FAILURE, f"over-all condition {missing[0]} broken")
                return
        try:
            status = run.action.step()
        except Exception as exc:
            run.action.failure_reason = _describe(exc)
            status = ActionStatus.FAILED
        if status == ActionStatus.RUNNING:
            return
        if status == ActionStatus.FAILED:
            self._end(run, "failed")
            self._failed(run.step, Outcome.EXECUTION_FAILURE, run.action.failure_reason or "step() failed")
            return
        if not self._end(run, "succeeded"):
            self._failed(
                run.step, Outcome.DEACTIVATION_FAILURE, run.action.failure_reason or "deactivation failed"
            )
            return
        self._finish_success(run, now)

    def _finish_success(self, run: _Running, now: float) -> None:
        step, schema = run.step, run.schema
        if schema.durative:
            missing = unmet_conditions(schema, step.args, self._facts(), "end")
            if missing:
                self._failed(step, Outcome.EXECUTION_FAILURE, f"at-end condition {missing[0]} does not hold")
                return
        sensed = self.sensing.get(step.name, frozenset())
        try:
            self._write(schema.add, schema.delete, step, sensed)
        except KnicError as exc:  # the knowledge base refused an effect: nothing was written
            self._failed(step, Outcome.EXECUTION_FAILURE, f"effects not written: {exc}")
            return
        facts = self._facts()
        unconfirmed = [a for a in ground(schema.add, step.args) if a[0] in sensed and a not in facts]
        if unconfirmed:
            self._failed(
                step,
                Outcome.POSTCONDITION_FAILURE,
                f"sensed effect {atom_str(unconfirmed[0])} not confirmed by perception",
            )
            return
        self.trace.emit(TraceEvent(EventKind.SUCCESS, now, action=str(step), outcome=Outcome.SUCCEEDED.value))
        self.index += 1
        self._step_failures = 0
        self._announce_achieved(self._active_goals(), facts)

    def _write(
        self, add: tuple[Any, ...], delete: tuple[Any, ...], step: PlanStep, sensed: frozenset[str]
    ) -> None:
        self._writing = True
        try:
            with self.kb.batch():
                for atom in ground(delete, step.args):
                    if atom[0] not in sensed:
                        self.kb.remove_fact(atom[0], *atom[1:], source=SOURCE, status=BeliefStatus.EFFECT)
                for atom in ground(add, step.args):
                    if atom[0] not in sensed:
                        self.kb.add_fact(atom[0], *atom[1:], source=SOURCE, status=BeliefStatus.EFFECT)
        finally:
            self._writing = False

    def _end(self, run: _Running, ending: str) -> bool:
        self.current = None
        run.action.ending = ending
        try:
            return bool(run.action.deactivation())
        except Exception as exc:
            run.action.failure_reason = _describe(exc)
            return False

    def _cancel_current(self, reason: str) -> None:
        run = self.current
        assert run is not None
        self._end(run, "cancelled")
        self.trace.emit(
            TraceEvent(
                EventKind.FAILURE,
                self.clock(),
                action=str(run.step),
                outcome=Outcome.CANCELLED.value,
                reason=reason,
            )
        )

    def _failed(self, step: PlanStep, outcome: Outcome, reason: str) -> None:
        now = self.clock()
        self.current = None
        self.trace.emit(
            TraceEvent(EventKind.FAILURE, now, action=str(step), outcome=outcome.value, reason=reason)
        )
        self._step_failures += 1
        decision = self.policy.decide(outcome, self._step_failures)
        if decision == Recovery.RETRY:
            return
        if decision == Recovery.DROP_GOAL:
            facts = set(self._facts())
            for goal in self._goals_served(facts):
                self._drop(goal, f"{outcome.value} of {step} ({reason})", now)
        self._need_plan = f"{outcome.value} of {step}"

    def _goals_served(self, facts: set[Atom]) -> list[Atom]:
        """Goals false now that the rest of the plan reaches only with its current step.

        The rest of the plan is simulated twice from ``facts``, with and without the current step, skipping
        steps whose at-start conditions fail; the goals reached only in the first run are the step's.
        """
        rest = self.plan[self.index :]

        def reached(steps: tuple[PlanStep, ...]) -> set[Atom]:
            state = set(facts)
            for step in steps:
                schema = self._strips().schemas[step.name]
                if not unmet_conditions(schema, step.args, state, "start"):
                    apply(schema, step.args, state)
            return state

        with_step, without = reached(rest), reached(rest[1:])
        return [g for g in self._active_goals() if g not in facts and g in with_step and g not in without]

    # -- goals ---------------------------------------------------------------------------------------
    def _active_goals(self) -> list[Atom]:
        if self._goals is None:
            self._goals = [(g.predicate, *g.args) for g in self.kb.goals()]
            self._goal_set = frozenset(self._goals)
        goals = self._goals
        if not self.dropped:
            return goals
        present = set(goals)
        for gone in [g for g in self.dropped if g not in present]:
            del self.dropped[gone]  # a goal removed and added again is a new goal
        return [g for g in goals if g not in self.dropped]

    def _drop(self, goal: Atom, reason: str, now: float) -> None:
        if goal in self.dropped:
            return
        self.dropped[goal] = reason
        self.trace.emit(TraceEvent(EventKind.GOAL_DROPPED, now, goal=atom_str(goal), reason=reason))

    def _announce_achieved(self, goals: list[Atom], facts: frozenset[Atom] | set[Atom]) -> None:
        now = self.clock()
        for goal in goals:
            if goal in facts and goal not in self.achieved:
                self.achieved.add(goal)
                self.trace.emit(TraceEvent(EventKind.GOAL_ACHIEVED, now, goal=atom_str(goal)))
            elif goal not in facts:
                self.achieved.discard(goal)

    def _finish_idle(self) -> None:
        self._replans_of.clear()
        self._need_plan = None  # whatever was pending is moot: no goal left to plan for
        if self.current is None:
            self.state = DispatcherState.IDLE
            self.plan, self.index, self._planned_goals = (), 0, None
        else:
            self._cancel_current("no goal left")
            self.state = DispatcherState.IDLE

    # -- helpers -------------------------------------------------------------------------------------
    def _facts(self) -> frozenset[Atom]:
        return frozenset((f.predicate, *f.args) for f in self.kb.facts())

    def _strips(self) -> Any:
        if self._domain is None:
            from planner.problem import strips_domain

            self._domain = strips_domain(self.kb.domain.up_domain)
        return self._domain


def _describe(exc: BaseException) -> str:
    text = str(exc).splitlines()[0] if str(exc) else ""
    return f"{type(exc).__name__}: {text}" if not isinstance(exc, KnicError) else text


__all__ = ["DispatchReport", "Dispatcher", "DispatcherState", "PlanningTask"]
