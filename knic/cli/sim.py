"""``knic sim --ros``: the simulated apartment as its own ROS 2 node (see :mod:`knic.ros.sim_node`).

It publishes the robot's sensors and ``/clock`` and executes the robot's commands; KnIC runs in another
process (``knic ros``). In lockstep (default) simulated time advances as KnIC grants it; ``--rate R`` runs
free at R times real time. It stops at ``--max-sim-time``, on Ctrl-C or SIGTERM, and then prints the
referee's verdict on the goals KnIC published (ground truth stays in this process).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import signal
import sys
from typing import Any

from core.errors import KnicError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--ros", action="store_true", help="run the simulator as a ROS 2 node (required)")
    parser.add_argument("--world", default="erl_home", help="world name or file (default erl_home)")
    parser.add_argument("--scenario", help="scenario name or file")
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulation (default 0)")
    parser.add_argument(
        "--rate", type=float, help="free running at this real-time factor (default: lockstep)"
    )
    parser.add_argument(
        "--max-sim-time", type=float, default=math.inf, metavar="S", help="stop after S simulated seconds"
    )
    parser.add_argument("--domain-id", type=int, help="ROS_DOMAIN_ID (default: the environment's)")
    parser.add_argument("--json", action="store_true", help="print the referee's verdict as JSON")


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


def run(args: argparse.Namespace) -> int:
    if not args.ros:
        raise KnicError("knic sim: only the ROS 2 node is available; pass --ros")
    if args.max_sim_time <= 0:
        raise KnicError(f"knic sim: --max-sim-time must be positive, got {args.max_sim_time}")
    from knic.ros.env import require_ros, ros_context
    from knic.ros.libraries import ensure_ros_libraries

    ensure_ros_libraries()
    require_ros()
    from knic.ros.sim_node import SimNode
    from worlds.simulation import Simulation

    signal.signal(signal.SIGTERM, _interrupt)
    sim = Simulation(args.world, seed=args.seed, scenario=args.scenario)
    try:
        with ros_context(args.domain_id) as context:
            node = SimNode(sim, context, rate=args.rate)
            print(f"knic sim: world {args.world}, seed {args.seed}, ready", file=sys.stderr, flush=True)
            with contextlib.suppress(KeyboardInterrupt):
                node.run(args.max_sim_time)
            verdict = node.referee()
            node.close()
    finally:
        sim.close()
    if args.json:
        print(json.dumps(verdict, sort_keys=True), flush=True)
    else:
        state = "hold" if verdict["success"] else "do not all hold"
        print(f"referee at t={verdict['sim_time']:.1f} s: goals {' '.join(verdict['goals'])} {state}")
    return 0
