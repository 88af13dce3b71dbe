"""The planner's own view of a PDDL domain and task: STRIPS action schemas and ground atoms.

This is the one conversion boundary between unified-planning's object model and the planner's fast paths
(grounding, search, plan checking, dispatch). :func:`domain_from_up` reads a unified-planning problem's
domain part (types, constants, predicates, actions); :class:`PlanningTask` holds one task (objects, facts,
goals) as plain tuples.

Atoms are tuples ``(predicate, arg1, arg2, ...)``; :func:`atom_str` / :func:`atom_from_str` convert to and
from PDDL text ``"(object_at glasses kitchen)"``. A lifted atom is ``(predicate, terms)`` where a term is
an ``int`` (index of the action parameter) or a ``str`` (a constant).

The fragment covered here is typed STRIPS with negative preconditions, plus durative actions whose
conditions and effects are such atoms (their timing is kept for dispatch). Anything else (numeric fluents,
conditional or quantified effects, disjunctions, equality) makes :attr:`StripsDomain.unsupported` name the
feature; such domains are planned by unified-planning engines only.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

Atom = tuple[str, ...]
Term = int | str
LiftedAtom = tuple[str, tuple[Term, ...]]


def atom_str(atom: Atom) -> str:
    """``("object_at", "glasses", "kitchen")`` -> ``"(object_at glasses kitchen)"``."""
    return "(" + " ".join(atom) + ")"


def atom_from_str(text: str) -> Atom:
    """``"(object_at glasses kitchen)"`` -> ``("object_at", "glasses", "kitchen")``; ValueError if bad."""
    body = text.strip()
    if not (body.startswith("(") and body.endswith(")")):
        raise ValueError(f"not a PDDL atom: {text!r}")
    parts = tuple(body[1:-1].split())
    if not parts:
        raise ValueError(f"empty PDDL atom: {text!r}")
    return parts


@dataclass(frozen=True)
class ActionSchema:
    """One PDDL action as lifted STRIPS.

    For an instantaneous action the preconditions are ``pre_pos``/``pre_neg`` (checked at start) and the
    effects ``add``/``delete`` (applied at the end). A durative action also has over-all and at-end
    conditions and at-start effects (``start_add``/``start_delete``).
    """

    name: str
    params: tuple[tuple[str, str], ...]
    pre_pos: tuple[LiftedAtom, ...] = ()
    pre_neg: tuple[LiftedAtom, ...] = ()
    add: tuple[LiftedAtom, ...] = ()
    delete: tuple[LiftedAtom, ...] = ()
    overall_pos: tuple[LiftedAtom, ...] = ()
    overall_neg: tuple[LiftedAtom, ...] = ()
    end_pos: tuple[LiftedAtom, ...] = ()
    end_neg: tuple[LiftedAtom, ...] = ()
    start_add: tuple[LiftedAtom, ...] = ()
    start_delete: tuple[LiftedAtom, ...] = ()
    durative: bool = False


def ground(lifted: Iterable[LiftedAtom], args: tuple[str, ...]) -> list[Atom]:
    """Instantiate lifted atoms with the action arguments ``args`` (by parameter index)."""
    return [(pred, *(args[t] if isinstance(t, int) else t for t in terms)) for pred, terms in lifted]


@dataclass
class StripsDomain:
    """A domain: type tree, constants, predicate signatures and action schemas.

    Attributes:
        name: PDDL domain name.
        types: type -> parent type (``None`` for roots; ``object`` is implicit).
        constants: constant name -> type.
        predicates: predicate -> argument types.
        schemas: action name -> schema.
        unsupported: ``None`` when every action is in the fragment above, else a one-line reason naming the
            action and the feature (such domains go to unified-planning engines).
        temporal: True when any action is durative.
    """

    name: str
    types: dict[str, str | None]
    constants: dict[str, str]
    predicates: dict[str, tuple[str, ...]]
    schemas: dict[str, ActionSchema]
    unsupported: str | None = None
    temporal: bool = False
    _static: frozenset[str] | None = field(default=None, repr=False)

    def is_subtype(self, sub: str, ancestor: str) -> bool:
        """True when ``sub`` is ``ancestor`` or below it in the type tree (every type is below ``object``)."""
        if ancestor == "object":
            return True
        seen: str | None = sub
        while seen is not None:
            if seen == ancestor:
                return True
            seen = self.types.get(seen)
        return False

    @property
    def static_predicates(self) -> frozenset[str]:
        """Predicates that no action adds or deletes (their facts never change during a plan)."""
        if self._static is None:
            changed = {
                pred
                for s in self.schemas.values()
                for pred, _ in (*s.add, *s.delete, *s.start_add, *s.start_delete)
            }
            self._static = frozenset(p for p in self.predicates if p not in changed)
        return self._static


@dataclass
class PlanningTask:
    """One planning task over a :class:`StripsDomain`.

    Attributes:
        domain: the domain.
        objects: object name -> type, constants included.
        facts: the atoms true in the initial state (closed world: everything else is false).
        goals: positive goal atoms, in the order given.
    """

    domain: StripsDomain
    objects: dict[str, str]
    facts: frozenset[Atom]
    goals: tuple[Atom, ...]

    def objects_of(self, type_name: str) -> list[str]:
        """Objects whose type is ``type_name`` or a subtype, sorted by name."""
        return sorted(o for o, t in self.objects.items() if self.domain.is_subtype(t, type_name))


class _Unsupported(Exception):
    pass


def _lifted(node: Any, params: Mapping[str, int]) -> LiftedAtom:
    if not node.is_fluent_exp():
        raise _Unsupported(f"condition or effect {node} is not a predicate atom")
    terms: list[Term] = []
    for arg in node.args:
        if arg.is_parameter_exp():
            terms.append(params[arg.parameter().name])
        elif arg.is_object_exp():
            terms.append(arg.object().name)
        else:
            raise _Unsupported(f"argument {arg} of {node} is neither a parameter nor a constant")
    return (node.fluent().name, tuple(terms))


def _literals(nodes: Iterable[Any], params: Mapping[str, int]) -> tuple[list[LiftedAtom], list[LiftedAtom]]:
    pos: list[LiftedAtom] = []
    neg: list[LiftedAtom] = []
    stack = list(nodes)
    while stack:
        node = stack.pop(0)
        if node.is_and():
            stack[0:0] = list(node.args)
        elif node.is_not():
            neg.append(_lifted(node.arg(0), params))
        elif node.is_true():
            continue
        else:
            pos.append(_lifted(node, params))
    return pos, neg


def _effects(effects: Iterable[Any], params: Mapping[str, int]) -> tuple[list[LiftedAtom], list[LiftedAtom]]:
    add: list[LiftedAtom] = []
    delete: list[LiftedAtom] = []
    for eff in effects:
        if eff.is_conditional():
            raise _Unsupported("conditional effect")
        if eff.is_forall():
            raise _Unsupported("forall effect")
        if not eff.is_assignment() or not eff.value.is_bool_constant():
            raise _Unsupported(f"numeric or non-constant effect {eff}")
        (add if eff.value.is_true() else delete).append(_lifted(eff.fluent, params))
    return add, delete


def _schema(action: Any) -> ActionSchema:
    import unified_planning.model as upm

    params = {p.name: i for i, p in enumerate(action.parameters)}
    signature = tuple((p.name, p.type.name) for p in action.parameters)
    if isinstance(action, upm.InstantaneousAction):
        pos, neg = _literals(action.preconditions, params)
        add, delete = _effects(action.effects, params)
        return ActionSchema(action.name, signature, tuple(pos), tuple(neg), tuple(add), tuple(delete))
    if isinstance(action, upm.DurativeAction):
        start: list[Any] = []
        overall: list[Any] = []
        end: list[Any] = []
        for interval, conditions in action.conditions.items():
            lower, upper = interval.lower, interval.upper
            if lower == upper:
                (start if lower.is_from_start() else end).extend(conditions)
            else:
                overall.extend(conditions)
        s_pos, s_neg = _literals(start, params)
        o_pos, o_neg = _literals(overall, params)
        e_pos, e_neg = _literals(end, params)
        s_add: list[LiftedAtom] = []
        s_del: list[LiftedAtom] = []
        add, delete = [], []
        for timing, effs in action.effects.items():
            a, d = _effects(effs, params)
            if timing.is_from_start():
                s_add += a
                s_del += d
            else:
                add += a
                delete += d
        return ActionSchema(
            action.name,
            signature,
            tuple(s_pos),
            tuple(s_neg),
            tuple(add),
            tuple(delete),
            tuple(o_pos),
            tuple(o_neg),
            tuple(e_pos),
            tuple(e_neg),
            tuple(s_add),
            tuple(s_del),
            durative=True,
        )
    raise _Unsupported(f"action kind {type(action).__name__}")


def domain_from_up(problem: Any) -> StripsDomain:
    """Read the domain part of a unified-planning ``Problem``.

    Never raises for features outside the fragment: the action concerned is left out and
    :attr:`StripsDomain.unsupported` names it (the caller then plans with unified-planning engines only).
    """
    types: dict[str, str | None] = {}
    for t in problem.user_types:
        father = t.father
        types[t.name] = father.name if father is not None else None
    predicates: dict[str, tuple[str, ...]] = {}
    unsupported: str | None = None
    for f in problem.fluents:
        if not f.type.is_bool_type():
            unsupported = unsupported or f"numeric function {f.name}"
            continue
        predicates[f.name] = tuple(p.type.name for p in f.signature)
    schemas: dict[str, ActionSchema] = {}
    temporal = False
    for action in problem.actions:
        try:
            schema = _schema(action)
        except _Unsupported as exc:
            unsupported = unsupported or f"action {action.name}: {exc}"
            continue
        temporal = temporal or schema.durative
        schemas[schema.name] = schema
    if problem.quality_metrics:
        unsupported = unsupported or "quality metrics"
    constants = {o.name: o.type.name for o in problem.all_objects}
    return StripsDomain(problem.name, types, constants, predicates, schemas, unsupported, temporal)


def task_from_up(problem: Any, domain: StripsDomain | None = None) -> PlanningTask:
    """The task of a unified-planning ``Problem`` (objects, true initial atoms, positive goal atoms).

    Raises:
        ValueError: a goal is not a conjunction of positive atoms, or an initial value is not a ground atom.
    """
    dom = domain if domain is not None else domain_from_up(problem)
    objects = {o.name: o.type.name for o in problem.all_objects}
    facts: set[Atom] = set()
    for fluent_exp, value in problem.explicit_initial_values.items():
        if value.is_true():
            facts.add((fluent_exp.fluent().name, *(a.object().name for a in fluent_exp.args)))
    goals: list[Atom] = []
    pos, neg = _literals(problem.goals, {})
    if neg:
        raise ValueError(f"negative goal ({neg[0][0]} ...) is outside the planner's fragment")
    for pred, terms in pos:
        goals.append((pred, *(str(t) for t in terms)))
    return PlanningTask(dom, objects, frozenset(facts), tuple(goals))
