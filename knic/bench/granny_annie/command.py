"""``knic bench granny-annie``: the ERL task benchmark "Catering for Granny Annie's Comfort".

Generates ``--episodes`` episodes from ``--seed`` in ``--world`` (:mod:`.episodes`), runs each under every
``--baseline`` (:mod:`.baselines`) with ``--workers`` processes or on Ray (:mod:`.runner`), scores each run
from ground truth on the ERL score sheet (:mod:`.referee`) and writes the report, the plots, the traces, the
journals and the ERL recordings (bags) into ``--out`` (:mod:`.report`, :mod:`.recording`). Prints the summary
per baseline (``--json``: one JSON object ``{"baselines": {...}, "wall_s": ...}``); a progress bar with the
running score goes to stderr when it is a terminal.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Any

from knic.bench.granny_annie.baselines import BASELINES


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--episodes", type=int, default=10, help="episodes to generate (default 10)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the episode generator (default 0)")
    parser.add_argument(
        "--out",
        type=Path,
        default=Path("granny_annie_report"),
        help="output directory (default ./granny_annie_report)",
    )
    parser.add_argument("--world", default="erl_home", help="world name or world file (default erl_home)")
    parser.add_argument(
        "--person",
        default=None,
        metavar="NAME",
        help="the person served, who calls and asks (default annie; else the world's first known person)",
    )
    parser.add_argument(
        "--baseline",
        default=",".join(BASELINES),
        help="comma-separated baselines of knic, static, oracle (default all)",
    )
    parser.add_argument(
        "--role", default="companion", help="the robot's role for every baseline (default companion)"
    )
    parser.add_argument(
        "--workers", type=int, default=1, help="worker processes, one simulator each (default 1)"
    )
    parser.add_argument(
        "--backend",
        choices=("local", "ray"),
        default="local",
        help="local processes or Ray tasks (default local)",
    )
    parser.add_argument(
        "--max-sim-time", type=float, default=600.0, metavar="S", help="time limit per run, simulated s (600)"
    )
    parser.add_argument(
        "--damage",
        type=Path,
        default=None,
        metavar="FILE.yaml",
        help="what damages the testbed (default: the shipped knic/bench/granny_annie/damage.yaml)",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def run(args: argparse.Namespace) -> int:
    from core.errors import KnicError
    from knic.bench.granny_annie.baselines import check_baselines
    from knic.bench.granny_annie.damage import load_damage
    from knic.bench.granny_annie.episodes import generate_episodes
    from knic.bench.granny_annie.report import write_report
    from knic.bench.granny_annie.runner import Task, ray_unavailable, run_tasks, write_world_files
    from knic.kgm2.roles import load_role

    where = "knic bench granny-annie"
    if args.episodes < 1:
        raise KnicError(f"{where}: --episodes must be at least 1, got {args.episodes}")
    if args.workers < 1:
        raise KnicError(f"{where}: --workers must be at least 1, got {args.workers}")
    if args.max_sim_time <= 0:
        raise KnicError(f"{where}: --max-sim-time must be positive, got {args.max_sim_time}")
    baselines = check_baselines([b.strip() for b in args.baseline.split(",") if b.strip()])
    load_role(args.role)  # an unknown role is refused before anything runs
    if args.damage is not None:
        load_damage(args.damage)  # a bad damage model is refused before anything runs
    if args.backend == "ray":
        reason = ray_unavailable()
        if reason is not None:
            raise KnicError(f"{where}: --backend ray: {reason}")
    wall0 = time.perf_counter()
    episodes = generate_episodes(args.world, args.episodes, args.seed, args.person)
    out: Path = args.out
    write_world_files(out, episodes)
    tasks = [
        Task(
            e.to_dict(),
            b,
            args.role,
            str(out),
            max_sim_time=args.max_sim_time,
            damage=None if args.damage is None else str(args.damage),
        )
        for e in episodes
        for b in baselines
    ]
    results = list(
        _with_progress(run_tasks(tasks, workers=args.workers, backend=args.backend), len(tasks), baselines)
    )
    config = {
        "world": args.world,
        "person": episodes[0].person,
        "episodes": args.episodes,
        "seed": args.seed,
        "role": args.role,
        "baselines": baselines,
        "workers": args.workers,
        "backend": args.backend,
        "max_sim_time": args.max_sim_time,
        "damage": str(args.damage) if args.damage is not None else "damage.yaml (shipped)",
    }
    wall = time.perf_counter() - wall0
    report = write_report(
        out,
        config=config,
        episodes=[e.to_dict() for e in episodes],
        results=results,
        baselines=baselines,
        wall_s=wall,
    )
    if args.json:
        print(json.dumps({"baselines": report["summary"], "wall_s": report["wall_s"]}, sort_keys=True))
    else:
        _print_summary(report, baselines, out)
    return 0


def _with_progress(results: Any, total: int, baselines: list[str]) -> Any:
    """Yield the results while a progress bar on stderr shows the running achievements share per baseline."""
    from tqdm import tqdm

    got: dict[str, list[int]] = {b: [0, 0] for b in baselines}
    with tqdm(
        total=total, desc="granny-annie", unit="run", file=sys.stderr, disable=not sys.stderr.isatty()
    ) as bar:
        for result in results:
            score = result["score"]
            got[result["baseline"]][0] += score["achievements"]
            got[result["baseline"]][1] += score["possible"]
            bar.set_postfix_str(" ".join(f"{b} {a / p:.2f}" if p else f"{b} -" for b, (a, p) in got.items()))
            bar.update(1)
            yield result


def _print_summary(report: dict[str, Any], baselines: list[str], out: Path) -> None:
    print(
        f"knic bench granny-annie: {report['config']['episodes']} episodes, wall {report['wall_s']} s,"
        f" report in {out}"
    )
    for b in baselines:
        s, r = report["summary"][b], report["ranking"][b]
        kinds = ", ".join(f"{k} {v['achieved']}/{v['achievable']}" for k, v in s["achievements"].items())
        print(
            f"{b:7s} achievements {s['achievements_share']} ({kinds}); penalties {s['penalties']};"
            f" disqualified runs {s['disqualified_runs']}; median time {s['time_median_s']} s;"
            f" mean rank {r['mean_rank']}, wins {r['wins']}"
        )
