"""Grounding: from a lifted :class:`~planner.model.PlanningTask` to ground actions, with relevance analysis.

Two analyses, both exact in the sense stated:

* **Relaxed reachability** (forward, delete effects ignored): every ground action whose positive
  preconditions can ever hold together is generated, nothing else. Atoms outside the reachable set can never
  become true, so a goal outside it is *provably unreachable* (reported by name, never searched for).
* **Backward relevance**: starting from the goal literals, an action is relevant when one of its effects makes
  a relevant literal true (``add p`` for ``p``, ``delete p`` for ``not p``); its preconditions become relevant
  in turn. Removing every irrelevant action from any valid plan leaves a valid plan: such an action only makes
  irrelevant literals true, so every relevant literal is true at least as long as before, and the remaining
  actions' preconditions and the goals are relevant literals. Hence pruning never changes solvability, and
  every plan over the pruned actions is valid for the whole task.

Static predicates (never changed by an action) are evaluated at grounding time and dropped from preconditions.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator
from dataclasses import dataclass

from planner.model import ActionSchema, Atom, LiftedAtom, PlanningTask, ground


@dataclass(frozen=True)
class GroundAction:
    """One applicable-in-principle action: name, arguments, preconditions (fluent atoms only) and effects."""

    name: str
    args: tuple[str, ...]
    pre_pos: tuple[Atom, ...]
    pre_neg: tuple[Atom, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]
    static_pos: tuple[Atom, ...] = ()
    static_neg: tuple[Atom, ...] = ()


@dataclass
class GroundedTask:
    """The result of grounding: reachable atoms, relevant ground actions, goals split by reachability."""

    task: PlanningTask
    reachable: set[Atom]
    actions: list[GroundAction]
    unreachable_goals: tuple[Atom, ...]
    generated: int


class _Index:
    """Reachable atoms by predicate and by (predicate, position, value)."""

    def __init__(self) -> None:
        self.by_pred: dict[str, list[tuple[str, ...]]] = {}
        self.by_pos: dict[tuple[str, int, str], list[tuple[str, ...]]] = {}

    def add(self, atom: Atom) -> None:
        args = atom[1:]
        self.by_pred.setdefault(atom[0], []).append(args)
        for i, value in enumerate(args):
            self.by_pos.setdefault((atom[0], i, value), []).append(args)

    def candidates(
        self, pred: str, terms: tuple[object, ...], binding: list[str | None]
    ) -> list[tuple[str, ...]]:
        best: list[tuple[str, ...]] | None = None
        for i, t in enumerate(terms):
            value = binding[t] if isinstance(t, int) else str(t)
            if value is not None:
                found = self.by_pos.get((pred, i, value), [])
                if best is None or len(found) < len(best):
                    best = found
        return best if best is not None else self.by_pred.get(pred, [])


class _Grounder:
    def __init__(self, task: PlanningTask) -> None:
        self.task = task
        dom = task.domain
        self.static = dom.static_predicates
        self.type_objects: dict[str, frozenset[str]] = {}
        for schema in dom.schemas.values():
            for _, type_name in schema.params:
                if type_name not in self.type_objects:
                    self.type_objects[type_name] = frozenset(task.objects_of(type_name))

    def _bind(
        self,
        schema: ActionSchema,
        terms: tuple[object, ...],
        args: tuple[str, ...],
        binding: list[str | None],
    ) -> list[str | None] | None:
        if len(terms) != len(args):
            return None
        new = list(binding)
        for t, a in zip(terms, args, strict=True):
            if isinstance(t, int):
                bound = new[t]
                if bound is None:
                    if a not in self.type_objects[schema.params[t][1]]:
                        return None
                    new[t] = a
                elif bound != a:
                    return None
            elif t != a:
                return None
        return new

    def join(
        self, schema: ActionSchema, pres: list[LiftedAtom], binding: list[str | None], index: _Index
    ) -> Iterator[tuple[str, ...]]:
        if not pres:
            free = [i for i, v in enumerate(binding) if v is None]
            if not free:
                yield tuple(v for v in binding if v is not None)
                return
            i = free[0]
            for obj in sorted(self.type_objects[schema.params[i][1]]):
                filled = list(binding)
                filled[i] = obj
                yield from self.join(schema, pres, filled, index)
            return

        def bound_count(pre: LiftedAtom) -> int:
            return sum(1 for t in pre[1] if not isinstance(t, int) or binding[t] is not None)

        k = max(range(len(pres)), key=lambda j: (bound_count(pres[j]), pres[j][0] in self.static))
        pred, terms = pres[k]
        rest = pres[:k] + pres[k + 1 :]
        for args in index.candidates(pred, terms, binding):
            new = self._bind(schema, terms, args, binding)
            if new is not None:
                yield from self.join(schema, rest, new, index)

    def run(self, relevance: bool = True) -> GroundedTask:
        task = self.task
        reach: set[Atom] = set(task.facts)
        ordered = sorted(task.facts)  # a fixed order makes grounding, and so plans, independent of hashing
        index = _Index()
        for atom in ordered:
            index.add(atom)
        triggers: dict[str, list[tuple[ActionSchema, int]]] = {}
        schemas = [s for s in task.domain.schemas.values() if not s.durative]
        for schema in schemas:
            for i, (pred, _) in enumerate(schema.pre_pos):
                triggers.setdefault(pred, []).append((schema, i))
        actions: dict[tuple[str, tuple[str, ...]], GroundAction | None] = {}
        queue: deque[Atom] = deque(ordered)

        def emit(schema: ActionSchema, args: tuple[str, ...]) -> None:
            key = (schema.name, args)
            if key in actions:
                return
            pre_neg = ground(schema.pre_neg, args)
            if any(a[0] in self.static and a in task.facts for a in pre_neg):
                actions[key] = None
                return
            add = ground(schema.add, args)
            pre_pos = ground(schema.pre_pos, args)
            act = GroundAction(
                schema.name,
                args,
                tuple(a for a in pre_pos if a[0] not in self.static),
                tuple(a for a in pre_neg if a[0] not in self.static),
                tuple(add),
                tuple(ground(schema.delete, args)),
                tuple(a for a in pre_pos if a[0] in self.static),
                tuple(a for a in pre_neg if a[0] in self.static),
            )
            actions[key] = act
            for atom in add:
                if atom not in reach:
                    reach.add(atom)
                    index.add(atom)
                    queue.append(atom)

        for schema in schemas:
            if not schema.pre_pos:
                for args in self.join(schema, [], [None] * len(schema.params), index):
                    emit(schema, args)
        while queue:
            atom = queue.popleft()
            for schema, i in triggers.get(atom[0], ()):
                pred, terms = schema.pre_pos[i]
                binding = self._bind(schema, terms, atom[1:], [None] * len(schema.params))
                if binding is None:
                    continue
                rest = list(schema.pre_pos[:i] + schema.pre_pos[i + 1 :])
                for args in self.join(schema, rest, binding, index):
                    emit(schema, args)
        generated = [a for a in actions.values() if a is not None]
        unreachable = tuple(g for g in task.goals if g not in reach)
        reachable_goals = [g for g in task.goals if g in reach]
        relevant = relevant_actions(generated, reachable_goals) if relevance else generated
        return GroundedTask(task, reach, relevant, unreachable, len(generated))


def relevant_actions(actions: list[GroundAction], goals: list[Atom]) -> list[GroundAction]:
    """The actions relevant to ``goals`` by backward relevance (see the module docstring), in input order."""
    achievers: dict[tuple[bool, Atom], list[int]] = {}
    for i, act in enumerate(actions):
        for atom in act.add:
            achievers.setdefault((True, atom), []).append(i)
        for atom in act.delete:
            achievers.setdefault((False, atom), []).append(i)
    relevant_literals: set[tuple[bool, Atom]] = {(True, g) for g in goals}
    stack = list(relevant_literals)
    chosen: set[int] = set()
    while stack:
        literal = stack.pop()
        for i in achievers.get(literal, ()):
            if i in chosen:
                continue
            chosen.add(i)
            act = actions[i]
            for lit in [(True, a) for a in act.pre_pos] + [(False, a) for a in act.pre_neg]:
                if lit not in relevant_literals:
                    relevant_literals.add(lit)
                    stack.append(lit)
    return [a for i, a in enumerate(actions) if i in chosen]


def ground_task(task: PlanningTask, *, relevance: bool = True) -> GroundedTask:
    """Ground ``task`` by relaxed reachability, then keep the actions relevant to its reachable goals.

    Args:
        task: the task.
        relevance: apply backward relevance (switch off only to compare pruned with unpruned).

    Durative actions are not grounded here (temporal tasks go to unified-planning engines).
    """
    return _Grounder(task).run(relevance)


@dataclass
class _CacheEntry:
    static: frozenset[Atom]
    reachable: set[Atom]
    actions: list[GroundAction]


class GroundingCache:
    """Reuses a grounding for later tasks over the same objects (the dispatcher's replans).

    A cached grounding of task T serves task T' when T' has the same objects, its static facts are a subset
    of T's, and its changeable initial facts are all relaxed-reachable in T. Then everything relaxed-reachable
    in T' is reachable in T (relaxed exploration is monotone), so T's actions whose static conditions still
    hold in T' include every action T' can use: the result equals grounding T' afresh, up to extra actions
    that no state of T' makes applicable. Doors found closed (static facts removed), objects seen elsewhere
    and failed actions all keep the cache valid; new objects or new doors do not.

    Args:
        size: most groundings kept (least recently stored dropped first).
    """

    def __init__(self, size: int = 8) -> None:
        self.size = size
        self._entries: dict[tuple[int, frozenset[tuple[str, str]]], list[_CacheEntry]] = {}
        self._order: list[tuple[tuple[int, frozenset[tuple[str, str]]], _CacheEntry]] = []
        self.hits = 0
        self.misses = 0

    def ground(self, task: PlanningTask) -> GroundedTask:
        """Like :func:`ground_task`, reusing a cached grounding when it is valid for ``task``."""
        static_preds = task.domain.static_predicates
        static = frozenset(a for a in task.facts if a[0] in static_preds)
        changeable = [a for a in task.facts if a[0] not in static_preds]
        key = (id(task.domain), frozenset(task.objects.items()))
        for entry in self._entries.get(key, ()):
            if static <= entry.static and all(a in entry.reachable for a in changeable):
                self.hits += 1
                actions = [
                    a
                    for a in entry.actions
                    if all(p in static for p in a.static_pos) and not any(n in static for n in a.static_neg)
                ]
                return _finish(task, entry.reachable, actions)
        self.misses += 1
        full = _Grounder(task).run(relevance=False)
        entry = _CacheEntry(static, full.reachable, full.actions)
        self._entries.setdefault(key, []).append(entry)
        self._order.append((key, entry))
        if len(self._order) > self.size:
            old_key, old = self._order.pop(0)
            self._entries[old_key].remove(old)
        return _finish(task, full.reachable, full.actions)


def _finish(task: PlanningTask, reachable: set[Atom], actions: list[GroundAction]) -> GroundedTask:
    unreachable = tuple(g for g in task.goals if g not in reachable)
    reachable_goals = [g for g in task.goals if g in reachable]
    return GroundedTask(
        task, reachable, relevant_actions(actions, reachable_goals), unreachable, len(actions)
    )
