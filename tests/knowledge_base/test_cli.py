"""``knic facts`` (table, JSON, --at, --why, --watch against a live writer) and ``knic bench kb``."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from knic.cli import main
from knowledge_base import KnowledgeBase

from .conftest import ERL_DOMAIN, PAPER_PROBLEM, FakeClock


@pytest.fixture
def journal(tmp_path: Path) -> Path:
    """A recorded run: the paper problem at t=0, glasses seen in the kitchen at 12.5, moved at 20."""
    path = tmp_path / "run.sqlite"
    clock = FakeClock(0.0)
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=clock)
    clock.t = 12.5
    kb.add_fact("object_at", "glasses", "kitchen", source="kp.object", status="observed", confidence=0.9,
                support=("llku:3",))  # fmt: skip
    clock.t = 20.0
    kb.add_fact("object_at", "glasses", "entrance", source="kp.object", status="observed")
    kb.close()
    return path


def run_cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_table(journal: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal))
    lines = out.splitlines()
    assert code == 0
    assert lines[0].split() == ["PREDICATE", "ARGUMENTS", "STATUS", "AUTHOR", "SINCE"]
    assert "object_at     glasses entrance         observed  kp.object  20.00" in lines
    assert lines[-1] == "23 fact(s)"


def test_json_predicate_and_at(journal: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal), "--predicate", "object_at", "--json")
    assert code == 0
    assert json.loads(out) == [
        {"predicate": "object_at", "arguments": ["glasses", "entrance"], "status": "observed",
         "author": "kp.object", "since": 20.0, "confidence": 1.0, "support": []}
    ]  # fmt: skip
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal), "--predicate", "object_at", "--json",
                           "--at", "15")  # fmt: skip
    assert [(r["arguments"], r["since"], r["support"]) for r in json.loads(out)] == [
        (["glasses", "kitchen"], 12.5, ["llku:3"])
    ]
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal), "--json", "--at", "5")
    assert not any(r["predicate"] == "object_at" for r in json.loads(out)) and len(json.loads(out)) == 22


def test_why(journal: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal), "--why", "(object_at glasses kitchen)",
                           "--at", "15")  # fmt: skip
    assert code == 0
    assert out.splitlines()[0] == (
        "(object_at glasses kitchen) is observed: written by kp.object at 12.50 with confidence 0.9, "
        "supported by llku:3"
    )
    code, out, _ = run_cli(capsys, "facts", "--journal", str(journal), "--why", "(object_at glasses kitchen)",
                           "--json")  # fmt: skip
    answer = json.loads(out)
    assert answer["holds"] is False
    assert [(h["change"], h["time"]) for h in answer["history"]] == [
        ("add_fact", 12.5),
        ("remove_fact", 20.0),
    ]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--journal", "missing.sqlite"], "missing.sqlite: no such journal file"),
        (["--why", "object_at glasses"], "cannot parse fact 'object_at glasses'"),
        (["--why", "(teleported glasses)"], "unknown predicate 'teleported'"),
        (["--why", "(object_at glasses moon)"], "'moon' is not an instance"),
        (["--why", "(object_at glasses)"], "object_at takes 2 argument(s), got 1"),
        (["--predicate", "teleported"], "unknown predicate 'teleported'"),
        (["--at", "yesterday"], "--at: expected a time in seconds"),
    ],
)
def test_bad_input_is_one_line_error(
    journal: Path, capsys: pytest.CaptureFixture[str], argv: list[str], message: str
) -> None:
    if argv[0] != "--journal":
        argv = ["--journal", str(journal), *argv]
    else:
        argv = ["--journal", str(journal.with_name(argv[1]))]
    code, out, err = run_cli(capsys, "facts", *argv)
    assert code == 2 and out == ""
    assert err.startswith("knic: error: ") and message in err and err.count("\n") == 1


def test_watch_follows_a_live_writer(journal: Path) -> None:
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    watcher = subprocess.Popen(
        [sys.executable, "-m", "knic", "facts", "--journal", str(journal), "--watch", "--watch-seconds", "4",
         "--poll", "0.05", "--predicate", "robot_at"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )  # fmt: skip
    try:
        assert watcher.stderr is not None
        assert "watching" in watcher.stderr.readline()  # the initial table is printed, polling has started
        kb = KnowledgeBase.from_journal(journal, clock=FakeClock(30.0))
        kb.add_fact("robot_at", "r2d2", "kitchen", source="kp.pose", status="observed")
        time.sleep(0.3)
        kb.add_fact("explored", "kitchen")  # filtered out by --predicate
        kb.close()
        out, _ = watcher.communicate(timeout=30)
    finally:
        if watcher.poll() is None:
            watcher.kill()
    assert watcher.returncode == 0
    assert out.splitlines()[-2:] == [
        "t=30.00 remove_fact (robot_at r2d2 bedroom) by kp.pose [observed]",
        "t=30.00 add_fact (robot_at r2d2 kitchen) by kp.pose [observed]",
    ]


def test_bench_kb_json(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run_cli(capsys, "bench", "kb", "--json", "--quick")
    figures = json.loads(out)
    assert code == 0
    for key in (
        "memory_changes_per_s",
        "durable_changes_per_s",
        "query_ms_10k_facts",
        "state_at_ms_100k_events",
    ):
        assert figures[key] > 0
    assert figures["query_facts"] == 10_000
    assert figures["state_at_events"] >= figures["size_state_at_events"]
    assert isinstance(figures["meets_targets"], bool)
