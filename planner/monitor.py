"""Monitoring the plan against the knowledge base: does the rest of the plan still reach the goals?

:class:`PlanMonitor` holds the plan being run (its steps, the index of the next or running step, the goals it
was made for) and answers the dispatcher's questions about it, on STRIPS semantics (:mod:`planner.validate`):

* :meth:`PlanMonitor.broken` -- after a knowledge-base change: why the plan no longer serves (the goals
  changed, or the rest of the plan, with the running step's effects assumed, does not reach the goals from
  the current facts), or None while it still does;
* :meth:`PlanMonitor.served_by_current` -- the goals only the current step leads to (the ones a
  ``drop_goal`` recovery drops);
* :meth:`PlanMonitor.unmet_at_end` -- why a finished plan needs a successor.

It reads facts it is given and writes nothing.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from planner.model import ActionSchema, Atom, atom_str
from planner.plan import PlanStep
from planner.validate import apply, check_plan, unmet_conditions


class PlanMonitor:
    """The plan being run and its checks (see the module docstring).

    Args:
        up_domain: the unified-planning domain the plans are for (read lazily as STRIPS).

    Attributes:
        plan: the steps of the current plan (empty when there is none or the planner found none).
        index: the position of the next step to start, or of the running step.
        goals: the goals the plan was made for; None when there is no plan (a plan must be made).
    """

    def __init__(self, up_domain: Any) -> None:
        self.up_domain = up_domain
        self.plan: tuple[PlanStep, ...] = ()
        self.index = 0
        self.goals: frozenset[Atom] | None = None
        self._domain: Any = None

    @property
    def strips(self) -> Any:
        """The domain as :class:`planner.model.StripsDomain` (read once)."""
        if self._domain is None:
            from planner.problem import strips_domain

            self._domain = strips_domain(self.up_domain)
        return self._domain

    def schema(self, step: PlanStep) -> ActionSchema:
        """The PDDL schema of ``step``."""
        schema: ActionSchema = self.strips.schemas[step.name]
        return schema

    def adopt(self, plan: tuple[PlanStep, ...], goals: Iterable[Atom]) -> None:
        """Start following ``plan`` (possibly empty) for ``goals`` from its first step."""
        self.plan, self.index, self.goals = plan, 0, frozenset(goals)

    def forget(self) -> None:
        """No plan any more: the next dispatcher step plans."""
        self.plan, self.index, self.goals = (), 0, None

    @property
    def next_step(self) -> PlanStep | None:
        """The step to start next, or None at the end of the plan."""
        return self.plan[self.index] if self.index < len(self.plan) else None

    def broken(self, facts: frozenset[Atom], goals: list[Atom], running: PlanStep | None) -> str | None:
        """Why the plan no longer serves ``goals`` from ``facts`` (None while it does).

        Args:
            facts: the knowledge base's facts.
            goals: the active goals.
            running: the step in progress (its effects are assumed), or None.
        """
        if self.goals is None:
            return None
        if frozenset(goals) != self.goals:
            return "goals changed"
        state = set(facts)
        rest = self.plan[self.index :]
        if running is not None:
            apply(self.schema(running), running.args, state)
            rest = self.plan[self.index + 1 :]
        check = check_plan(self.strips, state, rest, goals)
        return None if check.valid else f"knowledge change breaks the plan: {check.reason}"

    def served_by_current(self, facts: frozenset[Atom], goals: list[Atom]) -> list[Atom]:
        """Goals false now that the rest of the plan reaches only with its current step.

        The rest of the plan is simulated twice from ``facts``, with and without the current step, skipping
        steps whose at-start conditions fail; the goals reached only in the first run are the step's.
        """
        rest = self.plan[self.index :]

        def reached(steps: tuple[PlanStep, ...]) -> set[Atom]:
            state = set(facts)
            for step in steps:
                schema = self.schema(step)
                if not unmet_conditions(schema, step.args, state, "start"):
                    apply(schema, step.args, state)
            return state

        with_step, without = reached(rest), reached(rest[1:])
        return [g for g in goals if g not in facts and g in with_step and g not in without]

    def unmet_at_end(self, facts: frozenset[Atom], goals: list[Atom]) -> str | None:
        """At the end of the plan: why a new plan is needed (goals that do not hold), or None."""
        unmet = [g for g in goals if g not in facts]
        if not unmet:
            return None
        return "plan finished but goals do not hold: " + " ".join(atom_str(g) for g in unmet)
