"""The history journal: an append-only log of :class:`~knowledge_base.model.Change` events.

Two implementations share one interface:

* :class:`Journal` keeps the events in a list (a knowledge base without a path).
* :class:`SqliteJournal` keeps them in a SQLite database in WAL mode, together with the domain text and its
  metadata, so that a reader in another process needs nothing but the file.

Past states come from a :class:`~knowledge_base.timeline.Timeline` (every record's validity interval, in
memory), so ``state_at`` costs one vectorised interval test plus building the answer, whatever the length of
the history. The SQLite journal also takes periodic checkpoints (full state copies) so that reopening it
loads the last checkpoint and replays at most a checkpoint interval of events instead of the whole history;
it builds its timeline from the events only when a past state is first asked for. Checkpoints and the
timeline are derived data: losing them (say, to a crash) costs speed, never correctness, and a journal
written before the timeline existed needs no migration.

Time base: event times are the knowledge base's clock (wall or simulated seconds). ``state_at(t)`` is the
state after the last event, in journal order, whose time is at most ``t``; this stays meaningful when the
clock is switched once from wall time to simulated time after loading a problem.

Durability: every :meth:`Journal.append` is one SQLite transaction. The database runs with
``journal_mode=WAL`` and ``synchronous=NORMAL``: a commit writes the transaction to the WAL file before it
returns, so it survives the writing process being killed (SIGKILL included); only an operating-system crash
or power loss may lose the last transactions (``FULL`` would add an fsync per commit, which costs more than
the whole write path, for a robot whose history is diagnostic). One process writes a journal; any number of
processes may read it at the same time (WAL readers never block the writer).
"""

from __future__ import annotations

import bisect
import json
import math
import sqlite3
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import JournalError
from knowledge_base.model import BeliefStatus, Change, ChangeKind, Fact, Provenance, State, apply_change

if TYPE_CHECKING:  # numpy (the timeline's) is imported only when a journal is opened
    from knowledge_base.timeline import Timeline

__all__ = ["CorruptRow", "Journal", "SqliteJournal", "recover"]

#: Fewest events between two checkpoints; the interval grows with the state so checkpoints stay cheap.
CHECKPOINT_MIN_EVENTS = 1000
#: Decoded checkpoints kept in memory by a SQLite journal (reopening the same journal skips decoding).
DECODED_CHECKPOINTS = 2

_KINDS = {k.value: k for k in ChangeKind}
_STATUSES = {s.value: s for s in BeliefStatus}
_SEP = "\x1f"  # separates support ids (which, unlike PDDL names, may hold spaces)


class Journal:
    """In-memory history; the base of the SQLite journal.

    Lifecycle: created empty (or, for SQLite, opened on an existing file); :meth:`append` is called by the
    knowledge base once per committed write or batch; :meth:`close` releases resources.

    Args:
        base: The state before the first event (the domain's constants as instances).
    """

    def __init__(self, base: State) -> None:
        self._base = base.copy()
        self._times: list[float] = []
        self._monotone = True
        self._memory_events: list[Change] = []
        #: every record's validity interval (None until a SQLite journal with history first needs it)
        from knowledge_base.timeline import Timeline

        self._timeline: Timeline | None = Timeline(self._base)
        self.meta: dict[str, str] = {}

    # ----------------------------------------------------------------- writing
    @property
    def last_seq(self) -> int:
        """Sequence number of the last event (0 when empty)."""
        return len(self._times)

    def append(self, changes: Sequence[Change], state_after: State) -> None:
        """Record ``changes`` (already applied to ``state_after``) as one atomic, durable unit.

        Raises:
            JournalError: the storage refused the write; nothing was recorded.
        """
        if not changes:
            return
        self._store(changes, state_after)
        self._note_times([c.time for c in changes])
        self._feed_timeline(changes)

    def _feed_timeline(self, changes: Sequence[Change]) -> None:
        timeline = self._timeline
        if timeline is not None and changes and timeline.seq == changes[0].seq - 1:
            for c in changes:
                timeline.feed(c)

    def _note_times(self, times: Iterable[float]) -> None:
        for t in times:
            if self._times and t < self._times[-1]:
                self._monotone = False
            self._times.append(t)

    def _store(self, changes: Sequence[Change], state_after: State) -> None:
        self._memory_events.extend(changes)

    def set_meta(self, key: str, value: str) -> None:
        """Record a piece of metadata (e.g. the problem name) with the history."""
        self.meta[key] = value

    def close(self) -> None:
        """Release resources (nothing for the in-memory journal)."""

    # ----------------------------------------------------------------- reading
    def changes(self, after: int = 0, upto: int | None = None) -> list[Change]:
        """Events with ``after < seq <= upto`` (``upto`` None: to the end), in order."""
        end = self.last_seq if upto is None else upto
        return self._memory_events[after:end]

    def last_seq_at(self, t: float) -> int:
        """Sequence number of the last event (journal order) with time <= ``t``; 0 if there is none."""
        if self._monotone:
            return bisect.bisect_right(self._times, t)
        for i in range(len(self._times) - 1, -1, -1):
            if self._times[i] <= t:
                return i + 1
        return 0

    def state_at(self, t: float) -> State:
        """The state as it was at clock time ``t`` (see the module docstring for the exact meaning)."""
        return self.state_at_seq(self.last_seq_at(t))

    def state_at_seq(self, seq: int) -> State:
        """The state after event ``seq`` (0: the base state), from the timeline."""
        timeline = self.timeline()
        return timeline.state_at(seq, self._times[seq - 1] if seq > 0 else None)

    def timeline(self) -> Timeline:
        """The timeline of the whole history, brought up to the last event (built on first use)."""
        timeline = self._timeline
        if timeline is None:
            from knowledge_base.timeline import Timeline

            timeline = self._timeline = Timeline(self._base)
        if timeline.seq < self.last_seq:
            for change in self.changes(timeline.seq, self.last_seq):
                timeline.feed(change)
        return timeline


class SqliteJournal(Journal):
    """The history in a SQLite database (WAL), with the domain text so the file is self-contained.

    Args:
        path: Database file; created when missing (unless ``read_only``).
        base: State before the first event (domain constants).
        domain_text: Domain PDDL stored in a new journal (ignored when opening an existing one).
        meta_text: Domain sidecar YAML stored with it.
        domain_summary: JSON of ``DomainModel.to_summary()`` stored with it (readers skip the PDDL parser).
        read_only: Open an existing journal for reading only (another process may be writing it).

    Raises:
        JournalError: the file cannot be opened, or is not a KnIC journal.
    """

    def __init__(
        self,
        path: str | Path,
        base: State,
        *,
        domain_text: str = "",
        meta_text: str = "",
        domain_summary: str = "",
        read_only: bool = False,
    ) -> None:
        super().__init__(base)
        self._decoded: dict[int, State] = {}
        self._checkpoint_seqs: list[int] = [0]
        self._last_checkpoint = 0
        self._past_asked = False
        self.path = Path(path)
        self.read_only = read_only
        try:
            if read_only:
                if not self.path.is_file():
                    raise JournalError(f"{self.path}: no such journal file")
                self._db = sqlite3.connect(f"file:{self.path}?mode=ro", uri=True, isolation_level=None)
            else:
                self._db = sqlite3.connect(self.path, isolation_level=None)
                self._db.execute("PRAGMA journal_mode=WAL")
                self._db.execute("PRAGMA synchronous=NORMAL")
                self._create(domain_text, meta_text, domain_summary)
            self.meta = dict(self._db.execute("SELECT key, value FROM meta").fetchall())
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: not a readable KnIC journal ({exc})") from None
        try:
            times = self._db.execute("SELECT seq, t FROM events ORDER BY seq").fetchall()
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: not a readable KnIC journal ({exc})") from None
        for i, (seq, t) in enumerate(times, start=1):
            if seq != i or not isinstance(t, (int, float)) or not math.isfinite(t):
                why = f"sequence gap (expected {i})" if seq != i else f"time {t!r} is not a number"
                raise JournalError(f"{self.path}: {CorruptRow(seq, why)}")
        self._note_times(t for (_, t) in times)
        self._note_checkpoints()
        if self.last_seq:
            self._timeline = None  # built from the events when a past state is first asked for

    @staticmethod
    def read_meta(path: str | Path) -> dict[str, str]:
        """The stored metadata (``domain_text``, ``meta_text``, ``domain_source``...) of a journal file.

        Raises:
            JournalError: missing file or not a KnIC journal.
        """
        p = Path(path)
        if not p.is_file():
            raise JournalError(f"{p}: no such journal file")
        try:
            db = sqlite3.connect(f"file:{p}?mode=ro", uri=True)
            try:
                return dict(db.execute("SELECT key, value FROM meta").fetchall())
            finally:
                db.close()
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{p}: not a readable KnIC journal ({exc})") from None

    def _create(self, domain_text: str, meta_text: str, domain_summary: str) -> None:
        db = self._db
        db.execute("BEGIN IMMEDIATE")
        db.execute("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
        db.execute(
            "CREATE TABLE IF NOT EXISTS events (seq INTEGER PRIMARY KEY, t REAL NOT NULL, kind TEXT NOT NULL,"
            " name TEXT NOT NULL, args TEXT NOT NULL, value TEXT, source TEXT NOT NULL, status TEXT NOT NULL,"
            " confidence REAL NOT NULL, support TEXT NOT NULL)"
        )
        db.execute("CREATE TABLE IF NOT EXISTS checkpoints (seq INTEGER PRIMARY KEY, state TEXT NOT NULL)")
        db.execute("INSERT OR IGNORE INTO meta VALUES ('format', 'knic-journal-1')")
        db.execute("INSERT OR IGNORE INTO meta VALUES ('domain_text', ?)", (domain_text,))
        db.execute("INSERT OR IGNORE INTO meta VALUES ('meta_text', ?)", (meta_text,))
        db.execute("INSERT OR IGNORE INTO meta VALUES ('domain_summary', ?)", (domain_summary,))
        db.execute("COMMIT")

    def refresh(self) -> list[Change]:
        """Read events (and checkpoints) written since the last call, e.g. by another process.

        Returns:
            The new events, in order.
        """
        try:
            rows = self._db.execute(
                "SELECT * FROM events WHERE seq > ? ORDER BY seq", (self.last_seq,)
            ).fetchall()
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: cannot read journal ({exc})") from None
        changes = [_row_to_change(r) for r in rows]
        self._note_times(c.time for c in changes)
        self._note_checkpoints()
        self._feed_timeline(changes)
        return changes

    def _note_checkpoints(self) -> None:
        try:
            cps = self._db.execute(
                "SELECT seq FROM checkpoints WHERE seq > ? AND seq <= ? ORDER BY seq",
                (self._checkpoint_seqs[-1], self.last_seq),
            ).fetchall()
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: cannot read journal ({exc})") from None
        for (seq,) in cps:
            self._checkpoint_seqs.append(seq)
            self._last_checkpoint = seq

    def _store(self, changes: Sequence[Change], state_after: State) -> None:
        if self.read_only:
            raise JournalError(f"{self.path}: journal is open read-only")
        last = changes[-1].seq
        checkpoint = state_after if self._checkpoint_due(last, state_after) else None
        db = self._db
        try:
            db.execute("BEGIN")
            try:
                db.executemany(
                    "INSERT INTO events VALUES (?,?,?,?,?,?,?,?,?,?)", [_change_to_row(c) for c in changes]
                )
                if checkpoint is not None:
                    db.execute(
                        "INSERT INTO checkpoints VALUES (?, ?)", (checkpoint.seq, _state_to_json(checkpoint))
                    )
                db.execute("COMMIT")
            except BaseException:
                db.execute("ROLLBACK")
                raise
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: cannot write journal ({exc})") from None
        if checkpoint is not None:
            self._checkpoint_seqs.append(last)
            self._last_checkpoint = last

    def _checkpoint_due(self, seq: int, state: State) -> bool:
        # Replaying the events since a checkpoint should cost about as much as loading the checkpoint.
        interval = max(CHECKPOINT_MIN_EVENTS, (len(state.facts) + len(state.instances)) // 2)
        return seq - self._last_checkpoint >= interval

    def set_meta(self, key: str, value: str) -> None:
        if self.read_only:
            raise JournalError(f"{self.path}: journal is open read-only")
        try:
            self._db.execute("INSERT OR REPLACE INTO meta VALUES (?, ?)", (key, value))
        except sqlite3.DatabaseError as exc:
            raise JournalError(f"{self.path}: cannot write journal ({exc})") from None
        self.meta[key] = value

    def changes(self, after: int = 0, upto: int | None = None) -> list[Change]:
        end = self.last_seq if upto is None else upto
        rows = self._db.execute(
            "SELECT * FROM events WHERE seq > ? AND seq <= ? ORDER BY seq", (after, end)
        ).fetchall()
        return [_row_to_change(r) for r in rows]

    def state_at_seq(self, seq: int) -> State:
        """The state after event ``seq``: from the timeline once it is built.

        Until then the last state (the one a reopened journal needs) and the first past state asked for (a
        one-shot ``knic facts --at``) come from the nearest checkpoint plus replay, which reads far less than
        building the timeline from every event; the second past state builds it (a viewer moving through
        the history).
        """
        if self._timeline is None and (seq == self.last_seq or not self._past_asked):
            self._past_asked = self._past_asked or seq != self.last_seq
            index = bisect.bisect_right(self._checkpoint_seqs, seq) - 1
            state = self._checkpoint(index)
            for change in self.changes(self._checkpoint_seqs[index], seq):
                apply_change(state, change)
            return state
        return super().state_at_seq(seq)

    def _checkpoint(self, index: int) -> State:
        seq = self._checkpoint_seqs[index]
        if seq == 0:
            return self._base.copy()
        cached = self._decoded.get(seq)
        if cached is None:  # decoding a large checkpoint costs far more than copying it: keep the last few
            row = self._db.execute("SELECT state FROM checkpoints WHERE seq = ?", (seq,)).fetchone()
            if row is None:
                raise JournalError(f"{self.path}: checkpoint {seq} is missing")
            try:
                cached = _state_from_json(row[0])
            except (ValueError, TypeError, KeyError, IndexError) as exc:
                raise JournalError(f"{self.path}: checkpoint {seq} is corrupt ({exc})") from None
            self._decoded[seq] = cached
            while len(self._decoded) > DECODED_CHECKPOINTS:
                self._decoded.pop(next(iter(self._decoded)))
        else:
            self._decoded[seq] = self._decoded.pop(seq)  # most recently used last
        return cached.copy()

    def close(self) -> None:
        """Close the database connection (the data stays durable in the file)."""
        self._db.close()


# --------------------------------------------------------------------- encoding
def _change_to_row(c: Change) -> tuple[Any, ...]:
    p = c.provenance
    value = None if c.value is None else json.dumps(c.value, separators=(",", ":"))
    return (c.seq, c.time, c.kind.value, c.name, " ".join(c.args), value, p.source, p.status.value,
            p.confidence, _SEP.join(p.support))  # fmt: skip


def _row_to_change(r: tuple[Any, ...]) -> Change:
    """One events row as a Change; a row that is not one (edited, truncated, bit rot) raises JournalError."""
    try:
        seq, t, kind, name, args, value, source, status, confidence, support = r
        if not (isinstance(t, (int, float)) and math.isfinite(t)):
            raise ValueError(f"time {t!r} is not a number")
        if not all(isinstance(v, str) for v in (name, args, source, support)):
            raise ValueError("a name, argument, source or support field is not text")
        if not isinstance(confidence, (int, float)) or not 0.0 <= confidence <= 1.0:
            raise ValueError(f"confidence {confidence!r} is not in 0..1")
        if kind not in _KINDS or status not in _STATUSES:
            raise ValueError(f"unknown kind {kind!r} or status {status!r}")
        prov = Provenance(
            source, t, _STATUSES[status], confidence, tuple(support.split(_SEP)) if support else ()
        )
        return Change(seq, t, _KINDS[kind], name, tuple(args.split()) if args else (),
                      None if value is None else json.loads(value), prov)  # fmt: skip
    except (ValueError, TypeError) as exc:
        seq = r[0] if r else "?"
        raise CorruptRow(seq, str(exc).replace("\n", " ")) from None


class CorruptRow(JournalError):
    """An events row that does not decode; ``seq`` names it (the committed prefix ends before it)."""

    def __init__(self, seq: Any, reason: str) -> None:
        super().__init__(
            f"journal row seq {seq} is corrupt: {reason} (knic facts --recover OUT keeps the rows before it)"
        )
        self.seq = seq
        self.reason = reason


def recover(path: str | Path, out: str | Path) -> tuple[int, str]:
    """Copy the committed prefix of a damaged journal to a new journal ``out``: the domain, the metadata and
    every event before the first row that does not decode (checkpoints are derived data and are rebuilt).

    Returns:
        ``(events kept, what was dropped)``; the second is "" when no row was corrupt.

    Raises:
        JournalError: ``out`` exists, or ``path`` is not a journal at all.
    """
    src, dst = Path(path), Path(out)
    if dst.exists():
        raise JournalError(f"{dst}: exists; --recover writes a new file and replaces nothing")
    meta = SqliteJournal.read_meta(src)
    if "domain_text" not in meta:
        raise JournalError(f"{src}: not a KnIC journal (no domain stored)")
    db = sqlite3.connect(f"file:{src}?mode=ro", uri=True)
    kept: list[tuple[Any, ...]] = []
    dropped = ""
    try:
        expected = 1
        for row in db.execute("SELECT * FROM events ORDER BY seq"):
            try:
                _row_to_change(row)
                if row[0] != expected:
                    raise CorruptRow(row[0], f"sequence gap (expected {expected})")
            except CorruptRow as exc:
                dropped = f"row seq {exc.seq} and after ({exc.reason})"
                break
            kept.append(row)
            expected += 1
    except sqlite3.DatabaseError as exc:
        dropped = dropped or f"unreadable rows after seq {len(kept)} ({exc})"
    finally:
        db.close()
    target = sqlite3.connect(dst, isolation_level=None)
    try:
        target.execute("BEGIN")
        target.execute("CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
        target.execute(
            "CREATE TABLE events (seq INTEGER PRIMARY KEY, t REAL NOT NULL, kind TEXT NOT NULL,"
            " name TEXT NOT NULL, args TEXT NOT NULL, value TEXT, source TEXT NOT NULL, status TEXT NOT NULL,"
            " confidence REAL NOT NULL, support TEXT NOT NULL)"
        )
        target.execute("CREATE TABLE checkpoints (seq INTEGER PRIMARY KEY, state TEXT NOT NULL)")
        target.executemany("INSERT INTO meta VALUES (?, ?)", sorted(meta.items()))
        target.executemany("INSERT INTO events VALUES (?,?,?,?,?,?,?,?,?,?)", kept)
        target.execute("COMMIT")
    finally:
        target.close()
    return len(kept), dropped


def _prov_list(p: Provenance) -> list[Any]:
    return [p.source, p.since, p.status.value, p.confidence, list(p.support)]


def _prov_from(v: list[Any]) -> Provenance:
    return Provenance(v[0], v[1], _STATUSES[v[2]], v[3], tuple(v[4]))


def _state_to_json(s: State) -> str:
    data = {
        "seq": s.seq,
        "time": s.time,
        "instances": s.instances,
        "facts": [[f.predicate, f.args, *_prov_list(p)] for f, p in s.facts.items()],
        "goals": [[f.predicate, f.args, *_prov_list(p)] for f, p in s.goals.items()],
        "functions": [[f.predicate, f.args, v] for f, v in s.functions.items()],
        "anchors": [[k, g, *_prov_list(p)] for k, (g, p) in s.anchors.items()],
    }
    return json.dumps(data, separators=(",", ":"))


def _state_from_json(text: str) -> State:
    d = json.loads(text)
    return State(
        instances=d["instances"],
        facts={Fact(v[0], tuple(v[1])): _prov_from(v[2:]) for v in d["facts"]},
        goals={Fact(v[0], tuple(v[1])): _prov_from(v[2:]) for v in d["goals"]},
        functions={Fact(v[0], tuple(v[1])): v[2] for v in d["functions"]},
        anchors={v[0]: (v[1], _prov_from(v[2:])) for v in d["anchors"]},
        seq=d["seq"],
        time=d["time"],
    )
