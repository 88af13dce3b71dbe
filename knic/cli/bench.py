"""``knic bench NAME``: benchmarks that measure and print their figures (``--json`` for one JSON object)."""

from __future__ import annotations

import argparse

from knic.cli import add_command_modules

#: name -> (module, one-line help); each module provides add_arguments(parser) and run(args) -> int.
BENCHES: dict[str, tuple[str, str]] = {
    "kb": ("knic.bench.kb", "knowledge-base write, query and history throughput"),
    "reliability": ("knic.bench.reliability", "fuzzed inputs and SIGKILLed writers: crashes and lost writes"),
    "planner": ("knic.bench.planner", "replanning latency against naive re-planning, dispatch overhead"),
    "sim": ("knic.bench.sim", "simulator real-time factor and camera frame time"),
    "language": ("knic.bench.language", "text understanding on the development and held-out test sets"),
    "speech": ("knic.bench.speech", "speech recognition and command understanding on the shipped test set"),
    "startup": ("knic.bench.startup", "knic goal and knic say from a fresh process: wall time to the answer"),
    "grounding": ("knic.bench.grounding", "knowledge-base truth against the simulator's ground truth"),
    "ros": ("knic.bench.ros", "ROS 2: fact-event latency and rate, split run against one process"),
    "granny-annie": (
        "knic.bench.granny_annie.command",
        "the ERL Granny Annie task benchmark: episodes, score sheet, report",
    ),
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="bench", metavar="BENCH", required=True)
    add_command_modules(sub, BENCHES)


def run(args: argparse.Namespace) -> int:
    code: int = args._run(args)
    return code
