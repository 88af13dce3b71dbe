"""Steps found trying the reader as a new user. Coming back to the speaker as the last step of a chain is a
step, not talk: "..., come back to me" said after commas asks where the speaker is (without the commas it
did; with them the step was dropped as talk naming nothing), and "come back" with no place said after the
robot was sent somewhere is coming back to the speaker (``knic.language.stepwise.came_back``), where it was
left out. A door bell is heard, not worked ("ring the bell" asked how far to set it). "Every room" is the
whole home (it was the one room whose name ends in "room"). "Before" between two actions keeps their order
("switch the lights off before you close the blinds": "before you" was a thing the world lacks)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize(
    "text",
    [
        "go to the bedroom, go to the bathroom, come to me",
        "go to the bedroom, then go to the bathroom, then come back to me",
        "switch on the left light, then go to the bathroom, then come to me",
        "go to the kitchen and come back",
        "take the mug to the kitchen and come back",
        "put the mug on the kitchen counter, then go back",
        "go to the bathroom, then head back and switch off the hallway light",
    ],
)
def test_coming_back_to_the_speaker_asks_where_they_are(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames
    assert "where are you" in result.question.lower()


def test_a_place_said_after_coming_back_is_where_it_goes(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "go to the kitchen, then come back to the bedroom") == [
        {"frame": "MOTION", "goal": "kitchen"},
        {"frame": "MOTION", "goal": "bedroom"},
    ]
    assert frames_read(vocabulary, "go to the bedroom, go to the bathroom, come back to the kitchen") == [
        {"frame": "MOTION", "goal": "bedroom"},
        {"frame": "MOTION", "goal": "bathroom"},
        {"frame": "MOTION", "goal": "kitchen"},
    ]


def test_coming_back_after_a_bringing_to_the_speaker_adds_nothing(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me the mug, then come back") == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, "go to the kitchen, get the juice and come back") == [
        {"frame": "MOTION", "goal": "kitchen"},
        {"frame": "BRINGING", "theme": "juice", "source": "kitchen", "beneficiary": "me"},
    ]


def test_talk_said_with_me_is_still_talk(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "excuse me, bring me the mug") == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, "bring me the mug, trust me, it's the blue one") == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]


def test_coming_back_said_alone_still_asks_where(vocabulary: Vocabulary) -> None:
    result = understand("come back", vocabulary, speaker="annie")
    assert not result.accepted and "where" in result.reason.lower()


@pytest.mark.parametrize(
    "text", ["ring the door bell", "turn the door bell on", "switch on the left light and ring the bell"]
)
def test_a_bell_is_heard_not_worked(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.question and not result.frames
    assert "door bell" in result.reason


def test_a_bell_of_another_home_is_named() -> None:
    from .conftest import world_of

    result = understand(
        "ring the bell", world_of("worlds/test_bungalow/test_bungalow.yaml"), speaker="walter"
    )
    assert not result.accepted and "porch bell" in result.reason


@pytest.mark.parametrize(
    "text",
    [
        "could you turn the lights off in every room",
        "turn off the lights in all the rooms",
        "switch the lights off in each room",
        "turn off the lights in all rooms, please",
    ],
)
def test_every_room_is_the_whole_home(vocabulary: Vocabulary, text: str) -> None:
    assert frames_read(vocabulary, text) == [{"frame": "OPERATING", "device": "all_lights", "state": "off"}]


def test_before_between_two_actions_keeps_their_order(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "switch the lights off before you close the blinds") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"},
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"},
    ]
    assert frames_read(vocabulary, "open the blinds before bringing me the juice") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "open"},
        {"frame": "BRINGING", "theme": "juice", "beneficiary": "me"},
    ]
    # said first, "before" still puts its action last
    assert frames_read(vocabulary, "before you go to the bedroom, turn off the hallway light") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "off"},
        {"frame": "MOTION", "goal": "bedroom"},
    ]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("bring me the mug and switch it on", "the mug is not one"),
        ("put the mug on the kitchen table, then close it", "the mug is not one"),
        ("switch on the hallway light and bring it to me", "the hallway light is a device"),
        ("find tracy and switch her on", "tracy is not one"),
    ],
)
def test_a_pronoun_of_the_wrong_kind_says_what_it_would_be(
    vocabulary: Vocabulary, text: str, said: str
) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames and said in result.reason


def test_medium_is_half(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "set the dimmer to medium") == [
        {"frame": "OPERATING", "device": "living_room_dimmer", "state": "50"}
    ]


@pytest.mark.parametrize("text", ["take this to tracy", "bring that to me", "give this to tracy"])
def test_a_thing_pointed_at_and_not_named_is_asked_for(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.question and not result.frames
    assert "what?" in result.reason


def test_coming_back_needs_an_action_said_whole_before_it(vocabulary: Vocabulary) -> None:
    # "go get back and take him ...", a mishearing of "go get jack and take him ...": no coming back to me
    result = understand("go get back and take him to the kitchen", vocabulary, speaker="annie")
    assert not result.accepted and not result.question


@pytest.mark.parametrize(
    "text",
    [
        "the apple and the banana, bring them to me",
        "apple and banana, bring to me",
        "the banana and the apple, bring them",
    ],
)
def test_a_thing_the_world_lacks_listed_before_the_verb_is_named(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames and "'banana'" in result.reason


def test_a_light_by_a_piece_of_furniture_is_one_of_its_room(vocabulary: Vocabulary) -> None:
    result = understand("turn on the light by the bed", vocabulary, speaker="annie")
    assert not result.accepted and "left light or the right light" in result.question
    result = understand("switch on the lamp on the coffee table", vocabulary, speaker="annie")
    assert not result.accepted and "no lamp on the coffee table" in result.reason


@pytest.mark.parametrize(
    ("text", "state"),
    [
        ("if the hallway light is switched on, turn it off", "off"),
        ("when the hallway light is turned off switch it on", "on"),
    ],
)
def test_a_state_said_as_switched_in_a_condition_is_no_request(
    vocabulary: Vocabulary, text: str, state: str
) -> None:
    assert frames_read(vocabulary, text) == [
        {"frame": "OPERATING", "device": "hallway_light", "state": state}
    ]
