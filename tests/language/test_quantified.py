"""How many of a kind a plural means (``knic.language.quantified``): every one where "all" is said, where
the things are in one room, or where the world groups them; a question, offering all of them, where a plural
said alone names devices in several rooms ("open the blinds" in a home with blinds in five rooms)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

DUPLEX = "tests/fixtures/language/people26/city_duplex.yaml"
GUEST_HOUSE = "tests/fixtures/language/people25/guest_house.yaml"
DUPLEX_BLINDS = {
    "living_area_blinds",
    "cinema_blind",
    "gym_blind",
    "kit_room_blind",
    "kitchen_blind",
    "study_blind",
    "terrace_awning",
}


@pytest.fixture(scope="module")
def duplex() -> Vocabulary:
    """The city duplex of people26: blinds in six rooms and an awning on the terrace."""
    return world_of(DUPLEX)


@pytest.mark.parametrize(
    "text",
    ["open the blinds", "Shut the blinds please", "could you pull the blinds down", "blinds up"],
)
def test_a_plural_alone_of_devices_in_several_rooms_asks_which(duplex: Vocabulary, text: str) -> None:
    result = understand(text, duplex, speaker="darlene")
    assert not result.accepted and result.question
    assert "all of them" in result.question and "kitchen blind" in result.question
    assert not result.frames


def test_the_question_is_asked_in_another_home_too() -> None:
    result = understand("close the blinds", world_of(GUEST_HOUSE), speaker="beau")
    assert not result.accepted and result.question and "rowan room blind" in result.question


@pytest.mark.parametrize(
    "text",
    [
        "open all the blinds",
        "the blinds, all of them, open",
        "the blinds all of them open please",
    ],
)
def test_all_said_is_every_one(duplex: Vocabulary, text: str) -> None:
    frames = frames_read(duplex, text, "darlene")
    assert {f["device"] for f in frames} == DUPLEX_BLINDS
    assert {f["state"] for f in frames} == {"open"}


def test_a_plural_with_its_room_is_that_rooms(duplex: Vocabulary) -> None:
    assert frames_read(duplex, "shut the blinds in the kitchen", "darlene") == [
        {"frame": "OPERATING", "device": "kitchen_blind", "state": "closed"}
    ]


def test_a_plural_of_devices_in_one_room_is_every_one(vocabulary: Vocabulary) -> None:
    # the ERL apartment's two bedside lamps are both in the bedroom
    assert frames_read(vocabulary, "turn on the lamps") == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "on"}
    ]
    assert frames_read(vocabulary, "the lamps both off") == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}
    ]


def test_a_plural_the_world_groups_is_the_group(vocabulary: Vocabulary, duplex: Vocabulary) -> None:
    assert frames_read(vocabulary, "the lights, all of them, off please") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"}
    ]
    assert frames_read(duplex, "turn off the lights", "darlene") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"}
    ]
    assert frames_read(vocabulary, "close the blinds") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}
    ]


@pytest.mark.parametrize(
    "text", ["bring me all the drinks", "bring me every drink", "bring me all of the drinks"]
)
def test_every_thing_of_a_kind_is_each_of_them(vocabulary: Vocabulary, text: str) -> None:
    # the ERL apartment's drinks: the coke can, the juice and the water (knic.language.selecting)
    frames = frames_read(vocabulary, text)
    assert sorted(f["theme"] for f in frames) == ["coke_can", "juice", "water"]
    assert {f["frame"] for f in frames} == {"BRINGING"}


def test_every_thing_of_a_kind_is_placed(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "put all the fruit on the kitchen table") == [
        {"frame": "PLACING", "theme": "apple", "goal": "kitchen_table"},
        {"frame": "PLACING", "theme": "lemon", "goal": "kitchen_table"},
    ]


def test_one_thing_of_a_kind_still_asks_which(vocabulary: Vocabulary) -> None:
    result = understand("bring me a drink", vocabulary, speaker="annie")
    assert not result.accepted and "coke can" in result.question and "juice" in result.question


TERRACE = "tests/fixtures/language/people22/terraced_house.yaml"


@pytest.mark.parametrize("text", ["turn off the lights downstairs", "switch off all the lights upstairs"])
def test_devices_of_a_floor_the_world_does_not_know_ask_which_rooms(text: str) -> None:
    # a world file says no floors: every light is not the lights downstairs (knic.language.roles)
    result = understand(text, world_of(TERRACE), speaker="kerry")
    assert not result.accepted and not result.frames and "which rooms are" in result.question.lower()


def test_a_device_named_with_its_floor_is_still_that_one() -> None:
    assert frames_read(world_of(TERRACE), "turn on light in toilet downstairs", "kerry") == [
        {"frame": "OPERATING", "device": "toilet_light", "state": "on"}
    ]
