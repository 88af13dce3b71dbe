"""The referee judges from ground truth as it was when things happened (reports, where items came from)."""

from __future__ import annotations

from actions.erl.devices import spoken
from knic.system.verdict import Referee
from knowledge_base import Fact


class Truth:
    """A hand-driven oracle: the true facts now."""

    def __init__(self, facts: set[tuple[str, ...]]) -> None:
        self.facts = facts

    def ground_truth_facts(self, include_static: bool = False) -> set[tuple[str, ...]]:
        return set(self.facts)


def test_a_report_is_judged_by_where_the_entity_was_when_said() -> None:
    truth = Truth({("object_at", "tablet", "living_room"), ("object_on", "tablet", "side_table")})
    said: list[str] = []
    referee = Referee(truth, lambda: said, spoken)
    referee.observe(0.0)
    said.append("I found the tablet in the living room.")
    referee.observe(1.0)
    # then the robot picks it up and carries it away: the report stays true of its time
    truth.facts = {("holding", "r2d2", "tablet")}
    referee.observe(2.0)
    assert referee.holds(Fact("reported", ("tablet",)))
    assert referee.holds(Fact("taken_from", ("tablet", "side_table")))
    assert not referee.holds(Fact("taken_from", ("tablet", "coffee_table")))
    # a wrong report is not accepted, then or later
    said.append("I found the remote in the kitchen.")
    truth.facts |= {("object_at", "remote", "living_room")}
    referee.observe(3.0)
    assert not referee.holds(Fact("reported", ("remote",)))


def test_a_report_after_the_hand_over_names_the_person_and_their_room() -> None:
    truth = Truth({("has", "annie", "tablet"), ("person_at", "annie", "living_room")})
    said: list[str] = []
    referee = Referee(truth, lambda: said, spoken)
    said.append("I found the tablet with annie in the bedroom.")
    referee.observe(0.0)
    assert not referee.holds(Fact("reported", ("tablet",)))
    said.append("I found the tablet with annie in the living room.")
    referee.observe(1.0)
    assert referee.holds(Fact("reported", ("tablet",)))
