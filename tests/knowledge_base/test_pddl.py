"""Loading PDDL: the typed fixture domain, errors with file and line, and the export round trip."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import PDDLError, PDDLParseError, PDDLValidationError
from knowledge_base import Fact, KnowledgeBase
from knowledge_base.domain import DomainModel
from knowledge_base.export import state_from_up, state_to_up
from knowledge_base.problem import load_problem, parse_problem_text

from .conftest import BROKEN, DELIVERY_DOMAIN, DELIVERY_PROBLEM, REPO


def test_typed_domain_model(delivery_domain: DomainModel) -> None:
    d = delivery_domain
    assert d.name == "delivery"
    assert (
        d.types["fragile_parcel"] == "parcel"
        and d.types["parcel"] == "cargo"
        and d.types["place"] == "object"
    )
    assert d.subtypes("place") == {"place", "depot", "room"}
    assert d.constants == {"main_depot": "depot"}
    assert d.predicates["at"] == (("v", "vehicle"), ("p", "place"))
    assert set(d.functions) == {"fuel", "distance", "total_distance"}
    assert d.actions == ("drive", "load", "unload")
    assert d.single_valued == {"at": (0,), "cargo_at": (0,)}
    assert {a.name for a in d.up_domain.actions} == {"drive", "load", "unload"}


def test_domain_summary_round_trip(delivery_domain: DomainModel) -> None:
    again = DomainModel.from_summary(
        delivery_domain.to_summary(), delivery_domain.text, delivery_domain.meta_text
    )
    for field in ("name", "types", "predicates", "constants", "functions", "actions", "single_valued"):
        assert getattr(again, field) == getattr(delivery_domain, field)
    assert again.is_subtype("fragile_parcel", "cargo")
    assert {a.name for a in again.up_domain.actions} == {"drive", "load", "unload"}  # parsed on demand


@pytest.mark.parametrize(
    ("name", "error", "message"),
    [
        ("syntax_error_domain.pddl", PDDLParseError, r"syntax_error_domain\.pddl:7:5: Expected '\)'"),
        ("unknown_type_domain.pddl", PDDLValidationError, r"unknown_type_domain\.pddl: .*chamber"),
    ],
)
def test_broken_domains(name: str, error: type[Exception], message: str) -> None:
    with pytest.raises(error, match=message):
        DomainModel.from_file(BROKEN / name)


@pytest.mark.parametrize(
    ("name", "error", "message"),
    [
        ("problem_syntax_error.pddl", PDDLParseError, r"problem_syntax_error\.pddl:5:\d+: Expected"),
        ("problem_other_domain.pddl", PDDLValidationError,
         r"problem_other_domain\.pddl:2: problem is for domain 'logistics', but the domain loaded is "
         r"'delivery'"),
        ("problem_unknown_predicate.pddl", PDDLValidationError,
         r"problem_unknown_predicate\.pddl:6: unknown predicate 'parked' in \(parked t1 hall\)"),
        ("problem_wrong_type.pddl", PDDLValidationError,
         r"problem_wrong_type\.pddl:6: \(at box hall\): argument \?v must be of type vehicle, "
         r"'box' is a parcel"),
        ("problem_unknown_object.pddl", PDDLValidationError,
         r"problem_unknown_object\.pddl:5: unknown object 't2' in \(at t2 hall\)"),
        ("problem_unknown_object_type.pddl", PDDLValidationError,
         r"problem_unknown_object_type\.pddl:3: object 't1' has unknown type 'lorry'"),
    ],
)  # fmt: skip
def test_broken_problems(
    delivery_domain: DomainModel, name: str, error: type[Exception], message: str
) -> None:
    with pytest.raises(error, match=message):
        load_problem(delivery_domain, BROKEN / name)


def test_missing_files_and_bad_meta(tmp_path: Path, delivery_domain: DomainModel) -> None:
    with pytest.raises(PDDLParseError, match="cannot read domain file"):
        DomainModel.from_file(tmp_path / "nope.pddl")
    with pytest.raises(PDDLParseError, match="cannot read problem file"):
        load_problem(delivery_domain, tmp_path / "nope.pddl")
    domain = tmp_path / "d.pddl"
    domain.write_text(DELIVERY_DOMAIN.read_text())
    (tmp_path / "d.meta.yaml").write_text("single_valued:\n  parked: [0]\n")
    with pytest.raises(
        PDDLValidationError, match=r"d\.meta\.yaml: single_valued names unknown predicate 'parked'"
    ):
        DomainModel.from_file(domain)
    (tmp_path / "d.meta.yaml").write_text("single_valued:\n  at: [0, 1]\n")
    with pytest.raises(PDDLValidationError, match="must leave an argument free"):
        DomainModel.from_file(domain)
    (tmp_path / "d.meta.yaml").write_text("sensing: {fly: [at]}\n")
    with pytest.raises(PDDLValidationError, match="sensing names unknown action 'fly'"):
        DomainModel.from_file(domain)


def test_non_atomic_goal_is_refused(delivery_domain: DomainModel) -> None:
    text = DELIVERY_PROBLEM.read_text().replace(
        "(:goal (and (cargo_at box kitchen)", "(:goal (and (not (free t1))"
    )
    with pytest.raises(PDDLValidationError, match="not a conjunction of atoms"):
        parse_problem_text(delivery_domain, text, source="neg_goal.pddl")


def _problem_files() -> list[tuple[Path, Path]]:
    """Every PDDL problem in the repository with the domain file it names (broken fixtures excluded)."""
    files = [p for p in REPO.rglob("*.pddl") if ".venv" not in p.parts and "broken" not in p.parts]
    domains: dict[str, Path] = {}
    problems = []
    for path in files:
        text = path.read_text(encoding="utf-8").lower()
        if "(domain " in text and "(problem " not in text:
            domains[text.split("(domain ", 1)[1].split(")", 1)[0].strip()] = path
        else:
            problems.append(path)
    pairs = []
    for path in problems:
        text = path.read_text(encoding="utf-8").lower()
        name = text.split("(:domain", 1)[1].split(")", 1)[0].strip()
        pairs.append((domains[name], path))
    return sorted(pairs)


PROBLEMS = _problem_files()


def test_problem_files_found() -> None:
    names = {p.name for _, p in PROBLEMS}
    assert {"paper_problem.pddl", "erl_home_problem.pddl", "delivery_problem.pddl"} <= names


@pytest.mark.parametrize(("domain_path", "problem_path"), PROBLEMS, ids=[p.name for _, p in PROBLEMS])
def test_export_round_trip(domain_path: Path, problem_path: Path) -> None:
    """Load, export to PDDL text and to a UP problem, read both back: the same objects, facts, values, goals.

    Problems that are invalid by design (other tests' error fixtures) or whose goal is not a conjunction of
    atoms cannot enter a knowledge base; they are reported as skipped with the reason.
    """
    try:
        kb = KnowledgeBase.from_pddl(domain_path, problem_path, clock=lambda: 0.0)
    except PDDLError as exc:
        pytest.skip(f"not a knowledge-base problem: {exc}")
    original = load_problem(kb.domain, problem_path)
    text = kb.to_pddl_problem()
    again = parse_problem_text(kb.domain, text, source=f"{problem_path.name} (exported)")
    via_up = state_from_up(kb.domain, kb.to_up_problem())
    for content in (again, via_up):
        assert dict(content.objects) == dict(original.objects)
        assert set(content.facts) == set(original.facts)
        assert dict(content.functions) == dict(original.functions)
        assert list(content.goals) == list(original.goals)
    assert again.name == original.name
    # and the unified-planning view of the file agrees with the knowledge base's
    up_problem = state_to_up(kb.domain, kb.snapshot(), "check")
    true_atoms = {str(k) for k, v in up_problem.explicit_initial_values.items() if v.is_true()}
    assert true_atoms == {
        f"{f.predicate}({', '.join(f.args)})" if f.args else f.predicate for f in kb.facts()
    }


def test_export_after_changes_reparses() -> None:
    kb = KnowledgeBase.from_pddl(DELIVERY_DOMAIN, DELIVERY_PROBLEM, clock=lambda: 0.0)
    kb.add_fact("at", "t1", "hall")
    kb.set_function("fuel", "t1", value=42.5)
    kb.add_instance("parcel", "letter")
    kb.clear_goals()
    kb.add_goal("delivered", "letter")
    again = parse_problem_text(kb.domain, kb.to_pddl_problem())
    assert Fact("at", ("t1", "hall")) in again.facts and Fact("at", ("t1", "main_depot")) not in again.facts
    assert again.functions[Fact("fuel", ("t1",))] == 42.5
    assert again.objects["letter"] == "parcel" and "main_depot" not in again.objects
    assert again.goals == (Fact("delivered", ("letter",)),)
