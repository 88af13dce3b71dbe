"""``knic run --journal/--trace``: a refused run destroys nothing; outputs appear only for accepted goals."""

from __future__ import annotations

from pathlib import Path

import pytest

from knic.cli import main
from knowledge_base import KnowledgeBase

ERL = Path(__file__).resolve().parents[2] / "worlds" / "erl_home"


def test_existing_file_that_is_not_a_journal_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    notes = tmp_path / "notes.sqlite"
    notes.write_text("my notes\n", encoding="utf-8")
    code = main(["run", "--goal", "(object_at glasses bedroom)", "--journal", str(notes)])
    err = capsys.readouterr().err.strip()
    assert code == 2 and "is not a KnIC journal; not replaced" in err and len(err.splitlines()) == 1
    assert notes.read_text(encoding="utf-8") == "my notes\n"


def test_refused_goal_leaves_existing_journal_and_trace_untouched(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    journal, trace = tmp_path / "run.sqlite", tmp_path / "run.jsonl"
    kb = KnowledgeBase.from_pddl(ERL / "domain.pddl", ERL / "erl_home_problem.pddl", journal)
    kb.close()
    trace.write_text('{"kind": "plan"}\n', encoding="utf-8")
    before = journal.read_bytes()
    argv = ["run", "--goal", "(object_at unicorn kitchen)", "--journal", str(journal), "--trace", str(trace)]
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 2 and "unicorn" in err
    assert journal.read_bytes() == before
    assert trace.read_text(encoding="utf-8") == '{"kind": "plan"}\n'
    assert not [p.name for p in tmp_path.iterdir() if "partial" in p.name]
