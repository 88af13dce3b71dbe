"""``knic run`` end to end: PDDL, text and speech goals, exit codes and the trace file."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.cli import main

SPEECH = Path(__file__).resolve().parents[1] / "fixtures" / "speech"


def test_text_goal_bring_me_my_glasses(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    trace = tmp_path / "run.jsonl"
    journal = tmp_path / "run.sqlite"
    code = main(
        [
            "run",
            "--world",
            "erl_home_paper",
            "--goal",
            "bring me my glasses",
            "--trace",
            str(trace),
            "--journal",
            str(journal),
            "--max-sim-time",
            "300",
        ]
    )
    out = capsys.readouterr().out
    assert code == 0, out[-2000:]
    assert 'understood "bring me my glasses" as (has annie glasses)' in out
    assert "goal_achieved(hasannieglasses)" in out.replace(" ", "")
    events = [json.loads(line) for line in trace.read_text().splitlines()]
    assert any(e["kind"] == "success" and e["action"].startswith("(give r2d2 glasses annie") for e in events)
    assert journal.stat().st_size > 0


def test_speech_goal_look_for_my_glasses(capsys: pytest.CaptureFixture[str]) -> None:
    wav = SPEECH.parent / "speech_dev" / "dev_002.wav"  # "look for my glasses" (a development utterance)
    code = main(["run", "--world", "erl_home_paper", "--speech", str(wav), "--max-sim-time", "200", "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert code == 0, summary
    assert summary["goals"] == ["(reported glasses)"]
    assert summary["commands"][0]["text"] == "look for my glasses"


def test_unknown_goal_is_refused_with_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "--world", "erl_home_paper", "--goal", "(object_at unicorn bedroom)"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("knic: error:") and "unicorn" in err and "\n" not in err
    assert main(["run", "--world", "erl_home_paper", "--goal", "fly me to the moon"]) == 4


def test_a_negative_linger_is_refused_before_anything_runs(capsys: pytest.CaptureFixture[str]) -> None:
    goal = ["--world", "erl_home_paper", "--goal", "(object_at glasses bedroom)"]
    assert main(["run", *goal, "--ros", "--linger", "-1"]) == 2  # with --ros as with --serve
    assert capsys.readouterr().err.strip() == "knic: error: --linger: expected seconds >= 0, got -1.0"


def test_unreachable_in_time_exits_non_zero(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["run", "--world", "erl_home_paper", "--goal", "(object_at glasses bedroom)", "--max-sim-time", "5"]
    )
    assert code == 1
    assert "goals not reached within 5 s" in capsys.readouterr().err
