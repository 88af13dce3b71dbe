"""A thing said as "the one" where it is (``knic.language.placedones``): the kind said before it, else the one
thing the world places there, else a question; never the speaker taken to the place ("bring me the one on
the coffee table" was ACCOMPANYING me to the coffee table)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary
from knic.language.world import read_vocabulary

from .conftest import frames_read

NUMBERED = "tests/fixtures/language/numbered/numbered.pddl"  # things placed on furniture by object_on


@pytest.mark.parametrize(
    "text",
    ["bring me the one on the coffee table", "bring me the one by the sofa", "grab the one in the kitchen"],
)
def test_the_one_somewhere_the_world_places_nothing_asks_which(vocabulary: Vocabulary, text: str) -> None:
    # the ERL apartment's problem says where no thing is (the robot looks): which thing is asked
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames
    assert "which thing" in result.question.lower() and "name it" in result.question.lower()


def test_the_kind_said_before_is_the_one(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "the cup, bring me the one on the dining table") == [
        {"frame": "BRINGING", "theme": "cup", "source": "dining_table", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, "turn off all the lights but the one in the hallway") == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}
    ]


def test_the_one_thing_the_world_places_there_is_the_one() -> None:
    numbered = read_vocabulary(problem=NUMBERED)
    assert frames_read(numbered, "bring me the one on the kitchen table", "alice") == [
        {"frame": "BRINGING", "theme": "cup1", "source": "kitchen-table", "beneficiary": "me"}
    ]
    assert frames_read(numbered, "the mug, bring me the one on the kitchen counter", "alice") == [
        {"frame": "BRINGING", "theme": "red-mug", "source": "kitchencounter", "beneficiary": "me"}
    ]
