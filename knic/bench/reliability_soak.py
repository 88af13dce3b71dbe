"""The simulated soak of ``knic bench reliability``: the closed loop running errands for a long stretch of
simulated time, as fast as the simulator allows, with the process's resident memory sampled.

The robot runs errands in the simulated apartment, one after the other, in turn: carry the glasses to a
room, then go to another room (an errand that stays reachable whatever the robot believes about the
glasses). The next errand is given when the robot believes the previous one achieved, gave it up, or
``errand_s`` simulated seconds passed, until ``sim_s`` simulated seconds have passed. Resident memory (RSS,
from ``/proc/self/statm``) is sampled every ``sample_s`` simulated seconds.

Figures: ``errands`` given and ``reached`` (the referee found the goal holding in the ground truth),
``rss_start_mb`` (first sample, after the first errand began), ``rss_end_mb``, ``rss_peak_mb``,
``rss_slope_mb_per_h`` (least-squares slope over the second half of the samples, per simulated hour: a flat
process stays near 0), the knowledge base's history length (``journal_events``: the history is kept by
design and grows with the run), simulated and wall seconds, and why each errand not reached was missed
(``missed``; the last one may be cut off by the end).
"""

from __future__ import annotations

import os
import time
from typing import Any

__all__ = ["rss_mb", "soak"]

#: the errands, in turn
ERRANDS = (
    "(object_at glasses kitchen)",
    "(robot_at r2d2 bedroom)",
    "(object_at glasses living_room)",
    "(robot_at r2d2 entrance)",
    "(object_at glasses bedroom)",
    "(robot_at r2d2 kitchen)",
    "(object_at glasses entrance)",
    "(robot_at r2d2 living_room)",
)
WORLD = "erl_home_paper"


def rss_mb() -> float:
    """The process's resident memory now, in MB (``/proc/self/statm``; 0 where there is no /proc)."""
    try:
        with open("/proc/self/statm", encoding="ascii") as handle:
            pages = int(handle.read().split()[1])
    except (OSError, ValueError, IndexError):
        return 0.0
    return pages * os.sysconf("SC_PAGE_SIZE") / 1e6


def _slope_per_hour(samples: list[tuple[float, float]]) -> float:
    """Least-squares slope of (simulated seconds, MB) samples, in MB per simulated hour."""
    if len(samples) < 2:
        return 0.0
    n = len(samples)
    mt = sum(t for t, _ in samples) / n
    mm = sum(m for _, m in samples) / n
    var = sum((t - mt) ** 2 for t, _ in samples)
    if var == 0:
        return 0.0
    return sum((t - mt) * (m - mm) for t, m in samples) / var * 3600.0


def soak(
    sim_s: float = 3600.0, *, seed: int = 0, sample_s: float = 30.0, errand_s: float = 600.0
) -> dict[str, Any]:
    """Run errands for ``sim_s`` simulated seconds and report (see the module docstring)."""
    from knic.system import KnicSystem, RunConfig

    samples: list[tuple[float, float]] = []
    next_sample = [0.0]

    def sample(system: KnicSystem) -> None:
        now = system.sim.time
        if now >= next_sample[0]:
            samples.append((now, rss_mb()))
            next_sample[0] = now + sample_s

    errands = reached = 0
    missed: list[str] = []
    wall = time.perf_counter()
    with KnicSystem(RunConfig(world=WORLD, seed=seed, max_sim_time=sim_s)) as system:
        while system.sim.time < sim_s:
            for old in system.kb.goals():
                system.kb.remove_goal(old.predicate, *old.args, source="soak")
            goal = ERRANDS[errands % len(ERRANDS)]
            atom = system.add_goal(goal)
            # a run that ends unfinished stops the dispatcher for good (KnicSystem.run is one episode): the
            # soak's next errand takes it up again, and a goal dropped in an earlier round is tried afresh
            system.dispatcher.resume()
            system.dispatcher.retry((atom.predicate, *atom.args))
            errands += 1
            before = system.sim.time
            result = system.run(min(sim_s, before + errand_s), on_check=sample)
            reached += result.success
            if not result.success:
                missed.append(f"t={before:.0f} {goal}: {result.reason}")
            if system.sim.time <= before:  # pragma: no cover - a run always advances the clock
                break
        sample(system)
        events = system.kb.journal.last_seq
        end_time = system.sim.time
    tail = samples[len(samples) // 2 :]
    mbs = [m for _, m in samples]
    return {
        "sim_s": round(end_time, 1),
        "wall_s": round(time.perf_counter() - wall, 1),
        "errands": errands,
        "reached": reached,
        "samples": len(samples),
        "rss_start_mb": round(mbs[0], 1) if mbs else 0.0,
        "rss_end_mb": round(mbs[-1], 1) if mbs else 0.0,
        "rss_peak_mb": round(max(mbs), 1) if mbs else 0.0,
        "rss_slope_mb_per_h": round(_slope_per_hour(tail), 2),
        "journal_events": events,
        "missed": missed,
    }
