"""In-process heuristic search over a grounded STRIPS task (no subprocess, no files).

Greedy best-first search with the FF heuristic (relaxed plan over h-add best supporters) and helpful actions
(the relaxed plan's first-layer actions are tried in a preferred queue first, as in Fast Downward's
``lazy_greedy``/``eager_greedy`` with preferred operators). It is complete on finite tasks: when the search
space is exhausted the goals are unreachable together. A node limit bounds the effort; reaching it raises
:class:`SearchLimitReached` so that the caller can fall back to Fast Downward.
"""

from __future__ import annotations

import heapq
import itertools
import time
from dataclasses import dataclass

from planner.grounding import GroundAction
from planner.model import Atom

INF = float("inf")


class SearchLimitReached(Exception):
    """The node limit or the deadline was reached before a plan was found or the space was exhausted."""

    def __init__(self, message: str, *, timeout: bool = False) -> None:
        super().__init__(message)
        self.timeout = timeout


@dataclass
class _Op:
    pre: tuple[int, ...]
    neg: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]


class StripsSearch:
    """A search engine for one grounded task (atoms are numbered once; reuse it for several goal sets).

    Args:
        actions: ground actions (already pruned by relevance, or not).
        init: the atoms true in the initial state.
    """

    def __init__(self, actions: list[GroundAction], init: frozenset[Atom]) -> None:
        self.actions = actions
        self.atom_ids: dict[Atom, int] = {}
        for act in actions:
            for atom in (*act.pre_pos, *act.pre_neg, *act.add, *act.delete):
                self._id(atom)
        self.ops = [
            _Op(
                tuple(self.atom_ids[a] for a in act.pre_pos),
                tuple(self.atom_ids[a] for a in act.pre_neg),
                tuple(self.atom_ids[a] for a in act.add),
                tuple(self.atom_ids[a] for a in act.delete),
            )
            for act in actions
        ]
        self.pre_of: dict[int, list[int]] = {}
        for i, op in enumerate(self.ops):
            for p in op.pre:
                self.pre_of.setdefault(p, []).append(i)
        self.no_pre = [i for i, op in enumerate(self.ops) if not op.pre]
        self.init_atoms = init
        self.init = frozenset(self.atom_ids[a] for a in init if a in self.atom_ids)

    def _id(self, atom: Atom) -> int:
        found = self.atom_ids.get(atom)
        if found is None:
            found = len(self.atom_ids)
            self.atom_ids[atom] = found
        return found

    def heuristic(self, state: frozenset[int], goals: tuple[int, ...]) -> tuple[float, list[int]]:
        """FF value of ``state`` and its helpful actions (relaxed-plan actions applicable in ``state``)."""
        cost: dict[int, int] = dict.fromkeys(state, 0)
        supporter: dict[int, int] = {}
        remaining = [len(op.pre) for op in self.ops]
        op_cost = [0] * len(self.ops)
        heap: list[tuple[int, int]] = [(0, a) for a in state]
        heapq.heapify(heap)
        done: set[int] = set()
        for i in self.no_pre:
            for q in self.ops[i].add:
                if q not in cost or cost[q] > 1:
                    cost[q] = 1
                    supporter[q] = i
                    heapq.heappush(heap, (1, q))
        pending_goals = set(goals)
        while heap and pending_goals:
            c, p = heapq.heappop(heap)
            if p in done or cost.get(p, INF) < c:
                continue
            done.add(p)
            pending_goals.discard(p)
            for i in self.pre_of.get(p, ()):
                op_cost[i] += c
                remaining[i] -= 1
                if remaining[i] == 0:
                    new = op_cost[i] + 1
                    for q in self.ops[i].add:
                        if new < cost.get(q, INF):
                            cost[q] = new
                            supporter[q] = i
                            heapq.heappush(heap, (new, q))
        if pending_goals:
            return INF, []
        relaxed: set[int] = set()
        stack = [g for g in goals if g not in state]
        seen: set[int] = set()
        while stack:
            p = stack.pop()
            if p in seen or p in state:
                continue
            seen.add(p)
            i = supporter[p]
            if i not in relaxed:
                relaxed.add(i)
                stack.extend(self.ops[i].pre)
        helpful = [i for i in relaxed if all(p in state for p in self.ops[i].pre)]
        return float(len(relaxed)), helpful

    def _applicable(self, i: int, state: frozenset[int]) -> bool:
        op = self.ops[i]
        return all(p in state for p in op.pre) and not any(n in state for n in op.neg)

    def solve(
        self, goals: list[Atom], node_limit: int = 200_000, deadline: float | None = None
    ) -> list[GroundAction] | None:
        """A plan reaching every atom in ``goals`` from the initial state, or ``None`` when none exists.

        Args:
            goals: positive goal atoms.
            node_limit: most states to expand.
            deadline: ``time.perf_counter()`` value (wall clock) after which the search gives up.

        Raises:
            SearchLimitReached: the node limit or the deadline was reached (``.timeout`` tells which).
        """
        if any(g not in self.atom_ids and g not in self.init_atoms for g in goals):
            return None
        goal_ids = tuple(self.atom_ids[g] for g in goals if g in self.atom_ids)
        start = self.init
        if all(g in start for g in goal_ids):
            return []
        h0, helpful0 = self.heuristic(start, goal_ids)
        if h0 == INF:
            return None
        parents: dict[frozenset[int], tuple[frozenset[int] | None, int]] = {start: (None, -1)}
        counter = itertools.count()
        # Two open lists as in FD's preferred-operator search: helpful successors first, then all.
        preferred: list[tuple[float, int, frozenset[int]]] = []
        regular: list[tuple[float, int, frozenset[int]]] = []
        helpful_of: dict[frozenset[int], list[int]] = {start: helpful0}
        heapq.heappush(regular, (h0, next(counter), start))
        heapq.heappush(preferred, (h0, next(counter), start))
        closed: set[frozenset[int]] = set()
        expanded = 0
        use_preferred = True
        all_ops = range(len(self.ops))
        while preferred or regular:
            queue = preferred if (use_preferred and preferred) or not regular else regular
            use_preferred = not use_preferred
            _, _, state = heapq.heappop(queue)
            if state in closed:
                continue
            closed.add(state)
            expanded += 1
            if expanded > node_limit:
                raise SearchLimitReached(f"node limit {node_limit} reached")
            if deadline is not None and expanded % 64 == 0 and time.perf_counter() > deadline:
                raise SearchLimitReached("time limit reached", timeout=True)
            helpful = set(helpful_of.pop(state, ()))
            for i in all_ops:
                if not self._applicable(i, state):
                    continue
                op = self.ops[i]
                succ = (state - set(op.delete)) | set(op.add)
                if succ in parents:
                    continue
                parents[succ] = (state, i)
                if all(g in succ for g in goal_ids):
                    return self._extract(parents, succ)
                h, succ_helpful = self.heuristic(succ, goal_ids)
                if h == INF:
                    continue
                helpful_of[succ] = succ_helpful
                entry = (h, next(counter), succ)
                heapq.heappush(regular, entry)
                if i in helpful:
                    heapq.heappush(preferred, entry)
        return None

    def _extract(
        self, parents: dict[frozenset[int], tuple[frozenset[int] | None, int]], state: frozenset[int]
    ) -> list[GroundAction]:
        steps: list[GroundAction] = []
        current: frozenset[int] | None = state
        while current is not None:
            parent, i = parents[current]
            if parent is None:
                break
            steps.append(self.actions[i])
            current = parent
        steps.reverse()
        return steps
