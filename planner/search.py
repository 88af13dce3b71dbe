"""In-process heuristic search over a grounded STRIPS task (no subprocess, no files).

Lazy greedy best-first search with the FF heuristic (relaxed plan over first achievers) and helpful actions
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
        self.pre_count = [len(op.pre) for op in self.ops]
        # successor generation: candidates are the ops whose first precondition holds
        self.by_first: dict[int, list[int]] = {}
        for i, op in enumerate(self.ops):
            if op.pre:
                self.by_first.setdefault(op.pre[0], []).append(i)
        self.init_atoms = init
        self.init = frozenset(self.atom_ids[a] for a in init if a in self.atom_ids)

    def _id(self, atom: Atom) -> int:
        found = self.atom_ids.get(atom)
        if found is None:
            found = len(self.atom_ids)
            self.atom_ids[atom] = found
        return found

    def heuristic(self, state: frozenset[int], goals: tuple[int, ...]) -> tuple[float, list[int]]:
        """FF value of ``state`` and its helpful actions (relaxed-plan actions applicable in ``state``).

        The relaxed planning graph is built layer by layer (unit costs, each atom reached once, stopping as
        soon as every goal is reached); the relaxed plan is extracted backwards from the first achievers.
        """
        remaining = self.pre_count[:]
        achiever: dict[int, int] = {}
        reached = set(state)
        frontier = list(state)
        pending = sum(1 for g in goals if g not in reached)
        ops, pre_of = self.ops, self.pre_of
        for i in self.no_pre:
            for q in ops[i].add:
                if q not in reached:
                    reached.add(q)
                    achiever[q] = i
                    frontier.append(q)
                    if q in goals:
                        pending -= 1
        while pending > 0:
            if not frontier:
                return INF, []
            new: list[int] = []
            for p in frontier:
                for i in pre_of.get(p, ()):
                    remaining[i] -= 1
                    if remaining[i] == 0:
                        for q in ops[i].add:
                            if q not in reached:
                                reached.add(q)
                                achiever[q] = i
                                new.append(q)
            for q in new:
                if q in goals:
                    pending -= 1
            frontier = new
        relaxed: set[int] = set()
        stack = [g for g in goals if g not in state]
        seen: set[int] = set()
        while stack:
            p = stack.pop()
            if p in seen or p in state:
                continue
            seen.add(p)
            i = achiever[p]
            if i not in relaxed:
                relaxed.add(i)
                stack.extend(ops[i].pre)
        helpful = [i for i in relaxed if all(p in state for p in ops[i].pre)]
        return float(len(relaxed)), helpful

    def applicable(self, state: frozenset[int]) -> list[int]:
        """Indices of the ops applicable in ``state``."""
        ops = self.ops
        out = [i for i in self.no_pre if not any(n in state for n in ops[i].neg)]
        for atom in state:
            for i in self.by_first.get(atom, ()):
                op = ops[i]
                if all(p in state for p in op.pre) and not any(n in state for n in op.neg):
                    out.append(i)
        return out

    def solve(
        self,
        goals: list[Atom],
        node_limit: int = 200_000,
        deadline: float | None = None,
        start: frozenset[int] | None = None,
    ) -> list[GroundAction] | None:
        """A plan reaching every atom in ``goals`` from ``start`` (default: the initial state), or ``None``.

        Lazy greedy best-first search as Fast Downward's ``lazy_greedy([ff], preferred=[ff])``: successors
        are queued with their parent's value and evaluated when taken out; successors by helpful actions
        go to a preferred queue that is served first after each improvement (boost) and alternately otherwise.

        Args:
            goals: positive goal atoms.
            node_limit: most states to evaluate.
            deadline: ``time.perf_counter()`` value (wall clock) after which the search gives up.

        Raises:
            SearchLimitReached: the node limit or the deadline was reached (``.timeout`` tells which).
        """
        if any(g not in self.atom_ids and g not in self.init_atoms for g in goals):
            return None
        goal_ids = tuple(self.atom_ids[g] for g in goals if g in self.atom_ids)
        start = self.init if start is None else start
        parents: dict[frozenset[int], tuple[frozenset[int] | None, int]] = {start: (None, -1)}
        counter = itertools.count()
        preferred: list[tuple[float, int, frozenset[int], int]] = []
        regular: list[tuple[float, int, frozenset[int], int]] = []
        heapq.heappush(regular, (0.0, next(counter), start, -1))
        best = INF
        boost = 0
        turn = 0
        evaluated = 0
        while preferred or regular:
            if preferred and (boost > 0 or turn % 2 == 0 or not regular):
                _, _, parent, op_index = heapq.heappop(preferred)
                boost = max(boost - 1, 0)
            else:
                _, _, parent, op_index = heapq.heappop(regular)
            turn += 1
            if op_index < 0:
                state = parent
            else:
                op = self.ops[op_index]
                state = (parent - set(op.delete)) | set(op.add)
                if state in parents:
                    continue
                parents[state] = (parent, op_index)
            if all(g in state for g in goal_ids):
                return self._extract(parents, state)
            evaluated += 1
            if evaluated > node_limit:
                raise SearchLimitReached(f"node limit {node_limit} reached")
            if deadline is not None and evaluated % 32 == 0 and time.perf_counter() > deadline:
                raise SearchLimitReached("time limit reached", timeout=True)
            h, helpful = self.heuristic(state, goal_ids)
            if h == INF:
                continue
            if h < best:
                best = h
                boost += 1000
            helpful_set = set(helpful)
            for i in self.applicable(state):
                entry = (h, next(counter), state, i)
                if i in helpful_set:
                    heapq.heappush(preferred, entry)
                else:
                    heapq.heappush(regular, entry)
        return None

    def solve_serially(
        self, goals: list[Atom], node_limit: int, deadline: float | None = None
    ) -> list[GroundAction] | None:
        """Reach the goals one more at a time (FF's goal agenda): plan for the first goal, then from the
        state reached for the first two, and so on. Returns the concatenated plan, or ``None`` when a stage
        fails (the caller then searches for all goals at once). Raises SearchLimitReached only on timeout.
        """
        state = self.init
        plan: list[GroundAction] = []
        for i in range(1, len(goals) + 1):
            try:
                part = self.solve(goals[:i], node_limit, deadline, start=state)
            except SearchLimitReached as exc:
                if exc.timeout:
                    raise
                return None
            if part is None:
                return None
            state = self.apply_all(state, part)
            plan += part
        return plan

    def apply_all(self, state: frozenset[int], actions: list[GroundAction]) -> frozenset[int]:
        """The state reached by applying ``actions`` (assumed applicable) from ``state``."""
        ids = self.atom_ids
        current = set(state)
        for action in actions:
            current.difference_update(ids[a] for a in action.delete)
            current.update(ids[a] for a in action.add)
        return frozenset(current)

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
