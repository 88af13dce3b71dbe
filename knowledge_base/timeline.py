"""Validity intervals of every record of the history, so that ``state_at`` costs one vectorised query.

Each fact, goal, instance, function value and anchor the history ever held is a *span*: the record (key
and value, e.g. a :class:`~knowledge_base.model.Fact` and its :class:`~knowledge_base.model.Provenance`) with
the sequence number of the event that made it hold (``start``) and of the event that ended it (``end``; a
span that still holds ends at :data:`OPEN`). The state after event ``seq`` holds exactly the spans with
``start <= seq < end``.

:meth:`Timeline.state_at` answers from whichever starting point is cheapest: nothing (collect the spans that
held at ``seq``), the records that hold now, or a kept *copy* of the records (taken every so many events,
about half the state's size, so copies cost about as much memory as the spans themselves). From a starting
point it copies the records (a C-level dict copy that rehashes nothing) and patches the spans that began or
ended between it and ``seq``. The work is bounded by the size of the answer and by the events between ``seq``
and the nearest starting point, never by the length of the history; the interval tests over all spans are
numpy comparisons.

The timeline is derived data kept in memory (the journal's events are the durable truth): the in-memory
journal feeds it on every append; a SQLite journal builds it from its events the first time a past state is
asked for, then feeds it as well.
"""

from __future__ import annotations

from collections import deque
from typing import Any

import numpy as np

from knowledge_base.model import Change, ChangeKind, Fact, State

__all__ = ["OPEN", "Timeline"]

#: ``end`` of a span that still holds
OPEN = np.iinfo(np.int64).max
#: a dict copy costs about this many times less per entry than building the dict entry by entry (rehashing)
_COPY_ADVANTAGE = 8
#: fewest events between two kept copies (the interval grows with the state, see :meth:`Timeline.feed`)
COPY_MIN_EVENTS = 5000


class _Spans:
    """The spans of one kind of record (see the module docstring).

    ``current`` holds the records that hold now (key -> value), ``open`` their span indexes.
    """

    def __init__(self) -> None:
        self.keys: list[Any] = []
        self.values: list[Any] = []
        self._start = np.empty(256, dtype=np.int64)
        self._end = np.empty(256, dtype=np.int64)
        self.open: dict[Any, int] = {}
        self.current: dict[Any, Any] = {}
        #: (seq, copy of ``current`` after event seq), in order
        self.copies: list[tuple[int, dict[Any, Any]]] = []

    def __len__(self) -> int:
        return len(self.keys)

    def put(self, key: Any, value: Any, seq: int) -> None:
        """Event ``seq`` makes ``key`` hold with ``value`` (ending the span it had, if any)."""
        self.drop(key, seq)
        i = len(self.keys)
        if i == len(self._start):
            self._start = np.concatenate([self._start, np.empty(i, dtype=np.int64)])
            self._end = np.concatenate([self._end, np.empty(i, dtype=np.int64)])
        self._start[i] = seq
        self._end[i] = OPEN
        self.keys.append(key)
        self.values.append(value)
        self.open[key] = i
        self.current[key] = value

    def drop(self, key: Any, seq: int) -> None:
        """Event ``seq`` ends ``key``'s span (nothing if it does not hold)."""
        i = self.open.pop(key, None)
        if i is not None:
            self._end[i] = seq
            del self.current[key]

    def keep_copy(self, seq: int) -> None:
        """Keep a copy of the records that hold after event ``seq`` (the last one fed)."""
        self.copies.append((seq, dict(self.current)))

    def at(self, seq: int, last: int) -> dict[Any, Any]:
        """The records that held after event ``seq`` (key -> value), a new dict.

        Args:
            seq: Sequence number, at most ``last``.
            last: The last event fed (when :attr:`current` was true).
        """
        n = len(self.keys)
        start, end = self._start[:n], self._end[:n]
        held = (start <= seq) & (end > seq)
        # starting points: (cost, seq, records then); from nothing it costs the size of the answer
        best: tuple[float, int, dict[Any, Any] | None] = (float(np.count_nonzero(held)), -1, None)
        below = [c for c in self.copies if c[0] <= seq][-1:]
        above = [*(c for c in self.copies if c[0] > seq), (last, self.current)]
        for a_seq, records in [*below, above[0]]:
            lo, hi = min(a_seq, seq), max(a_seq, seq)
            between = np.count_nonzero((start > lo) & (start <= hi))
            between += np.count_nonzero((end > lo) & (end <= hi))
            cost = float(between) + len(records) / _COPY_ADVANTAGE
            if cost < best[0]:
                best = (cost, a_seq, records)
        keys, values = self.keys, self.values
        _, a_seq, kept = best
        if kept is None:
            idx = np.flatnonzero(held).tolist()
            return dict(zip(map(keys.__getitem__, idx), map(values.__getitem__, idx), strict=True))
        out = dict(kept)
        if a_seq <= seq:  # forward: drop what ended since the copy, add what began since and still held
            gone = (start <= a_seq) & (end > a_seq) & (end <= seq)
            came = (start > a_seq) & held
        else:  # backward: drop what began after seq and held at the copy, add what held and ended since
            gone = (start > seq) & (start <= a_seq) & (end > a_seq)
            came = held & (end <= a_seq)
        deque(map(out.__delitem__, map(keys.__getitem__, np.flatnonzero(gone).tolist())), maxlen=0)
        idx = np.flatnonzero(came).tolist()
        out.update(zip(map(keys.__getitem__, idx), map(values.__getitem__, idx), strict=True))
        return out


class Timeline:
    """The spans of a whole history (facts, goals, instances, functions, anchors), fed one event at a time.

    Args:
        base: The state before the first event (its records begin at sequence number 0).
    """

    def __init__(self, base: State) -> None:
        self.facts, self.goals, self.instances = _Spans(), _Spans(), _Spans()
        self.functions, self.anchors = _Spans(), _Spans()
        self.seq = base.seq
        self._last_copy = base.seq
        self._base_time = base.time
        for name, type_name in base.instances.items():
            self.instances.put(name, type_name, base.seq)
        for fact, prov in base.facts.items():
            self.facts.put(fact, prov, base.seq)
        for fact, prov in base.goals.items():
            self.goals.put(fact, prov, base.seq)
        for fact, value in base.functions.items():
            self.functions.put(fact, value, base.seq)
        for symbol, anchor in base.anchors.items():
            self.anchors.put(symbol, anchor, base.seq)

    @property
    def spans(self) -> int:
        """How many spans the timeline holds (records that hold now or held once)."""
        return sum(len(s) for s in self._kinds())

    def feed(self, c: Change) -> None:
        """Record one event (the next in journal order), as :func:`~knowledge_base.model.apply_change`."""
        kind, seq = c.kind, c.seq
        if kind is ChangeKind.ADD_FACT:
            self.facts.put(Fact(c.name, c.args), c.provenance, seq)
        elif kind is ChangeKind.REMOVE_FACT:
            self.facts.drop(Fact(c.name, c.args), seq)
        elif kind is ChangeKind.ADD_INSTANCE:
            self.instances.put(c.args[0], c.name, seq)
        elif kind is ChangeKind.REMOVE_INSTANCE:
            self.instances.drop(c.args[0], seq)
            self.anchors.drop(c.args[0], seq)
        elif kind is ChangeKind.ADD_GOAL:
            self.goals.put(Fact(c.name, c.args), c.provenance, seq)
        elif kind is ChangeKind.REMOVE_GOAL:
            self.goals.drop(Fact(c.name, c.args), seq)
        elif kind is ChangeKind.SET_FUNCTION:
            self.functions.put(Fact(c.name, c.args), float(c.value), seq)
        elif kind is ChangeKind.SET_ANCHOR:
            self.anchors.put(c.name, (c.value, c.provenance), seq)
        self.seq = seq
        since = seq - self._last_copy
        if since >= COPY_MIN_EVENTS and 2 * since >= self._size():
            for spans in self._kinds():
                spans.keep_copy(seq)
            self._last_copy = seq

    def _kinds(self) -> tuple[_Spans, ...]:
        return (self.facts, self.goals, self.instances, self.functions, self.anchors)

    def _size(self) -> int:
        return sum(len(s.current) for s in self._kinds())

    def state_at(self, seq: int, time: float | None) -> State:
        """The state after event ``seq`` (at most :attr:`seq`), stamped with that event's ``time``.

        ``time`` None means the base state's time (``seq`` 0).
        """
        last = self.seq
        return State(
            instances=self.instances.at(seq, last),
            facts=self.facts.at(seq, last),
            goals=self.goals.at(seq, last),
            functions=self.functions.at(seq, last),
            anchors=self.anchors.at(seq, last),
            seq=seq,
            time=self._base_time if time is None else time,
        )
