"""Phrasings from the people15 development set (requests that quantify, select and exclude, and people who
describe rather than name) the reader first got wrong, read by :mod:`knic.language.selecting`:

* a request said again ("like i said, ...", "i told you to ...");
* "the ones" set apart after a thing; a side said of a thing ("the lamp to the right of the bed"); two sides
  of one noun ("the right and the left light");
* all of a kind but some ("every light apart from the left lamp"); "all of them" said after the things;
* a room said before a device's name after "and" ("the hallway light and the bedroom lamps");
* a kind said for its use ("something to drink", "a piece of fruit"): the one such thing, else a question;
* "whichever" or "either ... or" of two things: a question; a landmark nobody knows beside a name that fits
  several things: a question which;
* "put it back" after the thing was taken from somewhere, or fell from somewhere: back there.
"""

from __future__ import annotations

from typing import Any

import pytest

from knic.language import understand

from .conftest import assert_asked, frames_read


def _on(device: str, state: str = "on") -> dict[str, str]:
    return {"frame": "OPERATING", "device": device, "state": state}


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("like i said, the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
        ("i told you to close the blinds", [_on("bedroom_blinds", "closed")]),
        ("i already said it, i said the bathroom", [{"frame": "MOTION", "goal": "bathroom"}]),
    ],
)
def test_a_request_said_again_is_the_request(vocabulary: Any, text: str, frames: Any) -> None:
    assert frames_read(vocabulary, text) == frames


def test_the_ones_set_apart_say_where_the_things_are(other_house: Any) -> None:
    assert frames_read(other_house, "bring me the keys, the ones on the desk", "oscar") == [
        {"frame": "BRINGING", "theme": "keys", "source": "desk", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("switch off the lamp to the right of the bed", [_on("bedroom_right_light", "off")]),
        ("turn on the light on the left hand side", [_on("bedroom_left_light")]),
        ("turn the right and the left light on", [_on("bedroom_right_light"), _on("bedroom_left_light")]),
    ],
)
def test_a_side_said_of_a_thing_picks_the_thing_of_that_side(vocabulary: Any, text: str, frames: Any) -> None:
    assert frames_read(vocabulary, text) == frames


def test_all_of_a_kind_but_some_is_those_left(vocabulary: Any, other_house: Any) -> None:
    assert frames_read(vocabulary, "switch off every light apart from the left lamp") == [
        _on("bedroom_right_light", "off"),
        _on("hallway_light", "off"),
    ]
    assert frames_read(vocabulary, "turn on all the lights except the ones in the bedroom") == [
        _on("hallway_light")
    ]
    assert frames_read(vocabulary, "turn off all lights except for the hallway light") == [
        _on("bedroom_lights", "off")
    ]
    assert frames_read(vocabulary, "turn on all the lights but the bedroom lights") == [_on("hallway_light")]
    assert frames_read(vocabulary, "switch off all the lamps but the one on the right") == [
        _on("bedroom_left_light", "off")
    ]
    assert frames_read(other_house, "turn on all the lights except the garage one", "maria") == [
        _on("desk_lamp")
    ]


def test_all_of_them_after_the_things_is_said_already(vocabulary: Any) -> None:
    assert frames_read(vocabulary, "switch the lights on, all of them") == [_on("all_lights")]
    assert frames_read(vocabulary, "the lamps both off please") == [_on("bedroom_lights", "off")]


def test_a_room_said_before_a_device_after_and_is_where_that_device_is(vocabulary: Any) -> None:
    assert frames_read(vocabulary, "switch on the hallway light and the bedroom lamps") == [
        _on("hallway_light"),
        _on("bedroom_lights"),
    ]
    assert frames_read(vocabulary, "turn off the hallway light and both bedroom lights") == [
        _on("hallway_light", "off"),
        _on("bedroom_lights", "off"),
    ]


def test_a_kind_said_for_its_use_is_the_one_such_thing_or_a_question(
    vocabulary: Any, other_house: Any
) -> None:
    assert_asked(vocabulary, "get tracy something cold to drink", "drink")
    assert_asked(vocabulary, "i'd like a piece of fruit", "fruit")
    assert frames_read(other_house, "bring oscar a drink", "maria") == [
        {"frame": "BRINGING", "theme": "bottle", "beneficiary": "oscar"}
    ]


def test_one_of_two_things_whichever_is_asked_about(vocabulary: Any, other_house: Any) -> None:
    assert_asked(vocabulary, "fetch the soap or the sponge, whichever is nearer", "whichever")
    assert_asked(other_house, "bring me either the keys or the laptop", "keys", "maria")


def test_a_landmark_nobody_knows_beside_a_name_of_several_things_asks_which(vocabulary: Any) -> None:
    assert_asked(vocabulary, "switch on the lamp beside the window", "lamp")
    result = understand("bring me the mug by the window", vocabulary, speaker="annie")
    assert not result.accepted and "window" in result.reason  # one mug: the landmark is still refused


def test_put_back_after_taking_is_back_where_it_was_taken_from(vocabulary: Any) -> None:
    assert frames_read(vocabulary, "pick up the candle from the side table, then put it back") == [
        {"frame": "TAKING", "theme": "candle", "source": "side_table"},
        {"frame": "PLACING", "theme": "candle", "goal": "side_table"},
    ]
    assert_asked(vocabulary, "put the candle back", "where")


def test_put_back_after_a_fall_is_back_where_it_fell_from(vocabulary: Any, other_house: Any) -> None:
    assert frames_read(vocabulary, "the candle fell off the side table, can you put it back") == [
        {"frame": "PLACING", "theme": "candle", "goal": "side_table"}
    ]
    assert frames_read(other_house, "oscar knocked the blanket off the couch, put it back", "maria") == [
        {"frame": "PLACING", "theme": "blanket", "goal": "couch"}
    ]
    assert frames_read(vocabulary, "the remote slipped off the sofa, put it back on the tv table") == [
        {"frame": "PLACING", "theme": "remote", "goal": "tv_table"}
    ]


def test_from_one_place_onto_another_is_a_source_then_a_goal(vocabulary: Any, other_house: Any) -> None:
    assert frames_read(vocabulary, "put the candle from the side table on the bookshelf") == [
        {"frame": "PLACING", "theme": "candle", "source": "side_table", "goal": "bookshelf"}
    ]
    assert frames_read(other_house, "put the hammer from the workbench on the desk", "oscar") == [
        {"frame": "PLACING", "theme": "hammer", "source": "workbench", "goal": "desk"}
    ]
    assert_asked(vocabulary, "put everything from the dining table in the kitchen", "everything")
    assert frames_read(vocabulary, "bring me the remote from the sofa in the living room") == [
        {"frame": "BRINGING", "theme": "remote", "source": "sofa", "beneficiary": "me"}
    ]
