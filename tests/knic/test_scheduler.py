"""The component scheduler: rates in simulated time, overrun reports, no overlapping steps, quiet shutdown."""

from __future__ import annotations

import pytest

from core.errors import InferenceError
from knic.scheduler import Component, Scheduler, SchedulerEvent


class Recorder(Component):
    def __init__(self, name: str, frequency: float, log: list[tuple[str, float]]) -> None:
        self.name = name
        self.frequency = frequency
        self.log = log

    def step(self, now: float) -> None:
        self.log.append((self.name, now))


def test_components_run_at_their_own_rates_in_registration_order() -> None:
    log: list[tuple[str, float]] = []
    sched = Scheduler()
    sched.add(Recorder("fast", 10.0, log))
    sched.add(Recorder("slow", 2.0, log))
    sched.run(until=1.0)
    fast = [t for n, t in log if n == "fast"]
    slow = [t for n, t in log if n == "slow"]
    assert fast == pytest.approx([i / 10 for i in range(11)])
    assert slow == pytest.approx([0.0, 0.5, 1.0])
    assert log[:2] == [("fast", 0.0), ("slow", 0.0)]
    assert list(sched.events) == []


def test_slow_step_is_reported_against_the_scaled_budget() -> None:
    wall = iter([0.0, 0.03, 1.0, 1.001])  # first step takes 30 ms of wall time, the second 1 ms
    sched = Scheduler(real_time_factor=10.0, wall_clock=lambda: next(wall))
    seen: list[SchedulerEvent] = []
    sched.on_event = seen.append
    sched.add(Recorder("vision", 5.0, []))  # 0.2 s period / factor 10 = 20 ms budget
    sched.tick(0.0)
    sched.tick(0.2)
    assert [(e.kind, e.component) for e in sched.events] == [("slow_step", "vision")]
    assert isinstance(sched.events[0], SchedulerEvent)
    assert sched.events[0].budget_s == pytest.approx(0.02)
    assert sched.events[0].wall_s == pytest.approx(0.03)
    assert seen == list(sched.events)
    assert sched.stats()["vision"].steps == 2 and sched.stats()["vision"].slow_steps == 1


def test_falling_behind_is_reported_and_missed_periods_are_skipped() -> None:
    log: list[tuple[str, float]] = []
    sched = Scheduler()
    sched.add(Recorder("kp", 10.0, log))
    sched.tick(0.0)
    sched.tick(1.0)  # nine whole periods went by unserved
    sched.tick(1.05)  # not due yet: the next due time is 1.1, not a burst of catch-up steps
    assert [t for _, t in log] == [0.0, 1.0]
    assert [(e.kind, e.missed) for e in sched.events] == [("behind", 9)]


def test_a_late_first_tick_is_not_an_overrun() -> None:
    log: list[tuple[str, float]] = []
    sched = Scheduler()
    sched.add(Recorder("kp", 10.0, log))
    sched.tick(0.1)  # the loop's first tick comes after its first simulation step
    sched.tick(0.2)
    assert [t for _, t in log] == [0.1, 0.2] and list(sched.events) == []


def test_steps_never_overlap() -> None:
    sched = Scheduler()

    class Reentrant(Component):
        name = "bad"
        frequency = 1.0

        def step(self, now: float) -> None:
            sched.tick(now)

    sched.add(Reentrant())
    with pytest.raises(InferenceError, match="never overlap"):
        sched.tick(0.0)
    sched.remove("bad")
    assert sched.tick(1.0) == []


def test_quiet_shutdown_and_bad_registrations() -> None:
    log: list[tuple[str, float]] = []
    sched = Scheduler()
    sched.add(Recorder("a", 1.0, log))
    with pytest.raises(InferenceError, match="already registered"):
        sched.add(Recorder("a", 1.0, log))
    with pytest.raises(InferenceError, match="frequency"):
        sched.add(Recorder("b", 0.0, log))
    sched.tick(0.0)
    assert sched.remove("a") and not sched.remove("a")
    sched.tick(5.0)
    assert log == [("a", 0.0)] and sched.next_due() is None


def test_overrun_warnings_are_rate_limited_but_every_event_is_kept(caplog: pytest.LogCaptureFixture) -> None:
    ticks = iter(float(i) for i in range(100))  # every step takes one wall second
    sched = Scheduler(real_time_factor=2.0, wall_clock=lambda: next(ticks), warn_interval_s=10.0)
    sched.add(Recorder("slow", 1.0, []))
    with caplog.at_level("WARNING", logger="knic.scheduler"):
        for t in range(12):
            sched.tick(float(t))
    assert len(sched.events) == 12 and sched.stats()["slow"].slow_steps == 12
    warnings = [r.getMessage() for r in caplog.records]
    assert len(warnings) == 2 and "9 more since the previous warning" in warnings[1]
