"""``knic bench planner``: replanning latency against naive re-planning; dispatch overhead per step.

For each world (small: the seven-room apartment ``worlds/erl_home/erl_home_problem.pddl``; large: a generated
house with 80 rooms and 200 objects on the same domain) and each kind of change that breaks the running plan
-- an object perceived elsewhere than the plan assumed, a door found closed (its ``connected`` facts
removed), the running action failing -- the bench

* **replan**: times, in a live :class:`~planner.dispatch.Dispatcher`, from the knowledge-base change (or the
  failed ``step()``) until the dispatcher has a validated new plan and has activated its first action;
* **naive**: on the same knowledge-base state, times writing the whole knowledge base as a PDDL problem and
  calling unified-planning's Fast Downward once (what ROS planning systems do).

The naive path is timed in every round on the small world and in the first round on the large one (there
it takes many seconds). Dispatch overhead: microseconds per :meth:`Dispatcher.step` while an action is
running (the action's own ``step`` returns at once). All times are wall-clock; figures are medians over
``--repeat`` rounds.
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from actions.base import Action, ActionRegistry, ActionStatus, Outcome

ROOT = Path(__file__).resolve().parents[2]
DOMAIN = ROOT / "worlds" / "erl_home" / "domain.pddl"
SMALL = ROOT / "worlds" / "erl_home" / "erl_home_problem.pddl"
SMALL_GOALS = ["(object_at glasses bedroom)", "(object_at mug living_room)", "(light_on bedroom_left_light)"]
CHANGES = ("object_elsewhere", "door_closed", "action_failed")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--repeat", type=int, default=3, help="rounds per change kind and world (default 3)")
    parser.add_argument("--skip-large", action="store_true", help="only the seven-room apartment")
    parser.add_argument("--seed", type=int, default=1, help="seed of the generated large house")


# -- the generated large house --------------------------------------------------------------------------
def generate_house(rooms: int = 80, objects: int = 200, seed: int = 1) -> tuple[str, list[str]]:
    """A PDDL problem on the ERL domain with ``rooms`` rooms on a grid with doors and ``objects`` objects.

    The objects are the robot, 3 people, 6 lights, one piece of furniture per room plus one more in every
    fourth room, and items for the rest (two thirds on known furniture, one third with three candidate
    rooms). Returns ``(problem_text, goals)``.
    """
    rng = random.Random(seed)
    width = 10
    names = [f"room{i:02d}" for i in range(rooms)]
    doors: list[tuple[str, str]] = []
    for i in range(rooms):
        right, down = i + 1, i + width
        if right < rooms and right % width != 0 and rng.random() < 0.8:
            doors.append((names[i], names[right]))
        if down < rooms:
            doors.append((names[i], names[down]))
    furniture_room = [(f"table{i:02d}", names[i]) for i in range(rooms)]
    furniture_room += [(f"shelf{i:02d}", names[i]) for i in range(0, rooms, 4)]
    furniture = [f for f, _ in furniture_room]
    people = [f"person{i}" for i in range(3)]
    lights = [f"light{i}" for i in range(6)]
    n_items = objects - 1 - len(furniture) - len(people) - len(lights)
    items = [f"item{i:03d}" for i in range(n_items)]
    init = ["(robot_at r2d2 room00)", "(hand_empty r2d2)"]
    for a, b in doors:
        init += [f"(connected {a} {b})", f"(connected {b} {a})"]
    init += [f"(furniture_in {f} {r})" for f, r in furniture_room]
    init += [f"(surface {f})" for f in furniture]
    for i, item in enumerate(items):
        if i % 3 == 2:
            for room in rng.sample(names, 3):
                init.append(f"(possibly_at {item} {room})")
        else:
            f, r = furniture_room[rng.randrange(len(furniture_room))]
            init += [f"(object_at {item} {r})", f"(object_on {item} {f})", f"(found {item})"]
    for person in people:
        init.append(f"(person_at {person} {rng.choice(names)})")
    init += [f"(light_off {light})" for light in lights]
    goals = ["(object_at item000 room79)", "(has person0 item003)", "(light_on light1)"]
    text = (
        "(define (problem generated_house)\n  (:domain erl_home)\n  (:objects\n"
        f"    {' '.join(names)} - room\n    {' '.join(furniture)} - furniture\n"
        f"    {' '.join(items)} - item\n    {' '.join(people)} - person\n    r2d2 - robot\n"
        f"    {' '.join(lights)} - light)\n  (:init\n    " + "\n    ".join(init) + ")\n"
        "  (:goal (and " + " ".join(goals) + ")))\n"
    )
    return text, goals


# -- actions that run until told otherwise ----------------------------------------------------------------
class _Control:
    def __init__(self) -> None:
        self.fail_next = False


class _HoldAction(Action):
    """Keeps running (so a plan is always in progress) until the bench injects a failure."""

    def __init__(self, name: str, args: tuple[str, ...], control: _Control) -> None:
        super().__init__(name, args)
        self.control = control

    def step(self) -> ActionStatus:
        if self.control.fail_next:
            self.control.fail_next = False
            self.failure_reason = "bench: injected failure"
            return ActionStatus.FAILED
        return ActionStatus.RUNNING


def _registry(names: tuple[str, ...], control: _Control) -> ActionRegistry:
    def factory_for(name: str) -> Callable[[tuple[str, ...]], Action]:
        return lambda args: _HoldAction(name, args, control)

    return ActionRegistry({n: factory_for(n) for n in names})


# -- changes that break the running plan -------------------------------------------------------------------
def _object_elsewhere(kb: Any, plan: list[Any]) -> None:
    """Perception sees the first item the rest of the plan searches for or picks in another room."""
    from knowledge_base import BeliefStatus

    rooms = kb.instances("room")
    for step in plan:
        if step.name in ("search_object", "pick"):
            item, room = step.args[1], step.args[2]
            elsewhere = next(r for r in rooms if r != room and r not in ("bedroom", "room79"))
            with kb.batch():
                kb.add_fact("found", item, source="kp_camera", status=BeliefStatus.OBSERVED)
                kb.add_fact("object_at", item, elsewhere, source="kp_camera", status=BeliefStatus.OBSERVED)
            return
    raise RuntimeError("bench: the plan neither searches nor picks")


def _door_closed(kb: Any, plan: list[Any]) -> None:
    """The door of the first move of the rest of the plan that has a way around is found closed (both
    ``connected`` facts go), so the goals stay reachable and both paths have something to plan."""
    from knowledge_base import BeliefStatus

    doors = {tuple(f.args) for f in kb.facts("connected")}
    for step in plan:
        if step.name == "move":
            a, b = step.args[1], step.args[2]
            if _still_connected(doors - {(a, b), (b, a)}, a, b):
                with kb.batch():
                    kb.remove_fact("connected", a, b, source="kp_door", status=BeliefStatus.OBSERVED)
                    kb.remove_fact("connected", b, a, source="kp_door", status=BeliefStatus.OBSERVED)
                return
    raise RuntimeError("bench: no move in the plan has a way around")


def _still_connected(doors: set[tuple[str, ...]], a: str, b: str) -> bool:
    seen, frontier = {a}, [a]
    while frontier:
        here = frontier.pop()
        for x, y in doors:
            if x == here and y not in seen:
                seen.add(y)
                frontier.append(y)
    return b in seen


def _one_round(
    problem: Path, goals: list[str], change: str, naive: bool = True
) -> tuple[float, float | None, dict[str, Any]]:
    from knowledge_base import KnowledgeBase
    from planner.dispatch import Dispatcher
    from planner.engines import TaskPlanner
    from planner.recovery import Recovery, RecoveryPolicy, RecoveryRule
    from planner.trace import EventKind, Trace

    kb = KnowledgeBase.from_pddl(DOMAIN, problem)
    kb.clear_goals()
    for goal in goals:
        pred, *args = goal.strip("()").split()
        kb.add_goal(pred, *args)
    control = _Control()
    trace = Trace()
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.REPLAN)})
    registry = _registry(kb.domain.actions, control)
    dispatcher = Dispatcher(kb, TaskPlanner(kb.domain.up_domain), registry, trace=trace, policy=policy)
    dispatcher.step()  # first plan, first action activated
    dispatcher.step()  # running
    plans_before = len(trace.of_kind(EventKind.PLAN))
    rest = list(dispatcher.plan[dispatcher.index + 1 :])
    start = time.perf_counter()
    if change == "action_failed":
        control.fail_next = True
        dispatcher.step()  # the action reports its failure
        dispatcher.step()  # replan, validate, activate the next action
    else:
        (_object_elsewhere if change == "object_elsewhere" else _door_closed)(kb, rest)
        dispatcher.step()  # notice, check the rest of the plan, replan, validate, activate
    replan_ms = (time.perf_counter() - start) * 1000.0
    plans = trace.of_kind(EventKind.PLAN)
    if len(plans) != plans_before + 1 or not trace.of_kind(EventKind.REPLAN) or dispatcher.current is None:
        raise RuntimeError(f"bench: change {change} did not lead to a new plan being dispatched")
    naive_ms = _naive(kb) if naive else None
    info = {"plan_steps": len(dispatcher.plan), "planning_ms": plans[-1].data.get("planning_ms")}
    dispatcher.close()
    return replan_ms, naive_ms, info


def _naive(kb: Any) -> float:
    """Whole knowledge base to PDDL, parsed by unified-planning, solved by Fast Downward once."""
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import OneshotPlanner

    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        problem_file = Path(tmp) / "problem.pddl"
        problem_file.write_text(kb.to_pddl_problem(), encoding="utf-8")
        problem = PDDLReader().parse_problem(str(DOMAIN), str(problem_file))
        with OneshotPlanner(name="fast-downward") as planner:
            result = planner.solve(problem)
    elapsed = (time.perf_counter() - start) * 1000.0
    if result.plan is None:
        raise RuntimeError(f"bench: naive Fast Downward found no plan ({result.status.name})")
    return elapsed


def _dispatch_overhead(steps: int = 20_000) -> float:
    from knowledge_base import KnowledgeBase
    from planner.dispatch import Dispatcher
    from planner.engines import TaskPlanner

    kb = KnowledgeBase.from_pddl(DOMAIN, SMALL)
    control = _Control()
    dispatcher = Dispatcher(kb, TaskPlanner(kb.domain.up_domain), _registry(kb.domain.actions, control))
    dispatcher.step()
    dispatcher.step()
    start = time.perf_counter()
    for _ in range(steps):
        dispatcher.step()
    elapsed = time.perf_counter() - start
    if dispatcher.current is None:
        raise RuntimeError("bench: no action was running")
    return elapsed / steps * 1e6


def _world(problem: Path, goals: list[str], repeat: int, naive_rounds: int) -> dict[str, Any]:
    replans: dict[str, list[float]] = {c: [] for c in CHANGES}
    naives: dict[str, list[float]] = {c: [] for c in CHANGES}
    for round_index in range(repeat):
        for change in CHANGES:
            r, n, _ = _one_round(problem, goals, change, naive=round_index < naive_rounds)
            replans[change].append(r)
            if n is not None:
                naives[change].append(n)
    all_r = [x for v in replans.values() for x in v]
    all_n = [x for v in naives.values() for x in v]
    return {
        "replan_ms_median": statistics.median(all_r),
        "naive_ms_median": statistics.median(all_n),
        "replan_ms_by_change": {c: round(statistics.median(v), 3) for c, v in replans.items()},
        "naive_ms_by_change": {c: round(statistics.median(v), 3) for c, v in naives.items()},
        "samples": len(all_r),
        "naive_samples": len(all_n),
    }


def run(args: argparse.Namespace) -> int:
    from core.errors import KnicError
    from planner.engines import silence_up

    if args.repeat < 1:
        raise KnicError(f"--repeat must be at least 1, got {args.repeat}")
    silence_up()
    out: dict[str, Any] = {}
    small = _world(SMALL, SMALL_GOALS, args.repeat, args.repeat)
    out["replan_ms_small_median"] = round(small["replan_ms_median"], 3)
    out["naive_ms_small_median"] = round(small["naive_ms_median"], 3)
    if not args.skip_large:
        text, goals = generate_house(seed=args.seed)
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "generated_house.pddl"
            path.write_text(text, encoding="utf-8")
            large = _world(path, goals, args.repeat, 1)  # naive Fast Downward takes many seconds here
        out["replan_ms_large_median"] = round(large["replan_ms_median"], 3)
        out["naive_ms_large_median"] = round(large["naive_ms_median"], 3)
        out["speedup_large"] = round(large["naive_ms_median"] / large["replan_ms_median"], 1)
    out["dispatch_overhead_us_per_step"] = round(_dispatch_overhead(), 3)
    out["speedup_small"] = round(small["naive_ms_median"] / small["replan_ms_median"], 1)
    out["detail"] = {"small": small, **({"large": large} if not args.skip_large else {})}
    out["worlds"] = {"small": "worlds/erl_home/erl_home_problem.pddl"}
    if not args.skip_large:
        out["worlds"]["large"] = f"generated (seed {args.seed}): 80 rooms, 200 objects"
    if args.json:
        print(json.dumps(out, sort_keys=True))
    else:
        for key, value in out.items():
            if key != "detail":
                print(f"{key}: {value}")
    return 0
