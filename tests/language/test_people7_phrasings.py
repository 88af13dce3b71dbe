"""Phrasings found with the seventh blind set (people7): digits typed for the word they sound like ("bring the
tablet 2 tracy": to; "4 me": for) unless a count follows ("2 apples"), and fractions ("3/4 of the way");
"when u get a sec"; "is it possible for you to ..." as a
polite request; "make the living room a bit brighter" (how far is asked); what the speaker says about someone
after the request ("find the teddy bear, oscar can't sleep without it") is talk, not a second action; someone
the world has no name for said before the thing ("bring my husband his glasses") is refused, not dropped;
a wished state with a level ("i'd like the blinds open halfway")."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read

READ = [
    ("bring the tablet 2 tracy pls", [{"frame": "BRINGING", "theme": "tablet", "beneficiary": "tracy"}]),
    ("take the cup 2 the kitchen", [{"frame": "BRINGING", "theme": "cup", "goal": "kitchen"}]),
    ("set the dimmer 2 50", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "50"}]),
    ("set the dimmer to 2", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "2"}]),
    ("bring me 2 apples", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
    ("find tracy 4 me", [{"frame": "SEARCHING", "theme": "tracy"}]),
    ("dimmer at 3/4 pls", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "75"}]),
    ("dimmer 2 1/2.", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "50"}]),
    ("i'd like the blinds open halfway", [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"}]),
    (
        "bring me the mug open the blinds halfway",
        [
            {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"},
            {"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"},
        ],
    ),
    ("when u get a sec bring me the mug", [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}]),
    (
        "bring the juice to tracy, tracy needs it",
        [{"frame": "BRINGING", "theme": "juice", "beneficiary": "tracy"}],
    ),
]

READ_IN_THE_OTHER_HOUSE = [
    (
        "open the study blinds 3/4 of the way",
        [{"frame": "OPERATING", "device": "study_blinds", "state": "75"}],
    ),
    ("is it possible for you to look for my keys", [{"frame": "SEARCHING", "theme": "keys"}]),
    ("would it be possible for you to go 2 the study", [{"frame": "MOTION", "goal": "study"}]),
    (
        "could you go to the nursery and find the teddy bear, oscar can't sleep without it",
        [
            {"frame": "MOTION", "goal": "nursery"},
            {"frame": "SEARCHING", "theme": "teddy_bear", "ground": "nursery"},
        ],
    ),
    (
        "find the keys oscar won't stop asking for them and then go 2 the garage",
        [{"frame": "SEARCHING", "theme": "keys"}, {"frame": "MOTION", "goal": "garage"}],
    ),
]


@pytest.mark.parametrize(("text", "frames"), READ)
def test_read_as_meant(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(("text", "frames"), READ_IN_THE_OTHER_HOUSE)
def test_read_as_meant_in_the_other_house(
    other_house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(other_house, text, "maria") == frames


@pytest.mark.parametrize("text", ["make the living room a bit brighter", "make the dimmer darker"])
def test_making_a_room_brighter_asks_how_far(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and "dimmer" in result.question


def test_making_something_else_is_still_refused(vocabulary: Vocabulary) -> None:
    result = understand("make me a sandwich", vocabulary)
    assert not result.accepted and "sandwich" in result.reason


@pytest.mark.parametrize(
    ("text", "word"), [("bring my husband his glasses", "husband"), ("give my son the remote", "son")]
)
def test_someone_the_world_has_no_name_for_is_refused(vocabulary: Vocabulary, text: str, word: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and word in result.reason


def test_talk_without_an_action_is_still_no_action(vocabulary: Vocabulary) -> None:
    result = understand("this concludes the test", vocabulary)
    assert not result.accepted and "no action" in result.reason


@pytest.mark.parametrize(
    ("text", "level"),
    [("set the living room dimmer to 2 percent", "2"), ("put the blinds at 2 please", "2")],
)
def test_a_typed_digit_after_a_level_word_or_before_percent_is_a_number(
    vocabulary: Vocabulary, text: str, level: str
) -> None:
    assert [f.get("state") for f in understand(text, vocabulary).frames] == [level]
