"""Conversions between knowledge-base states and unified-planning / PDDL problems.

``state_to_up`` and ``state_from_up`` are the two directions of the unified-planning boundary;
``state_to_pddl`` writes PDDL problem text for the knowledge base's own domain through unified-planning's
``PDDLWriter`` (domain constants stay in the domain, the ``:domain`` line names the real domain), and
``knowledge_base.problem.parse_problem_text`` reads it back. Exported: instances (constants excluded), the
facts that hold (closed world: everything else is false), numeric function values and the goal atoms.
Provenance, anchors and history are knowledge-base concepts and are not exported.
"""

from __future__ import annotations

import re
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
    """PDDL problem text for ``domain`` describing ``state`` (objects, init, goal)."""
    from unified_planning.io import PDDLWriter

    problem = state_to_up(domain, state, name)
    writer = PDDLWriter(problem)
    # Keep the domain's constants out of :objects: they are declared by the domain itself.
    constants: dict[Any, set[Any]] = {}
    for constant in domain.constants:
        obj = problem.object(constant)
        constants.setdefault(obj.type, set()).add(obj)
    writer.domain_objects = constants
    text: str = writer.get_problem()
    # The writer renames symbols that clash with PDDL keywords (a predicate "at" becomes "at_"); the text is
    # for the original domain, so put the original names back.
    for new_name, item in writer.nto_renamings.items():
        if new_name != item.name:
            text = re.sub(rf"(?<=[\s(]){re.escape(new_name)}(?=[\s)])", item.name, text)
    text = re.sub(r"\(define \(problem [^)\s]+\)", f"(define (problem {name})", text, count=1)
    text = re.sub(r"\(:domain [^)\s]+\)", f"(:domain {domain.name})", text, count=1)
    return text
