"""Conversions between knowledge-base states and unified-planning / PDDL problems.

``state_to_up`` and ``state_from_up`` are the two directions of the unified-planning boundary;
``state_to_pddl`` writes PDDL problem text for the knowledge base's own domain (domain constants stay in the
domain, the ``:domain`` line names the real domain), and
``knowledge_base.problem.parse_problem_text`` reads it back. Exported: instances (constants excluded), the
facts that hold (closed world: everything else is false), numeric function values and the goal atoms.
Provenance, anchors and history are knowledge-base concepts and are not exported.
"""

from __future__ import annotations

from typing import Any

from knowledge_base.domain import DomainModel
from knowledge_base.model import State
from knowledge_base.problem import ProblemContent, content_from_up

__all__ = ["state_from_up", "state_to_pddl", "state_to_up"]


def state_to_up(domain: DomainModel, state: State, name: str) -> Any:
    """A unified-planning ``Problem``: the domain with the state's objects, initial values and goals."""
    from unified_planning.model import Object

    problem = domain.up_domain.clone()
    problem.name = name
    for instance, type_name in state.instances.items():
        if instance not in domain.constants:
            problem.add_object(Object(instance, problem.user_type(type_name)))
    for fact in state.facts:
        fluent = problem.fluent(fact.predicate)
        problem.set_initial_value(fluent(*[problem.object(a) for a in fact.args]), True)
    for fact, value in state.functions.items():
        fluent = problem.fluent(fact.predicate)
        number: int | float = int(value) if fluent.type.is_int_type() else value
        problem.set_initial_value(fluent(*[problem.object(a) for a in fact.args]), number)
    for goal in state.goals:
        fluent = problem.fluent(goal.predicate)
        problem.add_goal(fluent(*[problem.object(a) for a in goal.args]))
    return problem


def state_from_up(domain: DomainModel, problem: Any) -> ProblemContent:
    """Objects, facts, functions and goals of a unified-planning ``Problem`` (inverse of ``state_to_up``)."""
    return content_from_up(domain, problem)


def state_to_pddl(domain: DomainModel, state: State, name: str) -> str:
    """PDDL problem text for ``domain`` describing ``state`` (objects, init, goal).

    Written directly (linear in the state's size: 100,000 facts take a fraction of a second, where going
    through unified-planning's writer took over a minute). Instance names are PDDL identifiers by
    construction (checked by ``add_instance``), and predicate and function names come from the domain, so
    nothing needs renaming; ``parse_problem_text`` reads the text back to the same state.
    """
    by_type: dict[str, list[str]] = {}
    for instance, type_name in state.instances.items():
        if instance not in domain.constants:
            by_type.setdefault(type_name, []).append(instance)
    lines = [f"(define (problem {name})", f" (:domain {domain.name})", " (:objects"]
    lines += [f"  {' '.join(names)} - {type_name}" for type_name, names in by_type.items()]
    lines.append(" )")
    lines.append(" (:init")
    join = " ".join  # the atoms written inline, not through Fact.__str__: a third faster at 100k facts
    lines += [f"  ({p} {join(args)})" if args else f"  ({p})" for p, args in state.facts]
    lines += [f"  (= {fact} {_number(value)})" for fact, value in state.functions.items()]
    lines.append(" )")
    lines.append(" (:goal (and")
    lines += [f"  {goal}" for goal in state.goals]
    lines.append(" ))")
    lines.append(")")
    return "\n".join(lines) + "\n"


def _number(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else repr(float(value))
