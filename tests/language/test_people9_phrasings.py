"""Phrasings found with the ninth blind set (people9): "transport" and "convey" carry a thing as "bring" does;
older and regional names of places and things: "curtains" for blinds, "bedside cabinet" (or cupboard) for a
bedside table, "scullery" for a kitchen, "passage" (or "passageway") for a hallway; "on the left of", "to the
right of", "on the left (hand) side of" place a thing beside another as "next to" does; a thing told from
others by its side said after it ("the light on the right", "the lamp on the left hand side") is the one the
world names with that side first, while "on the tv stand" stays a place; an object said only to show where
("put the stapler beside the laptop on the desk") gives way to the place said after it; devices each said
with their own state, with or without a verb ("lights off, blinds down", "desk lamp on and study blinds up",
"switch the lights off the blinds down"), are one action each; a place gone to before another action and
then a later place ("go to the lounge, switch the dimmer off, then come to the study") is only a waypoint,
as right before a second trip; "a cup of tea", "a bottle of milk": the drink is meant, so a drink the
world lacks is refused, not the cup brought (while "the remote of tv" stays the remote); a device said, with
no verb, to be still or again in a state ("the hallway light is still on", "the garage light has been left on
again", "the blinds are still open") is a complaint: the other state is meant, while "still on the table"
stays where a thing is; "pop", "stick", "chuck" a device on or off (British) switch it."""

from __future__ import annotations

import pytest

from knic.language import understand
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


@pytest.mark.parametrize(
    "relation",
    ["on the left of", "to the right of", "on the left side of", "on the right hand side of", "left of"],
)
def test_a_side_of_a_place_is_beside_it(
    vocabulary: Vocabulary, other_house: Vocabulary, relation: str
) -> None:
    assert frames_read(vocabulary, f"put the mug {relation} the sofa") == [
        {"frame": "PLACING", "theme": "mug", "goal": "sofa"}
    ]
    assert frames_read(other_house, f"look for the keys {relation} the couch", "maria") == [
        {"frame": "SEARCHING", "theme": "keys", "ground": "couch"}
    ]


@pytest.mark.parametrize(
    ("text", "device"),
    [
        ("switch on the light on the right in the bedroom", "bedroom_right_light"),
        ("switch on the lamp on the left", "bedroom_left_light"),
        ("switch on the light on the left hand side", "bedroom_left_light"),
    ],
)
def test_a_thing_told_by_its_side_said_after_it(vocabulary: Vocabulary, text: str, device: str) -> None:
    assert frames_read(vocabulary, text) == [{"frame": "OPERATING", "device": device, "state": "on"}]


def test_a_name_after_on_the_stays_a_place(vocabulary: Vocabulary) -> None:
    # "tv remote" is a name too: "the remote on the tv stand" is no "tv remote"
    assert frames_read(vocabulary, "put the remote on the tv stand") == [
        {"frame": "PLACING", "theme": "remote", "goal": "tv_table"}
    ]


def test_a_side_the_world_names_nothing_with_is_refused(other_house: Vocabulary) -> None:
    result = understand("switch on the light on the left", other_house, speaker="maria")
    assert not result.accepted and "left" in result.reason


@pytest.mark.parametrize(
    ("text", "frame"),
    [
        (
            "put the stapler beside the laptop on the desk",
            {"frame": "PLACING", "theme": "stapler", "goal": "desk"},
        ),
        (
            "look for the keys behind the laptop on the desk",
            {"frame": "SEARCHING", "theme": "keys", "ground": "desk"},
        ),
        (
            "bring me the keys next to the laptop on the desk",
            {"frame": "BRINGING", "theme": "keys", "source": "desk", "beneficiary": "me"},
        ),
    ],
)
def test_an_object_said_to_show_where_gives_way_to_the_place_after_it(
    other_house: Vocabulary, text: str, frame: dict[str, str]
) -> None:
    assert frames_read(other_house, text, "maria") == [frame]


def test_an_object_as_the_only_place_is_still_refused(other_house: Vocabulary) -> None:
    result = understand("put the stapler beside the laptop", other_house, speaker="maria")
    assert not result.accepted and "laptop" in result.reason


@pytest.mark.parametrize(
    "text",
    [
        "lights off, blinds down, now",
        "lights off and the blinds down",
        "switch the lights off the blinds down",
    ],
)
def test_devices_each_with_their_state_are_one_action_each(vocabulary: Vocabulary, text: str) -> None:
    assert frames_read(vocabulary, text) == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"},
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"},
    ]


def test_devices_each_with_their_state_or_level_in_the_other_house(other_house: Vocabulary) -> None:
    assert frames_read(other_house, "desk lamp on and study blinds up please", "maria") == [
        {"frame": "OPERATING", "device": "desk_lamp", "state": "on"},
        {"frame": "OPERATING", "device": "study_blinds", "state": "open"},
    ]
    assert frames_read(other_house, "lounge dimmer to 30, study blinds down", "maria") == [
        {"frame": "OPERATING", "device": "lounge_dimmer", "state": "30"},
        {"frame": "OPERATING", "device": "study_blinds", "state": "closed"},
    ]


def test_a_state_said_twice_for_two_devices_still_asks_about_an_ambiguous_one(vocabulary: Vocabulary) -> None:
    result = understand("turn the lamp on the blinds up", vocabulary)
    assert not result.accepted and "which lamp" in result.reason


def test_a_place_before_a_later_trip_is_a_waypoint(other_house: Vocabulary) -> None:
    result = understand(
        "go to the lounge, switch the dimmer off, then come to the study", other_house, speaker="maria"
    )
    assert result.accepted, result.reason
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "MOTION", "goal": "lounge"},
        {"frame": "OPERATING", "device": "lounge_dimmer", "state": "off"},
        {"frame": "MOTION", "goal": "study"},
    ]
    assert {str(g) for g in result.goals if g.predicate == "robot_at"} == {"(robot_at tiago study)"}


@pytest.mark.parametrize(
    ("text", "word"), [("I'd love a cup of tea", "tea"), ("bring me a cup of hot tea please", "hot tea")]
)
def test_a_container_of_a_drink_the_world_lacks_is_refused(
    vocabulary: Vocabulary, text: str, word: str
) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and f"'{word}'" in result.reason


def test_a_container_of_a_drink_the_world_lacks_in_the_other_house(other_house: Vocabulary) -> None:
    result = understand("bring me a bottle of milk", other_house, speaker="maria")
    assert not result.accepted and "milk" in result.reason


def test_a_container_of_a_known_drink_is_the_drink(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me a cup of water") == [
        {"frame": "BRINGING", "theme": "water", "beneficiary": "me"}
    ]


def test_a_thing_of_a_word_the_world_lacks_said_with_the_stays_the_thing(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "the remote of tv, bring it to me") == [
        {"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("the hallway light is still on", "hallway_light", "off"),
        ("the lights are still on", "all_lights", "off"),
        ("the blinds are still open", "bedroom_blinds", "closed"),
        ("the blinds are still down", "bedroom_blinds", "open"),
        ("the left light was left on", "bedroom_left_light", "off"),
    ],
)
def test_a_device_left_in_a_state_is_put_in_the_other(
    vocabulary: Vocabulary, text: str, device: str, state: str
) -> None:
    assert frames_read(vocabulary, text) == [{"frame": "OPERATING", "device": device, "state": state}]


def test_a_device_left_in_a_state_in_the_other_house(other_house: Vocabulary) -> None:
    assert frames_read(other_house, "the garage light has been left on again", "maria") == [
        {"frame": "OPERATING", "device": "garage_light", "state": "off"}
    ]
    assert frames_read(other_house, "the study blinds have been left open", "maria") == [
        {"frame": "OPERATING", "device": "study_blinds", "state": "closed"}
    ]


def test_said_with_a_verb_the_state_is_as_said(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "leave the hallway light on") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"}
    ]
    assert frames_read(vocabulary, "the hallway light is on") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"}
    ]


def test_a_thing_still_on_a_place_is_where_it_is(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "the mug is still on the kitchen table, put it in the cabinet") == [
        {"frame": "PLACING", "theme": "mug", "goal": "kitchen_cabinet"}
    ]


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("pop the big light on in the passage, duck", "hallway_light", "on"),
        ("stick the lights on", "all_lights", "on"),
        ("chuck the hallway light off", "hallway_light", "off"),
        ("pop the blinds down", "bedroom_blinds", "closed"),
    ],
)
def test_pop_or_stick_a_device_on_switches_it(
    vocabulary: Vocabulary, text: str, device: str, state: str
) -> None:
    assert frames_read(vocabulary, text) == [{"frame": "OPERATING", "device": device, "state": state}]


def test_pop_or_stick_a_thing_somewhere_still_puts_it_there(other_house: Vocabulary) -> None:
    assert frames_read(other_house, "pop the teddy bear in the crib", "maria") == [
        {"frame": "PLACING", "theme": "teddy_bear", "goal": "crib"}
    ]
    assert frames_read(other_house, "stick the garage light on", "maria") == [
        {"frame": "OPERATING", "device": "garage_light", "state": "on"}
    ]
