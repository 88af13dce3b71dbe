"""Plan validation: a fast lifted simulator and unified-planning's ``SequentialPlanValidator``.

:func:`check_plan` executes a plan step by step on a set of atoms (closed world), straight from the lifted
action schemas: it shares no code with grounding or search, so it is an independent check of what they
produce. It is what the dispatcher uses to validate a new plan and to test whether the rest of a running plan
still reaches the goals after a knowledge-base change (microseconds per step).

:func:`validate_with_up` asks unified-planning's sequential plan validator; the test suite checks that both
agree on every example problem's known valid and invalid plans.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from planner.model import ActionSchema, Atom, StripsDomain, atom_str, ground
from planner.plan import PlanStep, TimedStep


@dataclass(frozen=True)
class CheckResult:
    """Outcome of :func:`check_plan`.

    Attributes:
        valid: every step applicable in turn and every goal true at the end.
        failed_step: index of the first inapplicable step, ``None`` if all applied.
        reason: one line naming the step and the unmet condition or goals ("" when valid).
        final: atoms true after the last applied step.
        unmet_goals: goals false at the end.
    """

    valid: bool
    failed_step: int | None
    reason: str
    final: frozenset[Atom]
    unmet_goals: tuple[Atom, ...]


def step_problem(domain: StripsDomain, step: PlanStep, objects: Mapping[str, str] | None) -> str:
    """Why ``step`` is not a well-formed instance of a domain action ("" if it is)."""
    schema = domain.schemas.get(step.name)
    if schema is None:
        return f"{step}: unknown action {step.name!r}"
    if len(step.args) != len(schema.params):
        return f"{step}: {step.name} takes {len(schema.params)} arguments, got {len(step.args)}"
    if objects is not None:
        for arg, (pname, ptype) in zip(step.args, schema.params, strict=True):
            otype = objects.get(arg)
            if otype is None:
                return f"{step}: unknown object {arg!r}"
            if not domain.is_subtype(otype, ptype):
                return f"{step}: {arg} is a {otype}, parameter ?{pname} needs a {ptype}"
    return ""


def unmet_conditions(
    schema: ActionSchema, args: tuple[str, ...], facts: Iterable[Atom] | frozenset[Atom], which: str = "start"
) -> list[str]:
    """Conditions of ``schema(args)`` false in ``facts``, as PDDL text (``(not ...)`` for negative ones).

    ``which`` is ``"start"`` (preconditions), ``"overall"`` or ``"end"`` (durative actions only).
    """
    state = facts if isinstance(facts, (set, frozenset)) else set(facts)
    pos, neg = {
        "start": (schema.pre_pos, schema.pre_neg),
        "overall": (schema.overall_pos, schema.overall_neg),
        "end": (schema.end_pos, schema.end_neg),
    }[which]
    missing = [atom_str(a) for a in ground(pos, args) if a not in state]
    missing += [f"(not {atom_str(a)})" for a in ground(neg, args) if a in state]
    return missing


def apply(schema: ActionSchema, args: tuple[str, ...], state: set[Atom]) -> None:
    """Apply every effect of ``schema(args)`` to ``state`` in place (deletes first, then adds, as PDDL)."""
    for atoms, adding in (
        (schema.start_delete, False),
        (schema.start_add, True),
        (schema.delete, False),
        (schema.add, True),
    ):
        for atom in ground(atoms, args):
            if adding:
                state.add(atom)
            else:
                state.discard(atom)


def check_plan(
    domain: StripsDomain,
    facts: Iterable[Atom],
    steps: Sequence[PlanStep],
    goals: Iterable[Atom],
    objects: Mapping[str, str] | None = None,
) -> CheckResult:
    """Execute ``steps`` from ``facts`` and check each step's conditions and the goals at the end.

    Args:
        domain: the action schemas.
        facts: the atoms true at the start (closed world).
        steps: the plan.
        goals: positive goal atoms.
        objects: object -> type; when given, step arguments are type-checked too.
    """
    state = set(facts)
    goal_list = tuple(goals)
    for i, step in enumerate(steps):
        problem = step_problem(domain, step, objects)
        if problem:
            return CheckResult(False, i, f"step {i + 1} {problem}", frozenset(state), goal_list)
        schema = domain.schemas[step.name]
        missing = unmet_conditions(schema, step.args, state, "start")
        if schema.durative:
            missing += unmet_conditions(schema, step.args, state, "overall")
            missing += unmet_conditions(schema, step.args, state, "end")
        if missing:
            unmet = tuple(g for g in goal_list if g not in state)
            return CheckResult(
                False,
                i,
                f"step {i + 1} {step}: condition {missing[0]} does not hold",
                frozenset(state),
                unmet,
            )
        apply(schema, step.args, state)
    unmet = tuple(g for g in goal_list if g not in state)
    if unmet:
        text = " ".join(atom_str(g) for g in unmet)
        return CheckResult(False, None, f"goals not reached: {text}", frozenset(state), unmet)
    return CheckResult(True, None, "", frozenset(state), ())


def check_schedule(
    domain: StripsDomain,
    facts: Iterable[Atom],
    schedule: Sequence[TimedStep],
    goals: Iterable[Atom],
    objects: Mapping[str, str] | None = None,
) -> CheckResult:
    """Check a temporal plan (actions with start times and durations, possibly overlapping).

    The plan is executed as its happenings in time order: a durative action's start (at-start conditions
    checked, at-start effects applied) and its end (at-end conditions checked, at-end effects applied);
    at one instant ends come before starts. Over-all conditions must hold in every state while the action
    runs, i.e. after its start and after every happening before its end. Instantaneous actions (duration
    None) are one happening. ``failed_step`` indexes ``schedule``.
    """
    state = set(facts)
    goal_list = tuple(goals)
    happenings: list[tuple[float, int, int]] = []  # (time, 0 end / 1 start, index)
    for i, timed in enumerate(schedule):
        problem = step_problem(domain, timed.step, objects)
        if problem:
            return CheckResult(False, i, f"step {i + 1} {problem}", frozenset(state), goal_list)
        happenings.append((timed.start, 1, i))
        if domain.schemas[timed.step.name].durative:
            happenings.append((timed.start + (timed.duration or 0.0), 0, i))
    happenings.sort()
    running: set[int] = set()

    def fail(i: int, what: str, missing: list[str]) -> CheckResult:
        unmet = tuple(g for g in goal_list if g not in state)
        step = schedule[i].step
        reason = f"step {i + 1} {step} at {schedule[i].start:g}: {what} condition {missing[0]} does not hold"
        return CheckResult(False, i, reason, frozenset(state), unmet)

    for _, is_start, i in happenings:
        step = schedule[i].step
        schema = domain.schemas[step.name]
        if is_start:
            missing = unmet_conditions(schema, step.args, state, "start")
            if missing:
                return fail(i, "at-start", missing)
            if schema.durative:
                _apply_part(state, step.args, schema.start_delete, schema.start_add)
                running.add(i)
            else:
                apply(schema, step.args, state)
        else:
            running.discard(i)
            missing = unmet_conditions(schema, step.args, state, "end")
            if missing:
                return fail(i, "at-end", missing)
            _apply_part(state, step.args, schema.delete, schema.add)
        for j in sorted(running):
            other = schedule[j].step
            missing = unmet_conditions(domain.schemas[other.name], other.args, state, "overall")
            if missing:
                return fail(j, "over-all", missing)
    unmet = tuple(g for g in goal_list if g not in state)
    if unmet:
        text = " ".join(atom_str(g) for g in unmet)
        return CheckResult(False, None, f"goals not reached: {text}", frozenset(state), unmet)
    return CheckResult(True, None, "", frozenset(state), ())


def _apply_part(state: set[Atom], args: tuple[str, ...], delete: Iterable[Any], add: Iterable[Any]) -> None:
    for atom in ground(delete, args):
        state.discard(atom)
    for atom in ground(add, args):
        state.add(atom)


def validate_with_up(
    problem: Any, steps: Sequence[PlanStep], schedule: Sequence[TimedStep] = ()
) -> tuple[bool, str]:
    """Validate a plan for a unified-planning ``Problem`` with its validators.

    With ``schedule`` (a temporal plan) the time-triggered validator checks the actions at their start
    times with their durations; otherwise the sequential validator checks ``steps`` in order.

    Returns:
        ``(valid, reason)``; ``reason`` is the validator's explanation when invalid, "" otherwise.
    """
    from fractions import Fraction

    from unified_planning.engines import ValidationResultStatus
    from unified_planning.plans import ActionInstance, SequentialPlan, TimeTriggeredPlan
    from unified_planning.shortcuts import PlanValidator

    def instance(s: PlanStep) -> Any:
        return ActionInstance(problem.action(s.name), [problem.object(a) for a in s.args])

    try:
        if schedule:
            plan: Any = TimeTriggeredPlan(
                [
                    (
                        Fraction(str(t.start)),
                        instance(t.step),
                        None if t.duration is None else Fraction(str(t.duration)),
                    )
                    for t in schedule
                ]
            )
            name = "up_time_triggered_validator"
        else:
            plan = SequentialPlan([instance(s) for s in steps])
            name = "sequential_plan_validator"
    except Exception as exc:  # unknown action or object: UP raises its own error types
        return False, f"plan does not fit the problem: {exc}"
    with PlanValidator(name=name) as validator:
        result = validator.validate(problem, plan)
    if result.status == ValidationResultStatus.VALID:
        return True, ""
    return False, str(result.reason or result.status.name)
