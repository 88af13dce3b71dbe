"""Fusion: a weak assumption never overrides a fresh observation; old observations yield; every source."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.kgm3.fusion import claims, install
from knowledge_base import BeliefStatus, Fact, KnowledgeBase

AT_ENTRANCE = Fact("object_at", ("glasses", "entrance"))


def test_weak_assumption_does_not_override_a_fresh_observation(paper_kb: KnowledgeBase) -> None:
    now = [10.0]
    fusion = install(paper_kb, lambda: now[0], half_life_s=60.0)
    paper_kb.add_fact(
        "object_at",
        "glasses",
        "entrance",
        source="kp'.object_at",
        at=10.0,
        status=BeliefStatus.OBSERVED,
        confidence=0.95,
    )
    # an assumption of another place (single-valued: it would retract the observation) is refused ...
    assert not paper_kb.add_fact(
        "object_at",
        "glasses",
        "kitchen",
        source="prior",
        at=10.5,
        status=BeliefStatus.ASSUMED,
        confidence=0.1,
    )
    # ... as is an assumed retraction and an assumed re-write of the same fact
    assert not paper_kb.remove_fact(
        "object_at", "glasses", "entrance", source="prior", status=BeliefStatus.ASSUMED
    )
    paper_kb.add_fact(
        "object_at",
        "glasses",
        "entrance",
        source="prior",
        at=10.5,
        status=BeliefStatus.ASSUMED,
        confidence=0.1,
    )
    prov = paper_kb.why(AT_ENTRANCE)
    assert prov is not None and prov.source == "kp'.object_at" and prov.status == BeliefStatus.OBSERVED
    assert paper_kb.facts("object_at", "glasses") == [AT_ENTRANCE] and fusion.refused == 3
    # the observation ages (halving every minute): ten minutes later a confident assumption wins
    now[0] = 610.0
    assert paper_kb.add_fact(
        "object_at",
        "glasses",
        "kitchen",
        source="prior",
        at=610.0,
        status=BeliefStatus.ASSUMED,
        confidence=0.8,
    )
    assert paper_kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "kitchen"))]
    # an observation always passes, and a source may revise its own belief
    assert paper_kb.add_fact(
        "object_at",
        "glasses",
        "entrance",
        source="kp'.object_at",
        at=611.0,
        status=BeliefStatus.OBSERVED,
        confidence=0.9,
    )
    paper_kb.add_fact(
        "object_at",
        "glasses",
        "entrance",
        source="kp'.object_at",
        at=612.0,
        status=BeliefStatus.ASSUMED,
        confidence=0.2,
    )
    aged = paper_kb.why(AT_ENTRANCE)
    assert aged is not None and aged.status == BeliefStatus.ASSUMED


def test_claims_list_every_source(paper_kb: KnowledgeBase) -> None:
    install(paper_kb, lambda: 20.0)
    paper_kb.add_fact(
        "object_at", "glasses", "entrance", source="dispatcher", at=1.0, status=BeliefStatus.EFFECT
    )
    paper_kb.add_fact(
        "object_at",
        "glasses",
        "entrance",
        source="kp'.object_at",
        at=5.0,
        status=BeliefStatus.OBSERVED,
        confidence=0.9,
    )
    paper_kb.remove_fact("object_at", "glasses", "entrance", source="prior", status=BeliefStatus.ASSUMED)
    found = claims(paper_kb, AT_ENTRANCE, now=20.0)
    assert [c.source for c in found] == ["kp'.object_at", "dispatcher"]
    assert found[0].current and found[0].holds and not found[1].current
    assert found[0].weight > found[1].weight


def test_facts_why_lists_every_source(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from knic.cli import main
    from tests.knowledge_base.conftest import ERL_DOMAIN, PAPER_PROBLEM, FakeClock

    path = tmp_path / "run.sqlite"
    clock = FakeClock(0.0)
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=clock)
    clock.t = 5.0
    kb.add_fact("object_at", "glasses", "kitchen", source="dispatcher", status="effect")
    clock.t = 12.5
    kb.add_fact("object_at", "glasses", "kitchen", source="kp'.object_at", status="observed", confidence=0.9)
    kb.close()
    assert main(["facts", "--journal", str(path), "--why", "(object_at glasses kitchen)", "--json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    assert [(s["source"], s["status"], s["current"]) for s in answer["sources"]] == [
        ("kp'.object_at", "observed", True),
        ("dispatcher", "effect", False),
    ]
    assert main(["facts", "--journal", str(path), "--why", "(object_at glasses kitchen)"]) == 0
    text = capsys.readouterr().out
    assert (
        "source kp'.object_at: asserts it, observed" in text
        and "source dispatcher: asserts it, effect" in text
    )
