"""The dispatch loop (seed 004, Algorithm 1), steppable from a single-threaded scheduler.

:class:`Dispatcher` keeps the knowledge base's goals true: it plans, runs the plan action by action through
the activation / step / deactivation interface (:mod:`actions.base`), writes effects, and replans when an
action fails or when a knowledge-base change breaks the rest of the plan. See :mod:`planner` for the API.

It is a small state machine over three parts:

* :class:`~planner.executor.ActionExecutor` runs one action with its PDDL checks and time limit;
* :class:`~planner.monitor.PlanMonitor` holds the plan and checks it against the knowledge base;
* :class:`~planner.goals.GoalBook` keeps the active, achieved and dropped goals (and the goal retries of the
  recovery policy).

Its :attr:`Dispatcher.state` is a :class:`DispatcherState`; what it has to look at next is one
:class:`Pending` value (knowledge changed < goals changed < replan, with the replan's reason), raised by
knowledge-base changes and failures and consumed by :meth:`Dispatcher.step`. Each step does a bounded amount
of work, in this order:

0. dropped goals the recovery policy hands back come back, only while no action runs (a retry never cancels
   an action in progress for another goal); while IDLE (every goal achieved or dropped) nothing else happens
   unless the goals changed or a fact that is a goal changed (pending GOALS or more): an idle dispatcher
   costs nothing per tick and never plans when there is nothing to do;
1. pending KNOWLEDGE or GOALS: the plan monitor checks the plan; a broken plan makes the pending REPLAN;
2. when no action is running and every goal holds: go IDLE (no plan is made, even after a failure);
   otherwise plan when a REPLAN is pending or there is no plan (a running action is then cancelled first,
   ``deactivation`` with ending "cancelled"); the plan is validated against the current facts before it
   runs; goals the planner proves unreachable are dropped and reported by name;
3. the executor starts the next action or advances the running one; a failure goes to the recovery policy
   (retry the step, replan, or drop the goals the step served).

Time is the dispatcher's clock (default ``kb.now``: simulated seconds in the closed loop). Thinking takes
time on that clock (``planning_time``, :func:`thinking_seconds`): the plan's first action starts only once
the planner call's time has passed, so a slow planner costs the robot task time. ``"model"`` charges a
deterministic estimate (0.1 s plus the grounded task's size; a fallback to an external engine or a timeout
costs what those take), so runs stay reproducible under a seed; ``"wall"`` charges the wall time spent.
After a knowledge change breaks the plan, planning waits ``replan_settle_s`` (the running action goes on
meanwhile), so the KP' stepped at a lower rate can finish revising what the change implies (e.g. new search
candidates for a person just lost) before the planner judges the goals.

A step that fails the same way again changes the recovery (:class:`~planner.recovery.RepeatedFailure`):
the perceived beliefs it rests on are retracted (or the robot backs off), then the goals it served are
dropped. Only failures charge a goal's replan budget; replans forced by new knowledge do not.
"""

from __future__ import annotations

import enum
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from actions.base import ActionRegistry, Outcome
from knowledge_base import BeliefStatus, Change, KnowledgeBase
from planner.engines import Planner
from planner.executor import SOURCE, ActionExecutor, Running, StepEnd
from planner.goals import GoalBook
from planner.model import Atom, PlanningTask, atom_str, ground
from planner.monitor import PlanMonitor
from planner.plan import PlanResult, PlanStatus, PlanStep
from planner.problem import task_from_kb
from planner.recovery import Recovery, RecoveryPolicy
from planner.thinking import PLANNING_TIME, thinking_seconds
from planner.trace import EventKind, Trace, TraceEvent
from planner.validate import check_plan, unmet_conditions


class DispatcherState(enum.StrEnum):
    """IDLE: no goal left to work on (all achieved or dropped, or none). EXECUTING: goals are open (a plan is
    being made or run). STOPPED: cancelled by the caller; steps do nothing."""

    IDLE = "idle"
    EXECUTING = "executing"
    STOPPED = "stopped"


class Pending(enum.IntEnum):
    """What the next step must look at, by increasing urgency (a higher one includes the lower ones)."""

    NOTHING = 0
    KNOWLEDGE = 1  # a fact or instance changed: is the plan still good?
    GOALS = 2  # the goals, or a fact that is a goal, changed: wakes an idle dispatcher
    REPLAN = 3  # plan again (the reason is kept beside)


@dataclass
class DispatchReport:
    """What :meth:`Dispatcher.run` returns: goals achieved and dropped (with reasons), counts, final state."""

    state: DispatcherState
    achieved: list[str] = field(default_factory=list)
    dropped: dict[str, str] = field(default_factory=dict)
    ticks: int = 0
    plans: int = 0
    replans: int = 0


class Dispatcher:
    """Runs plans for the knowledge base's goals; call :meth:`step` once per tick (see the module docstring).

    Args:
        kb: the knowledge base (goals are read from it, effects written to it).
        planner: anything satisfying :class:`planner.engines.Planner`.
        registry: PDDL action name -> implementation factory.
        policy: recovery per outcome, the replan bound per goal and the goal retry rule.
        trace: where events go (a new :class:`Trace` when None).
        time_limit: seconds an action may run on the dispatcher's clock; per action name via ``time_limits``.
        time_limits: action name -> time limit, overriding ``time_limit``.
        planning_timeout: wall-clock seconds per planner call.
        clock: time source; ``kb.now`` when None.
        planning_time: how planning time is charged on the clock: ``"off"``, ``"model"`` or ``"wall"``
            (:func:`thinking_seconds`).
        replan_settle_s: clock seconds planning waits after a knowledge change broke the plan.

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
        planning_time: str = "off",
        replan_settle_s: float = 0.0,
    ) -> None:
        self.kb = kb
        self.planner = planner
        self.policy = policy or RecoveryPolicy()
        self.trace = trace if trace is not None else Trace()
        self.planning_timeout = planning_timeout
        self.clock = clock or kb.now
        sensing = {name: frozenset(preds) for name, preds in kb.domain.sensing.items()}
        self.executor = ActionExecutor(
            kb,
            registry,
            self.trace,
            self.clock,
            time_limit=time_limit,
            time_limits=time_limits,
            sensing=sensing,
        )
        self.monitor = PlanMonitor(kb.domain.up_domain)
        self.book = GoalBook(kb, self.trace, self.clock, self.policy.goal_retry)
        self.state = DispatcherState.IDLE
        self.pending = Pending.GOALS  # look at the knowledge base and its goals on the first step
        self.pending_reason = ""  # why, when pending is REPLAN
        self.last_result: PlanResult | None = None
        self.plans = 0
        self.replans = 0
        self._step_failures = 0
        if planning_time not in PLANNING_TIME:
            raise ValueError(f"planning_time must be one of {'/'.join(PLANNING_TIME)}, got {planning_time!r}")
        self.planning_time = planning_time
        self.replan_settle_s = replan_settle_s
        self.thinking_s = 0.0  # clock seconds charged for planning so far
        self._busy_until = -math.inf  # thinking: nothing runs before
        self._plan_not_before = -math.inf  # settling or backing off: no planning before
        self._charge_replan = False  # the pending replan follows a failure (charged to the goals)
        self._finish_first = False  # let the running action end before the pending replan
        self._failures: dict[tuple[str, str, str], int] = {}
        self._unsubscribe = kb.subscribe(self._on_change)

    # -- views of the parts ----------------------------------------------------------------------------
    @property
    def plan(self) -> tuple[PlanStep, ...]:
        """The plan being run (empty when none)."""
        return self.monitor.plan

    @property
    def index(self) -> int:
        """Position in :attr:`plan` of the running or next step."""
        return self.monitor.index

    @property
    def current(self) -> Running | None:
        """The running action, or None."""
        return self.executor.current

    @property
    def dropped(self) -> dict[Atom, str]:
        """Dropped goals with why."""
        return self.book.dropped

    @property
    def achieved(self) -> set[Atom]:
        """Goals achieved (and announced)."""
        return self.book.achieved

    # -- public ---------------------------------------------------------------------------------------
    def step(self) -> DispatcherState:
        """Do one bounded unit of work (see the module docstring) and return the resulting state."""
        if self.state == DispatcherState.STOPPED:
            return self.state
        if self.executor.current is None and self.book.due_retries():
            self._raise(Pending.GOALS)
        if self._asleep():
            return self.state  # nothing that matters changed since every goal was achieved or dropped
        if self.clock() < self._busy_until:
            return self.state  # still thinking about the plan just made
        pending = self.pending
        if pending < Pending.REPLAN:
            self.pending = Pending.NOTHING
        goals = self.book.active()
        if not goals:
            self._finish_idle()
            return self.state
        if Pending.KNOWLEDGE <= pending < Pending.REPLAN:
            running = self.executor.current
            broken = self.monitor.broken(self.executor.facts(), goals, running.step if running else None)
            if broken is not None:
                if self.pending < Pending.REPLAN:
                    self._plan_not_before = max(self._plan_not_before, self.clock() + self.replan_settle_s)
                    self._finish_first = running is not None and self._still_useful(running.step, goals)
                self._raise(Pending.REPLAN, broken)
        if self.executor.current is None:
            facts = self.executor.facts()
            if all(g in facts for g in goals):  # nothing to do, whatever was pending: no (empty) plan
                self.book.announce(goals, facts)
                self._finish_idle()
                return self.state
        self.state = DispatcherState.EXECUTING
        waiting = self.clock() < self._plan_not_before or self._finish_first
        if self.pending == Pending.REPLAN and waiting and self.executor.current is not None:
            # settling, backing off, or letting a still useful action finish: the running action goes on
            end = self.executor.advance()
            if end is not None:
                self._finish_first = False
                self._ended(end)
            return self.state
        if self.pending == Pending.REPLAN and self.clock() < self._plan_not_before:
            return self.state
        self._finish_first = False
        if self.pending == Pending.REPLAN or self.monitor.goals is None:
            if self.executor.current is not None:
                self.executor.cancel(self.pending_reason if self.pending == Pending.REPLAN else "replanning")
            self._make_plan(goals)
            goals = self.book.active()
            if not goals:
                self._finish_idle()
                return self.state
            if self.pending == Pending.REPLAN:  # planning failed or the plan was rejected: next tick
                return self.state
            if self.clock() < self._busy_until:  # the plan starts once its thinking time has passed
                return self.state
        if self.executor.current is None:
            self._start_next(goals)
        else:
            end = self.executor.advance()
            if end is not None:
                self._ended(end)
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
            sorted(atom_str(g) for g in self.book.achieved),
            {atom_str(g): why for g, why in self.book.dropped.items()},
            ticks,
            self.plans,
            self.replans,
        )

    def dropped_for_good(self) -> dict[str, str]:
        """Dropped goals (PDDL text) the recovery policy will not hand back, with why."""
        return self.book.for_good()

    def give_up(self, goal: Atom, reason: str) -> None:
        """Drop ``goal`` for good: no retry hands it back (a task flow told the user it gave up on it).

        Args:
            goal: the goal as an atom, ``("object_at", "glasses", "bedroom")``.
            reason: why, when the goal was not dropped yet (a GOAL_DROPPED trace event).
        """
        active = goal not in self.book.dropped
        self.book.give_up(goal, reason)
        if active:
            self._raise(Pending.GOALS)  # the active goals changed

    def cancel(self, reason: str = "cancelled by the caller") -> None:
        """Cancel the running action (outcome "cancelled") and stop; later steps do nothing."""
        if self.executor.current is not None:
            self.executor.cancel(reason)
        self.state = DispatcherState.STOPPED

    def resume(self) -> bool:
        """Take up work again after :meth:`cancel`: the next step looks at the goals afresh (plans for the
        open ones; dropped goals stay dropped until :meth:`retry` or news about them).

        Returns:
            False (and nothing changes) when the dispatcher was not stopped.
        """
        if self.state != DispatcherState.STOPPED:
            return False
        self.monitor.forget()  # the plan that ran before the stop is not resumed half-way
        self.state = DispatcherState.IDLE
        self._raise(Pending.GOALS)
        return True

    def retry(self, goal: Atom) -> bool:
        """Hand a dropped goal back: forget why it was dropped, so the next step plans for it again.

        Args:
            goal: the goal as an atom, ``("object_at", "glasses", "bedroom")``.

        Returns:
            False (and nothing changes) when the goal was not dropped.
        """
        if not self.book.undrop(goal):
            return False
        self._raise(Pending.GOALS)  # the active goals changed: an idle or running dispatcher must look
        return True

    def close(self) -> None:
        """Stop listening to the knowledge base."""
        self._unsubscribe()

    # -- pending work ---------------------------------------------------------------------------------
    def _raise(self, pending: Pending, reason: str = "") -> None:
        """Make ``pending`` pending unless something more urgent already is."""
        if pending > self.pending:
            self.pending = pending
            if pending == Pending.REPLAN:
                self.pending_reason = reason

    def _asleep(self) -> bool:
        """IDLE and nothing that matters happened since: the step has nothing to do."""
        return self.state == DispatcherState.IDLE and self.pending < Pending.GOALS

    def _on_change(self, change: Change) -> None:
        matters = self.book.on_change(change)
        if self.executor.writing:
            return  # our own effects: the plan assumed them
        self._raise(Pending.GOALS if matters else Pending.KNOWLEDGE)

    # -- planning ------------------------------------------------------------------------------------
    def _make_plan(self, goals: list[Atom]) -> None:
        reason = self.pending_reason if self.pending == Pending.REPLAN else None
        self.pending, self.pending_reason = Pending.NOTHING, ""
        now = self.clock()
        charge, self._charge_replan = self._charge_replan, False
        if reason is not None and self.monitor.goals is not None:
            self.replans += 1
            self.trace.emit(TraceEvent(EventKind.REPLAN, now, reason=reason))
            if charge:
                self.book.count_replan(goals, self.executor.facts(), self.policy.max_replans_per_goal)
            goals = self.book.active()
            if not goals:
                return
        task = task_from_kb(self.kb, goals)
        self.book.achieved.difference_update(g for g in goals if g not in task.facts)  # to be achieved again
        result = self.planner.solve(task, timeout=self.planning_timeout)
        self.last_result = result
        self.plans += 1
        thought = thinking_seconds(result, self.planning_time, self.planning_timeout)
        if thought > 0:
            self.thinking_s += thought
            self._busy_until = now + thought
        self.monitor.adopt((), goals)
        self._step_failures = 0
        if result.status == PlanStatus.TIMEOUT:
            # the same problem would time out again: the goals wait for news about them (as unreachable ones
            # do) instead of a planner call per timeout until the run's limit
            for goal in goals:
                if goal not in task.facts:
                    self.book.drop(goal, f"no plan within the planning timeout ({result.message})")
            self.monitor.adopt((), self.book.active())
            return
        if result.status == PlanStatus.ERROR:
            self._charge_replan = True  # a planner that keeps failing counts against the goals' replan budget
            self._raise(Pending.REPLAN, f"planning {result.status.value}: {result.message}")
            return
        retire = self.book.superseded(result.conflicts, task.facts)
        for goal, older in retire:  # planned again at the next step, without the older goals
            self.kb.remove_goal(older[0], *older[1:], source=SOURCE, at=now)
            reason = f"superseded by {atom_str(goal)}"
            self.trace.emit(TraceEvent(EventKind.GOAL_DROPPED, now, goal=atom_str(older), reason=reason))
        if retire:
            return
        why = {g: f"can never hold together with {atom_str(o)}" for g, o in result.conflicts}
        for goal in result.unreachable_goals:
            self.book.drop(
                goal, "unreachable: " + why.get(goal, "no plan reaches it from what the robot knows")
            )
        self.monitor.adopt((), self.book.active())
        if not result.has_plan:
            return
        check = check_plan(task.domain, task.facts, result.plan, result.reachable_goals, task.objects)
        if not check.valid:
            self._raise(Pending.REPLAN, f"plan rejected by validation: {check.reason}")
            return
        self.monitor.plan = result.plan
        self.trace.emit(
            TraceEvent(
                EventKind.PLAN,
                now,
                plan=tuple(str(s) for s in result.plan),
                data={
                    "planning_ms": round(result.planning_ms, 3),
                    "engine": result.engine,
                    "goals": [atom_str(g) for g in goals],
                },
            )
        )

    # -- execution -----------------------------------------------------------------------------------
    def _start_next(self, goals: list[Atom]) -> None:
        step = self.monitor.next_step
        if step is None:
            unmet = self.monitor.unmet_at_end(self.executor.facts(), goals)
            if unmet is not None:
                self._raise(Pending.REPLAN, unmet)
            return
        failure = self.executor.start(step, self.monitor.schema(step))
        if failure is not None:
            self._failed(failure)

    def _ended(self, end: StepEnd) -> None:
        if not end.ok:
            self._failed(end)
            return
        self.monitor.index += 1
        self._step_failures = 0
        self.book.announce(self.book.active(), self.executor.facts())

    def _failed(self, end: StepEnd) -> None:
        now = self.clock()
        self.trace.emit(
            TraceEvent(
                EventKind.FAILURE,
                now,
                action=str(end.step),
                outcome=end.outcome.value,
                reason=end.reason,
            )
        )
        self._step_failures += 1
        decision = self.policy.decide(end.outcome, self._step_failures)
        if decision == Recovery.RETRY:
            return
        self._charge_replan = True
        signature = (str(end.step), end.outcome.value, _shape(end.reason))
        times = self._failures[signature] = self._failures.get(signature, 0) + 1
        repeated = self.policy.repeated
        if repeated.drop_after and times >= repeated.drop_after:
            facts = self.executor.facts()
            why = f"{end.step} failed the same way {times} times ({end.reason})"
            for goal in self.monitor.served_by_current(facts, self.book.active()):
                self.book.drop(goal, why)
            self._raise(Pending.REPLAN, f"{end.outcome.value} of {end.step}, {times} times")
            return
        if repeated.retract_after and times >= repeated.retract_after:
            gone = self._retract_beliefs(end.step)
            if gone:
                what = "retracting " + " ".join(atom_str(a) for a in gone)
            else:
                wait = repeated.backoff_s * (times - repeated.retract_after + 1)
                self._plan_not_before = max(self._plan_not_before, now + wait)
                what = f"backing off {wait:g} s"
            reason = f"{end.step} failed the same way {times} times: {what}"
            self.trace.emit(TraceEvent(EventKind.REPLAN, now, reason=reason, action=str(end.step)))
            self._raise(Pending.REPLAN, reason)
            return
        if decision == Recovery.DROP_GOAL:
            facts = self.executor.facts()
            for goal in self.monitor.served_by_current(facts, self.book.active()):
                self.book.drop(goal, f"{end.outcome.value} of {end.step} ({end.reason})")
        self._raise(Pending.REPLAN, f"{end.outcome.value} of {end.step}")

    def _still_useful(self, step: PlanStep, goals: list[Atom]) -> bool:
        """Whether a running step whose *later* steps broke should finish before the replan: it is not a
        plain ``move`` (a drive somewhere may have become pointless; a pick, a hand-over or a search half
        done is not) and its at-start conditions still hold."""
        if step.name in REROUTABLE:
            return False
        return not unmet_conditions(self.monitor.schema(step), step.args, self.executor.facts(), "start")

    def _retract_beliefs(self, step: PlanStep) -> list[Atom]:
        """Retract the perceived positions (``RETRACTABLE``) among the step's at-start conditions that hold;
        perception must establish them again. Returns what was retracted."""
        schema = self.monitor.schema(step)
        facts = self.executor.facts()
        gone = [a for a in ground(schema.pre_pos, step.args) if a[0] in RETRACTABLE and a in facts]
        with self.kb.batch():
            for atom in gone:
                self.kb.remove_fact(atom[0], *atom[1:], source=SOURCE, status=BeliefStatus.OBSERVED)
        return gone

    def _finish_idle(self) -> None:
        self.book.reset_replans()
        if self.pending == Pending.REPLAN:  # whatever was pending is moot: no goal left to plan for
            self.pending, self.pending_reason = Pending.NOTHING, ""
        if self.executor.current is not None:
            self.executor.cancel("no goal left")
        else:
            self.monitor.forget()
        self.state = DispatcherState.IDLE


#: actions cancelled at once when a knowledge change breaks a later step of the plan (others finish first)
REROUTABLE = frozenset({"move"})
#: beliefs a repeatedly failing step may rest on wrongly: where people and items were perceived
RETRACTABLE = frozenset({"person_at", "object_at", "object_on"})


def _shape(reason: str) -> str:
    """A failure reason with its numbers blanked, so "1.26 m away" and "1.31 m away" count as the same."""
    return re.sub(r"-?\d+(\.\d+)?", "#", reason)


__all__ = ["SOURCE", "DispatchReport", "Dispatcher", "DispatcherState", "Outcome", "Pending", "PlanningTask"]
