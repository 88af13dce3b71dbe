"""The live state of a knowledge base with its derived indexes, and undoable application of changes.

:class:`IndexedState` is the part of :class:`~knowledge_base.kb.KnowledgeBase` that checks and mutates
state. Next to the :class:`~knowledge_base.model.State` it keeps the facts of each predicate (pattern
queries), the fact holding each single-valued key (retraction in one look-up) and how many facts, goals and
function values use each instance (``remove_instance`` refuses an instance in use). ``_check`` validates an
atom against the domain's precomputed type tables; ``_explain`` turns a failed check into the error
message. ``_apply`` applies an already-validated change and returns what ``_revert`` needs to undo it;
batches and failed commits roll back with it.
"""

from __future__ import annotations

import re
from typing import Any, NoReturn

from core.errors import KnowledgeBaseError
from knowledge_base.domain import DomainModel
from knowledge_base.model import Change, ChangeKind, Fact, Provenance, State

__all__ = ["IndexedState", "name_problem"]

#: longest instance name accepted
MAX_NAME_LENGTH = 128
_NAME_RE = re.compile(r"[a-z][a-z0-9_-]*")
#: words a PDDL reader takes for syntax wherever they appear: never instance names
RESERVED_NAMES = frozenset(
    {"and", "or", "not", "imply", "exists", "forall", "when", "either", "object", "number", "define"}
)


def name_problem(name: Any) -> str:
    """Why ``name`` cannot be an instance name ("" when it can).

    Instance names are PDDL identifiers as every reader takes them: lower-case ASCII letters, digits, ``-``
    and ``_``, starting with a letter, at most :data:`MAX_NAME_LENGTH` characters, and not one of
    :data:`RESERVED_NAMES`. So a name comes back unchanged after a journal reopen or a PDDL export and
    re-parse (control characters, ``\\r``, non-breaking spaces and upper case would not).
    """
    if not isinstance(name, str):
        return f"a name must be a string, not {type(name).__name__}"
    if not name:
        return "empty"
    if len(name) > MAX_NAME_LENGTH:
        return f"longer than {MAX_NAME_LENGTH} characters"
    if not _NAME_RE.fullmatch(name):
        return "not a PDDL identifier (lower-case letters, digits, '-' and '_', starting with a letter)"
    if name in RESERVED_NAMES:
        return "a PDDL keyword"
    return ""


_ADD_FACT, _REMOVE_FACT = ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT
_ADD_GOAL, _REMOVE_GOAL = ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL
_ADD_INSTANCE, _REMOVE_INSTANCE = ChangeKind.ADD_INSTANCE, ChangeKind.REMOVE_INSTANCE
_SET_FUNCTION, _SET_ANCHOR = ChangeKind.SET_FUNCTION, ChangeKind.SET_ANCHOR


class IndexedState:
    """Live state plus indexes; a base class of the knowledge base (not used on its own).

    Subclasses set ``_state`` and ``_single`` (predicate -> key positions) and call :meth:`_rebuild_indexes`.
    """

    domain: DomainModel
    _state: State
    _single: dict[str, tuple[int, ...]]
    _by_pred: dict[str, dict[Fact, None]]
    _sv_index: dict[tuple[str, tuple[str, ...]], Fact]
    _uses: dict[str, int]

    def _rebuild_indexes(self) -> None:
        self._by_pred: dict[str, dict[Fact, None]] = {}
        self._sv_index: dict[tuple[str, tuple[str, ...]], Fact] = {}
        self._uses: dict[str, int] = {}
        facts = dict(self._state.facts)
        self._state.facts.clear()
        for fact, prov in facts.items():
            self._put_fact(fact, prov)
        for fact in list(self._state.goals) + list(self._state.functions):
            self._use(fact.args, 1)

    def _use(self, args: tuple[str, ...], delta: int) -> None:
        uses = self._uses
        for a in args:
            uses[a] = uses.get(a, 0) + delta

    def _put_fact(self, fact: Fact, prov: Provenance) -> Provenance | None:
        facts = self._state.facts
        old = facts.get(fact)
        facts[fact] = prov
        if old is None:
            self._by_pred.setdefault(fact.predicate, {})[fact] = None
            positions = self._single.get(fact.predicate)
            if positions is not None:
                self._sv_index[(fact.predicate, tuple([fact.args[i] for i in positions]))] = fact
            self._use(fact.args, 1)
        return old

    def _drop_fact(self, fact: Fact) -> Provenance | None:
        old = self._state.facts.pop(fact, None)
        if old is not None:
            del self._by_pred[fact.predicate][fact]
            positions = self._single.get(fact.predicate)
            if positions is not None:
                self._sv_index.pop((fact.predicate, tuple([fact.args[i] for i in positions])), None)
            self._use(fact.args, -1)
        return old

    def _apply(self, c: Change) -> Any:
        """Apply a change to the live state; return what :meth:`_revert` needs to undo it."""
        state = self._state
        kind = c.kind
        old: Any = None
        if kind is _ADD_FACT:
            old = self._put_fact(Fact(c.name, c.args), c.provenance)
        elif kind is _REMOVE_FACT:
            old = self._drop_fact(Fact(c.name, c.args))
        elif kind is _ADD_INSTANCE:
            state.instances[c.args[0]] = c.name
        elif kind is _REMOVE_INSTANCE:
            old = (state.instances.pop(c.args[0]), state.anchors.pop(c.args[0], None))
        elif kind is _ADD_GOAL:
            state.goals[Fact(c.name, c.args)] = c.provenance
            self._use(c.args, 1)
        elif kind is _REMOVE_GOAL:
            old = state.goals.pop(Fact(c.name, c.args))
            self._use(c.args, -1)
        elif kind is _SET_FUNCTION:
            key = Fact(c.name, c.args)
            old = state.functions.get(key)
            state.functions[key] = c.value
            if old is None:
                self._use(c.args, 1)
        elif kind is _SET_ANCHOR:
            old = state.anchors.get(c.name)
            state.anchors[c.name] = (c.value, c.provenance)
        state.seq = c.seq
        state.time = c.time
        return old

    def _revert(self, c: Change, old: Any) -> None:
        state = self._state
        kind = c.kind
        if kind is _ADD_FACT:
            if old is None:
                self._drop_fact(Fact(c.name, c.args))
            else:
                state.facts[Fact(c.name, c.args)] = old
        elif kind is _REMOVE_FACT:
            self._put_fact(Fact(c.name, c.args), old)
        elif kind is _ADD_INSTANCE:
            del state.instances[c.args[0]]
        elif kind is _REMOVE_INSTANCE:
            state.instances[c.args[0]] = old[0]
            if old[1] is not None:
                state.anchors[c.args[0]] = old[1]
        elif kind is _ADD_GOAL:
            del state.goals[Fact(c.name, c.args)]
            self._use(c.args, -1)
        elif kind is _REMOVE_GOAL:
            state.goals[Fact(c.name, c.args)] = old
            self._use(c.args, 1)
        elif kind is _SET_FUNCTION:
            key = Fact(c.name, c.args)
            if old is None:
                del state.functions[key]
                self._use(c.args, -1)
            else:
                state.functions[key] = old
        elif kind is _SET_ANCHOR:
            if old is None:
                del state.anchors[c.name]
            else:
                state.anchors[c.name] = old

    def _user_of(self, name: str) -> str:
        for kind, items in (
            ("fact", self._state.facts),
            ("goal", self._state.goals),
            ("function", self._state.functions),
        ):
            for fact in items:
                if name in fact.args:
                    return f"{kind} {fact}"
        return "another record"  # pragma: no cover - use counts and contents agree

    def _check(
        self, name: str, args: tuple[str, ...], table: dict[str, tuple[frozenset[str], ...]], what: str
    ) -> None:
        try:
            allowed = table.get(name)
            if allowed is None or len(allowed) != len(args):
                self._explain(name, args, table, what)
            instances = self._state.instances
            for arg, types in zip(args, allowed, strict=True):
                if instances.get(arg) not in types:
                    self._explain(name, args, table, what)
        except TypeError:  # a list or another unhashable where a name belongs
            self._not_names(name, args)

    def _not_names(self, name: Any, args: tuple[Any, ...]) -> NoReturn:
        bad = next((a for a in (name, *args) if not isinstance(a, str)), name)
        raise KnowledgeBaseError(
            f"({name!r} {' '.join(repr(a) for a in args)}): names must be strings, got {type(bad).__name__} "
            f"{bad!r}"
        )

    def _explain(self, name: str, args: tuple[str, ...], table: dict[str, Any], what: str) -> NoReturn:
        atom = str(Fact(name, tuple(str(a) for a in args)))
        sig = self.domain.signature(name)
        if name not in table or sig is None:
            raise KnowledgeBaseError(f"{atom}: unknown {what} {name!r} in domain {self.domain.name}")
        if len(sig) != len(args):
            raise KnowledgeBaseError(f"{atom}: {name} takes {len(sig)} arguments, got {len(args)}")
        for (param, type_name), arg in zip(sig, args, strict=True):
            actual = self._state.instances.get(arg) if isinstance(arg, str) else None
            if actual is None:
                raise KnowledgeBaseError(f"{atom}: unknown instance {arg!r}")
            if not self.domain.is_subtype(actual, type_name):
                raise KnowledgeBaseError(
                    f"{atom}: argument ?{param} must be of type {type_name}, {arg!r} is a {actual}"
                )
        raise KnowledgeBaseError(f"{atom}: invalid")  # pragma: no cover - the checks above are exhaustive
