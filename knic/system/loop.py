"""The run loop: the scheduler advanced in simulated time until a stop condition fires.

A :class:`RunLoop` owns no parts; it steps a :class:`~knic.scheduler.Scheduler` from due time to due time and,
every ``check_period_s`` of simulated time, calls its check hooks (tests and benchmarks sample the state
there)
and then its stop conditions in the order they were added. The first condition that returns a value ends the
run; reaching ``until`` ends it too. Benchmarks add probes (:meth:`RunLoop.add_probe`, scheduled components
stepped after the parts at their own rate) and hooks instead of rewiring an assembled system.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

from knic.scheduler import Component, Scheduler

T = TypeVar("T")


class Probe(Component):
    """A measuring component: calls ``fn(now)`` at ``frequency`` Hz of simulated time."""

    def __init__(self, name: str, frequency: float, fn: Callable[[float], None]) -> None:
        self.name = name
        self.frequency = frequency
        self.fn = fn

    def step(self, now: float) -> None:
        """Call the probe's function at simulated time ``now``."""
        self.fn(now)


@dataclass(frozen=True)
class LoopEnd(Generic[T]):
    """How :meth:`RunLoop.run` ended: the stop condition's value (None when ``until`` was reached)."""

    stop: T | None
    sim_time: float


class RunLoop(Generic[T]):
    """Steps a scheduler until a stop condition returns a value (see the module docstring).

    Args:
        scheduler: the assembled scheduler (parts registered in stepping order).
        check_period_s: simulated seconds between two checks.
    """

    def __init__(self, scheduler: Scheduler, check_period_s: float = 0.5) -> None:
        self.scheduler = scheduler
        self.check_period_s = check_period_s
        self.stops: list[Callable[[float], T | None]] = []
        self.hooks: list[Callable[[float], None]] = []

    def add_stop(self, condition: Callable[[float], T | None]) -> None:
        """Add a stop condition, called at each check with the simulated time; a non-None value stops."""
        self.stops.append(condition)

    def add_hook(self, hook: Callable[[float], None]) -> None:
        """Add a hook called at each check (before the stop conditions) with the simulated time."""
        self.hooks.append(hook)

    def add_probe(self, name: str, frequency: float, fn: Callable[[float], None]) -> None:
        """Schedule ``fn(now)`` at ``frequency`` Hz, stepped after every part registered so far."""
        self.scheduler.add(Probe(name, frequency, fn))

    def run(self, until: float) -> LoopEnd[T]:
        """Advance simulated time until a stop condition fires or the next due time is past ``until``."""
        next_check = 0.0
        now = 0.0
        while True:
            due = self.scheduler.next_due()
            if due is None or due > until + 1e-9:
                return LoopEnd(None, now)
            self.scheduler.tick(due)
            now = due
            if due + 1e-9 < next_check:
                continue
            next_check = due + self.check_period_s
            for hook in self.hooks:
                hook(due)
            for condition in self.stops:
                stop = condition(due)
                if stop is not None:
                    return LoopEnd(stop, due)
