"""``knic bench ros``: the ROS 2 adapter's figures.

1. **Fact-event latency**: knowledge-base writes in this process (the KnIC node publishing each change from
   the change's callback) received by a subscriber in a process of its own (:mod:`knic.bench.ros_listener`,
   as ``ros2 topic echo`` would be) on a domain of its own; latency from just before the write to the
   subscriber's callback, wall clock (p50, p95, max), at a paced rate; and the writer's own share (the
   write with its synchronous publish, ``write_and_publish_ms_p50``).
2. **Sustained event rate**: the same writes as fast as they go; changes per second received, and losses.
3. **Split run against one process**: the paper trace (``erl_home_paper``, glasses to the bedroom) in one
   process (:class:`knic.system.KnicSystem`) and split over ROS 2 (``knic sim --ros`` and ``knic ros``, two
   processes); simulated seconds per wall second of each run loop (start-up excluded) and their ratio.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from core.errors import KnicError

ROOT = Path(__file__).resolve().parents[2]
GOAL = "(object_at glasses bedroom)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--events", type=int, default=2000, help="knowledge-base changes per figure")
    parser.add_argument("--rate", type=float, default=100.0, help="paced writes per second for the latency")
    parser.add_argument("--domain-id", type=int, default=97, help="ROS_DOMAIN_ID of the benchmark")
    parser.add_argument("--no-split", action="store_true", help="skip the split-run comparison")
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def measure_events(domain: int, events: int, rate: float) -> dict[str, Any]:
    """Latency (paced) and sustained rate (burst) from knowledge-base writes to ``/knic/fact_events``, as
    received by a subscriber in a process of its own (:mod:`knic.bench.ros_listener`)."""
    from knic.ros.env import ros_context
    from knic.ros.knic_node import KnicNode
    from knic.ros.robot import RosLink
    from knic.seed import seed_kb_from_world
    from knic.system.assembly import open_kb
    from planner.trace import Trace
    from worlds.simulation import Simulation

    sim = Simulation("erl_home_paper")
    listener = subprocess.Popen(
        [sys.executable, "-m", "knic.bench.ros_listener", str(domain)],
        cwd=ROOT,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert listener.stdout is not None and listener.stdin is not None
        if listener.stdout.readline().strip() != "ready":
            raise KnicError("bench ros: the listener process did not start")
        with ros_context(domain) as knic_ctx:
            link = RosLink(knic_ctx)
            kb = open_kb(None, lambda: sim.time)
            seed_kb_from_world(kb, sim.world)
            node = KnicNode(link, kb, Trace(), sim, sim.world)
            deadline = time.monotonic() + 20
            while node.pub_events.get_subscription_count() == 0 and time.monotonic() < deadline:
                time.sleep(0.05)
            time.sleep(0.5)  # discovery settles both ways before the first write
            rooms = list(sim.world.rooms)
            last_seq = [0]
            kb.subscribe(lambda change: last_seq.__setitem__(0, change.seq))

            def write(i: int) -> tuple[int, float]:
                room = rooms[(i // 2) % len(rooms)]
                t0 = time.perf_counter()
                if i % 2 == 0:
                    kb.add_fact("explored", room, source="bench")
                else:
                    kb.remove_fact("explored", room, source="bench")
                return last_seq[0], t0

            # paced: latency (sleeping between writes, as a run loop does between its components)
            sent: dict[int, float] = {}
            period = 1.0 / rate
            next_at = time.perf_counter()
            publish_s = []
            for i in range(events):
                pause = next_at - time.perf_counter()
                if pause > 0:
                    time.sleep(pause)
                seq, t0 = write(i)
                publish_s.append(time.perf_counter() - t0)
                sent[seq] = t0
                next_at += period
            # burst: sustained rate
            burst: dict[int, float] = {}
            time.sleep(1.0)
            start = time.perf_counter()
            for i in range(events):
                seq, t0 = write(i)
                burst[seq] = t0
            written = time.perf_counter() - start
            time.sleep(2.0)  # reliable delivery of the tail
            node.close()
            link.close()
            kb.close()
        out, _ = listener.communicate("", timeout=60)
    finally:
        if listener.poll() is None:
            listener.kill()
            listener.wait()
        sim.close()
    received = {int(k): float(v) for k, v in json.loads(out.strip().splitlines()[-1]).items()}
    latency = np.array([received[s] - t for s, t in sent.items() if s in received]) * 1000.0
    got = [received[s] for s in burst if s in received]
    span = (max(got) - start) if got else float("nan")
    return {
        "events": events,
        "paced_rate_hz": rate,
        "latency_ms_p50": round(float(np.percentile(latency, 50)), 3) if latency.size else None,
        "latency_ms_p95": round(float(np.percentile(latency, 95)), 3) if latency.size else None,
        "latency_ms_max": round(float(latency.max()), 3) if latency.size else None,
        "write_and_publish_ms_p50": round(float(np.percentile(publish_s, 50)) * 1000.0, 3),
        "lost_paced": len(sent) - latency.size,
        "burst_write_s": round(written, 3),
        "sustained_events_per_s": round(len(got) / span, 1) if got else 0.0,
        "lost_burst": len(burst) - len(got),
    }


def single_process_rtf() -> dict[str, Any]:
    """The paper trace in one process: simulated seconds per wall second of the run loop."""
    from knic.system import KnicSystem, RunConfig

    with KnicSystem(RunConfig(world="erl_home_paper", seed=0, max_sim_time=300)) as system:
        system.add_goal(GOAL)
        result = system.run()
    return {"success": result.success, "sim_time": result.sim_time, "wall_s": round(result.wall_s, 3)}


def split_rtf(domain: int) -> dict[str, Any]:
    """The paper trace split over ROS 2 (two processes); KnIC's run loop time and the referee's verdict."""
    env = dict(os.environ, ROS_DOMAIN_ID=str(domain))
    knic = [sys.executable, "-m", "knic"]
    sim = subprocess.Popen(
        [*knic, "sim", "--ros", "--world", "erl_home_paper", "--json"],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )
    try:
        out = subprocess.run(
            [*knic, "ros", "--world", "erl_home_paper", "--goal", GOAL, "--max-sim-time", "300", "--json"],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            timeout=600,
        )
    finally:
        sim.send_signal(signal.SIGTERM)
        sim_out, _ = sim.communicate(timeout=30)
    if out.returncode != 0:
        raise KnicError(f"bench ros: the split run failed: {out.stderr.strip().splitlines()[-1:]}")
    summary = json.loads(out.stdout.strip().splitlines()[-1])
    verdict = json.loads(sim_out.strip().splitlines()[-1])
    return {
        "success": bool(summary["done"] and verdict["success"]),
        "sim_time": summary["sim_time"],
        "wall_s": round(summary["wall_s"], 3),
    }


def run(args: argparse.Namespace) -> int:
    from knic.ros.env import require_ros
    from knic.ros.libraries import ensure_ros_libraries

    ensure_ros_libraries()
    require_ros()
    if args.events < 10 or args.rate <= 0:
        raise KnicError("bench ros: --events must be at least 10 and --rate positive")
    report: dict[str, Any] = {"fact_events": measure_events(args.domain_id, args.events, args.rate)}
    if not args.no_split:
        single = single_process_rtf()
        split = split_rtf(args.domain_id + 1)
        single["rtf"] = round(single["sim_time"] / single["wall_s"], 2)
        split["rtf"] = round(split["sim_time"] / split["wall_s"], 2)
        report["single_process"] = single
        report["split"] = split
        report["split_over_single"] = round(split["rtf"] / single["rtf"], 2)
    if args.json:
        print(json.dumps(report, sort_keys=True))
        return 0
    e = report["fact_events"]
    print(
        f"fact events: latency p50 {e['latency_ms_p50']} ms, p95 {e['latency_ms_p95']} ms, max "
        f"{e['latency_ms_max']} ms at {e['paced_rate_hz']:g}/s ({e['lost_paced']} lost of {e['events']})"
    )
    print(
        f"sustained: {e['sustained_events_per_s']} events/s received "
        f"({e['lost_burst']} lost of {e['events']})"
    )
    if "split" in report:
        s1, s2 = report["single_process"], report["split"]
        print(
            f"paper trace, one process: {s1['sim_time']:.1f} s simulated in {s1['wall_s']:.1f} s (RTF "
            f"{s1['rtf']}), success {s1['success']}"
        )
        print(
            f"paper trace, split over ROS 2: {s2['sim_time']:.1f} s simulated in {s2['wall_s']:.1f} s (RTF "
            f"{s2['rtf']}), success {s2['success']}; split/single {report['split_over_single']}"
        )
    return 0
