"""``knic bench kb``: knowledge-base write, query and history throughput on the ERL apartment.

Figures (wall-clock time on this machine; query and state_at figures are medians):

* ``memory_changes_per_s`` -- validated writes (add_fact / remove_fact, single-valued retraction included)
  per second, in-memory journal.
* ``durable_changes_per_s`` -- the same writes journaled to SQLite (WAL), one transaction per tick of
  ``tick_changes`` writes (``batch()``).
* ``query_ms_10k_facts`` -- a full-state query (``snapshot()``: every fact with its provenance, goals,
  instances) with 10,000 facts; ``facts_list_ms_10k_facts`` is ``facts()`` alone.
* ``state_at_ms_100k_events`` -- ``state_at(t)`` at random past times on a SQLite journal of 100,000 events
  (median).
* ``state_at_ms_100k_facts`` / ``export_ms_100k_facts`` -- ``state_at(t)`` at random past times (median) and
  ``to_pddl_problem()`` on a SQLite-journalled knowledge base holding 100,000 facts, built by writes that
  each change something; ``*_10k_facts`` the same at 10,000.
* ``changing_writes`` / ``noop_writes`` -- of the measured writes, how many changed the state and how many
  were no-ops (re-asserting what holds, retracting what does not): rates count only the first.
* ``*_per_cpu_s`` -- the write rates in process CPU time, which a busy shared machine does not distort;
  ``load_average_1min`` says how busy it was.

``--quick`` shrinks every size (for tests); the sizes used are in the output.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

TARGETS = {
    "memory_changes_per_s": (">=", 50_000.0),
    "durable_changes_per_s": (">=", 20_000.0),
    "query_ms_10k_facts": ("<", 5.0),
    "state_at_ms_100k_events": ("<", 50.0),
    "state_at_ms_100k_facts": ("<=", 50.0),
    "export_ms_100k_facts": ("<=", 200.0),
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--quick", action="store_true", help="small sizes (seconds, not representative)")
    parser.add_argument("--seed", type=int, default=0, help="random seed for the workload")


def run(args: argparse.Namespace) -> int:
    figures = measure(quick=args.quick, seed=args.seed)
    if args.json:
        print(json.dumps(figures))
    else:
        for key, value in figures.items():
            print(f"{key:28s} {value}")
    return 0


class _SimClock:
    """Simulated seconds advanced by the workload (the closed loop's time base)."""

    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


def measure(*, quick: bool = False, seed: int = 0) -> dict[str, Any]:
    """Run every measurement and return the figures (see the module docstring)."""
    from knowledge_base import KnowledgeBase

    root = Path(__file__).resolve().parents[2] / "worlds" / "erl_home"
    domain, problem = root / "domain.pddl", root / "erl_home_problem.pddl"
    sizes = {
        "memory_changes": 5_000 if quick else 200_000,
        "durable_changes": 5_000 if quick else 100_000,
        "tick_changes": 100,
        "query_facts": 10_000,
        "state_at_events": 5_000 if quick else 100_000,
    }
    rng = random.Random(seed)
    _COUNTS.update(changing_writes=0, noop_writes=0)
    out: dict[str, Any] = {}
    clock = _SimClock()
    kb = KnowledgeBase.from_pddl(domain, problem, clock=clock)
    cpu = time.process_time()
    out["memory_changes_per_s"] = round(_write_rate(kb, clock, sizes["memory_changes"], 0, rng), 1)
    out["memory_changes_per_cpu_s"] = round(sizes["memory_changes"] / (time.process_time() - cpu), 1)

    with tempfile.TemporaryDirectory(prefix="knic-bench-kb-") as tmp:
        clock = _SimClock()
        kb = KnowledgeBase.from_pddl(domain, problem, Path(tmp) / "durable.sqlite", clock=clock)
        cpu = time.process_time()
        out["durable_changes_per_s"] = round(
            _write_rate(kb, clock, sizes["durable_changes"], sizes["tick_changes"], rng), 1
        )
        out["durable_changes_per_cpu_s"] = round(sizes["durable_changes"] / (time.process_time() - cpu), 1)
        kb.close()

        query_kb = _with_facts(
            KnowledgeBase.from_pddl(domain, problem, clock=_SimClock()), sizes["query_facts"]
        )
        out["query_facts"] = len(query_kb.facts())
        out["query_ms_10k_facts"] = round(_median_ms(query_kb.snapshot, 30), 3)
        out["facts_list_ms_10k_facts"] = round(_median_ms(query_kb.facts, 30), 3)

        clock = _SimClock()
        history = KnowledgeBase.from_pddl(domain, problem, Path(tmp) / "history.sqlite", clock=clock)
        while history.journal.last_seq < sizes["state_at_events"]:
            _write_rate(history, clock, sizes["tick_changes"] * 10, sizes["tick_changes"], rng)
        events = history.journal.last_seq
        times = [rng.uniform(0.0, clock.t) for _ in range(15)]
        samples = []
        for t in times:
            start = time.perf_counter()
            state = history.state_at(t)
            samples.append((time.perf_counter() - start) * 1000.0)
            assert state.time <= t
        out["state_at_events"] = events
        out["state_at_ms_100k_events"] = round(statistics.median(samples), 3)
        out["state_at_ms_max"] = round(max(samples), 3)
        history.close()
        for label, n in (("10k", 10_000), ("100k", 1_000 if quick else 100_000)):
            state_ms, export_ms, facts = _large_state(
                domain, problem, Path(tmp) / f"large{label}.sqlite", n, rng
            )
            out[f"state_at_ms_{label}_facts"] = round(state_ms, 3)
            out[f"export_ms_{label}_facts"] = round(export_ms, 3)
            out[f"facts_{label}"] = facts
    out.update(_COUNTS)
    out.update({f"size_{k}": v for k, v in sizes.items()})
    out["load_average_1min"] = round(os.getloadavg()[0], 2)  # other processes competing for the CPUs
    checks = {">=": lambda a, b: a >= b, "<": lambda a, b: a < b, "<=": lambda a, b: a <= b}
    out["targets_missed"] = [k for k, (op, bound) in TARGETS.items() if not checks[op](out[k], bound)]
    out["meets_targets"] = not out["targets_missed"]
    return out


def _write_rate(kb: Any, clock: _SimClock, n: int, tick: int, rng: random.Random) -> float:
    """Validated writes per second: the robot moving, candidates appearing and going, rooms explored."""
    rooms = kb.instances("room")
    items = kb.instances("item")
    ops: list[tuple[str, tuple[str, ...], bool]] = []
    for _ in range(n):
        r = rng.random()
        room = rooms[rng.randrange(len(rooms))]
        if r < 0.2:
            ops.append(("robot_at", ("r2d2", room), True))
        elif r < 0.6:
            ops.append(("possibly_at", (items[rng.randrange(len(items))], room), rng.random() < 0.5))
        else:
            ops.append(("explored", (room,), rng.random() < 0.5))
    add, remove = kb.add_fact, kb.remove_fact
    before = kb.journal.last_seq
    start = time.perf_counter()
    if tick:
        for i in range(0, n, tick):
            clock.t += 0.1
            with kb.batch():
                for predicate, args, assert_it in ops[i : i + tick]:
                    (add if assert_it else remove)(predicate, *args, source="bench", status="observed")
    else:
        for i, (predicate, args, assert_it) in enumerate(ops):
            if i % 100 == 0:
                clock.t += 0.1
            (add if assert_it else remove)(predicate, *args, source="bench", status="observed")
    elapsed = time.perf_counter() - start
    changed = kb.journal.last_seq - before  # one event per write that changed something (+ retractions)
    _COUNTS["changing_writes"] += changed
    _COUNTS["noop_writes"] += max(n - changed, 0)
    return changed / elapsed


_COUNTS = {"changing_writes": 0, "noop_writes": 0}


def _large_state(
    domain: Path, problem: Path, path: Path, n: int, rng: random.Random
) -> tuple[float, float, int]:
    """A journalled knowledge base grown to ``n`` facts by changing writes (1,000 new facts per batch, and
    churn: 50 facts retracted and 50 earlier retractions re-asserted per batch); the median ``state_at`` at 7
    random past times and one ``to_pddl_problem`` (milliseconds), and the facts."""
    from knowledge_base import KnowledgeBase

    clock = _SimClock()
    kb = KnowledgeBase.from_pddl(domain, problem, path, clock=clock)
    side = int(n**0.5) + 1
    with kb.batch():
        for i in range(side):
            kb.add_instance("item", f"bench_item{i}")
            kb.add_instance("room", f"bench_room{i}")
    k = 0
    retracted: list[tuple[str, str]] = []
    while len(kb.facts()) < n:
        clock.t += 0.1
        with kb.batch():
            # churn: 5% of the held facts of recent batches go, earlier retractions come back
            held = kb.facts("possibly_at")[-2000:]
            for fact in rng.sample(held, min(50, len(held))):
                if kb.remove_fact("possibly_at", *fact.args, source="bench"):
                    retracted.append((fact.args[0], fact.args[1]))
            for item, room in retracted[:-50]:
                kb.add_fact("possibly_at", item, room, status="observed", source="bench")
            del retracted[:-50]
            for _ in range(min(1000, n - len(kb.facts()))):
                i, j = divmod(k, side)
                k += 1
                kb.add_fact("possibly_at", f"bench_item{i}", f"bench_room{j}", status="assumed")
    samples = []
    for _ in range(7):
        t = rng.uniform(0.0, clock.t)
        start = time.perf_counter()
        state = kb.state_at(t)
        samples.append((time.perf_counter() - start) * 1000.0)
        assert state.time <= t
    start = time.perf_counter()
    kb.to_pddl_problem()
    export = (time.perf_counter() - start) * 1000.0
    facts = len(kb.facts())
    kb.close()
    return statistics.median(samples), export, facts


def _with_facts(kb: Any, n: int) -> Any:
    """Add items and rooms until ``n`` facts hold (possibly_at item room over a grid)."""
    per_side = int(n**0.5) + 1
    missing = n - len(kb.facts())
    with kb.batch():
        for i in range(per_side):
            kb.add_instance("item", f"bench_item{i}")
            kb.add_instance("room", f"bench_room{i}")
        for k in range(missing):
            i, j = divmod(k, per_side)
            kb.add_fact("possibly_at", f"bench_item{i}", f"bench_room{j}", status="assumed")
    return kb


def _median_ms(fn: Any, repeat: int) -> float:
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples) * 1000.0
