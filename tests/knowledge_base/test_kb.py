"""KnowledgeBase writes, validation, single-valued predicates, provenance, batches, subscribers, anchors."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from core.errors import KnowledgeBaseError
from knowledge_base import BeliefStatus, Change, Fact, KnowledgeBase
from knowledge_base.domain import DomainModel
from knowledge_base.model import ChangeKind

from .conftest import DELIVERY_DOMAIN, DELIVERY_PROBLEM, ERL_DOMAIN, PAPER_PROBLEM, FakeClock


def test_problem_loads_objects_facts_goals_with_provenance(kb: KnowledgeBase) -> None:
    assert kb.type_of("glasses") == "item"
    assert kb.holds("robot_at", "r2d2", "bedroom")
    assert kb.holds(Fact.parse("(possibly_at glasses kitchen)"))
    assert kb.goals() == [Fact("object_at", ("glasses", "bedroom"))]
    assert not kb.goals_hold()
    prov = kb.why("(robot_at r2d2 bedroom)")
    assert prov is not None
    assert (prov.source, prov.since, prov.status) == ("problem", 10.0, BeliefStatus.GIVEN)


def test_constants_are_instances(kb: KnowledgeBase) -> None:
    assert set(kb.instances("level")) == {"l0", "l25", "l50", "l75", "l100"}
    with pytest.raises(KnowledgeBaseError, match="constant"):
        kb.remove_instance("l50")


def test_instances_by_type_include_subtypes(kb: KnowledgeBase) -> None:
    assert set(kb.instances("entity")) == {"glasses", "r2d2", "annie"}
    assert kb.instances("robot") == ["r2d2"]
    with pytest.raises(KnowledgeBaseError, match="unknown type 'robt'"):
        kb.instances("robt")


def test_add_instance_and_fact_with_subtype_argument(kb: KnowledgeBase) -> None:
    assert kb.add_instance("person", "jack", source="kp.person")
    assert not kb.add_instance("person", "jack")
    # possibly_at takes an entity: a person (subtype) is accepted
    assert kb.add_fact("possibly_at", "jack", "kitchen", status="assumed")
    assert kb.why(Fact("possibly_at", ("jack", "kitchen"))).status is BeliefStatus.ASSUMED  # type: ignore[union-attr]


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda kb: kb.add_fact("robot_in", "r2d2", "kitchen"), "unknown predicate 'robot_in'"),
        (lambda kb: kb.add_fact("robot_at", "r2d2"), "robot_at takes 2 arguments, got 1"),
        (lambda kb: kb.add_fact("robot_at", "r2d2", "garage"), "unknown instance 'garage'"),
        (
            lambda kb: kb.add_fact("robot_at", "annie", "kitchen"),
            "must be of type robot, 'annie' is a person",
        ),
        (lambda kb: kb.add_fact("hand_empty", "r2d2", status="guessed"), "unknown belief status"),
        (lambda kb: kb.add_fact("hand_empty", "r2d2", confidence=1.5), "outside 0..1"),
        (
            lambda kb: kb.add_goal("object_at", "glasses", "sofa"),
            "must be of type room, 'sofa' is a furniture",
        ),
        (lambda kb: kb.remove_fact("found", "kitchen"), "must be of type entity, 'kitchen' is a room"),
        (lambda kb: kb.add_instance("robt", "r3"), "unknown type 'robt'"),
        (lambda kb: kb.add_instance("person", "r2d2"), "already an instance of 'robot'"),
        (lambda kb: kb.add_instance("person", "two words"), "invalid instance name"),
        (lambda kb: kb.remove_instance("glasses"), "still used by fact \\(possibly_at glasses"),
        (lambda kb: kb.remove_instance("bedroom"), "still used by"),
        (lambda kb: kb.set_function("battery", "r2d2", value=1.0), "unknown function 'battery'"),
        (lambda kb: kb.set_anchor("garage", {"region": []}), "unknown instance 'garage'"),
        (lambda kb: kb.set_anchor("kitchen", {"pose": object()}), "JSON-able"),
    ],
)
def test_refused_write_raises_and_changes_nothing(
    kb: KnowledgeBase, call: Callable[[KnowledgeBase], object], message: str
) -> None:
    before = kb.snapshot()
    seen: list[Change] = []
    kb.subscribe(seen.append)
    with pytest.raises(KnowledgeBaseError, match=message):
        call(kb)
    assert kb.snapshot() == before
    assert seen == []
    assert kb.journal.last_seq == before.seq


def test_single_valued_predicate_retracts_the_others(kb: KnowledgeBase, clock: FakeClock) -> None:
    clock.t = 20.0
    seen: list[Change] = []
    kb.subscribe(seen.append)
    assert kb.add_fact(
        "robot_at", "r2d2", "kitchen", source="kp.pose", status="observed", support=("llku:7",)
    )
    assert kb.facts("robot_at", "r2d2") == [Fact("robot_at", ("r2d2", "kitchen"))]
    assert [(c.kind, c.fact) for c in seen] == [
        (ChangeKind.REMOVE_FACT, Fact("robot_at", ("r2d2", "bedroom"))),
        (ChangeKind.ADD_FACT, Fact("robot_at", ("r2d2", "kitchen"))),
    ]
    prov = kb.why("(robot_at r2d2 kitchen)")
    assert prov is not None
    assert (prov.source, prov.since, prov.status, prov.support) == (
        "kp.pose",
        20.0,
        BeliefStatus.OBSERVED,
        ("llku:7",),
    )
    # not single-valued: possibly_at keeps every candidate
    assert len(kb.facts("possibly_at", "glasses")) == 3


def test_reassert_same_fact_is_no_change_but_new_status_refreshes(
    kb: KnowledgeBase, clock: FakeClock
) -> None:
    seq = kb.journal.last_seq
    assert not kb.add_fact("robot_at", "r2d2", "bedroom", source="problem")
    assert kb.journal.last_seq == seq
    clock.t = 30.0
    assert not kb.add_fact("robot_at", "r2d2", "bedroom", source="kp.pose", status="observed")
    prov = kb.why("(robot_at r2d2 bedroom)")
    assert prov is not None and (prov.source, prov.since) == ("kp.pose", 30.0)


def test_remove_fact_and_goals(kb: KnowledgeBase) -> None:
    assert kb.remove_fact("possibly_at", "glasses", "kitchen")
    assert not kb.remove_fact("possibly_at", "glasses", "kitchen")
    assert kb.why("(possibly_at glasses kitchen)") is None
    assert kb.add_fact("object_at", "glasses", "bedroom", status="effect", source="dispatcher")
    assert kb.goals_hold()
    assert kb.add_goal("found", "glasses")
    assert not kb.add_goal("found", "glasses")
    assert not kb.goals_hold()
    assert kb.remove_goal("found", "glasses")
    assert kb.clear_goals() == 1
    assert kb.goals() == [] and kb.goals_hold()


def test_fact_patterns(kb: KnowledgeBase) -> None:
    assert {f.args[1] for f in kb.facts("possibly_at", "glasses", "?")} == {
        "kitchen",
        "entrance",
        "living_room",
    }
    assert kb.facts("connected", None, "kitchen") == [
        Fact("connected", ("bedroom", "kitchen")),
        Fact("connected", ("entrance", "kitchen")),
    ]
    assert kb.facts("found") == []
    assert len(kb.facts()) == 22  # the paper problem: 18 facts and 4 (surface ...) facts
    with pytest.raises(KnowledgeBaseError, match="unknown predicate"):
        kb.facts("nope")


def test_remove_instance_once_unused(kb: KnowledgeBase) -> None:
    kb.add_instance("item", "mug")
    kb.add_goal("found", "mug")
    with pytest.raises(KnowledgeBaseError, match="still used by goal \\(found mug\\)"):
        kb.remove_instance("mug")
    kb.remove_goal("found", "mug")
    kb.set_anchor("mug", {"pose": [1.0, 2.0, 0.8]})
    assert kb.remove_instance("mug")
    assert kb.type_of("mug") is None and kb.anchor("mug") is None
    assert not kb.remove_instance("mug")


def test_batch_is_all_or_nothing(kb: KnowledgeBase) -> None:
    before = kb.snapshot()
    seen: list[Change] = []
    kb.subscribe(seen.append)
    with pytest.raises(RuntimeError), kb.batch():
        kb.add_instance("item", "mug")
        kb.add_fact("robot_at", "r2d2", "kitchen")
        kb.remove_fact("hand_empty", "r2d2")
        kb.set_anchor("kitchen", {"region": [[0, 0], [4, 0], [4, 3]]})
        assert kb.holds("robot_at", "r2d2", "kitchen")  # visible inside the batch
        raise RuntimeError("abort")
    assert kb.snapshot() == before
    assert seen == [] and kb.journal.last_seq == before.seq
    # a refused write inside a batch changes nothing; the batch goes on
    with kb.batch():
        kb.add_fact("found", "glasses")
        with pytest.raises(KnowledgeBaseError):
            kb.add_fact("found", "sofa")
        kb.add_fact("explored", "kitchen")
        assert seen == []  # notifications come after the commit
    assert [c.fact for c in seen] == [Fact("found", ("glasses",)), Fact("explored", ("kitchen",))]
    assert kb.journal.last_seq == before.seq + 2


def test_nested_batch_failure_undoes_only_inner(kb: KnowledgeBase) -> None:
    with kb.batch():
        kb.add_fact("found", "glasses")
        with pytest.raises(ValueError), kb.batch():
            kb.add_fact("explored", "kitchen")
            raise ValueError
        kb.add_fact("explored", "bedroom")
    assert kb.holds("found", "glasses") and kb.holds("explored", "bedroom")
    assert not kb.holds("explored", "kitchen")
    assert [c.seq for c in kb.changes()][-2:] == [kb.journal.last_seq - 1, kb.journal.last_seq]


def test_subscribers_and_unsubscribe(kb: KnowledgeBase) -> None:
    seen: list[Change] = []
    unsubscribe = kb.subscribe(seen.append)

    def broken(change: Change) -> None:
        raise RuntimeError("subscriber bug")

    kb.subscribe(broken)
    kb.add_fact("found", "glasses", source="kp.camera", status="observed", confidence=0.9)
    assert len(seen) == 1
    change = seen[0]
    assert change.kind is ChangeKind.ADD_FACT and change.fact == Fact("found", ("glasses",))
    assert change.provenance.confidence == 0.9 and change.time == 10.0
    unsubscribe()
    kb.add_fact("explored", "kitchen")
    assert len(seen) == 1


def test_anchors_are_copied_and_journaled(kb: KnowledgeBase) -> None:
    geometry = {"region": [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]], "waypoints": [[2.0, 1.5]]}
    kb.set_anchor("kitchen", geometry, source="map")
    geometry["waypoints"].append([9.0, 9.0])
    assert kb.anchor("kitchen") == {
        "region": [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]],
        "waypoints": [[2.0, 1.5]],
    }
    assert kb.changes()[-1].kind is ChangeKind.SET_ANCHOR
    assert kb.state_at(10.0).anchors["kitchen"][0]["waypoints"] == [[2.0, 1.5]]


def test_functions_on_typed_numeric_domain(delivery_domain: DomainModel) -> None:
    kb = KnowledgeBase.from_pddl(DELIVERY_DOMAIN, DELIVERY_PROBLEM, clock=FakeClock(0.0))
    assert kb.function("fuel", "t1") == 100.0 and kb.function("total_distance") == 0.0
    assert kb.set_function("fuel", "t1", value=90)
    assert not kb.set_function("fuel", "t1", value=90.0)
    # fragile_parcel < parcel < cargo: accepted where cargo is expected; a drone is a vehicle
    assert kb.add_fact("in", "vase", "d1")
    assert set(kb.instances("cargo")) == {"box", "vase"}
    assert kb.domain.is_subtype("fragile_parcel", "cargo") and not kb.domain.is_subtype("cargo", "parcel")
    with pytest.raises(KnowledgeBaseError, match="not a finite number"):
        kb.set_function("fuel", "t1", value=float("nan"))
    with pytest.raises(KnowledgeBaseError, match="must be of type vehicle, 'kitchen' is a room"):
        kb.set_function("fuel", "kitchen", value=1.0)
    with pytest.raises(KnowledgeBaseError, match="still used by function \\(fuel d1\\)"):
        kb.remove_fact("in", "vase", "d1")
        kb.remove_fact("at", "d1", "hall")
        kb.remove_fact("free", "d1")
        kb.remove_instance("d1")


def test_from_pddl_defaults_to_wall_clock_and_set_clock_switches() -> None:
    import time

    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM)
    prov = kb.why("(hand_empty r2d2)")
    assert prov is not None and abs(prov.since - time.time()) < 60
    kb.set_clock(lambda: 5.0)
    kb.add_fact("found", "glasses")
    assert kb.why("(found glasses)").since == 5.0  # type: ignore[union-attr]
    assert kb.domain.single_valued["robot_at"] == (0,)
    assert kb.domain.sensing["search_object"] == ("found", "object_at")


def test_fact_text_round_trip() -> None:
    fact = Fact.parse("  ( Object_At glasses  KITCHEN ) ")
    assert fact == Fact("object_at", ("glasses", "kitchen")) and str(fact) == "(object_at glasses kitchen)"
    assert str(Fact.parse("(hand_empty r2d2)")) == "(hand_empty r2d2)" and str(Fact("total", ())) == "(total)"
    for bad in ("object_at glasses", "(object_at (glasses) kitchen)", "(?p a)", "(object_at ?o kitchen)", ""):
        with pytest.raises(KnowledgeBaseError, match="cannot parse fact"):
            Fact.parse(bad)
    assert BeliefStatus("assumed") is BeliefStatus.ASSUMED and str(BeliefStatus.EFFECT) == "effect"
