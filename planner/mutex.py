"""Goals that can never hold together: pairwise reachability (h^2) on a grounded STRIPS task.

Relaxed reachability (:mod:`planner.grounding`) proves a single goal unreachable when no sequence of actions,
delete effects ignored, makes it true. It cannot see that two goals each reachable alone exclude each other:
``(has olga book)`` and ``(object_at book lounge)`` in the ERL domain (giving the book takes it out of the
robot's hand for good, and only a robot holding the book can put it in a room). A search asked for both then
has to exhaust the whole state space before it gives up, which on a flat with a few movable items already
takes longer than any planning time limit.

:func:`pair_reachability` computes the h^2 fixpoint (Haslum and Geffner, 2000): the set of atom pairs that
some state reachable from the initial state may contain, over-approximated. A pair outside it is *provably*
never true in one state:

* an action whose preconditions are pairwise reachable makes its add effects reachable, every pair of its
  add effects, and every pair ``(p, e)`` of an add effect ``e`` with an atom ``p`` it neither adds nor deletes
  that is pairwise reachable with all its preconditions (``p`` may have been true before and stays true);
* a negative precondition ``(not p)`` is compiled into a positive atom ``("not", *p)``, true initially when
  ``p`` is not, added by the actions that delete ``p`` and deleted by those that add it (an equivalent task,
  so "never searched again once found" is seen: ``not`` is a PDDL keyword, no predicate has that name).

Running it on the relevance-pruned actions is sound: pruning keeps every plan for the goals valid
(:mod:`planner.grounding`). Cost: one pass is one set intersection per action over the reachable atoms; a
few passes reach the fixpoint. :func:`compatible_goals` keeps the goals in the order given, skipping each
goal that cannot hold together with a goal already kept, and names the goal it conflicts with.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from planner.grounding import GroundAction
from planner.model import Atom


@dataclass
class PairReachability:
    """The atoms and atom pairs that may be true together in some reachable state (h^2 over-approximation).

    Attributes:
        partners: atom -> every atom that may be true with it (an atom is its own partner when reachable).
    """

    partners: dict[Atom, set[Atom]]

    def reachable(self, atom: Atom) -> bool:
        """Whether ``atom`` may ever be true."""
        return atom in self.partners

    def together(self, a: Atom, b: Atom) -> bool:
        """Whether ``a`` and ``b`` may be true in one reachable state (False: provably never)."""
        return b in self.partners.get(a, ())


def pair_reachability(actions: Sequence[GroundAction], init: Iterable[Atom]) -> PairReachability:
    """The h^2 fixpoint of ``actions`` from ``init`` (see the module docstring).

    Args:
        actions: ground actions (relevance-pruned or not).
        init: atoms true in the initial state.
    """
    ops, start = _positive(actions, init)
    partners: dict[Atom, set[Atom]] = {a: set(start) for a in start}
    changed = True
    while changed:
        changed = False
        for act in ops:
            pre = act.pre_pos
            if not all(p in partners for p in pre):
                continue
            if any(q not in partners[p] for i, p in enumerate(pre) for q in pre[i + 1 :]):
                continue
            for e in act.add:
                if e not in partners:
                    partners[e] = {e}
                    changed = True
            for i, e in enumerate(act.add):
                for f in act.add[i + 1 :]:
                    changed |= _join(partners, e, f)
            kept = set.intersection(*(partners[p] for p in pre)) if pre else set(partners)
            kept.difference_update(act.delete)
            kept.difference_update(act.add)
            for e in act.add:
                new = kept - partners[e]
                if new:
                    changed = True
                    partners[e] |= new
                    for p in new:
                        partners[p].add(e)
    return PairReachability(partners)


@dataclass(frozen=True)
class _Op:
    pre_pos: tuple[Atom, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]


def _negated(atom: Atom) -> Atom:
    return ("not", *atom)


def _positive(actions: Sequence[GroundAction], init: Iterable[Atom]) -> tuple[list[_Op], set[Atom]]:
    """The actions and initial state with every negative precondition compiled into a positive atom."""
    negated = {a for act in actions for a in act.pre_neg}
    start = set(init)
    ops = [
        _Op(
            (*act.pre_pos, *(_negated(a) for a in act.pre_neg)),
            (*act.add, *(_negated(a) for a in act.delete if a in negated)),
            (*act.delete, *(_negated(a) for a in act.add if a in negated)),
        )
        for act in actions
    ]
    start.update(_negated(a) for a in negated if a not in start)
    return ops, start


def _join(partners: dict[Atom, set[Atom]], a: Atom, b: Atom) -> bool:
    if b in partners[a]:
        return False
    partners[a].add(b)
    partners[b].add(a)
    return True


def compatible_goals(goals: Sequence[Atom], reach: PairReachability) -> tuple[list[Atom], dict[Atom, Atom]]:
    """Split ``goals`` into those kept and those that cannot hold together with an earlier kept goal.

    Goals are taken in order (the first said wins). Goals not reachable on their own are left to the caller
    (relaxed reachability names them) and kept here.

    Returns:
        ``(kept, conflicts)``: the kept goals in order, and each skipped goal -> the kept goal it excludes.
    """
    kept: list[Atom] = []
    conflicts: dict[Atom, Atom] = {}
    for goal in goals:
        if not reach.reachable(goal):
            kept.append(goal)
            continue
        clash = next((k for k in kept if reach.reachable(k) and not reach.together(goal, k)), None)
        if clash is None:
            kept.append(goal)
        else:
            conflicts[goal] = clash
    return kept, conflicts
