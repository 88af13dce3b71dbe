"""The text-understanding bench: both sets run, the figures are printed, the other world needs no names."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.bench.language import SETS, evaluate
from knic.cli import main


def test_the_development_set_is_understood() -> None:
    figures = evaluate(SETS["dev"])
    assert figures["accuracy"] >= 0.95, figures["errors"]
    assert figures["by_class"]["other_world"] == 1.0


def test_the_held_out_set_stays_above_the_floor() -> None:
    figures = evaluate(SETS["test"])
    # no errors in the message: the held-out sentences are not to be read while working on the reader
    assert figures["main_argument_accuracy"] >= 0.85, "the held-out set fell below its floor"
    assert figures["refusal_accuracy"] >= 0.9


def test_bench_language_prints_dev_and_test(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "language", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) == {
        "dev",
        "test",
        "people2-dev",
        "people2-test",
        "people3-dev",
        "people4-dev",
        "people5-dev",
        "people6-dev",
        "people7-dev",
        "people8-dev",
        "people9-dev",
        "people10-dev",
        "people11-dev",
        "people12-dev",
        "people13-dev",
        "people14-dev",
        "people15-dev",
        "people16-dev",
        "people17-dev",
        "people18-dev",
        "people19-dev",
        "people20-dev",
        "people21-dev",
        "people22-dev",
        "people23-dev",
        "people24-dev",
        "people25-dev",
        "people26-dev",
        "people27-dev",
        "people28-dev",
        "people29-dev",
        "people30-dev",
        "people31-dev",
        "people32-dev",
        "people33-dev",
        "people34-dev",
        "people35-dev",
        "people36-dev",
        "people37-dev",
        "people38-dev",
        "people39-dev",
        "people40-dev",
        "people41-dev",
    }
    for figures in data.values():
        assert 0.0 <= figures["accuracy"] <= 1.0 and figures["cases"] >= 40
        assert {"fillers", "relative", "chains", "levels", "several"} <= set(figures["by_class"])


def test_bench_language_runs_a_set_of_ones_own(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    own = tmp_path / "mine.yaml"
    own.write_text(
        "cases:\n"
        '  - {text: "pick up the apple", frames: ["TAKING theme=apple"], class: plain}\n'
        '  - {text: "fully open the blinds", frames: ["OPERATING device=bedroom_blinds state=open"]}\n'
        '  - {text: "bring me the banana", reject: "banana", class: missing}\n'
    )
    assert main(["bench", "language", "--file", str(own), "--json"]) == 0
    figures = json.loads(capsys.readouterr().out)[str(own)]
    assert figures["cases"] == 3 and figures["accuracy"] == 1.0  # "open" is the blinds at 100 percent
    assert figures["goal_accuracy"] is None  # no gold goals: judged by the frames
    own.write_text("cases: [{text: 1}\n")
    assert main(["bench", "language", "--file", str(own)]) == 2
    assert "mine.yaml:2: not valid YAML" in capsys.readouterr().err


def test_a_case_can_name_a_simulator_world(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    own = tmp_path / "worlds.yaml"
    own.write_text(
        "cases:\n"
        '  - {text: "bring me the book", frames: ["BRINGING theme=book beneficiary=me"], world: test_flat,'
        " speaker: olga}\n"
        '  - {text: "bring me the book", reject: "book", world: erl}\n'
    )
    assert main(["bench", "language", "--file", str(own), "--json"]) == 0
    figures = json.loads(capsys.readouterr().out)[str(own)]
    assert figures["accuracy"] == 1.0 and figures["cases"] == 2  # the flat has a book, the apartment none
    own.write_text('cases:\n  - {text: "bring me the book", reject: "book", world: atlantis}\n')
    assert main(["bench", "language", "--file", str(own)]) == 2
    assert "world 'atlantis'" in capsys.readouterr().err
