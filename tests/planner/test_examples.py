"""The example registry: known plans against both validators, the planner on every example, pruning."""

from __future__ import annotations

import pytest

from planner.engines import TaskPlanner
from planner.grounding import GroundAction, ground_task
from planner.model import PlanningTask
from planner.plan import PlanStatus, PlanStep
from planner.problem import focus_task, task_to_up
from planner.search import StripsSearch
from planner.validate import check_plan, validate_with_up
from tests.planner.examples import Example, examples

IDS = [e.name for e in examples()]


@pytest.mark.parametrize("ex", examples(), ids=IDS)
def test_known_plans_agree_with_unified_planning_validator(ex: Example) -> None:
    _, up_problem, task = ex.load()
    for plan in ex.valid:
        assert check_plan(task.domain, task.facts, plan, task.goals, task.objects).valid
        assert validate_with_up(up_problem, plan) == (True, "")
    for plan, breaks_at in ex.invalid:
        check = check_plan(task.domain, task.facts, plan, task.goals, task.objects)
        assert not check.valid
        assert (check.failed_step + 1 if check.failed_step is not None else 0) == breaks_at, check.reason
        valid, reason = validate_with_up(up_problem, plan)
        assert not valid and reason


@pytest.mark.parametrize("ex", examples(), ids=IDS)
def test_in_process_planner_solves_each_example_as_expected(ex: Example) -> None:
    up_domain, _, task = ex.load()
    result = TaskPlanner(up_domain, engine="knic").solve(task)
    expected = {"yes": PlanStatus.SOLVED, "partial": PlanStatus.PARTIAL, "no": PlanStatus.UNSOLVABLE}
    assert result.status == expected[ex.solvable]
    assert set(result.unreachable_goals) == set(ex.unreachable)
    if result.has_plan:
        reachable = PlanningTask(task.domain, task.objects, task.facts, result.reachable_goals)
        assert validate_with_up(task_to_up(reachable, up_domain), result.plan) == (True, "")


@pytest.mark.parametrize("ex", examples(), ids=IDS)
def test_pruning_never_changes_solvability_and_pruned_plans_are_valid_unpruned(ex: Example) -> None:
    _, _, task = ex.load()
    variants = {
        "focused+relevant": (focus_task(task), True),
        "focused": (focus_task(task), False),
        "full+relevant": (task, True),
        "full": (task, False),
    }
    outcomes: dict[str, frozenset[tuple[str, ...]]] = {}
    for label, (sub, relevant_only) in variants.items():
        grounded = ground_task(sub, relevance=relevant_only)
        search = StripsSearch(grounded.actions, sub.facts)
        reachable = frozenset(g for g in task.goals if g not in grounded.unreachable_goals)
        solved = frozenset(g for g in reachable if search.solve([g]) is not None)
        outcomes[label] = solved
        plan = search.solve(sorted(solved))
        assert plan is not None
        steps = [_step(a) for a in plan]
        assert check_plan(task.domain, task.facts, steps, solved, task.objects).valid, label
    if ex.solvable != "partial":  # focusing may need the full-task retry only when goals are unreachable
        assert len(set(outcomes.values())) == 1, outcomes
    assert outcomes["full+relevant"] == outcomes["full"]
    assert outcomes["focused+relevant"] == outcomes["focused"]


def test_focusing_drops_objects_the_goal_cannot_involve() -> None:
    ex = next(e for e in examples() if e.name == "erl_home")
    _, _, task = ex.load()
    kept = set(focus_task(task).objects)
    assert {"glasses", "r2d2", "bedroom", "hallway", "bed"} <= kept
    assert not {"tablet", "sponge", "door_bell", "doorbell"} & kept


def _step(action: GroundAction) -> PlanStep:
    return PlanStep(action.name, action.args)
