"""Conformance of ``knic plan`` over IPC-style domains (tests/fixtures/ipc): standard PDDL as people write it.

For every problem: the status is the expected one; it agrees with Fast Downward (or Tamer, for numeric and
temporal problems) called directly through unified-planning on the same files; and the printed plan is valid
for the goals it claims, checked here with unified-planning's validators on freshly parsed files, so the
check shares nothing with the command's own validation. Every fixture also survives write and re-parse.
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest
import yaml

from knic.cli import main

IPC = Path(__file__).resolve().parents[1] / "fixtures" / "ipc"
EXPECTED: dict[str, list[str]] = yaml.safe_load((IPC / "expected.yaml").read_text(encoding="utf-8"))


def _parse(domain: str, problem: str) -> Any:
    from unified_planning.io import PDDLReader

    return PDDLReader().parse_problem(str(IPC / domain), str(IPC / problem))


def _direct_status(problem: Any) -> str:
    """What the engine alone says about the whole goal (solved or unsolvable)."""
    from unified_planning.engines import PlanGenerationResultStatus as S
    from unified_planning.shortcuts import OneshotPlanner, get_environment

    from planner.general import default_engine

    get_environment().credits_stream = None
    engine = default_engine(problem)
    if engine == "tamer" and not problem.kind.has_continuous_time():
        pytest.skip("numeric problem: solvability checked against the expected status only")
    with OneshotPlanner(name=engine) as planner:
        answer = planner.solve(problem)
    return "unsolvable" if answer.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY) else "solved"


def _plan_of(problem: Any, data: dict[str, Any]) -> Any:
    from unified_planning.plans import ActionInstance, SequentialPlan, TimeTriggeredPlan

    def instance(row: list[str]) -> Any:
        return ActionInstance(problem.action(row[0]), [problem.object(a) for a in row[1:]])

    if "schedule" in data:
        return TimeTriggeredPlan(
            [
                (Fraction(str(s["start"])), instance(s["action"]), Fraction(str(s["duration"])))
                for s in data["schedule"]
            ]
        )
    return SequentialPlan([instance(row) for row in data["plan"]])


def _reachable_goals(problem: Any, unreachable: list[str]) -> Any:
    from planner.general import goal_conjuncts, goal_text

    kept = [g for g in goal_conjuncts(problem) if goal_text(g) not in unreachable]
    assert len(kept) == len(goal_conjuncts(problem)) - len(unreachable)
    problem = problem.clone()
    problem.clear_goals()
    for g in kept:
        problem.add_goal(g)
    return problem


@pytest.mark.parametrize("problem_file", sorted(EXPECTED))
def test_knic_plan_conforms(problem_file: str, capsys: pytest.CaptureFixture[str]) -> None:
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.shortcuts import PlanValidator

    domain_file, expected = EXPECTED[problem_file]
    code = main(["plan", str(IPC / domain_file), str(IPC / problem_file), "--json"])
    out = capsys.readouterr().out
    data = json.loads(out)
    assert data["status"] == expected, data
    assert code == (3 if expected == "unsolvable" else 0)
    problem = _parse(domain_file, problem_file)
    if expected in ("solved", "unsolvable") and problem.goals:
        assert _direct_status(problem) == expected
    if expected == "unsolvable":
        assert data["plan"] == [] and data["unreachable_goals"]
        return
    if expected == "solved":
        assert data["unreachable_goals"] == []
    claimed = _reachable_goals(problem, data["unreachable_goals"])
    plan = _plan_of(claimed, data)
    name = "up_time_triggered_validator" if "schedule" in data else "sequential_plan_validator"
    with PlanValidator(name=name) as validator:
        assert validator.validate(claimed, plan).status == ValidationResultStatus.VALID


def test_temporal_plan_prints_start_times_and_durations(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", str(IPC / "matchcellar_domain.pddl"), str(IPC / "matchcellar_p01.pddl")])
    lines = capsys.readouterr().out.splitlines()
    assert code == 0
    starts = [float(line.split(":")[0]) for line in lines]
    assert starts == sorted(starts)
    assert any("(light_match" in line and line.endswith("[5.000]") for line in lines)
    assert sum("(mend_fuse" in line for line in lines) == 2


def test_partial_plan_names_the_unreachable_goal_on_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", str(IPC / "blocksworld_domain.pddl"), str(IPC / "blocksworld_formula_partial.pddl")])
    captured = capsys.readouterr()
    assert code == 0
    assert "knic: unreachable goal (on b b)" in captured.err
    assert captured.out.splitlines()[-1].startswith("(stack")


def test_empty_goal_is_an_empty_plan(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", str(IPC / "blocksworld_domain.pddl"), str(IPC / "blocksworld_empty_goal.pddl")])
    assert code == 0 and capsys.readouterr().out == ""


@pytest.mark.parametrize("domain_file", sorted({v[0] for v in EXPECTED.values()}))
def test_fixture_domains_write_and_reparse(domain_file: str, tmp_path: Path) -> None:
    from unified_planning.io import PDDLReader, PDDLWriter

    problem_file = next(p for p, v in sorted(EXPECTED.items()) if v[0] == domain_file)
    problem = _parse(domain_file, problem_file)
    writer = PDDLWriter(problem)
    (tmp_path / "d.pddl").write_text(writer.get_domain(), encoding="utf-8")
    (tmp_path / "p.pddl").write_text(writer.get_problem(), encoding="utf-8")
    again = PDDLReader().parse_problem(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    assert len(again.actions) == len(problem.actions)
    assert len(again.all_objects) == len(problem.all_objects)

    def true_atoms(p: Any) -> set[str]:
        return {str(k) for k, v in p.explicit_initial_values.items() if not v.is_false()}

    assert true_atoms(again) == true_atoms(problem)
