"""``knic goal`` and ``knic say``: JSON output and exit codes (in-process, through knic.cli.main)."""

from __future__ import annotations

import json
import os
import tempfile
import time
from pathlib import Path
from typing import Any

import pytest

from knic.cli import main
from knic.language import sayd

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


def test_say_remembers_the_model_and_hears_the_same_the_next_time(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The first start builds and keeps the world's command model and vocabulary; the next decodes in child
    processes with them (knic.language.oneshot) and reads the same; a damaged copy is ignored."""
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    monkeypatch.setenv("TMPDIR", str(tmp_path))  # the daemon's too
    ask, wav = sayd.ask, str(SPEECH_FIXTURES / "cmd_011.wav")
    assert main(["say", wav, "--json"]) == 0
    first = json.loads(capsys.readouterr().out)
    kept = sorted(p.name for p in tmp_path.glob("knic-oneshot-*"))
    assert len(kept) == 3 and any(n.endswith("-vocabulary.json") for n in kept)
    # a say daemon keeps everything loaded for the next command (knic.language.sayd), which it answers
    deadline = time.monotonic() + 60.0
    sockets = tmp_path / f"knic-{os.getuid()}"  # only its folder: other knic-* folders come and go meanwhile
    while not any(map(sayd.running, sockets.glob("say-*.sock"))) and time.monotonic() < deadline:
        time.sleep(0.05)
    answered: list[dict[str, Any] | None] = []

    def asked(*args: Any) -> dict[str, Any] | None:
        answered.append(ask(*args))
        return answered[-1]

    monkeypatch.setattr(sayd, "ask", asked)
    assert main(["say", wav, "--json"]) == 0
    second = json.loads(capsys.readouterr().out)
    assert second["transcript"] == first["transcript"] == "bring me my glasses"
    assert second["goals"] == first["goals"] == ["(has annie glasses)"]
    assert answered[0] is not None  # by the daemon
    monkeypatch.setenv(sayd.IDLE_ENV, "0")  # no daemon asked: the remembered copies are read
    for path in tmp_path.glob("knic-oneshot-*.json"):
        path.write_text("{not json")
    assert main(["say", wav, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["goals"] == ["(has annie glasses)"]


FLAT = Path(__file__).resolve().parents[2] / "worlds" / "test_flat" / "test_flat.yaml"


def test_goal_world_file_uses_that_worlds_names(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["goal", "--world", str(FLAT), "--json", "carry the teacup to the lounge"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["frames"] == [{"frame": "BRINGING", "theme": "teacup", "goal": "lounge"}]
    assert data["goals"] == ["(object_at teacup lounge)"]
    # "me" is the world's own person when it has no annie; furniture is placed in its room
    assert main(["goal", "--world", str(FLAT), "--json", "bring me the book from the desk"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert "(has olga book)" in data["goals"] and "(possibly_at book study)" in data["hints"]


def test_goal_world_file_refuses_what_it_lacks(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["goal", "--world", str(FLAT), "--json", "bring me my glasses"]) == 4
    data = json.loads(capsys.readouterr().out)
    assert data["accepted"] is False and "glasses" in data["reason"]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--world", "no/such/world.yaml"], "unknown world 'no/such/world.yaml'"),
        (["--world", str(FLAT), "--problem", str(FLAT)], "--world and --problem"),
    ],
)
def test_goal_bad_world_is_one_line(
    argv: list[str], message: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["goal", *argv, "go to the lounge"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and message in captured.err and captured.err.count("\n") == 1


def test_the_remembered_model_follows_the_phrasings(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """People's phrasings are part of the command model: a changed phrasings file is another world key, so
    ``knic say`` builds the model again instead of reusing the one remembered."""
    from knic.language import oneshot

    code = tmp_path / "language"
    code.mkdir()
    phrasings = code / "phrasings.txt"
    phrasings.write_text("bring me the {item=apple}\n", encoding="utf-8")
    monkeypatch.setattr(oneshot, "_CODE", [code])
    before = oneshot.world_key(["worlds/erl_home/erl_home_domain.pddl"], "auto")
    phrasings.write_text("bring me the {item=apple} love\n", encoding="utf-8")
    assert oneshot.world_key(["worlds/erl_home/erl_home_domain.pddl"], "auto") != before


def test_goal_batch_answers_each_line_and_stops_quietly_when_its_reader_leaves() -> None:
    import subprocess
    import sys

    knic = [sys.executable, "-c", "import sys; from knic.cli import main; sys.exit(main())", "goal", "-"]
    lines = "bring me the mug\n\ngo to the kitchen\nsing me a song\n"
    done = subprocess.run(knic, input=lines, capture_output=True, text=True, timeout=120, check=False)
    answers = [json.loads(line) for line in done.stdout.splitlines()]
    assert [a["accepted"] for a in answers] == [True, True, False]  # the empty line is skipped
    assert answers[1]["frames"] == [{"frame": "MOTION", "goal": "kitchen"}]
    assert done.returncode == 4 and "1 command(s) not understood" in done.stderr
    # the reader takes one answer and leaves ("knic goal - | head -1"): no traceback, the shell's SIGPIPE code
    process = subprocess.Popen(
        knic, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    assert process.stdin is not None and process.stdout is not None
    process.stdin.write("bring me the mug\n")
    process.stdin.flush()
    assert json.loads(process.stdout.readline())["accepted"]
    process.stdout.close()
    _, errors = process.communicate("go to the kitchen\n" * 200, timeout=120)
    assert process.returncode == 141 and "Traceback" not in errors


def test_goal_in_a_domain_whose_types_no_command_names_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    domain, problem = tmp_path / "office.pddl", tmp_path / "office_problem.pddl"
    domain.write_text(
        "(define (domain office) (:requirements :strips :typing) (:types bay widget drone)\n"
        "  (:predicates (at ?a - drone ?p - bay) (in ?t - widget ?p - bay)))\n"
    )
    problem.write_text(
        "(define (problem p) (:domain office) (:objects lobby - bay stapler - widget bot - drone)\n"
        "  (:init (at bot lobby) (in stapler lobby)) (:goal (at bot lobby)))\n"
    )
    code = main(["goal", "--domain", str(domain), "--problem", str(problem), "bring me the stapler"])
    err = capsys.readouterr().err.strip()
    assert code == 4 and len(err.splitlines()) == 1
    assert str(domain) in err and "declares none" in err and "bay, drone, widget" in err


def test_goal_in_a_problem_without_annie_is_for_its_first_person(capsys: pytest.CaptureFixture[str]) -> None:
    other = Path(__file__).resolve().parents[1] / "fixtures" / "language" / "other_world" / "problem.pddl"
    assert main(["goal", "--problem", str(other), "--json", "bring me the teddy bear"]) == 0
    assert json.loads(capsys.readouterr().out)["goals"] == ["(has maria teddy_bear)"]  # maria, oscar: maria
    assert (
        main(["goal", "--problem", str(other), "--speaker", "oscar", "--json", "bring me the teddy bear"])
        == 0
    )
    assert json.loads(capsys.readouterr().out)["goals"] == ["(has oscar teddy_bear)"]
