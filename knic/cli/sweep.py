"""``knic sweep``: run the task suites over seeds and roles and print how many runs succeeded.

Suites (``--suite``, repeatable; default all but ``flat``, which needs ``--world``):

* ``chain``: the rulebook's chain "Locate Tracy, lead her to the bedroom, and bring me an apple from the
  kitchen cabinet" in ``erl_home`` (the source kept as ``(taken_from apple kitchen_cabinet)``);
* ``tablet``: "locate the tablet and bring it to me" under every role (semi-autonomous: the robot asks and
  gets a yes; teleoperated: the operator's goal);
* ``granny_annie``: the task scenario (:mod:`knic.system.granny_annie`): call, come, spoken request,
  confirmation, actions, report; a run succeeds when the robot told Annie it was done and the referee finds
  every goal holding in the ground truth;
* ``flat``: "bring me the <item>" for each item of ``--world`` (a world file with no priors).

Every run is judged by the referee (ground truth), never by the robot's beliefs alone. Runs go through the
goal intake as a user's would. ``--workers`` runs cases in parallel processes (each has its own simulator).
Figures: per case one line; per suite ``succeeded/runs`` and the mean simulated time of the successes.
"""

from __future__ import annotations

import argparse
import json
import time
from typing import Any

from core.errors import KnicError

CHAIN = "Locate Tracy, lead her to the bedroom, and bring me an apple from the kitchen cabinet"
TABLET = "locate the tablet and bring it to me"
ROLES = ("companion", "service_autonomous", "service_semi_autonomous", "teleoperated")
SUITES = ("chain", "tablet", "granny_annie", "flat")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--suite", action="append", choices=SUITES, help="suite to run (repeatable; default: all but flat)"
    )
    parser.add_argument("--seeds", default="", help="seeds as 0-9 or 0,3,5 (default: per suite)")
    parser.add_argument("--world", default=None, help="world file for the flat suite")
    parser.add_argument("--workers", type=int, default=1, help="parallel processes (default 1)")
    parser.add_argument(
        "--max-sim-time", type=float, default=600.0, metavar="S", help="per run (default 600)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object at the end")


def parse_seeds(text: str) -> list[int]:
    """``"0-9"`` or ``"0,3,5"`` as a list of seeds.

    Raises:
        KnicError: not seeds.
    """
    seeds: list[int] = []
    try:
        for part in text.split(","):
            if "-" in part.strip()[1:]:
                lo, hi = part.split("-", 1)
                seeds += list(range(int(lo), int(hi) + 1))
            elif part.strip():
                seeds.append(int(part))
    except ValueError:
        raise KnicError(f"knic sweep: --seeds {text!r} is not like 0-9 or 0,3,5") from None
    return seeds


def cases(suites: list[str], seeds: list[int], world: str | None, limit: float) -> list[dict[str, Any]]:
    """The runs of the suites (plain dicts, so worker processes can take them)."""
    out: list[dict[str, Any]] = []
    for suite in suites:
        if suite == "chain":
            out += [
                {"suite": suite, "seed": s, "goal": CHAIN, "role": "companion"} for s in seeds or range(5)
            ]
        elif suite == "tablet":
            out += [
                {"suite": suite, "seed": s, "goal": TABLET, "role": r} for r in ROLES for s in seeds or [0]
            ]
        elif suite == "granny_annie":
            out += [{"suite": suite, "seed": s, "role": "companion"} for s in seeds or range(10)]
        elif suite == "flat":
            if world is None:
                raise KnicError("knic sweep: the flat suite needs --world FILE")
            from worlds.api import load_world
            from worlds.granny_annie import DEFAULT_PERSON, first_person

            flat = load_world(world)
            speaker = first_person(flat) or DEFAULT_PERSON
            out += [
                {
                    "suite": suite,
                    "seed": s,
                    "goal": f"bring me the {i.replace('_', ' ')}",
                    "role": ROLES[0],
                    "speaker": speaker,
                }
                for i in sorted(flat.items)
                for s in seeds or [0]
            ]
    for case in out:
        case.setdefault("role", ROLES[0])
        case["world"] = world if case["suite"] == "flat" else "erl_home"
        case["max_sim_time"] = limit
    return out


def run_case(case: dict[str, Any]) -> dict[str, Any]:
    """Run one case and judge it (a module-level function, so worker processes can run it)."""
    import logging

    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)
    wall0 = time.perf_counter()
    try:
        if case["suite"] == "granny_annie":
            result, extra = _granny_annie(case)
        else:
            result, extra = _goal_case(case)
    except KnicError as exc:
        return {**case, "success": False, "reason": f"{type(exc).__name__}: {exc}", "sim_time": 0.0}
    return {
        **case,
        "success": result.success,
        "reason": result.reason,
        "sim_time": round(result.sim_time, 1),
        "plans": result.plans,
        "replans": result.replans,
        "wall_s": round(time.perf_counter() - wall0, 1),
        **extra,
    }


def _granny_annie(case: dict[str, Any]) -> tuple[Any, dict[str, Any]]:
    from knic.cli.runtask import judge_task
    from knic.system.granny_annie import granny_annie_system

    system, flow, episode = granny_annie_system(
        case["seed"], role=case["role"], max_sim_time=case["max_sim_time"]
    )
    with system:
        result = system.run()
    judge_task(result, flow, episode.request.text)
    extra = {"request": episode.request.text, "seat": episode.seat, "goals": [str(g) for g in flow.goals]}
    return result, extra


def _goal_case(case: dict[str, Any]) -> tuple[Any, dict[str, Any]]:
    from knic.intake import GoalIntake, Outcome
    from knic.kgm2.roles import load_role
    from knic.system import KnicSystem, RunConfig
    from knic.system.names import run_vocabulary

    role = load_role(case["role"])
    config = RunConfig(
        world=case["world"], seed=case["seed"], role=case["role"], max_sim_time=case["max_sim_time"]
    )
    with KnicSystem(config) as system:
        vocabulary = run_vocabulary(system)
        intake = GoalIntake(system.kb, vocabulary, say=system.context.say, confirm=role.confirm_actions)
        source = "operator" if role.operator_only else "user"
        reply = intake.submit(case["goal"], speaker=case.get("speaker", "annie"), source=source)
        if reply.outcome == Outcome.ASKED:
            reply = intake.hear("yes")
        if reply.outcome != Outcome.ADDED:
            raise KnicError(f"the goal was not taken: {reply.reason or reply.outcome.value}")
        result = system.run()
        return result, {"goals": [str(g) for g in system.kb.goals()]}


def run(args: argparse.Namespace) -> int:
    suites = list(args.suite or ["chain", "tablet", "granny_annie"])
    if args.workers < 1:
        raise KnicError(f"knic sweep: --workers must be >= 1, got {args.workers}")
    todo = cases(suites, parse_seeds(args.seeds), args.world, args.max_sim_time)
    results: list[dict[str, Any]] = []
    for result in _run_all(todo, args.workers):
        results.append(result)
        if not args.json:
            print(line(result), flush=True)
    totals = summarise(results)
    if args.json:
        print(json.dumps({"totals": totals, "runs": results}, sort_keys=True))
    else:
        for suite, t in totals.items():
            mean = f", mean {t['mean_sim_time']:.0f} s simulated" if t["succeeded"] else ""
            print(f"{suite}: {t['succeeded']}/{t['runs']} succeeded{mean}")
    return 0 if all(r["success"] for r in results) else 1


def _run_all(todo: list[dict[str, Any]], workers: int) -> Any:
    if workers == 1:
        for case in todo:
            yield run_case(case)
        return
    import multiprocessing

    with multiprocessing.get_context("spawn").Pool(workers) as pool:
        yield from pool.imap(run_case, todo)


def line(r: dict[str, Any]) -> str:
    """One case as one line."""
    what = r.get("request") or r.get("goal", "")
    state = "ok  " if r["success"] else "FAIL"
    return f"{state} {r['suite']:<12} seed {r['seed']:<2} {r['role']:<24} {r['sim_time']:6.1f} s  {what}" + (
        "" if r["success"] else f"  -- {r['reason']}"
    )


def summarise(results: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """Per suite: runs, succeeded, mean simulated time of the successes."""
    totals: dict[str, dict[str, Any]] = {}
    for r in results:
        t = totals.setdefault(r["suite"], {"runs": 0, "succeeded": 0, "sim_times": []})
        t["runs"] += 1
        if r["success"]:
            t["succeeded"] += 1
            t["sim_times"].append(r["sim_time"])
    for t in totals.values():
        times = t.pop("sim_times")
        t["mean_sim_time"] = round(sum(times) / len(times), 1) if times else 0.0
    return totals
