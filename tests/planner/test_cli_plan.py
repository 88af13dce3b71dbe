"""``knic plan``: output format, JSON, exit codes and one-line errors naming file, line and symbol."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.cli import main
from tests.planner.examples import FIXTURES, ROOT

DOMAIN = str(ROOT / "worlds" / "erl_home" / "domain.pddl")
IPC = ROOT / "tests" / "fixtures" / "ipc"


def test_prints_one_action_per_line(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", DOMAIN, str(ROOT / "worlds" / "erl_home" / "erl_home_problem.pddl")])
    out = capsys.readouterr().out.splitlines()
    assert code == 0
    assert out == [
        "(move r2d2 entrance_hall hallway)",
        "(move r2d2 hallway bedroom)",
        "(search_object r2d2 glasses bedroom)",
    ]


def test_json_names_unreachable_goals(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", DOMAIN, str(FIXTURES / "erl_partial.pddl"), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0
    assert data["status"] == "partial"
    assert sorted(data["unreachable_goals"]) == ["(has annie tissues)", "(robot_at r2d2 bathroom)"]
    assert ["switch_on", "r2d2", "hallway_light"] in data["plan"]
    assert isinstance(data["planning_ms"], float)


def test_exit_3_when_no_goal_can_be_reached(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", DOMAIN, str(FIXTURES / "erl_blocked.pddl")])
    err = capsys.readouterr().err
    assert code == 3
    assert "unreachable goal (robot_at r2d2 bathroom)" in err and "no goal can be reached" in err


@pytest.mark.parametrize(
    ("problem", "expected"),
    [
        ("bad_predicate.pddl", ["bad_predicate.pddl:6", "door_open"]),
        ("bad_type.pddl", ["bad_type.pddl:6", "glasses"]),
        ("other_domain.pddl", ["other_domain.pddl:2", "blocksworld"]),
        ("bad_syntax.pddl", ["bad_syntax.pddl:6"]),
    ],
)
def test_bad_input_is_one_line_naming_file_line_and_symbol(
    problem: str, expected: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(["plan", DOMAIN, str(FIXTURES / problem)])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1
    for part in expected:
        assert part in err


def test_other_domain_and_engine_option(capsys: pytest.CaptureFixture[str]) -> None:
    domain = str(FIXTURES / "blocks_domain.pddl")
    code = main(["plan", domain, str(FIXTURES / "blocks_problem.pddl"), "--engine", "knic", "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["engine"] == "knic" and len(data["plan"]) == 6


def _gripper_problem(balls: int) -> str:
    names = " ".join(f"ball{i}" for i in range(balls))
    init = " ".join(f"(ball ball{i}) (at ball{i} rooma)" for i in range(balls))
    goal = " ".join(f"(at ball{i} roomb)" for i in range(balls))
    return (
        f"(define (problem big) (:domain gripper-strips) (:objects rooma roomb left right {names})\n"
        f"(:init (room rooma) (room roomb) (gripper left) (gripper right) (at-robby rooma) (free left)"
        f" (free right) {init})\n(:goal (and {goal})))\n"
    )


def test_timeout_bounds_parsing_too(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    problem = tmp_path / "big.pddl"
    problem.write_text(_gripper_problem(20_000), encoding="utf-8")
    code = main(["plan", str(IPC / "gripper_domain.pddl"), str(problem), "--timeout", "0.5"])
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert err == "knic: error: knic plan timed out after 0.5 s (--timeout)"


@pytest.mark.parametrize("value", ["nan", "inf", "-1", "0"])
def test_timeout_must_be_a_finite_positive_number(value: str, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", DOMAIN, str(FIXTURES / "erl_partial.pddl"), f"--timeout={value}"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and "--timeout" in err


def test_non_utf8_and_oversized_files_are_one_line_errors(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    latin = tmp_path / "latin.pddl"
    latin.write_bytes(b"(define (domain caf\xe9)\n (:predicates (p)))\n")
    code = main(["plan", str(latin), str(IPC / "gripper_p01.pddl")])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.startswith(f"knic: error: {latin}:1: domain file is not UTF-8")
    code = main(["plan", str(IPC / "gripper_domain.pddl"), "/dev/zero"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and "/dev/zero" in err


def test_untyped_domain_plans(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["plan", str(IPC / "depot_domain.pddl"), str(IPC / "depot_p01.pddl")])
    out = capsys.readouterr().out.splitlines()
    assert code == 0 and out[-1] == "(drop hoist1 crate1 crate0 distributor0)"
