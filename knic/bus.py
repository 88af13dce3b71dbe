"""The message bus between KnIC components: hierarchical topics, time stamps and authors (seeds 000 and 003).

Topics are dot-separated names from general to specific, as in the Cognitive Map's message types
(``percept.vision.object.glasses``). A subscription pattern matches a topic when its levels match the topic's
first levels, ``*`` matching any one level; a pattern is therefore always a prefix subscription:
``percept.vision`` receives every vision percept, ``percept.*.person`` every person percept from any modality.

Every :class:`Message` carries the simulated time it was published at and the component that published it, so
the bus doubles as the seed 003 whiteboard: "at time X, module Z believed Y" (:meth:`Bus.latest`).

Topics used by the pipeline (see :mod:`knic.pipeline`):

* ``percept.<modality>.<kind>.<label>``: LLKUs from KGM-1 (modality ``vision``, ``pose``, ``audio``,
  ``device``, ``map``).
* ``cognition.<kind>.<symbol>``: CKUs from KGM-2.
* ``cognition.location.<room>``: location CKUs (one octomap per room).

Delivery is synchronous, in the publisher's call, in subscription order; the bus is single-threaded like the
scheduler that drives it. A callback that raises propagates to the publisher (a component bug must not be
hidden); the other subscribers of that message are not called.
"""

from __future__ import annotations

import functools
import itertools
import re
from collections import deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from core.errors import InferenceError

_LEVEL = re.compile(r"^[a-z0-9_]+$")

#: sets the ``__dict__`` of a frozen dataclass instance (its own ``__setattr__`` refuses)
_set_dict = object.__setattr__
_new_object = object.__new__


@dataclass(frozen=True, init=False)
class Message:
    """One published message.

    Attributes:
        topic: full hierarchical topic name.
        payload: the unit or value published (an LLKU, a CKU, a dict ...).
        source: name of the publishing component.
        stamp: simulated time of publication, seconds.
        seq: bus-wide sequence number (publication order).
    """

    topic: str
    payload: Any
    source: str
    stamp: float
    seq: int

    def __init__(self, topic: str, payload: Any, source: str, stamp: float, seq: int) -> None:
        # the dataclass's own __init__ without its per-field frozen ``object.__setattr__`` calls (one
        # message per unit published): the instance's attributes given as one dict
        _set_dict(
            self,
            "__dict__",
            {"topic": topic, "payload": payload, "source": source, "stamp": stamp, "seq": seq},
        )


def check_topic(topic: str) -> tuple[str, ...]:
    """Return the levels of a topic name.

    Raises:
        InferenceError: a level is empty or uses characters other than lower-case letters, digits and ``_``.
    """
    levels = tuple(topic.split("."))
    for level in levels:
        if not _LEVEL.match(level):
            raise InferenceError(f"bad topic {topic!r}: level {level!r} must match [a-z0-9_]+")
    return levels


@functools.lru_cache(maxsize=4096)
def topic_level(name: str) -> str:
    """Turn a free name (a symbol, a class label) into a valid topic level (lower case, ``_`` for others)."""
    level = re.sub(r"[^a-z0-9_]", "_", name.lower())
    return level or "_"


def _check_pattern(pattern: str) -> tuple[str, ...]:
    levels = tuple(pattern.split("."))
    for level in levels:
        if level != "*" and not _LEVEL.match(level):
            raise InferenceError(f"bad subscription pattern {pattern!r}: level {level!r}")
    return levels


def matches(pattern: tuple[str, ...], topic: tuple[str, ...]) -> bool:
    """True when ``pattern`` is a prefix of ``topic`` level by level, ``*`` matching any level."""
    if len(pattern) > len(topic):
        return False
    return all(p in ("*", t) for p, t in zip(pattern, topic, strict=False))


@dataclass(eq=False)
class Subscription:
    """A registered interest in a topic pattern; call :meth:`Bus.unsubscribe` (or :meth:`cancel`) to end
    it."""

    pattern: str
    levels: tuple[str, ...]
    callback: Callable[[Message], None]
    bus: Bus
    active: bool = True

    def cancel(self) -> None:
        """Stop delivery to this subscription (idempotent)."""
        self.bus.unsubscribe(self)


@dataclass(eq=False)
class Inbox:
    """A bounded queue of messages for a component to drain in its ``step()`` (pull-style consumption).

    When full, the oldest message is dropped and :attr:`dropped` counts it: a slow consumer loses old
    percepts,
    never blocks the producers.
    """

    capacity: int = 1000
    dropped: int = 0
    _queue: deque[Message] = field(default_factory=deque)

    def put(self, message: Message) -> None:
        """Queue a message (drops the oldest when full)."""
        if len(self._queue) >= self.capacity:
            self._queue.popleft()
            self.dropped += 1
        self._queue.append(message)

    def drain(self) -> list[Message]:
        """Return and remove every queued message, oldest first."""
        items = list(self._queue)
        self._queue.clear()
        return items

    def __len__(self) -> int:
        return len(self._queue)


class Bus:
    """Publish/subscribe on hierarchical topics, with a latest-value cache per topic (the whiteboard view)
    and a bounded history of each topic's recent messages (:meth:`recent`).

    Args:
        history: messages kept per topic (the oldest goes when a new one comes); 0 keeps none.
    """

    def __init__(self, history: int = 20) -> None:
        self._subs: list[Subscription] = []
        #: topic -> the subscriptions matching it, as a tuple: never changed in place (a subscription made
        #: or ended clears the cache), so a delivery in progress goes on over the routes it started with
        self._route_cache: dict[str, tuple[Subscription, ...]] = {}
        self._latest: dict[str, Message] = {}
        self._history: dict[str, deque[Message]] = {}
        self.history = max(0, history)
        self._seq = itertools.count(1)
        self.published = 0

    def subscribe(self, pattern: str, callback: Callable[[Message], None]) -> Subscription:
        """Call ``callback(message)`` for every message whose topic matches ``pattern`` from now on.

        Raises:
            InferenceError: the pattern is not a valid topic pattern.
        """
        sub = Subscription(pattern, _check_pattern(pattern), callback, self)
        self._subs.append(sub)
        self._route_cache.clear()
        return sub

    def inbox(self, pattern: str, capacity: int = 1000) -> Inbox:
        """Subscribe a new bounded :class:`Inbox` to ``pattern`` and return it."""
        box = Inbox(capacity=capacity)
        self.subscribe(pattern, box.put)
        return box

    def unsubscribe(self, sub: Subscription) -> None:
        """End a subscription; messages published later are not delivered to it (idempotent)."""
        if sub.active:
            sub.active = False
            self._subs.remove(sub)
            self._route_cache.clear()

    def publish(self, topic: str, payload: Any, *, source: str, stamp: float) -> Message:
        """Publish ``payload`` on ``topic``, signed by ``source`` at simulated time ``stamp``.

        Raises:
            InferenceError: the topic name is invalid or ``source`` is empty; nothing is delivered.
        """
        route = self._route_cache.get(topic)
        if route is None:
            levels = check_topic(topic)
            route = tuple(s for s in self._subs if matches(s.levels, levels))
            self._route_cache[topic] = route
        if not source:
            raise InferenceError(f"message on {topic!r} has no publishing component")
        # Message(topic, payload, source, stamp, seq) without the class call (one per unit published)
        message: Message = _new_object(Message)
        _set_dict(
            message,
            "__dict__",
            {
                "topic": topic,
                "payload": payload,
                "source": source,
                "stamp": float(stamp),
                "seq": next(self._seq),
            },
        )
        self._latest[topic] = message
        recent = self._history.get(topic)
        if recent is None:
            recent = self._history[topic] = deque(maxlen=self.history)
        recent.append(message)
        self.published += 1
        for sub in route:  # a tuple nobody changes: no copy needed for callbacks that (un)subscribe
            if sub.active:
                sub.callback(message)
        return message

    def latest(self, pattern: str) -> list[Message]:
        """The most recent message of every topic matching ``pattern``, in publication order."""
        levels = _check_pattern(pattern)
        found = [m for t, m in self._latest.items() if matches(levels, tuple(t.split(".")))]
        return sorted(found, key=lambda m: m.seq)

    def recent(self, pattern: str = "*") -> dict[str, list[Message]]:
        """The kept recent messages (oldest first) of every topic matching ``pattern``, by topic name.

        Raises:
            InferenceError: the pattern is not a valid topic pattern.
        """
        levels = _check_pattern(pattern)
        return {t: list(m) for t, m in sorted(self._history.items()) if matches(levels, tuple(t.split(".")))}

    def topics(self) -> Iterator[str]:
        """Every topic published so far."""
        return iter(sorted(self._latest))
