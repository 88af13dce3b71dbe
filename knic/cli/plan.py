"""``knic plan DOMAIN.pddl PROBLEM.pddl``: plan a PDDL problem and print the plan.

Any PDDL that unified-planning reads is accepted: typed or untyped domains, constants, equality, goal
formulas (``not``, ``or``, ``imply``, ``exists``, ``forall``), conditional and quantified effects, numeric
fluents (planned by Tamer) and durative actions (Tamer). Problems in the knowledge base's fragment (STRIPS
with atomic goals) go through the planner the dispatcher uses (object focus, relaxed reachability); all
others through :func:`planner.general.solve_problem`. Every plan is validated before it is printed.

Output: one action per line as ``(name arg1 arg2)``; a temporal plan prints one action per line with its
start time and duration, ``0.000: (name arg1) [5.000]``. Unreachable goals are named on stderr. With
``--json`` one object: ``{"status", "plan": [["name", "arg1", ...], ...], "unreachable_goals": [...],
"planning_ms", "engine"}`` plus ``"schedule": [{"start", "action", "duration"}, ...]`` for temporal plans.

Exit codes: 0 with a plan (also when some goals are unreachable, when the goal is empty, or when the goals
already hold), 3 when no goal can be reached, 2 on bad input (one line naming the file, the line and the
offending symbol), 1 when the engine failed or the time limit passed. ``--timeout`` bounds the whole command:
reading, parsing and planning.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from core.errors import KnicError

EXIT_UNREACHABLE = 3


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("domain", metavar="DOMAIN.pddl", help="PDDL domain file")
    parser.add_argument("problem", metavar="PROBLEM.pddl", help="PDDL problem file")
    parser.add_argument(
        "--engine",
        default=None,
        choices=["auto", "knic", "fast-downward", "tamer"],
        help="planning engine (default: fast-downward, or tamer for durative or numeric problems; auto: the "
        "in-process knic search with fast-downward as fall-back, as the dispatcher uses it)",
    )
    parser.add_argument(
        "--timeout",
        type=float,
        default=60.0,
        help="time limit in seconds for the whole command, parsing included (default 60)",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--no-focus", action="store_true", help="plan without object focusing (for comparison)"
    )


def run(args: argparse.Namespace) -> int:
    from knic.cli.bounded import positive_seconds, run_bounded

    timeout = positive_seconds(args.timeout, "--timeout")
    return run_bounded(lambda: plan_files(args, timeout), timeout, "knic plan")


def plan_files(args: argparse.Namespace, timeout: float) -> int:
    """Read, check, plan, validate and print (the work :func:`run` bounds in time)."""
    from knowledge_base.domain import DomainModel, read_pddl
    from knowledge_base.problem import parse_problem_up
    from planner.engines import silence_up

    silence_up()
    domain = DomainModel.from_file(args.domain)
    text = read_pddl(args.problem, "problem")
    up_problem = parse_problem_up(domain, text, source=args.problem)
    task = _fragment_task(domain, up_problem)
    if task is not None:
        result: Any = _plan_fragment(args, domain, task, timeout)
        unreachable = [_atom(g) for g in result.unreachable_goals]
    else:
        from planner.general import solve_problem

        result = solve_problem(up_problem, engine=args.engine or "auto", timeout=timeout)
        unreachable = list(result.unreachable_goals)
    return _report(args, result, unreachable)


def _atom(goal: tuple[str, ...]) -> str:
    return "(" + " ".join(goal) + ")"


def _fragment_task(domain: Any, up_problem: Any) -> Any:
    """The planner task when the problem is in the knowledge base's fragment, else None."""
    from planner.general import goal_conjuncts
    from planner.model import task_from_up
    from planner.problem import strips_domain

    strips = strips_domain(domain.up_domain)
    if strips.unsupported is not None or domain.functions:
        return None
    if not all(g.is_fluent_exp() for g in goal_conjuncts(up_problem)):
        return None
    try:
        return task_from_up(up_problem, strips)
    except (ValueError, AttributeError):
        return None


def _plan_fragment(args: argparse.Namespace, domain: Any, task: Any, timeout: float) -> Any:
    from planner.engines import TaskPlanner
    from planner.model import PlanningTask
    from planner.problem import task_to_up
    from planner.validate import validate_with_up

    engine = args.engine or ("tamer" if task.domain.temporal else "fast-downward")
    planner = TaskPlanner(domain.up_domain, engine=engine, timeout=timeout, focus=not args.no_focus)
    result = planner.solve(task)
    if result.has_plan:  # a second, independent check by unified-planning's validators
        reachable = PlanningTask(task.domain, task.objects, task.facts, result.reachable_goals)
        valid, reason = validate_with_up(
            task_to_up(reachable, domain.up_domain), result.plan, result.schedule
        )
        if not valid:
            raise KnicError(f"{args.problem}: plan from {result.engine} failed validation: {reason}")
    return result


def _report(args: argparse.Namespace, result: Any, unreachable: list[str]) -> int:
    from planner.plan import PlanStatus

    if args.json:
        print(json.dumps(result.to_json()))
    else:
        for line in result.schedule or result.plan:
            print(line)
        for goal in unreachable:
            print(f"knic: unreachable goal {goal}", file=sys.stderr)
    if result.status in (PlanStatus.SOLVED, PlanStatus.PARTIAL):
        return 0
    if result.status == PlanStatus.UNSOLVABLE:
        if not args.json:
            print(f"knic: no goal can be reached in {args.problem}", file=sys.stderr)
        return EXIT_UNREACHABLE
    if not args.json:
        print(f"knic: error: planning {result.status.value}: {result.message}", file=sys.stderr)
    return 1
