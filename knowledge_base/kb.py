"""The knowledge base: the robot's symbolic world (instances, facts, goals, functions, anchors), its history.

Lifecycle: build it with :meth:`KnowledgeBase.from_pddl` (domain, optional problem, optional journal path) or
reopen a journal with :meth:`KnowledgeBase.from_journal`; write with the paper's operations
(``add_instance``, ``add_fact``, ``remove_fact``, ``add_goal``, ...), read with the queries, and
``close()`` it when done. It is single-threaded: one thread writes and reads; other processes read the
journal file.

Every write is validated against the domain before anything changes (unknown predicate, function or type,
wrong arity, unknown instance, argument of the wrong type, removing an instance still in use, bad
provenance). A refused write raises :class:`~core.errors.KnowledgeBaseError` naming what is wrong and leaves
the knowledge base exactly as it was; inside :meth:`KnowledgeBase.batch` a refused write changes nothing and
an exception escaping the batch undoes the whole batch.

Every accepted write becomes one or more :class:`~knowledge_base.model.Change` events: appended to the
journal (one transaction per write, or per batch), then delivered to subscribers. Times come from the clock:
``time.time`` by default, simulated seconds after ``set_clock(sim.time)``.
"""

from __future__ import annotations

import json
import logging
import math
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from core.errors import JournalError, KnowledgeBaseError
from knowledge_base.domain import DomainModel
from knowledge_base.journal import Journal, SqliteJournal
from knowledge_base.model import BeliefStatus, Change, ChangeKind, Fact, Provenance, State
from knowledge_base.queries import KnowledgeQueries
from knowledge_base.store import name_problem

__all__ = ["KnowledgeBase"]

log = logging.getLogger(__name__)

Clock = Callable[[], float]
Subscriber = Callable[[Change], None]

_STATUSES: dict[Any, BeliefStatus] = {s.value: s for s in BeliefStatus} | {s: s for s in BeliefStatus}
_ADD_FACT, _REMOVE_FACT = ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT
_ADD_GOAL, _REMOVE_GOAL = ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL
_ADD_INSTANCE, _REMOVE_INSTANCE = ChangeKind.ADD_INSTANCE, ChangeKind.REMOVE_INSTANCE
_SET_FUNCTION, _SET_ANCHOR = ChangeKind.SET_FUNCTION, ChangeKind.SET_ANCHOR


class KnowledgeBase(KnowledgeQueries):
    """The PDDL model of the world as the robot believes it, with provenance and history.

    Args:
        domain: The domain every write is checked against.
        journal: Where the history goes; an in-memory journal when None.
        clock: Seconds (wall or simulated) stamped on writes without ``at``; ``time.time`` when None.
        read_only: Refuse writes (a viewer of a journal another process writes; see :meth:`refresh`).

    Use :meth:`from_pddl` or :meth:`from_journal` rather than this constructor.
    """

    def __init__(
        self,
        domain: DomainModel,
        *,
        journal: Journal | None = None,
        clock: Clock | None = None,
        read_only: bool = False,
    ) -> None:
        self.domain = domain
        self.read_only = read_only
        self._clock: Clock = clock or time.time
        base = State(instances=dict(domain.constants))
        self._journal = journal if journal is not None else Journal(base)
        #: Name used when exporting the state as a PDDL problem (the loaded problem's, kept in the journal).
        self.problem_name = self._journal.meta.get("problem_name") or f"{domain.name}_problem"
        self._state = self._journal.state_at_seq(self._journal.last_seq)
        self._seq = self._state.seq
        self._subscribers: list[Subscriber] = []
        self._depth = 0
        self._pending: list[Change] = []
        self._undo: list[tuple[Change, Any]] = []
        # validation tables: per predicate/function, the admissible instance types of each argument
        self._pred_types = {
            p: tuple(domain.subtypes(t) for _, t in sig) for p, sig in domain.predicates.items()
        }
        self._func_types = {
            f: tuple(domain.subtypes(t) for _, t in sig) for f, sig in domain.functions.items()
        }
        self._single = dict(domain.single_valued)
        #: fusion hook: (fact, its current provenance, the write's provenance) -> whether the write may
        #: replace or retract that belief (None: every write may); a refused write changes nothing
        self.arbiter: Callable[[Fact, Provenance, Provenance], bool] | None = None
        self._rebuild_indexes()

    # ================================================================= construction
    @classmethod
    def from_pddl(
        cls,
        domain_path: str | Path,
        problem_path: str | Path | None = None,
        journal: str | Path | None = None,
        *,
        clock: Clock | None = None,
    ) -> KnowledgeBase:
        """Load a domain (with its ``.meta.yaml`` sidecar), optionally a problem, optionally a journal file.

        A journal file that already holds events is reopened and restores its exact state; the problem is
        then not loaded again (it is already in the history). A new or empty journal gets the domain text
        and, if given, the problem's objects, facts and goals as its first events (source ``"problem"``).

        Raises:
            PDDLParseError, PDDLValidationError: the domain or problem is broken.
            JournalError: the journal cannot be opened or was written for another domain.
        """
        from knowledge_base.problem import load_problem

        domain = DomainModel.from_file(domain_path)
        if journal is None:
            kb = cls(domain, clock=clock)
        else:
            base = State(instances=dict(domain.constants))
            summary = json.dumps(domain.to_summary())
            store = SqliteJournal(
                journal, base, domain_text=domain.text, meta_text=domain.meta_text, domain_summary=summary
            )
            if store.meta.get("domain_text") != domain.text:
                store.close()
                raise JournalError(f"{journal}: journal was written for another domain than {domain_path}")
            kb = cls(domain, journal=store, clock=clock)
            if store.last_seq > 0:
                return kb
        if problem_path is not None:
            kb.load_problem(load_problem(domain, problem_path))
        return kb

    @classmethod
    def from_journal(
        cls, path: str | Path, *, clock: Clock | None = None, read_only: bool = False
    ) -> KnowledgeBase:
        """Reopen a journal file alone (it stores its domain); ``read_only`` for a viewer in another process.

        Raises:
            JournalError: missing file or not a KnIC journal.
            PDDLParseError, PDDLValidationError: the stored domain no longer loads.
        """
        domain = DomainModel.from_journal_meta(path, SqliteJournal.read_meta(path))
        store = SqliteJournal(path, State(instances=dict(domain.constants)), read_only=read_only)
        return cls(domain, journal=store, clock=clock, read_only=read_only)

    def load_problem(self, problem: Any, *, source: str = "problem") -> None:
        """Add a parsed problem's objects, facts, functions and goals in one batch (status given).

        Args:
            problem: A :class:`knowledge_base.problem.ProblemContent`.
            source: Provenance source of these writes.
        """
        with self.batch():
            for name, type_name in problem.objects.items():
                self.add_instance(type_name, name, source=source)
            for fact in problem.facts:
                self.add_fact(fact.predicate, *fact.args, source=source)
            for fact, value in problem.functions.items():
                self.set_function(fact.predicate, *fact.args, value=value, source=source)
            for fact in problem.goals:
                self.add_goal(fact.predicate, *fact.args, source=source)
        self.problem_name = problem.name
        self._journal.set_meta("problem_name", problem.name)

    def set_clock(self, clock: Clock) -> None:
        """Stamp later writes with ``clock()`` (e.g. ``sim.time`` for simulated seconds)."""
        self._clock = clock

    def now(self) -> float:
        """The clock's current time in seconds."""
        return self._clock()

    def close(self) -> None:
        """Close the journal. Every write that returned is already durable."""
        self._journal.close()

    @property
    def journal(self) -> Journal:
        """The history journal (in memory or SQLite)."""
        return self._journal

    # ================================================================= writes
    def add_instance(
        self,
        type: str,
        name: str,
        *,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Declare ``name`` an instance of ``type``. Returns False if it already is one of that type.

        Raises:
            KnowledgeBaseError: unknown type, bad name, or ``name`` already exists with another type.
        """
        if not isinstance(type, str) or not self.domain.is_type(type):
            raise KnowledgeBaseError(f"add_instance {name!r}: unknown type {type!r}")
        problem = name_problem(name)
        if problem:
            raise KnowledgeBaseError(f"add_instance: invalid instance name {name!r}: {problem}")
        current = self._state.instances.get(name)
        if current == type:
            return False
        if current is not None:
            raise KnowledgeBaseError(
                f"add_instance {name} - {type}: {name!r} is already an instance of {current!r}"
            )
        prov = self._prov(source, at, status, confidence, support)
        self._commit([self._change(prov, _ADD_INSTANCE, type, (name,))])
        return True

    def remove_instance(
        self,
        name: str,
        *,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Remove an instance (and its anchor). Returns False if there is no such instance.

        Raises:
            KnowledgeBaseError: it is a domain constant, or a fact, goal or function value still uses it.
        """
        type_name = self._state.instances.get(name) if isinstance(name, str) else None
        if type_name is None:
            return False
        if name in self.domain.constants:
            raise KnowledgeBaseError(
                f"remove_instance {name}: {name!r} is a constant of domain {self.domain.name}"
            )
        if self._uses.get(name, 0):
            raise KnowledgeBaseError(f"remove_instance {name}: still used by {self._user_of(name)}")
        prov = self._prov(source, at, status, confidence, support)
        self._commit([self._change(prov, _REMOVE_INSTANCE, type_name, (name,))])
        return True

    def add_fact(
        self,
        predicate: str,
        *args: str,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Assert a fact. Returns True if it did not hold before.

        For a single-valued predicate, every other fact agreeing on the key positions is retracted in the
        same write. Re-asserting a holding fact with the same source, status, confidence and support changes
        nothing; with different ones it refreshes the provenance (and ``since``) and returns False.

        Raises:
            KnowledgeBaseError: unknown predicate, wrong arity, unknown instance, wrong argument type, bad
                provenance.
        """
        # validation inlined (hot path): same checks as _check
        try:
            allowed = self._pred_types.get(predicate)
            if allowed is None or len(allowed) != len(args):
                self._explain(predicate, args, self._pred_types, "predicate")
            instances = self._state.instances
            for arg, types in zip(args, allowed, strict=True):
                if instances.get(arg) not in types:
                    self._explain(predicate, args, self._pred_types, "predicate")
        except TypeError:  # a list or another unhashable where a name belongs
            self._not_names(predicate, args)
        prov = self._prov(source, at, status, confidence, support)
        fact = Fact(predicate, args)
        old = self._state.facts.get(fact)
        if old is not None and (old[0], old[2], old[3], old[4]) == (prov[0], prov[2], prov[3], prov[4]):
            return False
        if old is not None and self.arbiter is not None and not self.arbiter(fact, old, prov):
            return False
        changes = []
        positions = self._single.get(predicate)
        if positions is not None:
            other = self._sv_index.get((predicate, tuple([args[i] for i in positions])))
            if other is not None and other != fact:
                if self.arbiter is not None and not self.arbiter(other, self._state.facts[other], prov):
                    return False
                changes.append(self._change(prov, _REMOVE_FACT, predicate, other.args))
        changes.append(self._change(prov, _ADD_FACT, predicate, args))
        self._commit(changes)
        return old is None

    def remove_fact(
        self,
        predicate: str,
        *args: str,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Retract a fact. Returns False if it did not hold.

        Raises:
            KnowledgeBaseError: the atom is invalid (as for :meth:`add_fact`).
        """
        self._check(predicate, args, self._pred_types, "predicate")
        old = self._state.facts.get(Fact(predicate, args))
        if old is None:
            return False
        prov = self._prov(source, at, status, confidence, support)
        if self.arbiter is not None and not self.arbiter(Fact(predicate, args), old, prov):
            return False
        self._commit([self._change(prov, _REMOVE_FACT, predicate, args)])
        return True

    def add_goal(
        self,
        predicate: str,
        *args: str,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Add a goal atom. Returns False if it already is a goal.

        Raises:
            KnowledgeBaseError: the atom is invalid (as for :meth:`add_fact`).
        """
        self._check(predicate, args, self._pred_types, "predicate")
        fact = Fact(predicate, args)
        if fact in self._state.goals:
            return False
        prov = self._prov(source, at, status, confidence, support)
        self._commit([self._change(prov, _ADD_GOAL, predicate, args)])
        return True

    def remove_goal(self, predicate: str, *args: str, source: str = "user", at: float | None = None) -> bool:
        """Drop a goal atom. Returns False if it was not a goal.

        Raises:
            KnowledgeBaseError: the atom is invalid.
        """
        self._check(predicate, args, self._pred_types, "predicate")
        if Fact(predicate, args) not in self._state.goals:
            return False
        prov = self._prov(source, at, BeliefStatus.GIVEN, 1.0, ())
        self._commit([self._change(prov, _REMOVE_GOAL, predicate, args)])
        return True

    def clear_goals(self, *, source: str = "user", at: float | None = None) -> int:
        """Drop every goal in one write. Returns how many there were."""
        goals = list(self._state.goals)
        if goals:
            prov = self._prov(source, at, BeliefStatus.GIVEN, 1.0, ())
            self._commit([self._change(prov, _REMOVE_GOAL, g.predicate, g.args) for g in goals])
        return len(goals)

    def set_function(
        self,
        name: str,
        *args: str,
        value: float,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> bool:
        """Set a numeric function, e.g. ``set_function("battery", "r2d2", value=0.8)``. True if it changed.

        Raises:
            KnowledgeBaseError: unknown function, wrong arity or types, non-finite value.
        """
        self._check(name, args, self._func_types, "function")
        try:
            number = float(value)
        except (TypeError, ValueError):
            number = math.nan
        if not math.isfinite(number):
            raise KnowledgeBaseError(
                f"set_function {Fact(name, args)}: value {value!r} is not a finite number"
            )
        if self._state.functions.get(Fact(name, args)) == number:
            return False
        prov = self._prov(source, at, status, confidence, support)
        self._commit([self._change(prov, _SET_FUNCTION, name, args, number)])
        return True

    def set_anchor(
        self,
        symbol: str,
        geometry: dict[str, Any],
        *,
        source: str = "user",
        at: float | None = None,
        status: BeliefStatus | str = BeliefStatus.GIVEN,
        confidence: float = 1.0,
        support: Sequence[str] = (),
    ) -> None:
        """Anchor an instance to geometry in the world frame (metres, radians), e.g. a room's region polygon
        and waypoints, or an object's last known pose. Replaces the previous anchor.

        Raises:
            KnowledgeBaseError: unknown instance, or geometry not a JSON-serialisable dict.
        """
        if not isinstance(symbol, str) or symbol not in self._state.instances:
            raise KnowledgeBaseError(f"set_anchor {symbol!r}: unknown instance {symbol!r}")
        try:
            if not isinstance(geometry, dict):
                raise TypeError("not a dict")
            copy = json.loads(json.dumps(geometry, allow_nan=False))
        except (TypeError, ValueError) as exc:
            raise KnowledgeBaseError(
                f"set_anchor {symbol}: geometry must be a JSON-able dict ({exc})"
            ) from None
        prov = self._prov(source, at, status, confidence, support)
        self._commit([self._change(prov, _SET_ANCHOR, symbol, (), copy)])

    @contextmanager
    def batch(self) -> Iterator[KnowledgeBase]:
        """Group writes: one journal transaction, notifications after it commits, all-or-nothing.

        Writes inside are visible to queries at once. If an exception escapes the block, every write made
        in it is undone (a nested batch undoes only its own writes) and the exception propagates. A refused
        write inside the block changes nothing, so catching its error keeps the batch going.
        """
        mark = len(self._undo)
        seq_mark, time_mark = self._seq, self._state.time
        self._depth += 1
        try:
            yield self
        except BaseException:
            self._depth -= 1
            self._rollback(mark, seq_mark, time_mark)
            raise
        self._depth -= 1
        if self._depth == 0:
            pending, self._pending = self._pending, []
            try:
                self._journal.append(pending, self._state)
            except BaseException:
                self._rollback(0, seq_mark, time_mark)
                raise
            finally:
                self._undo = []
            self._notify(pending)

    def subscribe(self, callback: Subscriber) -> Callable[[], None]:
        """Call ``callback(change)`` for every committed change, in order. Returns the unsubscribe function.

        Callbacks run synchronously after the commit; one that raises is logged and does not stop the others.
        """
        self._subscribers.append(callback)

        def unsubscribe() -> None:
            if callback in self._subscribers:
                self._subscribers.remove(callback)

        return unsubscribe

    def refresh(self) -> list[Change]:
        """Pick up changes another process appended to the journal file (read-only viewers); notify them."""
        if not isinstance(self._journal, SqliteJournal):
            return []
        changes = self._journal.refresh()
        for change in changes:
            self._apply(change)
        if changes:
            self._seq = changes[-1].seq
        self._notify(changes)
        return changes

    # ================================================================= internals
    def _prov(
        self, source: str, at: float | None, status: Any, confidence: float, support: Sequence[str]
    ) -> Provenance:
        belief = _STATUSES.get(status)
        if belief is not None and confidence == 1.0 and not support and source.__class__ is str and source:
            # the common case, checked cheaply
            return Provenance(source, self._clock() if at is None else float(at), belief, 1.0, ())
        if belief is None:
            raise KnowledgeBaseError(
                f"unknown belief status {status!r}: use one of {[s.value for s in BeliefStatus]}"
            )
        if not 0.0 <= confidence <= 1.0:
            raise KnowledgeBaseError(f"confidence {confidence!r} is outside 0..1")
        if not isinstance(source, str) or not source:
            raise KnowledgeBaseError(f"source must be a non-empty component name, got {source!r}")
        stamp = self._clock() if at is None else float(at)
        return Provenance(source, stamp, belief, float(confidence), tuple(support) if support else ())

    def _change(
        self, prov: Provenance, kind: ChangeKind, name: str, args: tuple[str, ...], value: Any = None
    ) -> Change:
        self._seq += 1
        return Change(self._seq, prov.since, kind, name, args, value, prov)

    def _commit(self, changes: list[Change]) -> None:
        if self.read_only:
            self._seq -= len(changes)
            raise KnowledgeBaseError("knowledge base is read-only (a viewer of a journal written elsewhere)")
        seq_mark, time_mark = changes[0].seq - 1, self._state.time
        undo = [(c, self._apply(c)) for c in changes]
        if self._depth:
            self._pending.extend(changes)
            self._undo.extend(undo)
            return
        try:
            self._journal.append(changes, self._state)
        except BaseException:
            self._undo = undo
            self._rollback(0, seq_mark, time_mark)
            raise
        self._notify(changes)

    def _notify(self, changes: Sequence[Change]) -> None:
        if not self._subscribers:
            return
        for callback in list(self._subscribers):
            for change in changes:
                try:
                    callback(change)
                except Exception:
                    log.exception("knowledge-base subscriber %r failed on %s", callback, change.describe())

    def _rollback(self, mark: int, seq: int, stamp: float) -> None:
        while len(self._undo) > mark:
            change, old = self._undo.pop()
            self._revert(change, old)
        del self._pending[len(self._pending) - (self._seq - seq) :]
        self._seq = seq
        self._state.seq = seq
        self._state.time = stamp
