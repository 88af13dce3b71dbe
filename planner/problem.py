"""Planning problems from the knowledge base, object focusing, and conversion to unified-planning.

``task_from_kb`` reads the knowledge base's instances, facts and goals into a :class:`PlanningTask`.
``task_to_up`` writes a task as a unified-planning ``Problem`` for the engines that need one.

Relevance pruning happens at two levels:

1. **Object focus** (:func:`focus_task`, here): keep the objects that the goals can involve and drop the rest
   with their facts. The kept set is the map (every object of a type related to itself by a static
   predicate that has facts, e.g. rooms joined by ``connected``), the constants, the goal objects, every
   object of an action parameter type that no kept object can fill (e.g. the robot, the furniture), and,
   transitively, the objects in facts whose first argument is a kept non-map object (``(holding r2d2 mug)``
   keeps the mug; ``(object_on mug table)`` does not make a table keep its mug). A plan of the focused task
   is a plan of the full task: a ground action's conditions and effects mention only its arguments and the
   constants, and the focused initial state is the full one restricted to the kept objects. The converse may
   fail (a goal might need an object that was dropped), so :class:`~planner.engines.TaskPlanner` plans the
   full task whenever the focused one leaves a goal unreached: focusing never changes solvability.
2. **Action relevance** on the ground task (:mod:`planner.grounding`): provably keeps solvability and plan
   validity.
"""

from __future__ import annotations

from typing import Any, Protocol

from planner.model import Atom, PlanningTask, StripsDomain, domain_from_up, task_from_up


class FactLike(Protocol):
    """A knowledge-base fact: ``predicate`` and ``args`` (``knowledge_base.Fact`` satisfies it)."""

    @property
    def predicate(self) -> str: ...

    @property
    def args(self) -> tuple[str, ...]: ...


class DomainModelLike(Protocol):
    """The part of ``knowledge_base.DomainModel`` the planner reads."""

    @property
    def up_domain(self) -> Any: ...

    @property
    def sensing(self) -> dict[str, tuple[str, ...]]: ...


class KnowledgeView(Protocol):
    """The read side of the knowledge base the planner needs (``knowledge_base.KnowledgeBase`` fits)."""

    @property
    def domain(self) -> Any: ...

    def instances(self, type: str | None = None) -> list[str]: ...

    def type_of(self, name: str) -> str | None: ...

    def facts(self, predicate: str | None = None, *pattern: str | None) -> list[Any]: ...

    def goals(self) -> list[Any]: ...


_DOMAINS: dict[int, tuple[Any, StripsDomain]] = {}


def strips_domain(up_domain: Any) -> StripsDomain:
    """The :class:`StripsDomain` of a unified-planning domain problem, cached per problem object."""
    cached = _DOMAINS.get(id(up_domain))
    if cached is not None and cached[0] is up_domain:
        return cached[1]
    dom = domain_from_up(up_domain)
    _DOMAINS[id(up_domain)] = (up_domain, dom)
    return dom


def fact_atom(fact: FactLike) -> Atom:
    """A knowledge-base fact as an atom tuple."""
    return (fact.predicate, *fact.args)


def task_from_kb(kb: KnowledgeView, goals: list[Atom] | None = None) -> PlanningTask:
    """The knowledge base's current state as a planning task.

    Args:
        kb: the knowledge base (read only).
        goals: the goals to plan for; default every goal in the knowledge base.
    """
    domain = strips_domain(kb.domain.up_domain)
    objects = dict(domain.constants)
    for name in kb.instances():
        type_name = kb.type_of(name)
        if type_name is not None:
            objects[name] = type_name
    facts = frozenset(fact_atom(f) for f in kb.facts())
    goal_atoms = tuple(goals) if goals is not None else tuple(fact_atom(g) for g in kb.goals())
    return PlanningTask(domain, objects, facts, goal_atoms)


def focus_objects(task: PlanningTask) -> set[str]:
    """The objects kept by object focusing (see the module docstring)."""
    dom = task.domain
    static = dom.static_predicates
    # Graph types: a static relation between two objects of one type (rooms joined by doors) is the map.
    used_static = {atom[0] for atom in task.facts if atom[0] in static}
    graph_types: set[str] = set()
    for pred in used_static:
        arg_types = dom.predicates.get(pred, ())
        graph_types.update(t for t in arg_types if arg_types.count(t) > 1)
    kept: set[str] = set(dom.constants)
    kept.update(o for o, t in task.objects.items() if any(dom.is_subtype(t, g) for g in graph_types))
    hubs = set(kept)
    seeds = {obj for g in task.goals for obj in g[1:]}
    for schema in dom.schemas.values():
        for _, type_name in schema.params:
            members = task.objects_of(type_name)
            if not any(m in kept or m in seeds for m in members):
                seeds.update(members)
    facts_of: dict[str, list[Atom]] = {}
    for atom in task.facts:
        if len(atom) > 1:
            facts_of.setdefault(atom[1], []).append(atom)
    kept.update(seeds)
    stack = [s for s in seeds if s not in hubs]
    while stack:
        obj = stack.pop()
        for atom in facts_of.get(obj, ()):
            for other in atom[1:]:
                if other not in kept:
                    kept.add(other)
                    if other not in hubs:
                        stack.append(other)
    return {o for o in kept if o in task.objects}


def focus_task(task: PlanningTask) -> PlanningTask:
    """``task`` restricted to :func:`focus_objects`; every plan of the result is a plan of ``task``."""
    kept = focus_objects(task)
    if len(kept) == len(task.objects):
        return task
    objects = {o: t for o, t in task.objects.items() if o in kept}
    facts = frozenset(a for a in task.facts if all(x in kept for x in a[1:]))
    return PlanningTask(task.domain, objects, facts, task.goals)


def task_to_up(task: PlanningTask, up_domain: Any) -> Any:
    """``task`` as a unified-planning ``Problem`` over the fluents and actions of ``up_domain``.

    Boolean fluents default to false (closed world), so only true facts are written.
    """
    from unified_planning.model import Object, Problem

    problem = Problem(f"{task.domain.name}_task", initial_defaults={})
    for fluent in up_domain.fluents:
        problem.add_fluent(fluent, default_initial_value=False)
    for action in up_domain.actions:
        problem.add_action(action)
    for obj in up_domain.all_objects:
        problem.add_object(obj)
    have = {o.name for o in up_domain.all_objects}
    types = {t.name: t for t in up_domain.user_types}
    for name, type_name in sorted(task.objects.items()):
        if name not in have:
            problem.add_object(Object(name, types[type_name]))
    for atom in sorted(task.facts):
        fluent = problem.fluent(atom[0])
        problem.set_initial_value(fluent(*(problem.object(a) for a in atom[1:])), True)
    for atom in task.goals:
        problem.add_goal(problem.fluent(atom[0])(*(problem.object(a) for a in atom[1:])))
    return problem


def load_pddl(domain_path: str, problem_path: str) -> tuple[Any, Any, PlanningTask]:
    """Parse a PDDL domain and problem with unified-planning's reader.

    Returns:
        ``(up_domain, up_problem, task)``: the domain alone (its objects are the domain's constants), the
        whole problem, and the task over :func:`strips_domain` of the domain.

    Raises:
        Whatever unified-planning's reader raises for malformed files (callers turn it into PDDLParseError).
    """
    from unified_planning.io import PDDLReader

    up_domain = PDDLReader().parse_problem(domain_path)
    up_problem = PDDLReader().parse_problem(domain_path, problem_path)
    domain = strips_domain(up_domain)
    task = task_from_up(up_problem, domain)
    return up_domain, up_problem, task
