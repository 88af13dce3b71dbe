"""``knic goal`` and ``knic say``: JSON output and exit codes (in-process, through knic.cli.main)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.cli import main

from .conftest import SPEECH_FIXTURES


def test_goal_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["goal", "bring me my glasses", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data == {
        "text": "bring me my glasses",
        "frames": [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}],
        "goals": ["(has annie glasses)"],
        "accepted": True,
    }


def test_goal_rejected_prints_json_then_exits_4(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["goal", "bring me the banana", "--json", "--speaker", "tracy"]) == 4
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    assert data["accepted"] is False and data["goals"] == [] and "banana" in data["reason"]
    assert captured.err.startswith("knic: error: not understood:") and captured.err.count("\n") == 1


def test_say_refuses_non_wav_before_loading_anything(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text_file = tmp_path / "command.txt"
    text_file.write_text("bring me my glasses")
    assert main(["say", str(text_file), "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and "not a WAV file" in captured.err


def test_say_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["say", str(SPEECH_FIXTURES / "cmd_011.wav"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["transcript"] == "bring me my glasses"
    assert data["goals"] == ["(has annie glasses)"] and data["accepted"] is True
    assert data["audio"]["duration_s"] > 0.5
