"""Hard inputs at the knowledge base's boundary: names, non-strings, non-UTF-8 and oversized files, YAML."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import KnicError, KnowledgeBaseError, PDDLParseError
from core.inputs import safe_yaml
from knowledge_base import KnowledgeBase
from knowledge_base.domain import DomainModel, read_pddl
from knowledge_base.problem import parse_problem_text

BOMB = "\n".join(
    ["a: &a [x, x, x, x, x, x, x, x, x]"]
    + [f"{n}: &{n} [{', '.join(['*' + p] * 9)}]" for p, n in zip("abcdefgh", "bcdefghi", strict=True)]
)


@pytest.mark.parametrize(
    ("name", "why"),
    [
        ("mug\r", "not a PDDL identifier"),
        ("mug\u00a0cup", "not a PDDL identifier"),
        ("mug\x07", "not a PDDL identifier"),
        ("Mug", "not a PDDL identifier"),
        ("-x", "not a PDDL identifier"),
        ("?x", "not a PDDL identifier"),
        ("and", "a PDDL keyword"),
        ("forall", "a PDDL keyword"),
        ("m" * 200, "longer than 128"),
        ("", "empty"),
        (["mug"], "must be a string"),
    ],
)
def test_names_that_are_not_pddl_identifiers_are_refused(kb: KnowledgeBase, name: object, why: str) -> None:
    before = kb.snapshot()
    with pytest.raises(KnowledgeBaseError, match=why):
        kb.add_instance("item", name)  # type: ignore[arg-type]
    assert kb.snapshot().same_content(before)


def test_non_string_arguments_are_one_line_errors(kb: KnowledgeBase) -> None:
    before = kb.snapshot()
    for call in (
        lambda: kb.add_fact("object_at", ["glasses"], "kitchen"),  # type: ignore[arg-type]
        lambda: kb.remove_fact("object_at", "glasses", {"room": 1}),  # type: ignore[arg-type]
        lambda: kb.add_goal(["object_at"], "glasses", "kitchen"),  # type: ignore[arg-type]
    ):
        with pytest.raises(KnowledgeBaseError, match="names must be strings"):
            call()
    assert kb.snapshot().same_content(before)


def test_accepted_names_survive_export_and_reparse(kb: KnowledgeBase) -> None:
    for name in ("mug-2", "cup_b", "a1"):
        kb.add_instance("item", name)
        kb.add_fact("object_at", name, "kitchen")
    again = parse_problem_text(kb.domain, kb.to_pddl_problem(), source="export")
    assert {"mug-2", "cup_b", "a1"} <= set(again.objects)
    assert set(again.facts) == set(kb.facts())


def test_pddl_files_with_bad_bytes_or_size_are_one_line_errors(tmp_path: Path) -> None:
    latin = tmp_path / "d.pddl"
    latin.write_bytes(b"(define (domain d)\n (:predicates (caf\xe9)))\n")
    with pytest.raises(PDDLParseError, match=r"d.pddl:2: domain file is not UTF-8"):
        DomainModel.from_file(latin)
    big = tmp_path / "big.pddl"
    big.write_text("x" * 2000, encoding="utf-8")
    with pytest.raises(PDDLParseError, match="more than the limit of 1000"):
        read_pddl(big, "problem", max_bytes=1000)
    with pytest.raises(PDDLParseError, match="not a regular file"):
        read_pddl("/dev/zero", "problem")


def test_yaml_alias_bomb_and_deep_nesting_are_refused() -> None:
    with pytest.raises(KnicError, match=r"bomb.yaml:2: YAML aliases"):
        safe_yaml(BOMB, "bomb.yaml")
    with pytest.raises(KnicError, match="nested deeper than 64"):
        safe_yaml("x: " + "[" * 100 + "]" * 100, "deep.yaml")
    assert safe_yaml("a: [1, {b: 2}]", "ok.yaml") == {"a": [1, {"b": 2}]}


def test_sidecar_with_aliases_is_refused(tmp_path: Path) -> None:
    domain = tmp_path / "tiny.pddl"
    domain.write_text("(define (domain tiny) (:predicates (p ?x)))", encoding="utf-8")
    (tmp_path / "tiny.meta.yaml").write_text(BOMB, encoding="utf-8")
    with pytest.raises(PDDLParseError, match="YAML aliases"):
        DomainModel.from_file(domain)


def _journal(tmp_path: Path) -> Path:
    from .conftest import ERL_DOMAIN, PAPER_PROBLEM

    path = tmp_path / "run.sqlite"
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=lambda: 1.0)
    kb.add_fact("object_at", "glasses", "kitchen", source="kp.object", status="observed")
    kb.add_fact("object_at", "glasses", "entrance", source="kp.object", status="observed")
    kb.close()
    return path


@pytest.mark.parametrize(
    ("update", "why"),
    [
        ("kind = 'bogus'", "unknown kind 'bogus'"),
        ("t = 'soon'", "time 'soon' is not a number"),
        ("value = '{not json'", "corrupt"),
    ],
)
def test_corrupt_journal_row_is_one_line_naming_the_row(
    tmp_path: Path, update: str, why: str, capsys: pytest.CaptureFixture[str]
) -> None:
    import sqlite3

    from knic.cli import main

    path = _journal(tmp_path)
    db = sqlite3.connect(path)
    last = db.execute("SELECT max(seq) FROM events").fetchone()[0]
    db.execute(f"UPDATE events SET {update} WHERE seq = ?", (last - 1,))
    if "value" in update:
        db.execute("UPDATE events SET kind = 'set_anchor' WHERE seq = ?", (last - 1,))
    db.commit()
    db.close()
    code = main(["facts", "--journal", str(path)])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1
    assert f"seq {last - 1}" in err and why in err
    out = tmp_path / "recovered.sqlite"
    assert main(["facts", "--journal", str(path), "--recover", str(out)]) == 0
    assert f"kept {last - 2} event(s)" in capsys.readouterr().out
    again = KnowledgeBase.from_journal(out, read_only=True)
    assert again.journal.last_seq == last - 2
    assert not again.holds("object_at", "glasses", "entrance")
    again.close()
    assert main(["facts", "--journal", str(path), "--recover", str(out)]) == 2  # never replaced
    assert "exists" in capsys.readouterr().err
