"""The read side of the knowledge base: queries, snapshots, history and export.

:class:`KnowledgeQueries` is a base class of :class:`~knowledge_base.kb.KnowledgeBase` (not used on its own):
it reads the live state and indexes kept by :class:`~knowledge_base.store.IndexedState` and the journal.
Queries never change anything; pattern and single-valued look-ups use the per-predicate indexes.
"""

from __future__ import annotations

import json
from typing import Any

from core.errors import KnowledgeBaseError
from knowledge_base.journal import Journal
from knowledge_base.model import Change, Fact, Provenance, State
from knowledge_base.store import IndexedState

__all__ = ["KnowledgeQueries"]

_WILDCARDS = (None, "?")


class KnowledgeQueries(IndexedState):
    """Queries over the live state (see :class:`~knowledge_base.kb.KnowledgeBase` for the lifecycle)."""

    _journal: Journal
    _seq: int
    _depth: int
    problem_name: str

    def instances(self, type: str | None = None) -> list[str]:
        """Instance names, optionally of one type including its subtypes (constants included).

        Raises:
            KnowledgeBaseError: unknown type.
        """
        if type is None:
            return list(self._state.instances)
        if not self.domain.is_type(type):
            raise KnowledgeBaseError(f"instances: unknown type {type!r}")
        allowed = self.domain.subtypes(type)
        return [n for n, t in self._state.instances.items() if t in allowed]

    def type_of(self, name: str) -> str | None:
        """The type of an instance, or None if there is no such instance."""
        return self._state.instances.get(name)

    def facts(self, predicate: str | None = None, *pattern: str | None) -> list[Fact]:
        """Facts that hold, optionally of one predicate and matching ``pattern`` (``"?"`` or None: any).

        A pattern shorter than the arity leaves the remaining arguments free.

        Raises:
            KnowledgeBaseError: unknown predicate or a pattern longer than its arity.
        """
        if predicate is None:
            return list(self._state.facts)
        sig = self.domain.predicates.get(predicate)
        if sig is None:
            raise KnowledgeBaseError(f"facts: unknown predicate {predicate!r}")
        if len(pattern) > len(sig):
            raise KnowledgeBaseError(
                f"facts: pattern for {predicate} has {len(pattern)} items, arity {len(sig)}"
            )
        found = self._by_pred.get(predicate)
        if not found:
            return []
        fixed = [(i, v) for i, v in enumerate(pattern) if v not in _WILDCARDS and not str(v).startswith("?")]
        if not fixed:
            return list(found)
        positions = self._single.get(predicate)
        if positions is not None and len(fixed) == len(positions) and all(i in positions for i, _ in fixed):
            # the pattern fixes exactly the key of a single-valued predicate: one index look-up
            key = tuple([v for _, v in sorted(fixed, key=lambda iv: positions.index(iv[0]))])
            hit = self._sv_index.get((predicate, key))
            return [] if hit is None else [hit]
        return [f for f in found if all(f.args[i] == v for i, v in fixed)]

    def holds(self, predicate: str | Fact, *args: str) -> bool:
        """Whether a fact holds: ``holds("robot_at", "r2d2", "kitchen")`` or ``holds(fact)``."""
        if isinstance(predicate, Fact):
            return predicate in self._state.facts
        return Fact(predicate, args) in self._state.facts

    def goals(self) -> list[Fact]:
        """The goal atoms, in the order they were added."""
        return list(self._state.goals)

    def goals_hold(self) -> bool:
        """Whether every goal holds now (True when there are no goals)."""
        facts = self._state.facts
        return all(g in facts for g in self._state.goals)

    def function(self, name: str, *args: str) -> float | None:
        """A numeric function's value, or None if it was never set."""
        return self._state.functions.get(Fact(name, args))

    def why(self, fact: Fact | str) -> Provenance | None:
        """Why a fact is believed (source, since, status, confidence, support); None if it does not hold."""
        if isinstance(fact, str):
            fact = Fact.parse(fact)
        return self._state.facts.get(fact)

    def anchor(self, symbol: str) -> dict[str, Any] | None:
        """The geometry anchored to ``symbol`` (a copy), or None."""
        entry = self._state.anchors.get(symbol)
        return None if entry is None else json.loads(json.dumps(entry[0]))

    def snapshot(self) -> State:
        """A copy of the current state."""
        return self._state.copy()

    def state_at(self, t: float) -> State:
        """The committed state at clock time ``t`` (seconds): the state after the last change stamped <= t."""
        seq = self._journal.last_seq_at(t)
        if seq == self._seq and not self._depth:
            return self._state.copy()  # now (or later): the live state, no replay
        return self._journal.state_at_seq(seq)

    def changes(self, after: int = 0) -> list[Change]:
        """Committed changes with sequence number greater than ``after``."""
        return self._journal.changes(after)

    def to_up_problem(self) -> Any:
        """The current state as a unified-planning ``Problem`` (see :mod:`knowledge_base.export`)."""
        from knowledge_base.export import state_to_up

        return state_to_up(self.domain, self._state, self.problem_name)

    def to_pddl_problem(self) -> str:
        """The current state as PDDL problem text for this domain (see :mod:`knowledge_base.export`)."""
        from knowledge_base.export import state_to_pddl

        return state_to_pddl(self.domain, self._state, self.problem_name)
