"""Things left out of "all" (``knic.language.excepting``): "close all the blinds except the ones in the study"
closes every blind but the study's (it closed only the study's), "bring me all the drinks except the juice"
brings the others (it brought the juice too)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

FAMILY_HOME = "tests/fixtures/language/people32/family_home.yaml"


@pytest.mark.parametrize(
    "text",
    [
        "turn off all the lights except the hallway light",
        "turn off every light but the hallway one",
        "Please, switch off all the lights, apart from the hallway light.",
        "turn off all the lights except for the one in the hallway",
        "switch all the lights off other than the hallway light",
    ],
)
def test_all_the_lights_but_one_are_the_others(vocabulary: Vocabulary, text: str) -> None:
    assert frames_read(vocabulary, text) == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}
    ]


def test_the_things_left_are_each_acted_on_when_no_group_names_them(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "turn off all the lights except the left one") == [
        {"frame": "OPERATING", "device": "bedroom_right_light", "state": "off"},
        {"frame": "OPERATING", "device": "hallway_light", "state": "off"},
    ]
    assert frames_read(vocabulary, "bring me all the drinks except the juice") == [
        {"frame": "BRINGING", "theme": "coke_can", "beneficiary": "me"},
        {"frame": "BRINGING", "theme": "water", "beneficiary": "me"},
    ]


def test_the_rest_of_the_command_still_follows(vocabulary: Vocabulary) -> None:
    assert frames_read(
        vocabulary, "turn all the lights off except the hallway light and then go to the kitchen"
    ) == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "off"},
        {"frame": "MOTION", "goal": "kitchen"},
    ]


def test_a_room_said_of_the_things_left_out_is_where_the_world_places_them() -> None:
    home = world_of(FAMILY_HOME)
    assert frames_read(home, "close all the blinds except the ones in the study", speaker="graham") == [
        {"frame": "OPERATING", "device": "kitchen_blinds", "state": "closed"}
    ]
    frames = frames_read(home, "turn off all the lights except the one in the study", speaker="graham")
    devices = {f["device"] for f in frames}
    assert "study_light" not in devices and {"kitchen_light", "landing_light", "hallway_light"} <= devices
    assert {f["state"] for f in frames} == {"off"}


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("turn off all the lights except the telly", "none of the things"),
        ("close all the blinds except the bedroom ones", "leaves nothing"),
    ],
)
def test_an_exception_that_leaves_out_nothing_or_everything_is_refused(
    vocabulary: Vocabulary, text: str, said: str
) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames and said in result.reason


def test_a_thing_that_is_none_of_them_leaves_them_all(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "turn off all the lights except the blinds") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"}
    ]


def test_but_without_all_is_no_exception(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "turn off all the lights but first go to the kitchen") == [
        {"frame": "MOTION", "goal": "kitchen"},
        {"frame": "OPERATING", "device": "all_lights", "state": "off"},
    ]
    assert frames_read(vocabulary, "bring me the mug but not the apple") == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]


def test_a_name_leaves_out_that_thing_only_and_each_exception_its_own_action() -> None:
    home = world_of(FAMILY_HOME)
    text = (
        "turn off all the lights except the hallway light, then close all the blinds except the kitchen ones"
    )
    frames = frames_read(home, text, speaker="graham")
    lights = {f["device"] for f in frames if f["state"] == "off"}
    assert "hallway_light" not in lights and {"porch_light", "kitchen_light"} <= lights  # the porch light too
    assert [f for f in frames if f["state"] == "closed"] == [
        {"frame": "OPERATING", "device": "study_blinds", "state": "closed"}
    ]
    frames = frames_read(home, "turn off all the lights except the ones in the hallway", speaker="graham")
    assert not {"hallway_light", "porch_light"} & {f["device"] for f in frames}


def test_a_thing_left_out_by_its_order_in_another_pddl_problem() -> None:
    from knic.language.world import read_vocabulary

    numbered = read_vocabulary(problem="tests/fixtures/language/numbered/numbered.pddl")
    assert frames_read(numbered, "bring me all the cups except the second one", speaker="alice") == [
        {"frame": "BRINGING", "theme": "cup1", "beneficiary": "me"}
    ]
    assert frames_read(numbered, "turn off every lamp but the first", speaker="alice") == [
        {"frame": "OPERATING", "device": "lamp_02", "state": "off"}
    ]
