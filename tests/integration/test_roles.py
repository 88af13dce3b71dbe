"""Roles in ``knic run``: the semi-autonomous robot asks before a goal is added; the teleoperated one runs the
operator's goals with perception still grounding the knowledge base. Paper world, short runs."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.cli import main
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from knowledge_base.model import ChangeKind

ANSWERS = Path(__file__).resolve().parent / "fixtures"
SEMI = "service_semi_autonomous"


def run_cli(*args: str) -> int:
    return main(["run", "--world", "erl_home_paper", "--max-sim-time", "120", *args])


def test_semi_autonomous_no_adds_no_goal_and_fails(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    journal = tmp_path / "no.sqlite"
    code = run_cli(
        "--role", SEMI, "--goal", "bring me my glasses", "--confirm", "no", "--journal", str(journal)
    )
    captured = capsys.readouterr()
    assert code == 1
    assert "robot: You asked me to bring the reading glasses to you. Is that right?" in captured.out
    assert "robot: Okay, I will not do it." in captured.out
    err = captured.err.strip()
    assert err.startswith("knic: error:") and "not confirmed" in err and "\n" not in err
    kb = KnowledgeBase.from_journal(journal, read_only=True)
    try:
        assert kb.goals() == []
        assert not any(c.kind == ChangeKind.ADD_GOAL for c in kb.changes())
        assert kb.holds("robot_at", "r2d2", "bedroom")  # the world was set up, nothing was done
    finally:
        kb.close()


def test_semi_autonomous_yes_reaches_the_goal(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    journal = tmp_path / "yes.sqlite"
    code = run_cli(
        "--role", SEMI, "--goal", "go to the kitchen", "--confirm", "yes", "--journal", str(journal)
    )
    out = capsys.readouterr().out
    assert code == 0, out[-2000:]
    question = out.index("robot: You asked me to go to the kitchen. Is that right?")
    assert question < out.index("robot: Okay, I will do it.") < out.index("run succeeded")
    kb = KnowledgeBase.from_journal(journal, read_only=True)
    try:
        assert kb.goals() == [Fact("robot_at", ("r2d2", "kitchen"))]
        prov = kb.why(Fact("robot_at", ("r2d2", "kitchen")))
        assert prov is not None and prov.status == BeliefStatus.OBSERVED
    finally:
        kb.close()


def test_spoken_answers_confirm_or_decline(capsys: pytest.CaptureFixture[str]) -> None:
    no = str(ANSWERS / "answer_no.wav")
    assert run_cli("--role", SEMI, "--goal", "(robot_at r2d2 kitchen)", "--confirm-speech", no, "--json") == 1
    captured = capsys.readouterr()
    assert "robot: You asked me to make (robot_at r2d2 kitchen) true. Is that right?" in captured.err
    assert "robot: Okay, I will not do it." in captured.err and captured.out == ""
    yes = str(ANSWERS / "answer_yes.wav")
    code = run_cli("--role", SEMI, "--goal", "(robot_at r2d2 kitchen)", "--confirm-speech", yes, "--json")
    captured = capsys.readouterr()
    summary = json.loads(captured.out)
    assert code == 0 and summary["success"] and summary["goals"] == ["(robot_at r2d2 kitchen)"]
    assert "robot: Okay, I will do it." in captured.err


def test_semi_autonomous_without_a_way_to_ask_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    assert run_cli("--role", SEMI, "--goal", "go to the kitchen") == 2  # pytest's stdin is not a terminal
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert err.startswith("knic: error:") and "--confirm" in err and "\n" not in err
    assert "robot:" not in captured.out


def test_teleoperated_runs_the_operators_goal_with_grounding_live(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    journal = tmp_path / "teleop.sqlite"
    code = run_cli("--role", "teleoperated", "--goal", "(robot_at r2d2 kitchen)", "--journal", str(journal))
    out = capsys.readouterr().out
    assert code == 0, out[-2000:]
    assert "robot:" not in out  # nothing to confirm
    kb = KnowledgeBase.from_journal(journal, read_only=True)
    try:
        added = [c for c in kb.changes() if c.kind == ChangeKind.ADD_GOAL]
        assert [(c.name, c.args, c.provenance.source) for c in added] == [
            ("robot_at", ("r2d2", "kitchen"), "operator")
        ]
        prov = kb.why(Fact("robot_at", ("r2d2", "kitchen")))
        assert prov is not None and prov.status == BeliefStatus.OBSERVED and prov.source != "dispatcher"
        assert prov.source == "kp'.robot_at" and prov.support  # asserted by KGM-3 from perception units
    finally:
        kb.close()
