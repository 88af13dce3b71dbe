"""Parts of the assembled loop that need no simulator: surfaces in the ERL domain, goal parsing."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import KnowledgeBaseError
from knic.seed import seed_kb_from_world
from knic.system import parse_goal
from knowledge_base import KnowledgeBase
from planner.engines import TaskPlanner
from planner.problem import task_from_kb
from worlds.api import load_world

DOMAIN = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "domain.pddl"


def _holding_in(furniture: dict[str, bool]) -> KnowledgeBase:
    """The robot in the kitchen holding the mug; ``furniture`` -> whether it has a surface."""
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: 0.0)
    with kb.batch():
        kb.add_instance("room", "kitchen")
        kb.add_instance("robot", "r2d2")
        kb.add_instance("item", "mug")
        kb.add_fact("robot_at", "r2d2", "kitchen")
        kb.add_fact("holding", "r2d2", "mug")
        for name, surface in furniture.items():
            kb.add_instance("furniture", name)
            kb.add_fact("furniture_in", name, "kitchen")
            if surface:
                kb.add_fact("surface", name)
    return kb


def test_items_are_placed_only_on_furniture_with_a_surface() -> None:
    planner = TaskPlanner(KnowledgeBase.from_pddl(DOMAIN).domain.up_domain)
    goal: list[tuple[str, ...]] = [("object_at", "mug", "kitchen")]
    kb = _holding_in({"bin": False, "kitchen_table": True})
    result = planner.solve(task_from_kb(kb, goal))
    assert [str(s) for s in result.plan] == ["(place r2d2 mug kitchen_table kitchen)"]
    only_bin = planner.solve(task_from_kb(_holding_in({"bin": False}), goal))
    assert not only_bin.has_plan and list(only_bin.unreachable_goals) == goal


def test_the_world_data_says_which_furniture_carries_items() -> None:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: 0.0)
    seed_kb_from_world(kb, load_world("erl_home"))
    assert not kb.holds("surface", "bin") and not kb.holds("surface", "plant")
    assert kb.holds("surface", "kitchen_table") and kb.holds("surface", "entrance_shelf")


def test_goal_text_must_be_a_pddl_atom() -> None:
    assert str(parse_goal("(object_at glasses bedroom)")) == "(object_at glasses bedroom)"
    with pytest.raises(KnowledgeBaseError, match="not a PDDL atom"):
        parse_goal("object_at glasses bedroom)")
