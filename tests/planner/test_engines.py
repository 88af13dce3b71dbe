"""Engine choice by problem features, Fast Downward and Tamer through unified-planning, unreachable goals."""

from __future__ import annotations

import pytest

from core.errors import PlanningError
from planner.engines import TaskPlanner, choose_engine
from planner.grounding import GroundingCache, ground_task
from planner.model import PlanningTask
from planner.plan import PlanStatus
from planner.problem import load_pddl
from planner.validate import check_plan
from tests.planner.examples import FIXTURES, example


def durative() -> tuple[object, PlanningTask]:
    up_domain, _, task = load_pddl(
        str(FIXTURES / "durative_domain.pddl"), str(FIXTURES / "durative_problem.pddl")
    )
    return up_domain, task


def test_auto_picks_in_process_for_strips_and_tamer_for_durative() -> None:
    _, _, task = example("erl_home").load()
    assert choose_engine(task) == "knic"
    _, timed = durative()
    assert choose_engine(timed) == "tamer"


def test_engines_name_the_features_they_lack() -> None:
    up_domain, timed = durative()
    with pytest.raises(
        PlanningError, match="knic cannot plan domain timed_rooms: unsupported feature durative"
    ):
        TaskPlanner(up_domain, engine="knic").solve(timed)
    with pytest.raises(PlanningError, match=r"fast-downward cannot plan .*CONTINUOUS_TIME"):
        TaskPlanner(up_domain, engine="fast-downward").solve(timed)
    erl_domain, _, erl = example("erl_home").load()
    with pytest.raises(PlanningError, match=r"tamer cannot plan domain erl_home: .*HIERARCHICAL_TYPING"):
        TaskPlanner(erl_domain, engine="tamer").solve(erl)
    with pytest.raises(PlanningError, match="unknown engine 'lama'"):
        TaskPlanner(erl_domain, engine="lama")


def test_tamer_plans_the_durative_example() -> None:
    up_domain, timed = durative()
    result = TaskPlanner(up_domain).solve(timed)
    assert result.engine == "tamer" and result.status == PlanStatus.SOLVED
    assert [str(s) for s in result.plan] == ["(move r2d2 kitchen hallway)", "(move r2d2 hallway bedroom)"]


def test_fast_downward_plan_is_validated_and_reaches_the_goal() -> None:
    up_domain, _, task = example("erl_paper").load()
    result = TaskPlanner(up_domain, engine="fast-downward").solve(task)
    assert result.engine == "fast-downward" and result.status == PlanStatus.SOLVED
    assert check_plan(task.domain, task.facts, result.plan, task.goals, task.objects).valid


def test_goals_not_reachable_together_keep_the_first_and_name_the_other() -> None:
    up_domain, _, task = example("erl_home").load()
    both = PlanningTask(
        task.domain,
        task.objects,
        task.facts,
        (("robot_at", "r2d2", "kitchen"), ("robot_at", "r2d2", "bedroom")),
    )
    result = TaskPlanner(up_domain, engine="knic").solve(both)
    assert result.status == PlanStatus.PARTIAL
    assert result.unreachable_goals == (("robot_at", "r2d2", "bedroom"),)
    assert check_plan(task.domain, task.facts, result.plan, [("robot_at", "r2d2", "kitchen")]).valid


def test_no_reachable_goal_is_unsolvable_with_every_goal_named() -> None:
    up_domain, _, task = example("erl_blocked").load()
    for engine in ("knic", "fast-downward"):
        result = TaskPlanner(up_domain, engine=engine).solve(task)
        assert result.status == PlanStatus.UNSOLVABLE, engine
        assert set(result.unreachable_goals) == set(task.goals)


def test_grounding_cache_equals_fresh_grounding_after_typical_changes() -> None:
    _, _, task = example("erl_multi").load()
    cache = GroundingCache()
    cache.ground(task)
    door_closed = task.facts - {("connected", "hallway", "kitchen"), ("connected", "kitchen", "hallway")}
    moved = (task.facts - {("object_at", "mug", "kitchen")}) | {("object_at", "mug", "dining_room")}
    for facts in (door_closed, moved):
        changed = PlanningTask(task.domain, task.objects, facts, task.goals)
        cached = cache.ground(changed)
        fresh = ground_task(changed)
        fresh_set = {(a.name, a.args) for a in fresh.actions}
        cached_set = {(a.name, a.args) for a in cached.actions}
        assert fresh_set <= cached_set  # never misses an action
        door_used = any(a.name == "move" and a.args[1:] == ("hallway", "kitchen") for a in cached.actions)
        assert door_used == (facts is moved)
    assert cache.hits == 2 and cache.misses == 1
    new_door = PlanningTask(
        task.domain, task.objects, task.facts | {("connected", "bedroom", "kitchen")}, task.goals
    )
    cache.ground(new_door)
    assert cache.misses == 2
