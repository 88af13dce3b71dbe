"""``knic plan DOMAIN.pddl PROBLEM.pddl``: plan a PDDL problem and print the plan.

Output: one action per line as ``(name arg1 arg2)``; unreachable goals are named on stderr. With ``--json``
one object: ``{"status", "plan": [["name", "arg1", ...], ...], "unreachable_goals": [...], "planning_ms",
"engine"}``.

Exit codes: 0 with a plan (also when some goals are unreachable, or when the goals already hold), 3 when no
goal can be reached, 2 on bad input (one line naming the file, the line and the offending symbol), 1 when
the engine failed or timed out.
"""

from __future__ import annotations

import argparse
import json
import sys

from core.errors import KnicError

EXIT_UNREACHABLE = 3


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("domain", metavar="DOMAIN.pddl", help="PDDL domain file")
    parser.add_argument("problem", metavar="PROBLEM.pddl", help="PDDL problem file")
    parser.add_argument(
        "--engine",
        default=None,
        choices=["auto", "knic", "fast-downward", "tamer"],
        help="planning engine (default: fast-downward, or tamer for durative domains; auto: the in-process "
        "knic search with fast-downward as fall-back, as the dispatcher uses it)",
    )
    parser.add_argument(
        "--timeout", type=float, default=60.0, help="planning time limit in seconds (default 60)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--no-focus", action="store_true", help="plan without object focusing (for comparison)"
    )


def run(args: argparse.Namespace) -> int:
    from knowledge_base import KnowledgeBase
    from planner.engines import TaskPlanner, silence_up
    from planner.model import PlanningTask, atom_str
    from planner.plan import PlanStatus
    from planner.problem import task_from_kb, task_to_up
    from planner.validate import validate_with_up

    if args.timeout <= 0:
        raise KnicError(f"--timeout must be positive, got {args.timeout:g}")
    silence_up()
    kb = KnowledgeBase.from_pddl(args.domain, args.problem)
    task = task_from_kb(kb)
    engine = args.engine or ("tamer" if task.domain.temporal else "fast-downward")
    planner = TaskPlanner(kb.domain.up_domain, engine=engine, timeout=args.timeout, focus=not args.no_focus)
    result = planner.solve(task)
    if result.has_plan and not task.domain.temporal:
        reachable = PlanningTask(task.domain, task.objects, task.facts, result.reachable_goals)
        valid, reason = validate_with_up(task_to_up(reachable, kb.domain.up_domain), result.plan)
        if not valid:
            raise KnicError(f"{args.problem}: plan from {result.engine} failed validation: {reason}")
    if args.json:
        print(json.dumps(result.to_json()))
    else:
        for step in result.plan:
            print(step)
        for goal in result.unreachable_goals:
            print(f"knic: unreachable goal {atom_str(goal)}", file=sys.stderr)
    if result.status in (PlanStatus.SOLVED, PlanStatus.PARTIAL):
        return 0
    if result.status == PlanStatus.UNSOLVABLE:
        if not args.json:
            print(f"knic: no goal can be reached in {args.problem}", file=sys.stderr)
        return EXIT_UNREACHABLE
    if not args.json:
        print(f"knic: error: planning {result.status.value}: {result.message}", file=sys.stderr)
    return 1
