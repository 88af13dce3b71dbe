"""What the page shows, read from a run's files: the journal (facts, goals, anchors, history) and the trace.

:class:`JournalView` follows a SQLite journal read-only, as ``knic facts --watch`` does: it never writes, so
it is safe beside a running system (SQLite WAL readers never block the writer), and it shows a finished run
the same way. :class:`TraceFile` follows the execution trace's JSON lines (``knic run --trace``).

Threading: a view owns a SQLite connection, which belongs to the thread that opened it; the web server opens
its view on its event-loop thread and calls it only there (see :mod:`knic.web.app`).

Times are the journal's clock: simulated seconds in a closed-loop run.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from core.errors import KnicError
from knic.web.scene import beliefs, static_layout
from knowledge_base import Change, ChangeKind, Fact, KnowledgeBase, Provenance, State

if TYPE_CHECKING:
    from worlds.model import World

_FACT_KINDS = (ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT, ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL)
#: the longest fact text /api/why takes
MAX_FACT_TEXT = 400
#: the columns of a compact fact row
COMPACT_COLUMNS = ("fact", "status", "author", "since", "confidence")


class BadQuery(KnicError):
    """A query names what the journal does not have, or is malformed (HTTP 400)."""

    exit_code = 2


class TraceSource(Protocol):
    """Where the execution trace comes from: a trace file, or the running system's trace."""

    def events(self, after: int = 0) -> list[dict[str, Any]]:
        """Trace events (as :meth:`planner.trace.TraceEvent.to_dict`) after the first ``after``, in order."""
        ...


class TraceFile:
    """Follows a trace JSON-lines file as it grows (a line is read once it is complete).

    Args:
        path: the file (``knic run --trace FILE``); missing is allowed (the run may not have opened it yet).
        max_events: the most events kept (older ones are dropped from the start; indices stay global).
    """

    def __init__(self, path: str | Path, *, max_events: int = 100_000) -> None:
        self.path = Path(path)
        self.max_events = max_events
        self._offset = 0
        self._events: list[dict[str, Any]] = []
        self._dropped = 0
        self.bad_lines = 0

    def poll(self) -> int:
        """Read the lines appended since the last call; returns how many events were added."""
        try:
            with self.path.open("rb") as f:
                f.seek(self._offset)
                data = f.read()
        except FileNotFoundError:
            return 0
        end = data.rfind(b"\n")
        if end < 0:
            return 0
        self._offset += end + 1
        added = 0
        for line in data[: end + 1].splitlines():
            try:
                event = json.loads(line)
            except ValueError:
                self.bad_lines += 1
                continue
            if isinstance(event, dict):
                self._events.append(event)
                added += 1
        excess = len(self._events) - self.max_events
        if excess > 0:
            del self._events[:excess]
            self._dropped += excess
        return added

    def events(self, after: int = 0) -> list[dict[str, Any]]:
        """The events after the first ``after`` read so far."""
        self.poll()
        return self._events[max(0, after - self._dropped) :]

    @property
    def count(self) -> int:
        """Events read so far (dropped ones included)."""
        return self._dropped + len(self._events)


class JournalView:
    """A read-only follower of a run's journal and the queries the page and the JSON API make.

    Args:
        journal: the SQLite journal file.
        world: the world data, for the doors and devices the journal does not anchor (optional).
        trace: the execution trace (optional).

    Raises:
        JournalError: missing file or not a KnIC journal.
    """

    def __init__(self, journal: str | Path, *, world: World | None = None, trace: TraceSource | None = None):
        self.path = Path(journal)
        self.kb = KnowledgeBase.from_journal(journal, read_only=True)
        self.world = world
        self.trace = trace
        self._history: dict[Fact, list[Change]] | None = None
        self._layout: tuple[int, dict[str, Any]] | None = None
        self._anchor_seq = 0

    def close(self) -> None:
        """Close the journal connection."""
        self.kb.close()

    # ------------------------------------------------------------------ following
    @property
    def seq(self) -> int:
        """Sequence number of the last journal event read."""
        return self.kb.journal.last_seq

    def refresh(self) -> list[Change]:
        """Read the events the writer appended since the last call (and index them)."""
        changes = self.kb.refresh()
        if self._history is not None:
            self._index(changes)
        for c in changes:
            if c.kind in (ChangeKind.SET_ANCHOR, ChangeKind.REMOVE_INSTANCE):
                self._anchor_seq = c.seq
        return changes

    def changes_after(self, seq: int, limit: int = 5000) -> list[dict[str, Any]]:
        """Journal events after ``seq`` (at most ``limit``), as :func:`change_record` dicts."""
        return [change_record(c) for c in self.kb.journal.changes(seq, min(self.seq, seq + limit))]

    # ------------------------------------------------------------------ queries
    def state(self, at: float | None = None) -> State:
        """The state now (``at`` None) or at clock time ``at``."""
        return self.kb.snapshot() if at is None else self.kb.state_at(at)

    def timeline(self) -> dict[str, Any]:
        """The journal's span: first and last event times, last sequence number, domain and problem."""
        seq = self.seq
        first = self.kb.journal.changes(0, 1) if seq else []
        last = self.kb.journal.changes(seq - 1, seq) if seq else []
        return {
            "seq": self.seq,
            "first": first[0].time if first else None,
            "last": last[0].time if last else None,
            "domain": self.kb.domain.name,
            "problem": self.kb.problem_name,
            "journal": self.path.name,
        }

    def facts(
        self,
        at: float | None = None,
        *,
        predicate: str | None = None,
        status: str | None = None,
        author: str | None = None,
        text: str | None = None,
        compact: bool = False,
    ) -> dict[str, Any]:
        """The fact table (and the goals) now or at ``at``, optionally filtered.

        With ``compact`` the facts come as ``"rows"`` of :data:`COMPACT_COLUMNS` (about half the bytes and
        the encoding time of one object per fact: what the page loads) instead of ``"facts"``.

        Raises:
            BadQuery: unknown predicate.
        """
        if predicate is not None and predicate not in self.kb.domain.predicates:
            raise BadQuery(f"predicate: unknown predicate {predicate!r} in domain {self.kb.domain.name}")
        state = self.state(at)
        needle = text.lower() if text else None
        chosen = [
            (f, p)
            for f, p in state.facts.items()
            if (predicate is None or f.predicate == predicate)
            and (status is None or p.status.value == status)
            and (author is None or p.source == author)
            and (needle is None or needle in str(f))
        ]
        out: dict[str, Any] = {
            "seq": state.seq,
            "time": state.time if math.isfinite(state.time) else None,
            "at": at,
            "goals": [fact_record(f, p) for f, p in state.goals.items()],
        }
        if compact:
            out["columns"] = list(COMPACT_COLUMNS)
            out["rows"] = [[str(f), p.status.value, p.source, p.since, p.confidence] for f, p in chosen]
        else:
            out["facts"] = [fact_record(f, p) for f, p in chosen]
        return out

    def why(self, text: str, at: float | None = None) -> dict[str, Any]:
        """Why a fact is (or is not) believed: provenance, supporting units and its whole history.

        Raises:
            BadQuery: not a fact of this domain (one line saying what is wrong).
        """
        fact = self.parse_fact(text)
        state = self.state(at)
        prov = state.facts.get(fact)
        history = [c for c in self._fact_history(fact) if c.seq <= state.seq]
        out: dict[str, Any] = {"fact": str(fact), "holds": prov is not None, "at": at}
        if prov is not None:
            out.update(fact_record(fact, prov))
            out["support"] = list(prov.support)
        out["goal"] = fact in state.goals
        out["history"] = [change_record(c) for c in history]
        return out

    def parse_fact(self, text: str) -> Fact:
        """A fact of this journal's domain from ``"(pred a b)"``.

        Raises:
            BadQuery: malformed, unknown predicate, wrong arity or unknown instance.
        """
        if len(text) > MAX_FACT_TEXT:
            raise BadQuery(f"fact: longer than {MAX_FACT_TEXT} characters")
        try:
            fact = Fact.parse(text)
        except KnicError as exc:
            raise BadQuery(f"fact: {exc}") from None
        domain = self.kb.domain
        if fact.predicate not in domain.predicates:
            raise BadQuery(f"fact {fact}: unknown predicate {fact.predicate!r} in domain {domain.name}")
        arity = len(domain.predicates[fact.predicate])
        if len(fact.args) != arity:
            raise BadQuery(f"fact {fact}: {fact.predicate} takes {arity} argument(s), got {len(fact.args)}")
        known = self.kb.snapshot().instances
        for arg in fact.args:
            if arg not in known and arg not in domain.constants:
                raise BadQuery(f"fact {fact}: {arg!r} is not an instance known to this journal")
        return fact

    def map(self, at: float | None = None) -> dict[str, Any]:
        """The floor plan and where things are believed to be (see :mod:`knic.web.scene`)."""
        state = self.state(at)
        if at is None and self._layout is not None and self._layout[0] == self._anchor_seq:
            layout = self._layout[1]
        else:
            layout = static_layout(state, self.world)
            if at is None:
                self._layout = (self._anchor_seq, layout)
        return {
            "seq": state.seq,
            "at": at,
            **layout,
            "believed": beliefs(state, self.kb.domain, layout),
            "goals": [str(g) for g in state.goals],
        }

    # ------------------------------------------------------------------ internals
    def _fact_history(self, fact: Fact) -> list[Change]:
        if self._history is None:
            self._history = {}
            self._index(self.kb.changes())
        return self._history.get(fact, [])

    def _index(self, changes: Iterable[Change]) -> None:
        assert self._history is not None
        for c in changes:
            if c.kind in _FACT_KINDS:
                self._history.setdefault(Fact(c.name, c.args), []).append(c)


def fact_record(fact: Fact, prov: Provenance) -> dict[str, Any]:
    """One row of the fact table (JSON)."""
    return {
        "fact": str(fact),
        "predicate": fact.predicate,
        "arguments": list(fact.args),
        "status": prov.status.value,
        "author": prov.source,
        "since": prov.since,
        "confidence": prov.confidence,
    }


def change_record(c: Change) -> dict[str, Any]:
    """One journal event (JSON): what changed, when, by whom."""
    out: dict[str, Any] = {
        "seq": c.seq,
        "time": c.time,
        "kind": c.kind.value,
        "name": c.name,
        "arguments": list(c.args),
        "author": c.provenance.source,
        "status": c.provenance.status.value,
        "confidence": c.provenance.confidence,
    }
    if c.kind in _FACT_KINDS:
        out["fact"] = str(Fact(c.name, c.args))
    if c.value is not None:
        out["value"] = c.value
    if c.provenance.support:
        out["support"] = list(c.provenance.support)
    return out
