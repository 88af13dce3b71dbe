"""Phrasings found with the eighth blind set (people8): someone the world has no name for said before "wants"
or "needs" ("the kid wants the remote") is refused naming them, not served to the speaker; a thing's name
opening a command right before a determiner is a verb the robot does not know ("water the plant"), not a
request for the thing; a word the world lacks said right after "for" at the end of an action whose person is
already said is what for, not for whom ("bring me the remote for once", "get me an apple for breakfast");
"brighten the living room" asks how far, as "make the living room brighter" does, and so does a dimmer or
blinds, or a room with one of them, operated without a state or level ("dim the living room", "set the
blinds"); "find me the stapler" looks for the stapler, not the speaker; "follow me to the study" goes there;
"help oscar find his teddy bear" (or "help me to find ...") is the search; "never mind", "on second thought",
"forget that" correct what was said before; "need water", "want juice" opening a command are the speaker's
"i need", "i want"; a search for someone the world has no name for ("go find mommy") names them."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("the kid wants the remote", "kid"),
        ("my husband would like the remote", "husband"),
        ("my neighbour needs a glass of water", "neighbour"),
    ],
)
def test_someone_unknown_who_wants_something_is_refused(vocabulary: Vocabulary, text: str, word: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and word in result.reason


def test_someone_unknown_who_wants_something_is_refused_in_the_other_house(other_house: Vocabulary) -> None:
    result = understand("my son needs his blanket", other_house, speaker="maria")
    assert not result.accepted and "son" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("tracy wants the remote", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "tracy"}]),
        (
            "bring me the remote, the kid wants it",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
    ],
)
def test_someone_known_who_wants_something_is_served(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize("text", ["water the plant", "please water my plant", "juice the lemon"])
def test_a_name_used_as_a_verb_is_no_request_for_it(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and not result.frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("water please", [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}]),
        ("water for tracy", [{"frame": "BRINGING", "theme": "water", "beneficiary": "tracy"}]),
        ("the remote please", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]),
    ],
)
def test_a_name_alone_is_still_a_request_for_it(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("bring me the remote for once", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]),
        ("get me an apple for breakfast", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
        (
            "bring me water for later and then go to the kitchen",
            [
                {"frame": "BRINGING", "theme": "water", "beneficiary": "me"},
                {"frame": "MOTION", "goal": "kitchen"},
            ],
        ),
    ],
)
def test_what_for_after_the_person_is_talk(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("bring the mug for grandpa", "grandpa"),
        ("bring me the mug for my husband", "husband"),
        ("bring me for once", "once"),
    ],
)
def test_for_someone_unknown_is_still_refused(vocabulary: Vocabulary, text: str, word: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and word in result.reason


@pytest.mark.parametrize(
    "text",
    ["brighten the living room", "could you brighten up the living room", "darken the living room a bit"],
)
def test_brightening_a_room_asks_how_far(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and "dimmer" in result.question


def test_brightening_to_a_level_sets_it(vocabulary: Vocabulary, other_house: Vocabulary) -> None:
    result = understand("brighten the living room to 80", vocabulary)
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "OPERATING", "device": "living_room_dimmer", "state": "80"}
    ]
    result = understand("brighten the lounge please", other_house, speaker="maria")
    assert not result.accepted and "lounge dimmer" in result.question


@pytest.mark.parametrize(
    ("text", "device"),
    [("dim the living room", "dimmer"), ("dim the dimmer", "dimmer"), ("set the blinds", "blinds")],
)
def test_a_dimmer_or_blinds_without_a_level_asks_how_far(
    vocabulary: Vocabulary, text: str, device: str
) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and device in result.question and "how far" in result.question.lower()


def test_a_room_dimmed_to_a_level_is_its_dimmer(other_house: Vocabulary) -> None:
    result = understand("dim the lounge to 30", other_house, speaker="maria")
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "OPERATING", "device": "lounge_dimmer", "state": "30"}
    ]
    result = understand("dim the lounge", other_house, speaker="maria")
    assert not result.accepted and "lounge dimmer" in result.question


def test_lights_without_a_state_are_still_refused(vocabulary: Vocabulary) -> None:
    result = understand("dim the lights", vocabulary)
    assert not result.accepted and not result.question


READ_IN_THE_OTHER_HOUSE = [
    ("find me the stapler", [{"frame": "SEARCHING", "theme": "stapler"}]),
    ("follow me to the study", [{"frame": "MOTION", "goal": "study"}]),
    ("help oscar find his teddy bear", [{"frame": "SEARCHING", "theme": "teddy_bear"}]),
    ("please help oscar look for his keys", [{"frame": "SEARCHING", "theme": "keys"}]),
]

READ = [
    ("come find me", [{"frame": "SEARCHING", "theme": "me"}]),
    (
        "can you find me the tissues in the bathroom",
        [{"frame": "SEARCHING", "theme": "tissues", "ground": "bathroom"}],
    ),
    ("help me to find my glasses", [{"frame": "SEARCHING", "theme": "glasses"}]),
    ("help tracy to the kitchen", [{"frame": "ACCOMPANYING", "theme": "tracy", "goal": "kitchen"}]),
    ("follow me into the kitchen please", [{"frame": "MOTION", "goal": "kitchen"}]),
    ("go to the bathroom. never mind, go to the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    (
        "bring me the mug. on second thought, the glass",
        [{"frame": "BRINGING", "theme": "glass", "beneficiary": "me"}],
    ),
    (
        "bring me the juice, forget that, bring me the water",
        [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}],
    ),
    ("need water", [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}]),
    ("want juice", [{"frame": "BRINGING", "theme": "juice", "beneficiary": "me"}]),
    ("need the tissues, quick", [{"frame": "BRINGING", "theme": "tissues", "beneficiary": "me"}]),
    ("need the blinds closed", [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}]),
]


@pytest.mark.parametrize(("text", "frames"), READ_IN_THE_OTHER_HOUSE)
def test_read_as_meant_in_the_other_house(
    other_house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(other_house, text, "maria") == frames


@pytest.mark.parametrize(("text", "frames"), READ)
def test_read_as_meant(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize("text", ["i don't need the remote anymore", "do you need anything"])
def test_need_inside_a_sentence_is_no_request(vocabulary: Vocabulary, text: str) -> None:
    assert not understand(text, vocabulary).accepted


def test_a_search_for_someone_unknown_names_them(vocabulary: Vocabulary) -> None:
    result = understand("robot go find mommy", vocabulary)
    assert not result.accepted and "mommy" in result.reason
