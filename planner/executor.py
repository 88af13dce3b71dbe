"""Running one plan step: its PDDL checks, its time limit, its effects (seed 004, Algorithm 1).

:class:`ActionExecutor` drives one :class:`~actions.base.Action` at a time through its lifecycle
(:mod:`actions.base`) on behalf of the :class:`~planner.dispatch.Dispatcher`, one call per dispatcher step:

1. :meth:`ActionExecutor.start` -- called once per plan step, when no action is running. Checks the at-start
   conditions against the knowledge base, builds the action from the registry and calls ``activation()``;
   writes the at-start effects of a durative action. Returns None when the action now runs, else the
   failure (*precondition failure*, *activation failure*).
2. :meth:`ActionExecutor.advance` -- called once per step while the action runs. Checks the time limit
   (*timeout*) and the over-all conditions of a durative action, calls ``step()``; when the action ends:
   ``deactivation()``, the at-end conditions, the effects written to the knowledge base (belief status
   "effect", source "dispatcher"; sensed effects are left to perception and checked, *postcondition failure*
   if perception did not assert them). Returns None while the action runs, else how it ended.
3. :meth:`ActionExecutor.cancel` -- called when the dispatcher abandons the running action (the plan broke,
   no goal is left, the caller stopped): ``deactivation()`` with ending "cancelled" and a FAILURE trace event.

The executor emits the DISPATCH, ACTIVATION, SUCCESS and cancellation events; the dispatcher emits the
FAILURE event of a failed step, since it decides the recovery. Errors in action code become failures of
that action (never exceptions). Time is the executor's clock (simulated seconds in the closed loop).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from actions.base import Action, ActionRegistry, ActionStatus, Outcome
from core.errors import KnicError
from knowledge_base import BeliefStatus, KnowledgeBase
from planner.model import ActionSchema, Atom, atom_str, ground
from planner.plan import PlanStep
from planner.trace import EventKind, Trace, TraceEvent
from planner.validate import unmet_conditions

#: the source of every fact the executor writes
SOURCE = "dispatcher"


@dataclass
class Running:
    """The action in progress: its plan step, PDDL schema, implementation and start time (clock seconds)."""

    step: PlanStep
    schema: ActionSchema
    action: Action
    started: float


@dataclass(frozen=True)
class StepEnd:
    """How a plan step ended: ``outcome`` (SUCCEEDED or a failure) and, for a failure, one line why."""

    step: PlanStep
    outcome: Outcome
    reason: str = ""

    @property
    def ok(self) -> bool:
        """The step succeeded and its effects are in the knowledge base."""
        return self.outcome == Outcome.SUCCEEDED


class ActionExecutor:
    """Runs one plan step at a time (see the module docstring).

    Args:
        kb: the knowledge base (conditions are read from it, effects written to it).
        registry: PDDL action name -> implementation factory.
        trace: where events go.
        clock: time source (seconds).
        time_limit: seconds an action may run; per action name via ``time_limits``.
        time_limits: action name -> time limit, overriding ``time_limit``.
        sensing: action name -> predicates of its effects that perception asserts (from the domain's meta).

    Attributes:
        current: the running action, or None.
        writing: True while the executor writes effects (the dispatcher ignores its own writes).
    """

    def __init__(
        self,
        kb: KnowledgeBase,
        registry: ActionRegistry,
        trace: Trace,
        clock: Callable[[], float],
        *,
        time_limit: float = 120.0,
        time_limits: Mapping[str, float] | None = None,
        sensing: Mapping[str, frozenset[str]] | None = None,
    ) -> None:
        self.kb = kb
        self.registry = registry
        self.trace = trace
        self.clock = clock
        self.time_limit = time_limit
        self.time_limits = dict(time_limits or {})
        self.sensing = dict(sensing or {})
        self.current: Running | None = None
        self.writing = False

    def facts(self) -> frozenset[Atom]:
        """The knowledge base's facts as atoms."""
        return frozenset((f.predicate, *f.args) for f in self.kb.facts())

    def start(self, step: PlanStep, schema: ActionSchema) -> StepEnd | None:
        """Check the at-start conditions and activate ``step``; None when it now runs, else the failure."""
        now = self.clock()
        self.trace.emit(TraceEvent(EventKind.DISPATCH, now, action=str(step)))
        missing = unmet_conditions(schema, step.args, self.facts(), "start")
        if missing:
            why = f"at-start condition {missing[0]} does not hold"
            return StepEnd(step, Outcome.PRECONDITION_FAILURE, why)
        try:
            action = self.registry.create(step.name, step.args)
            ok = action.activation()
            why = action.failure_reason
        except Exception as exc:  # action code must not stop the loop
            ok, why = False, describe(exc)
        if not ok:
            return StepEnd(step, Outcome.ACTIVATION_FAILURE, why or "activation() returned False")
        self.trace.emit(TraceEvent(EventKind.ACTIVATION, now, action=str(step)))
        self.current = Running(step, schema, action, now)
        if schema.start_add or schema.start_delete:
            self.write(schema.start_add, schema.start_delete, step, frozenset())
        return None

    def advance(self) -> StepEnd | None:
        """One ``step()`` of the running action with its checks; None while it runs, else how it ended."""
        run = self.current
        assert run is not None, "advance() needs a running action"
        now = self.clock()
        limit = self.time_limits.get(run.step.name, self.time_limit)
        if now - run.started > limit:
            self._end(run, "timeout")
            return StepEnd(run.step, Outcome.TIMEOUT, f"still running after {limit:g} s")
        if run.schema.durative:
            missing = unmet_conditions(run.schema, run.step.args, self.facts(), "overall")
            if missing:
                self._end(run, "failed")
                return StepEnd(run.step, Outcome.EXECUTION_FAILURE, f"over-all condition {missing[0]} broken")
        try:
            status = run.action.step()
        except Exception as exc:
            run.action.failure_reason = describe(exc)
            status = ActionStatus.FAILED
        if status == ActionStatus.RUNNING:
            return None
        if status == ActionStatus.FAILED:
            self._end(run, "failed")
            return StepEnd(run.step, Outcome.EXECUTION_FAILURE, run.action.failure_reason or "step() failed")
        if not self._end(run, "succeeded"):
            reason = run.action.failure_reason or "deactivation failed"
            return StepEnd(run.step, Outcome.DEACTIVATION_FAILURE, reason)
        return self._finish(run, now)

    def _finish(self, run: Running, now: float) -> StepEnd:
        """At-end conditions, effects, sensed effects of a step whose action succeeded."""
        step, schema = run.step, run.schema
        if schema.durative:
            missing = unmet_conditions(schema, step.args, self.facts(), "end")
            if missing:
                why = f"at-end condition {missing[0]} does not hold"
                return StepEnd(step, Outcome.EXECUTION_FAILURE, why)
        sensed = self.sensing.get(step.name, frozenset())
        try:
            self.write(schema.add, schema.delete, step, sensed)
        except KnicError as exc:  # the knowledge base refused an effect: nothing was written
            return StepEnd(step, Outcome.EXECUTION_FAILURE, f"effects not written: {exc}")
        facts = self.facts()
        unconfirmed = [a for a in ground(schema.add, step.args) if a[0] in sensed and a not in facts]
        if unconfirmed:
            why = f"sensed effect {atom_str(unconfirmed[0])} not confirmed by perception"
            return StepEnd(step, Outcome.POSTCONDITION_FAILURE, why)
        self.trace.emit(TraceEvent(EventKind.SUCCESS, now, action=str(step), outcome=Outcome.SUCCEEDED.value))
        return StepEnd(step, Outcome.SUCCEEDED)

    def write(
        self, add: tuple[Any, ...], delete: tuple[Any, ...], step: PlanStep, sensed: frozenset[str]
    ) -> None:
        """Write the ground effects of ``step`` in one batch (deletes first), except sensed predicates.

        Raises:
            KnicError: the knowledge base refused a write (the batch is rolled back).
        """
        self.writing = True
        try:
            with self.kb.batch():
                for atom in ground(delete, step.args):
                    if atom[0] not in sensed:
                        self.kb.remove_fact(atom[0], *atom[1:], source=SOURCE, status=BeliefStatus.EFFECT)
                for atom in ground(add, step.args):
                    if atom[0] not in sensed:
                        self.kb.add_fact(atom[0], *atom[1:], source=SOURCE, status=BeliefStatus.EFFECT)
        finally:
            self.writing = False

    def cancel(self, reason: str) -> None:
        """Deactivate the running action with ending "cancelled" and trace it as a cancelled FAILURE."""
        run = self.current
        assert run is not None, "cancel() needs a running action"
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

    def _end(self, run: Running, ending: str) -> bool:
        """``deactivation()`` with ``ending``; False when it failed or raised."""
        self.current = None
        run.action.ending = ending
        try:
            return bool(run.action.deactivation())
        except Exception as exc:
            run.action.failure_reason = describe(exc)
            return False


def describe(exc: BaseException) -> str:
    """One line for an exception escaping action code (the project's errors need no type name)."""
    text = str(exc).splitlines()[0] if str(exc) else ""
    return f"{type(exc).__name__}: {text}" if not isinstance(exc, KnicError) else text
