"""Phrasings a new user tried after the eighth round: a search said with a place but no object right after a
question about a thing ("where are my glasses? have a look by the sofa") or after a statement about one ("the
glasses are probably in the bedroom, can you look") looks for that thing there, once; older and other names of
rooms ("front room", "loo"); levels said as the lowest or highest ("to the minimum", "min", "the max")."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize(
    ("text", "ground"),
    [
        ("where are my glasses? have a look by the sofa", "sofa"),
        ("have you seen my glasses? look in the kitchen", "kitchen"),
        ("i lost my glasses, could you have a look in the bedroom", "bedroom"),
        ("the glasses are probably in the bedroom, can you look", "bedroom"),
        ("where are my glasses, look for them in the kitchen", "kitchen"),
    ],
)
def test_a_search_with_only_a_place_looks_for_what_was_just_asked_about(
    vocabulary: Vocabulary, text: str, ground: str
) -> None:
    assert frames_read(vocabulary, text) == [{"frame": "SEARCHING", "theme": "glasses", "ground": ground}]


def test_the_same_in_the_other_house(other_house: Vocabulary) -> None:
    frames = frames_read(other_house, "where's the hammer? have a look in the garage", speaker="maria")
    assert frames == [{"frame": "SEARCHING", "theme": "hammer", "ground": "garage"}]


@pytest.mark.parametrize(
    "text",
    [
        "look in the kitchen",  # nothing asked about before
        "bring me my glasses, then look in the kitchen",  # an action, not a question, before
    ],
)
def test_a_search_with_only_a_place_and_nothing_asked_before_asks_what(
    vocabulary: Vocabulary, text: str
) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and "what?" in result.reason


def test_two_searches_for_different_things_stay_two(vocabulary: Vocabulary) -> None:
    frames = frames_read(vocabulary, "where are my glasses? and find the remote in the living room")
    assert frames == [
        {"frame": "SEARCHING", "theme": "glasses"},
        {"frame": "SEARCHING", "theme": "remote", "ground": "living_room"},
    ]


@pytest.mark.parametrize(
    ("text", "room"),
    [
        ("go to the front room", "living_room"),
        ("take me to the loo", "bathroom"),
        ("go to the washroom", "bathroom"),
    ],
)
def test_other_names_of_rooms(vocabulary: Vocabulary, text: str, room: str) -> None:
    assert frames_read(vocabulary, text)[0]["goal"] == room


@pytest.mark.parametrize(
    ("text", "level"),
    [
        ("dim the living room light to the minimum", "0"),
        ("set the dimmer to min", "0"),
        ("turn the dimmer up to the max", "100"),
        ("open the blinds to the highest", "100"),
    ],
)
def test_the_lowest_and_highest_levels(vocabulary: Vocabulary, text: str, level: str) -> None:
    assert frames_read(vocabulary, text)[0]["state"] == level
