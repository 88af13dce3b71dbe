"""The component scheduler: BICA-style ``step()`` components at their own frequencies in simulated time (seed
001).

Lifecycle of a :class:`Component`: construct it offline (no simulator needed), register it with
:meth:`Scheduler.add`, and the scheduler calls ``step(now)`` whenever its period has elapsed in **simulated
time**; removing it is a quiet shutdown: its ``step`` is simply not called any more, so a component never
assumes it will be called again. There is one loop and one thread: steps never overlap, and a step that takes
too long delays the others without cancelling any (graceful degradation).

The scheduler reports two kinds of overrun as :class:`SchedulerEvent` (and a ``logging`` warning):

* ``slow_step``: a step's wall-clock time exceeded its period divided by the real-time factor (at factor 10 a
  10 Hz component has 10 ms of wall time per step).
* ``behind``: when a component came due, at least one whole period had already passed since its due time (the
  loop is not ticking often enough, or earlier steps took too long); missed periods are skipped, not replayed.
"""

from __future__ import annotations

import logging
import time
from abc import ABC, abstractmethod
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from core.errors import InferenceError

log = logging.getLogger(__name__)


class Component(ABC):
    """A unit of periodic work (a KP, the cognitive layer, a KP').

    Subclasses set :attr:`name` and :attr:`frequency` (Hz of simulated time) and implement :meth:`step`.
    """

    name: str = "component"
    frequency: float = 1.0

    @abstractmethod
    def step(self, now: float) -> None:
        """Do one iteration of work at simulated time ``now`` (seconds); must return promptly.

        Called by the scheduler only, never re-entrantly. Errors propagate to the loop (a bug is not hidden).
        """


@dataclass(frozen=True)
class SchedulerEvent:
    """An overrun report: ``kind`` is ``"slow_step"`` or ``"behind"``.

    Attributes:
        kind: which overrun.
        component: the component's name.
        now: simulated time of the step, seconds.
        period_s: the component's period in simulated seconds.
        wall_s: wall-clock duration of the step (``slow_step``), seconds.
        budget_s: the wall-clock budget it exceeded (``slow_step``), seconds.
        missed: whole periods skipped (``behind``).
    """

    kind: str
    component: str
    now: float
    period_s: float
    wall_s: float = 0.0
    budget_s: float = 0.0
    missed: int = 0


@dataclass
class ComponentStats:
    """Per-component counters: steps run, total and worst wall time and total process CPU time (seconds),
    overruns reported."""

    steps: int = 0
    wall_s: float = 0.0
    cpu_s: float = 0.0
    max_wall_s: float = 0.0
    slow_steps: int = 0
    behind: int = 0


@dataclass
class _Entry:
    component: Component
    period: float
    next_due: float
    stats: ComponentStats = field(default_factory=ComponentStats)


class Scheduler:
    """Steps registered components when due, in registration order, one at a time.

    Args:
        real_time_factor: how many simulated seconds pass per wall second when the loop runs at full speed;
            scales the wall-clock budget of a step (period / factor).
        on_event: called with every overrun event (besides the ``logging`` warning).
        wall_clock: wall-clock source in seconds (``time.perf_counter``); tests may substitute it.
        max_events: how many recent overrun events :attr:`events` keeps (the counters in :meth:`stats` keep
            counting).
        warn_interval_s: simulated seconds between two logged warnings of one component and kind; the
            overruns in between are counted and mentioned in the next warning (every event still reaches
            :attr:`events` and ``on_event``).
    """

    def __init__(
        self,
        *,
        real_time_factor: float = 1.0,
        on_event: Callable[[SchedulerEvent], None] | None = None,
        wall_clock: Callable[[], float] = time.perf_counter,
        max_events: int = 10000,
        warn_interval_s: float = 10.0,
    ) -> None:
        if real_time_factor <= 0:
            raise InferenceError(f"scheduler real_time_factor must be > 0, got {real_time_factor}")
        self.real_time_factor = real_time_factor
        self.on_event = on_event
        self.events: deque[SchedulerEvent] = deque(maxlen=max_events)
        self._wall = wall_clock
        self.warn_interval_s = warn_interval_s
        self._warned: dict[tuple[str, str], float] = {}
        self._suppressed: dict[tuple[str, str], int] = {}
        self._entries: dict[str, _Entry] = {}
        self._running = False

    def add(self, component: Component, *, start: float = 0.0) -> None:
        """Register ``component``; it is first due at simulated time ``start``.

        Raises:
            InferenceError: the name is already registered or the frequency is not positive.
        """
        if component.name in self._entries:
            raise InferenceError(f"scheduler: a component named {component.name!r} is already registered")
        if not component.frequency > 0:
            raise InferenceError(
                f"scheduler: component {component.name!r} has frequency {component.frequency}"
            )
        self._entries[component.name] = _Entry(component, 1.0 / component.frequency, start)

    def remove(self, name: str) -> bool:
        """Quiet shutdown: ``name`` is not stepped any more. False if it was not registered."""
        return self._entries.pop(name, None) is not None

    @property
    def components(self) -> list[Component]:
        """Registered components in stepping order."""
        return [e.component for e in self._entries.values()]

    def stats(self) -> dict[str, ComponentStats]:
        """Counters per component name."""
        return {name: e.stats for name, e in self._entries.items()}

    def report(self, sim_time: float) -> list[dict[str, float | int | str]]:
        """Per component, in stepping order (JSON-able): ``name``, nominal ``frequency`` and measured ``rate``
        (steps per simulated second over ``sim_time``), ``steps``, ``mean_ms`` and ``max_ms`` of wall time per
        step, ``cpu_s``, and the overruns: ``slow_steps``, ``behind`` and their sum ``overruns``."""
        out: list[dict[str, float | int | str]] = []
        for name, e in self._entries.items():
            s = e.stats
            out.append(
                {
                    "name": name,
                    "frequency": e.component.frequency,
                    "rate": s.steps / sim_time if sim_time > 0 else 0.0,
                    "steps": s.steps,
                    "mean_ms": 1000.0 * s.wall_s / s.steps if s.steps else 0.0,
                    "max_ms": 1000.0 * s.max_wall_s,
                    "cpu_s": s.cpu_s,
                    "slow_steps": s.slow_steps,
                    "behind": s.behind,
                    "overruns": s.slow_steps + s.behind,
                }
            )
        return out

    def next_due(self) -> float | None:
        """Earliest simulated time at which a component is due, or None when none is registered."""
        return min((e.next_due for e in self._entries.values()), default=None)

    def tick(self, now: float) -> list[str]:
        """Step every component due at simulated time ``now``; return their names in stepping order.

        Raises:
            InferenceError: called from inside a step (steps never overlap).
        """
        if self._running:
            raise InferenceError("scheduler.tick called from inside a component step; steps never overlap")
        self._running = True
        stepped: list[str] = []
        try:
            for entry in list(self._entries.values()):
                if entry.next_due > now + 1e-9 or entry.component.name not in self._entries:
                    continue
                missed = int((now - entry.next_due) / entry.period + 1e-9)
                if missed >= 1 and entry.stats.steps == 0:  # a late first tick is not an overrun
                    entry.next_due = now + entry.period
                elif missed >= 1:
                    entry.stats.behind += 1
                    self._report(
                        SchedulerEvent("behind", entry.component.name, now, entry.period, missed=missed)
                    )
                    entry.next_due = now + entry.period
                else:
                    entry.next_due += entry.period
                start, cpu_start = self._wall(), time.process_time()
                entry.component.step(now)
                wall = self._wall() - start
                entry.stats.cpu_s += time.process_time() - cpu_start
                stepped.append(entry.component.name)
                self._account(entry, now, wall)
        finally:
            self._running = False
        return stepped

    def run(
        self, until: float, *, start: float = 0.0, before_tick: Callable[[float], None] | None = None
    ) -> None:
        """Advance simulated time from ``start`` to ``until`` jumping from due time to due time.

        ``before_tick(t)`` runs before each tick (a loop advances its simulator to ``t`` there).
        """
        now = start
        while True:
            due = self.next_due()
            if due is None:
                return
            now = max(now, due)
            if now > until:
                return
            if before_tick is not None:
                before_tick(now)
            self.tick(now)

    def _account(self, entry: _Entry, now: float, wall: float) -> None:
        stats = entry.stats
        stats.steps += 1
        stats.wall_s += wall
        stats.max_wall_s = max(stats.max_wall_s, wall)
        budget = entry.period / self.real_time_factor
        if wall > budget:
            stats.slow_steps += 1
            self._report(
                SchedulerEvent(
                    "slow_step", entry.component.name, now, entry.period, wall_s=wall, budget_s=budget
                )
            )

    def _report(self, event: SchedulerEvent) -> None:
        self.events.append(event)
        if self.on_event is not None:
            self.on_event(event)
        key = (event.component, event.kind)
        last = self._warned.get(key)
        if last is not None and event.now - last < self.warn_interval_s:
            self._suppressed[key] = self._suppressed.get(key, 0) + 1
            return
        self._warned[key] = event.now
        more = self._suppressed.pop(key, 0)
        log.warning(
            "component %s overrun (%s) at t=%.3f: period %.3fs, wall %.4fs, budget %.4fs, missed %d%s",
            event.component,
            event.kind,
            event.now,
            event.period_s,
            event.wall_s,
            event.budget_s,
            event.missed,
            f" ({more} more since the previous warning)" if more else "",
        )
