"""Phrasings found with the ninth blind set (people9): "transport" and "convey" carry a thing as "bring" does;
older and regional names of places and things: "curtains" for blinds, "bedside cabinet" (or cupboard) for a
bedside table, "scullery" for a kitchen, "passage" (or "passageway") for a hallway."""

from __future__ import annotations

import pytest

from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize("verb", ["transport", "convey"])
def test_transport_and_convey_carry_a_thing(vocabulary: Vocabulary, verb: str) -> None:
    assert frames_read(vocabulary, f"{verb} the soap to the bathroom") == [
        {"frame": "BRINGING", "theme": "soap", "goal": "bathroom"}
    ]


def test_transport_from_a_room_to_another_in_the_other_house(other_house: Vocabulary) -> None:
    assert frames_read(
        other_house, "please transport the teddy bear from the nursery to the lounge", "maria"
    ) == [{"frame": "BRINGING", "theme": "teddy_bear", "source": "nursery", "goal": "lounge"}]


def test_curtains_are_the_blinds(vocabulary: Vocabulary, other_house: Vocabulary) -> None:
    assert frames_read(vocabulary, "shut the curtains in the bedroom") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}
    ]
    assert frames_read(other_house, "open the study curtains", "maria") == [
        {"frame": "OPERATING", "device": "study_blinds", "state": "open"}
    ]


@pytest.mark.parametrize("name", ["bedside cabinet", "bedside cupboard"])
def test_a_bedside_cabinet_is_the_bedside_table_not_the_kitchen_cabinet(
    vocabulary: Vocabulary, name: str
) -> None:
    assert frames_read(vocabulary, f"pop my glasses on the {name}") == [
        {"frame": "PLACING", "theme": "glasses", "goal": "bedside_table"}
    ]


def test_the_scullery_is_the_kitchen(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "take my cup through to the scullery") == [
        {"frame": "BRINGING", "theme": "cup", "goal": "kitchen"}
    ]


@pytest.mark.parametrize("name", ["passage", "passageway"])
def test_the_passage_is_the_hallway(vocabulary: Vocabulary, name: str) -> None:
    assert frames_read(vocabulary, f"go to the {name}") == [{"frame": "MOTION", "goal": "hallway"}]
    assert frames_read(vocabulary, f"put the light off in the {name}") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "off"}
    ]
