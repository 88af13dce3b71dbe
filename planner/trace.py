"""The execution trace: what the dispatcher planned, dispatched, and how each action and goal ended.

Every event has a kind, the time on the dispatcher's clock (the knowledge base's clock: simulated seconds in
the closed loop, wall-clock seconds otherwise) and the plan or action concerned. Subscribers are called
synchronously, in order, when an event is emitted; the trace can also write each event as one JSON line to a
stream and print it readably.
"""

from __future__ import annotations

import enum
import json
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TextIO


class EventKind(enum.StrEnum):
    """The kinds of trace events."""

    PLAN = "plan"
    DISPATCH = "dispatch"
    ACTIVATION = "activation"
    SUCCESS = "success"
    FAILURE = "failure"
    REPLAN = "replan"
    GOAL_ACHIEVED = "goal_achieved"
    GOAL_DROPPED = "goal_dropped"
    TASK = "task"  # a step of a task flow (the Granny Annie dialogue): ``action`` names it

    def __str__(self) -> str:
        return self.value


@dataclass(frozen=True)
class TraceEvent:
    """One trace event.

    Attributes:
        kind: what happened.
        time: dispatcher clock time in seconds.
        action: the action concerned, as ``(name arg1 arg2)`` (dispatch, activation, success, failure).
        plan: the plan's steps as ``(name ...)`` strings (plan events).
        outcome: the named outcome (failure and success events), e.g. ``"execution failure"``.
        reason: one line explaining a failure, a replan or a dropped goal.
        goal: the goal concerned, as ``(predicate arg ...)`` (goal events).
        data: extra figures (e.g. ``planning_ms``, ``engine``).
    """

    kind: EventKind
    time: float
    action: str | None = None
    plan: tuple[str, ...] | None = None
    outcome: str | None = None
    reason: str | None = None
    goal: str | None = None
    data: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """A JSON-able dict without the empty fields."""
        out: dict[str, Any] = {"kind": self.kind.value, "time": round(self.time, 6)}
        for key in ("action", "outcome", "reason", "goal"):
            value = getattr(self, key)
            if value is not None:
                out[key] = value
        if self.plan is not None:
            out["plan"] = list(self.plan)
        if self.data:
            out["data"] = self.data
        return out

    def to_json(self) -> str:
        """The event as one JSON line (no newline)."""
        return json.dumps(self.to_dict(), sort_keys=True)

    def __str__(self) -> str:
        head = f"{self.time:9.2f}  {self.kind.value:<13} "
        if self.kind == EventKind.PLAN and self.plan is not None:
            extra = f" ({self.data['planning_ms']:.1f} ms)" if "planning_ms" in self.data else ""
            body = f"{len(self.plan)} steps{extra}: " + " ".join(self.plan)
        elif self.goal is not None:
            body = self.goal + (f": {self.reason}" if self.reason else "")
        else:
            body = self.action or ""
            if self.outcome and self.kind == EventKind.FAILURE:
                body += f" -> {self.outcome}"
            if self.reason:
                body += f" ({self.reason})" if body else self.reason
        return (head + body).rstrip()


Subscriber = Callable[[TraceEvent], None]


class Trace:
    """Collects trace events; subscribers and an optional JSON-lines stream see each one as it happens.

    Args:
        jsonl: a text stream that receives one JSON line per event (flushed each time), or ``None``.
        keep: keep the events in :attr:`events` (switch off for endless runs).
    """

    def __init__(self, jsonl: TextIO | None = None, *, keep: bool = True) -> None:
        self.events: list[TraceEvent] = []
        self._keep = keep
        self._jsonl = jsonl
        self._subscribers: list[Subscriber] = []

    def subscribe(self, callback: Subscriber) -> Callable[[], None]:
        """Call ``callback(event)`` for every later event. Returns the unsubscribe function."""
        self._subscribers.append(callback)

        def unsubscribe() -> None:
            if callback in self._subscribers:
                self._subscribers.remove(callback)

        return unsubscribe

    def emit(self, event: TraceEvent) -> None:
        """Record ``event``, write it to the JSON-lines stream, and pass it to every subscriber."""
        if self._keep:
            self.events.append(event)
        if self._jsonl is not None:
            self._jsonl.write(event.to_json() + "\n")
            self._jsonl.flush()
        for callback in list(self._subscribers):
            callback(event)

    def of_kind(self, kind: EventKind | str) -> list[TraceEvent]:
        """The kept events of one kind, in order."""
        wanted = EventKind(kind)
        return [e for e in self.events if e.kind == wanted]

    def print_to(self, stream: TextIO) -> Callable[[], None]:
        """Print every later event readably on ``stream``, one line each. Returns the unsubscribe function."""

        def show(event: TraceEvent) -> None:
            stream.write(str(event) + "\n")
            stream.flush()

        return self.subscribe(show)
