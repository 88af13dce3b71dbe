"""Parts of the assembled loop that need no simulator: the surface-aware planner, goal parsing."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import KnowledgeBaseError
from knic.system import parse_goal
from knic.system.assembly import SurfaceAwarePlanner
from knowledge_base import KnowledgeBase
from planner.model import PlanningTask
from planner.plan import PlanResult, PlanStatus
from planner.problem import task_from_kb

DOMAIN = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "domain.pddl"


class _Recording:
    """A planner double that records the task it was given."""

    def __init__(self) -> None:
        self.tasks: list[PlanningTask] = []

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        self.tasks.append(task)
        return PlanResult(PlanStatus.SOLVED, (), task.goals, (), 0.0, "stub", "")


def test_surfaceless_furniture_is_no_place_to_plan_with() -> None:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: 0.0)
    with kb.batch():
        kb.add_instance("room", "kitchen")
        kb.add_instance("furniture", "bin")
        kb.add_instance("furniture", "kitchen_table")
        kb.add_fact("furniture_in", "bin", "kitchen")
        kb.add_fact("furniture_in", "kitchen_table", "kitchen")
    inner = _Recording()
    SurfaceAwarePlanner(inner, frozenset({"bin"})).solve(task_from_kb(kb))
    facts = inner.tasks[0].facts
    assert ("furniture_in", "kitchen_table", "kitchen") in facts
    assert ("furniture_in", "bin", "kitchen") not in facts
    assert kb.holds("furniture_in", "bin", "kitchen")  # the knowledge base still knows where the bin is


def test_goal_text_must_be_a_pddl_atom() -> None:
    assert str(parse_goal("(object_at glasses bedroom)")) == "(object_at glasses bedroom)"
    with pytest.raises(KnowledgeBaseError, match="not a PDDL atom"):
        parse_goal("object_at glasses bedroom)")
