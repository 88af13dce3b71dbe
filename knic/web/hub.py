"""The server's live loop: follow the journal, the trace and the running system; fan out server-sent events.

One :class:`Hub` per app. On the server's event-loop thread it opens the :class:`~knic.web.view.JournalView`
(SQLite connections belong to their thread), then polls every ``poll_s`` wall seconds: new journal events,
new trace events and, when a run is attached, a new live snapshot (at most ``live_hz`` a second). Each is
formatted once as an SSE message and queued to every connected page.

Events (``event:`` name, ``data:`` JSON):

* ``changes``: ``{"seq": last, "changes": [change records]}``, in journal order; ``id`` is the last seq;
* ``trace``: ``{"after": n, "events": [trace events]}`` (events after the first ``n``);
* ``live``: the run's snapshot (:mod:`knic.web.live`);
* ``score``: the Granny Annie referee's running score, when the run writes one beside its journal
  (:mod:`knic.bench.granny_annie.livescore`);
* ``reset``: the page fell too far behind; it reloads the state (``/api/facts``) and reconnects.

A page that connects with ``after=SEQ`` first gets the journal events after ``SEQ`` (so nothing is lost
between loading ``/api/facts`` and connecting), then the live events.

Following a journal alone (``knic serve``), the hub also keeps page loads quick at 10k facts and more: the
whole fact table a page loads first is encoded once per journal seq (ahead of time once the journal rests
:data:`WARM_IDLE_S`), and the objects the view holds are kept out of the collector's full passes
(:meth:`Hub._freeze_gc`).
"""

from __future__ import annotations

import asyncio
import contextlib
import gc
import json
import logging
import time
from collections.abc import AsyncIterator, Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import KnicError
from knic.web.view import JournalView, TraceSource, change_record

if TYPE_CHECKING:
    from knic.web.live import LiveLink

log = logging.getLogger(__name__)

#: journal events per SSE message; a page further behind than BACKLOG_LIMIT events gets a reset
CHUNK, BACKLOG_LIMIT = 2000, 20000
#: messages queued per page before it counts as too slow (it gets a reset)
QUEUE_SIZE = 500
#: seconds between keep-alive comments on an idle stream
KEEPALIVE_S = 15.0
#: wall seconds without a journal write after which the fact table is encoded ahead of the next page load
WARM_IDLE_S = 1.0
#: journal events read after which the collector is frozen again (see :meth:`Hub._freeze_gc`)
FREEZE_AFTER = 5000


def sse(event: str, data: Any, event_id: int | None = None) -> str:
    """One server-sent event (``data`` as compact JSON on one line)."""
    head = f"id: {event_id}\n" if event_id is not None else ""
    return f"{head}event: {event}\ndata: {json.dumps(data, separators=(',', ':'))}\n\n"


class Hub:
    """Follows the run's files and the live link; keeps the connected pages' queues (see module docstring).

    Args:
        open_view: opens the journal view (called on the event-loop thread, in :meth:`start`).
        live: the running system's link (``knic run --serve``), or None when following files only.
        trace: the trace source when following files (the live link is the trace source of a run).
        poll_s: wall seconds between two polls.
        live_hz: most live snapshots sent per wall second.
        score: the run's score file (:func:`knic.bench.granny_annie.livescore.score_path`), followed when it
            appears; None: no score.
    """

    def __init__(
        self,
        open_view: Callable[[], JournalView],
        *,
        live: LiveLink | None = None,
        trace: TraceSource | None = None,
        poll_s: float = 0.05,
        live_hz: float = 4.0,
        score: Path | None = None,
    ) -> None:
        self._open_view = open_view
        self.live = live
        self.trace: TraceSource | None = live if live is not None else trace
        self.poll_s = poll_s
        self.live_period = 1.0 / live_hz
        self._view: JournalView | None = None
        self._queues: set[asyncio.Queue[str | None]] = set()
        self._task: asyncio.Task[None] | None = None
        self.trace_count = 0
        self._live_version = -1
        self._live_sent = 0.0
        self._unfrozen = 0
        self._whole: tuple[int, bytes] | None = None
        self._changed_at = 0.0
        self.score_file = score
        self.score: dict[str, Any] | None = None
        self._score_stamp: tuple[int, int] | None = None

    @property
    def view(self) -> JournalView:
        """The journal view (open between :meth:`start` and :meth:`stop`)."""
        if self._view is None:
            raise KnicError("the web view's journal is not open")
        return self._view

    async def start(self) -> None:
        """Open the view and start polling (event-loop thread)."""
        self._view = self._open_view()
        self._freeze_gc()
        if self.trace is not None:
            self.trace_count = len(self.trace.events())
        self._task = asyncio.create_task(self._poll())

    async def stop(self) -> None:
        """Stop polling, end every stream, close the view."""
        if self._task is not None:
            self._task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._task
        for q in list(self._queues):
            self._put(q, None)
        if self._view is not None:
            self._view.close()
            self._view = None
        if self.live is None:
            gc.unfreeze()  # what was frozen is the collector's again

    # ------------------------------------------------------------------ polling
    async def _poll(self) -> None:
        while True:
            await asyncio.sleep(self.poll_s)
            try:
                seq = self.view.seq
                self.poll_once()
                now = time.monotonic()
                if self.view.seq != seq:
                    self._changed_at = now
                elif self.live is None and now - self._changed_at >= WARM_IDLE_S:
                    self.whole_facts()  # the journal rests: the next page load finds its table ready
            except KnicError as exc:  # the writer may be mid-way; the next poll retries
                log.warning("web view: %s", exc)

    def whole_facts(self) -> bytes:
        """``/api/facts?compact=true`` now, encoded once per journal seq (what every page loads first)."""
        seq = self.view.seq
        if self._whole is None or self._whole[0] != seq:
            body = self.view.facts(compact=True)
            text = json.dumps(body, ensure_ascii=False, allow_nan=False, separators=(",", ":"))
            self._whole = (seq, text.encode())
        return self._whole[1]

    def poll_once(self) -> None:
        """Read what is new and queue it to every page (event-loop thread)."""
        changes = self.view.refresh()
        self._unfrozen += len(changes)
        if self._unfrozen >= FREEZE_AFTER:
            self._freeze_gc()
        for start in range(0, len(changes), CHUNK):
            part = changes[start : start + CHUNK]
            records = [change_record(c) for c in part]
            self._publish(sse("changes", {"seq": part[-1].seq, "changes": records}, part[-1].seq))
        if self.trace is not None:
            events = self.trace.events(self.trace_count)
            if events:
                self._publish(sse("trace", {"after": self.trace_count, "events": events}))
                self.trace_count += len(events)
        live = self.live
        now = time.monotonic()
        if (
            live is not None
            and live.version != self._live_version
            and now - self._live_sent >= self.live_period
        ):
            self._live_version = live.version
            self._live_sent = now
            self._publish(sse("live", live.snapshot))
        if self._read_score():
            self._publish(sse("score", self.score))

    def _freeze_gc(self) -> None:
        """Following a journal alone (``knic serve``), the process is the server's: after a collection, the
        objects alive now (the view's knowledge base: several per fact) move out of the collector's sight
        (:func:`gc.freeze`), so a full collection, which would otherwise walk every one of them and hold a
        request up for a few hundred milliseconds at 10k facts, walks only what the requests allocate. A run
        (``knic run --serve``) owns its process's collector: nothing is frozen there."""
        self._unfrozen = 0
        if self.live is None:
            gc.collect()
            gc.freeze()

    def _read_score(self) -> bool:
        """Read the score file when it changed (a stat per poll); whether the score is new."""
        if self.score_file is None:
            return False
        from knic.bench.granny_annie.livescore import read_score

        try:
            st = self.score_file.stat()
        except OSError:
            return False
        stamp = (st.st_mtime_ns, st.st_size)
        if stamp == self._score_stamp:
            return False
        self._score_stamp = stamp
        score = read_score(self.score_file)
        if score is None or score == self.score:
            return False
        self.score = score
        return True

    def _publish(self, message: str) -> None:
        for q in list(self._queues):
            self._put(q, message)

    def _put(self, q: asyncio.Queue[str | None], message: str | None) -> None:
        if q.qsize() >= QUEUE_SIZE - 1 and message is not None:
            while not q.empty():
                q.get_nowait()
            message = sse("reset", {"reason": "too far behind"})
        q.put_nowait(message)

    # ------------------------------------------------------------------ streams
    async def stream(self, after: int, trace_after: int) -> AsyncIterator[str]:
        """One page's event stream: the backlog after ``after`` / ``trace_after``, then live events."""
        with contextlib.suppress(KnicError):
            self.poll_once()  # what the writer appended so far goes to the backlog below, not twice
        q: asyncio.Queue[str | None] = asyncio.Queue(maxsize=QUEUE_SIZE)
        self._queues.add(q)
        try:
            view = self.view
            backlog: list[str] = []
            if view.seq - after > BACKLOG_LIMIT:
                backlog.append(sse("reset", {"reason": "too far behind"}))
            elif after < view.seq:
                records = view.changes_after(after, BACKLOG_LIMIT)
                for start in range(0, len(records), CHUNK):
                    part = records[start : start + CHUNK]
                    backlog.append(sse("changes", {"seq": part[-1]["seq"], "changes": part}, part[-1]["seq"]))
            if self.trace is not None and trace_after < self.trace_count:
                events = self.trace.events(trace_after)[: self.trace_count - trace_after]
                backlog.append(sse("trace", {"after": trace_after, "events": events}))
            if self.live is not None:
                backlog.append(sse("live", self.live.snapshot))
            if self.score is not None:
                backlog.append(sse("score", self.score))
            yield sse("hello", {"seq": view.seq, "trace": self.trace_count})
            for message in backlog:
                yield message
            while True:
                try:
                    item = await asyncio.wait_for(q.get(), KEEPALIVE_S)
                except TimeoutError:
                    yield ": keep-alive\n\n"
                    continue
                if item is None:
                    return
                yield item
        finally:
            self._queues.discard(q)
