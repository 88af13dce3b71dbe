"""The conversion boundary: unified-planning problems to tasks and back, atoms and plan steps as text."""

from __future__ import annotations

import pytest

from planner.model import atom_from_str, atom_str, task_from_up
from planner.plan import PlanResult, PlanStatus, PlanStep, steps_from_lists
from planner.problem import strips_domain, task_to_up
from tests.planner.examples import Example, examples


def test_atom_text_round_trip() -> None:
    atom = ("object_at", "glasses", "kitchen")
    assert atom_str(atom) == "(object_at glasses kitchen)"
    assert atom_from_str(atom_str(atom)) == atom
    with pytest.raises(ValueError):
        atom_from_str("object_at glasses")


def test_plan_step_text_and_json_round_trip() -> None:
    step = PlanStep.parse("(move r2d2 kitchen bedroom)")
    assert step == PlanStep("move", ("r2d2", "kitchen", "bedroom"))
    assert str(step) == "(move r2d2 kitchen bedroom)"
    assert steps_from_lists([step.as_list()]) == (step,)
    result = PlanResult(
        PlanStatus.PARTIAL, (step,), (("robot_at", "r2d2", "x"),), (("robot_at", "r2d2", "x"),)
    )
    assert result.to_json()["plan"] == [["move", "r2d2", "kitchen", "bedroom"]]
    assert result.to_json()["unreachable_goals"] == ["(robot_at r2d2 x)"]


@pytest.mark.parametrize("ex", examples(), ids=[e.name for e in examples()])
def test_task_to_up_and_back_is_identity(ex: Example) -> None:
    up_domain, _, task = ex.load()
    again = task_from_up(task_to_up(task, up_domain), strips_domain(up_domain))
    assert again.objects == task.objects
    assert again.facts == task.facts
    assert again.goals == task.goals


def test_domain_reads_schemas_static_predicates_and_constants() -> None:
    up_domain, _, _ = next(e for e in examples() if e.name == "erl_home").load()
    dom = strips_domain(up_domain)
    assert dom.unsupported is None and not dom.temporal
    assert set(dom.constants) == {"l0", "l25", "l50", "l75", "l100"}
    assert {"connected", "furniture_in", "possibly_at"} <= dom.static_predicates
    move = dom.schemas["move"]
    assert move.params == (("r", "robot"), ("from", "room"), ("to", "room"))
    assert move.pre_pos == (("robot_at", (0, 1)), ("connected", (1, 2)))
    search = dom.schemas["search_object"]
    assert ("found", (1,)) in search.pre_neg and ("searched", (1, 2)) in search.pre_neg
    assert dom.is_subtype("light", "device") and not dom.is_subtype("room", "entity")


@pytest.mark.parametrize("ex", examples(), ids=[e.name for e in examples()])
def test_every_fixture_writes_to_pddl_and_parses_back(ex: Example) -> None:
    from unified_planning.io import PDDLReader, PDDLWriter

    up_domain, _, task = ex.load()
    writer = PDDLWriter(task_to_up(task, up_domain))
    again = task_from_up(PDDLReader().parse_problem_string(writer.get_domain(), writer.get_problem()))
    assert again.objects == task.objects
    assert again.facts == task.facts
    assert again.goals == task.goals
