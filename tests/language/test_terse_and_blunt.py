"""Phrasings found with the fifth blind set (people5) and sentences tried on the spot: terse and blunt verbs
("goto", "snatch", "hunt down", "kill the lights", "pop", "drop off"; "the shelf" for a shelf unit), each
object to its own place, things taken back ("not the mug", "instead of the juice"), a level said in words
counted down from full ("all the way down"), and words the world does not know said before an ambiguous
name, which the question back names ("the kitchen light" in a house without a kitchen)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read

READ = [
    ("goto bathroom", [{"frame": "MOTION", "goal": "bathroom"}]),
    (
        "goto the kitchen and grab the mug",
        [
            {"frame": "MOTION", "goal": "kitchen"},
            {"frame": "TAKING", "theme": "mug", "source": "kitchen"},
        ],
    ),
    ("hunt down the remote control", [{"frame": "SEARCHING", "theme": "remote"}]),
    ("snatch the apple", [{"frame": "TAKING", "theme": "apple"}]),
    ("nab the tablet", [{"frame": "TAKING", "theme": "tablet"}]),
    ("kill all the lights", [{"frame": "OPERATING", "device": "all_lights", "state": "off"}]),
    ("cut the hall light", [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}]),
    ("power down the left lamp", [{"frame": "OPERATING", "device": "bedroom_left_light", "state": "off"}]),
    (
        "turn the dimmer all the way down",
        [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "0"}],
    ),
    (
        "turn the dimmer down all the way",
        [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "0"}],
    ),
    (
        "turn the dimmer all the way up",
        [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "100"}],
    ),
    # each object to its own place
    (
        "take the mug to the kitchen and the glass to the dining room",
        [
            {"frame": "BRINGING", "theme": "mug", "goal": "kitchen"},
            {"frame": "BRINGING", "theme": "glass", "goal": "dining_room"},
        ],
    ),
    (
        "bring the mug to the kitchen and the cup",
        [
            {"frame": "BRINGING", "theme": "mug", "goal": "kitchen"},
            {"frame": "BRINGING", "theme": "cup", "goal": "kitchen"},
        ],
    ),
    # terse: where a thing goes said without "to"; something named in talk before the request
    ("put mug kitchen table", [{"frame": "PLACING", "theme": "mug", "goal": "kitchen_table"}]),
    ("bring tablet living room", [{"frame": "BRINGING", "theme": "tablet", "goal": "living_room"}]),
    (
        "I seem to have misplaced my spectacles, could you have a look for them",
        [{"frame": "SEARCHING", "theme": "glasses"}],
    ),
    # what is taken back is not meant
    ("get me the glasses, not the mug", [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}]),
    (
        "bring me the water instead of the juice",
        [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}],
    ),
    (
        "bring me the water rather than the juice",
        [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}],
    ),
    (
        "take the apple but not the lemon to tracy",
        [{"frame": "BRINGING", "theme": "apple", "beneficiary": "tracy"}],
    ),
    ("go to the kitchen not the bathroom", [{"frame": "MOTION", "goal": "kitchen"}]),
    (
        "turn the dimmer down to 30 percent",
        [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "30"}],
    ),
]


READ_IN_THE_OTHER_HOUSE = [
    ("grab the hammer off the shelf", [{"frame": "TAKING", "theme": "hammer", "source": "shelf_unit"}]),
    ("drop off the keys at the shelf unit", [{"frame": "PLACING", "theme": "keys", "goal": "shelf_unit"}]),
    ("pop the bottle on the desk", [{"frame": "PLACING", "theme": "bottle", "goal": "desk"}]),
    ("pop to the garage", [{"frame": "MOTION", "goal": "garage"}]),
    ("put laptop desk", [{"frame": "PLACING", "theme": "laptop", "goal": "desk"}]),
]


@pytest.mark.parametrize(("text", "frames"), READ_IN_THE_OTHER_HOUSE)
def test_read_as_meant_in_the_other_house(
    other_house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(other_house, text, "maria") == frames


@pytest.mark.parametrize(("text", "frames"), READ)
def test_read_as_meant(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_blunt_verb_of_a_thing_the_world_lacks_names_it(vocabulary: Vocabulary) -> None:
    result = understand("kill the spider", vocabulary)
    assert not result.accepted and "spider" in result.reason


@pytest.mark.parametrize("text", ["turn on the kitchen light", "switch the bedroom light on"])
def test_an_unknown_word_before_an_ambiguous_name_is_said_back(other_house: Vocabulary, text: str) -> None:
    result = understand(text, other_house, speaker="maria")
    assert not result.accepted
    said = text.split(" the ")[1].split(" on")[0]
    assert result.question.startswith(f"I know no '{said}' here. Which light do you mean:")


def test_a_known_name_with_an_unknown_word_before_it_is_still_read(vocabulary: Vocabulary) -> None:
    result = understand("bring me the red mug", vocabulary)
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]
    result = understand("turn on the light", vocabulary)
    assert result.question.startswith("Which light do you mean:")
