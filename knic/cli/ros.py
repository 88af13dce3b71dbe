"""``knic ros``: KnIC as a ROS 2 node beside a robot that publishes its own sensors (or ``knic sim --ros``).

KnIC reads the robot only through ROS 2 topics (:class:`knic.ros.robot.RosRobot`), publishes what it believes
and does (:mod:`knic.ros.knic_node`) and takes goals on ``/knic/goal`` besides ``--goal``; under a role that
confirms, the question goes out on ``/knic/question`` and the answer comes in on ``/knic/answer``. With
``--listen``, speech the robot hears (``/robot/heard``) gives goals and answers too. With goals (or
``--listen``) it stops when it believes them achieved or dropped (exit 0 when achieved, 1 otherwise);
without, it serves until ``--max-sim-time``, Ctrl-C or SIGTERM.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import signal
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from core.errors import KnicError


class RosRunFailed(KnicError):
    """The goals were not achieved."""

    exit_code = 1


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--world", default="erl_home", help="the robot's map: world name or file")
    parser.add_argument("--role", default="companion", help="robot role (default companion)")
    parser.add_argument("--goal", action="append", default=[], metavar="TEXT", help="a goal (repeatable)")
    parser.add_argument(
        "--max-sim-time", type=float, default=math.inf, metavar="S", help="stop after S seconds of robot time"
    )
    parser.add_argument("--serve", action="store_true", help="keep serving after the goals are achieved")
    parser.add_argument(
        "--listen",
        action="store_true",
        help="speech the robot hears (/robot/heard) gives goals and answers; stop when they are achieved",
    )
    parser.add_argument("--journal", type=Path, metavar="FILE.sqlite", help="record the knowledge base")
    parser.add_argument("--trace", type=Path, metavar="FILE.jsonl", help="write the trace as JSON lines")
    parser.add_argument("--domain-id", type=int, help="ROS_DOMAIN_ID (default: the environment's)")
    parser.add_argument("--json", action="store_true", help="print only a JSON summary at the end")


def _interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


def run(args: argparse.Namespace) -> int:
    if args.max_sim_time <= 0:
        raise KnicError(f"knic ros: --max-sim-time must be positive, got {args.max_sim_time}")
    from knic.ros.env import require_ros, ros_context
    from knic.ros.libraries import ensure_ros_libraries

    ensure_ros_libraries()
    require_ros()
    from knic.ros.robot import RosLink
    from knic.ros.split import RosRun
    from knic.system.config import RunConfig

    signal.signal(signal.SIGTERM, _interrupt)
    wants_goals = bool(args.goal) or args.listen
    trace_file = args.trace.open("w", encoding="utf-8") if args.trace else None
    try:
        with ros_context(args.domain_id) as context:
            link = RosLink(context)
            config = RunConfig(args.world, role=args.role, journal=args.journal, trace_stream=trace_file)
            ros_run = RosRun(link, config, listen=args.listen)
            try:
                for text in args.goal:
                    reply = ros_run.add_goal(text)
                    if reply["outcome"] == "asked":  # a role that confirms: the answer comes over ROS 2
                        print(
                            f"knic ros: {reply['reply']} ({reply['question']}: answer on /knic/answer)",
                            file=sys.stderr,
                            flush=True,
                        )
                    elif reply["outcome"] != "added":
                        raise KnicError(f"knic ros: goal {text!r} {reply['outcome']}: {reply['reason']}")
                if not args.json:
                    print("knic ros: ready; goals on /knic/goal", file=sys.stderr, flush=True)
                    ros_run.trace.print_to(sys.stdout)
                try:
                    result = ros_run.run(args.max_sim_time, until_done=wants_goals and not args.serve)
                except KeyboardInterrupt:
                    result = None
            finally:
                ros_run.close()
                link.close()
    finally:
        if trace_file is not None:
            trace_file.close()
    if result is None:
        return 0
    if args.json:
        print(json.dumps(result.to_dict(), sort_keys=True), flush=True)
    else:
        print(f"knic ros: {result.reason} at t={result.sim_time:.1f} s (wall {result.wall_s:.1f} s)")
    if wants_goals and not result.done:
        raise RosRunFailed(f"knic ros: {result.reason}")
    return 0


def add_run_ros_argument(parser: argparse.ArgumentParser) -> None:
    """``knic run --ros``: the usual run, also published on ROS 2 (the ``ros`` extra)."""
    parser.add_argument(
        "--ros",
        action="store_true",
        help="also run KnIC as a ROS 2 node (topics in the README; ROS_DOMAIN_ID)",
    )


@contextmanager
def ros_attached(args: argparse.Namespace, system: Any) -> Iterator[Any]:
    """With ``--ros``: the KnIC node attached to a built single-process run (its bridge is stepped by the
    run's scheduler), closed afterwards; otherwise nothing."""
    if not getattr(args, "ros", False):
        yield None
        return
    from knic.ros.env import require_ros, ros_context

    require_ros()
    from knic.ros.robot import RosLink
    from knic.ros.split import attach

    with ros_context() as context:
        link = RosLink(context)
        node = attach(system, link)
        try:
            yield node
        finally:
            node.publish_snapshot()
            linger = float(getattr(args, "linger", 0.0) or 0.0)
            if linger > 0:  # DDS serves what is kept to subscribers that join now, in its own threads
                print(f"knic: run over; the ROS 2 node stays up {linger:g} s", file=sys.stderr)
                with contextlib.suppress(KeyboardInterrupt):
                    end = time.monotonic() + linger
                    while (left := end - time.monotonic()) > 0:
                        time.sleep(min(0.5, left))
                        # octomaps go only to those who listen: one who joins now gets them too
                        node.publish_octomaps(node.last_tick)
            node.close()
            link.close()
