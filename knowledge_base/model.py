"""Value types of the knowledge base: facts, provenance, changes and states.

Everything here is a plain immutable value (``NamedTuple`` for speed: hashing and comparing a fact costs one
tuple operation) except :class:`State`, a mutable container that the knowledge base, the journal replay and
``state_at`` share. Times are seconds on the knowledge base's clock: wall time (``time.time``) by default,
simulated seconds once the closed loop calls ``kb.set_clock(sim.time)``.

A :class:`Change` is one event of the append-only history. :func:`apply_change` applies it to a
:class:`State` without validation (validation happened when the change was made); replaying every change of a
journal in order rebuilds the live state exactly.
"""

from __future__ import annotations

import enum
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from core.errors import KnowledgeBaseError

__all__ = [
    "BeliefStatus",
    "Change",
    "ChangeKind",
    "Fact",
    "Provenance",
    "State",
    "apply_change",
]

_ATOM_RE = re.compile(r"^\(\s*([^\s()]+)((?:\s+[^\s()]+)*)\s*\)$")


class Fact(NamedTuple):
    """A ground atom such as ``(object_at glasses kitchen)``.

    Attributes:
        predicate: PDDL predicate (or, for numeric state, function) name.
        args: Instance names, in the predicate's parameter order.
    """

    predicate: str
    args: tuple[str, ...]

    def __str__(self) -> str:
        if not self.args:
            return f"({self.predicate})"
        return f"({self.predicate} {' '.join(self.args)})"

    @classmethod
    def parse(cls, text: str) -> Fact:
        """Parse ``"(pred a b)"`` (surrounding whitespace allowed, names lower-cased as PDDL does).

        Raises:
            KnowledgeBaseError: the text is not one parenthesised ground atom.
        """
        match = _ATOM_RE.match(text.strip())
        if match is None or match.group(1).startswith("?"):
            raise KnowledgeBaseError(
                f"cannot parse fact {text!r}: expected a ground atom like '(pred arg1 arg2)'"
            )
        args = tuple(a.lower() for a in match.group(2).split())
        if any(a.startswith("?") for a in args):
            raise KnowledgeBaseError(
                f"cannot parse fact {text!r}: variables ('?x') are not allowed in a fact"
            )
        return cls(match.group(1).lower(), args)


class BeliefStatus(enum.StrEnum):
    """Why a fact is believed: given (problem file, user), observed (perception), assumed (prior), effect."""

    GIVEN = "given"
    OBSERVED = "observed"
    ASSUMED = "assumed"
    EFFECT = "effect"


class Provenance(NamedTuple):
    """Who made a belief, when, and on what grounds.

    Attributes:
        source: Component name that wrote it ("user", "problem", "kp.object_location", "dispatcher", ...).
        since: Clock time (seconds) of the write that made it hold.
        status: Belief status.
        confidence: 0..1.
        support: Ids of the knowledge units (LLKU/CKU) that support it.
    """

    source: str
    since: float
    status: BeliefStatus
    confidence: float
    support: tuple[str, ...]


class ChangeKind(enum.StrEnum):
    """The kinds of events in the history journal."""

    ADD_INSTANCE = "add_instance"
    REMOVE_INSTANCE = "remove_instance"
    ADD_FACT = "add_fact"
    REMOVE_FACT = "remove_fact"
    ADD_GOAL = "add_goal"
    REMOVE_GOAL = "remove_goal"
    SET_FUNCTION = "set_function"
    SET_ANCHOR = "set_anchor"


class Change(NamedTuple):
    """One event of the history: what changed, when and on whose authority.

    Attributes:
        seq: Position in the journal (1-based, strictly increasing).
        time: Clock time (seconds) of the write.
        kind: What happened.
        name: Predicate (facts, goals), function, type (instances: ``args == (instance,)``) or anchor symbol.
        args: Fact/goal/function arguments; ``(instance,)`` for instances; ``(symbol,)`` for anchors.
        value: Function value (float) or anchor geometry (JSON-able dict); None otherwise.
        provenance: Provenance of the write (for ``ADD_FACT`` it becomes the fact's provenance).
    """

    seq: int
    time: float
    kind: ChangeKind
    name: str
    args: tuple[str, ...]
    value: Any
    provenance: Provenance

    @property
    def fact(self) -> Fact | None:
        """The fact or goal this change is about, or None for instance, function and anchor changes."""
        if self.kind in _FACT_KINDS:
            return Fact(self.name, self.args)
        return None

    def describe(self) -> str:
        """One human-readable line, e.g. ``"t=12.50 +fact (robot_at r2d2 kitchen) by kp.pose [observed]"``."""
        prov = self.provenance
        if self.kind in _FACT_KINDS:
            what = str(Fact(self.name, self.args))
        elif self.kind in (ChangeKind.ADD_INSTANCE, ChangeKind.REMOVE_INSTANCE):
            what = f"{self.args[0]} - {self.name}"
        elif self.kind is ChangeKind.SET_FUNCTION:
            what = f"(= {Fact(self.name, self.args)} {self.value})"
        else:
            what = f"{self.name} -> {self.value}"
        return f"t={self.time:.2f} {self.kind.value} {what} by {prov.source} [{prov.status.value}]"


_FACT_KINDS = frozenset(
    {ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT, ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL}
)


@dataclass
class State:
    """A complete knowledge-base state: the live one, a snapshot, or one rebuilt by ``state_at``.

    Attributes:
        instances: Instance name -> PDDL type (domain constants included).
        facts: Facts that hold -> their provenance (insertion-ordered).
        goals: Goal atoms -> provenance.
        functions: Numeric fluent (as a Fact of function name and args) -> value.
        anchors: Symbol -> (geometry, provenance); geometry is a JSON-able dict in the world frame.
        seq: Sequence number of the last change included (0: nothing yet).
        time: Clock time of that change (``-inf`` when empty).
    """

    instances: dict[str, str] = field(default_factory=dict)
    facts: dict[Fact, Provenance] = field(default_factory=dict)
    goals: dict[Fact, Provenance] = field(default_factory=dict)
    functions: dict[Fact, float] = field(default_factory=dict)
    anchors: dict[str, tuple[dict[str, Any], Provenance]] = field(default_factory=dict)
    seq: int = 0
    time: float = float("-inf")

    def copy(self) -> State:
        """An independent copy (values are immutable, so shallow dict copies suffice)."""
        return State(
            dict(self.instances),
            dict(self.facts),
            dict(self.goals),
            dict(self.functions),
            dict(self.anchors),
            self.seq,
            self.time,
        )

    def holds(self, fact: Fact) -> bool:
        """Whether ``fact`` holds in this state."""
        return fact in self.facts

    def facts_of(self, predicate: str) -> Iterator[Fact]:
        """The facts of one predicate."""
        return (f for f in self.facts if f.predicate == predicate)

    def same_content(self, other: State) -> bool:
        """Whether both states hold the same instances, facts (with provenance), goals, functions, anchors."""
        return (
            self.instances == other.instances
            and self.facts == other.facts
            and self.goals == other.goals
            and self.functions == other.functions
            and self.anchors == other.anchors
        )


def apply_change(state: State, change: Change) -> None:
    """Apply one already-validated change to ``state`` (journal replay; no checks, no notifications)."""
    kind = change.kind
    if kind is ChangeKind.ADD_FACT:
        state.facts[Fact(change.name, change.args)] = change.provenance
    elif kind is ChangeKind.REMOVE_FACT:
        state.facts.pop(Fact(change.name, change.args), None)
    elif kind is ChangeKind.ADD_INSTANCE:
        state.instances[change.args[0]] = change.name
    elif kind is ChangeKind.REMOVE_INSTANCE:
        state.instances.pop(change.args[0], None)
        state.anchors.pop(change.args[0], None)
    elif kind is ChangeKind.ADD_GOAL:
        state.goals[Fact(change.name, change.args)] = change.provenance
    elif kind is ChangeKind.REMOVE_GOAL:
        state.goals.pop(Fact(change.name, change.args), None)
    elif kind is ChangeKind.SET_FUNCTION:
        state.functions[Fact(change.name, change.args)] = float(change.value)
    elif kind is ChangeKind.SET_ANCHOR:
        state.anchors[change.name] = (change.value, change.provenance)
    state.seq = change.seq
    state.time = change.time
