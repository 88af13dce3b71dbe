"""A destination said after fetch/get/grab replaces "for the speaker" (a house other than the ERL one)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary
from knic.language.world import load_world

OTHER_WORLD = Path(__file__).resolve().parents[1] / "fixtures" / "language" / "other_world" / "problem.pddl"


@pytest.fixture(scope="module")
def other() -> Vocabulary:
    world: tuple[Any, Vocabulary] = load_world(problem=OTHER_WORLD)
    return world[1]


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        (
            "hey robot, would you fetch the stapler from the workbench and put it in the study",
            ["(taken_from stapler workbench)", "(object_at stapler study)"],
        ),
        (
            "could you get the keys off the shelf unit and bring it to the garage",
            ["(taken_from keys shelf_unit)", "(object_at keys garage)"],
        ),
        ("grab the laptop then take it to the couch", ["(object_on laptop couch)"]),
        (
            "fetch the blanket from the crib and leave it on the couch",
            ["(taken_from blanket crib)", "(object_on blanket couch)"],
        ),
        ("get the hammer and give it to oscar", ["(has oscar hammer)"]),
        ("fetch the bottle and bring it to me", ["(has maria bottle)"]),
    ],
)
def test_a_later_destination_is_where_the_object_ends(other: Vocabulary, text: str, goals: list[str]) -> None:
    result = understand(text, other, speaker="maria")
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == goals
    assert not any(g.predicate == "has" and g.args[0] == "maria" for g in result.goals) or "me" in text


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        ("fetch the bottle", ["(has maria bottle)"]),
        ("i need the laptop and find oscar", ["(has maria laptop)", "(reported oscar)"]),
        ("get the keys from the desk", ["(taken_from keys desk)", "(has maria keys)"]),
        # another object put somewhere: the first is still for the speaker
        ("fetch the bottle and put the keys on the desk", ["(has maria bottle)", "(object_on keys desk)"]),
    ],
)
def test_without_a_later_destination_it_is_for_the_speaker(
    other: Vocabulary, text: str, goals: list[str]
) -> None:
    result = understand(text, other, speaker="maria")
    assert [str(g) for g in result.goals] == goals, result.reason


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        ("bring oscar to the garage", ["(person_at oscar garage)"]),
        ("please carry the keys to the study", ["(object_at keys study)"]),
        ("get oscar to the lounge", ["(person_at oscar lounge)"]),
    ],
)
def test_a_carry_verb_with_a_person_reads_as_accompanying(
    other: Vocabulary, text: str, goals: list[str]
) -> None:
    """A verb with several readings tries each on the clause as heard (the first, failed, reading must not
    leave its marks on the arguments the next one reads)."""
    result = understand(text, other, speaker="maria")
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == goals
