"""Words of robot competitions' commands (RoboCup@Home, ERL): "meet X at Y" finds X there
(``commands.yaml``), and an action the robot has none for said of a person ("... and follow her") is
refused by name (``knic.language.remarks.unknown_action``), as one said of a thing is."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


def test_meeting_someone_somewhere_finds_them_there(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "meet tracy at the entrance") == [
        {"frame": "SEARCHING", "theme": "tracy", "ground": "entrance_hall"}
    ]
    assert frames_read(vocabulary, "meet tracy in the kitchen and take her to the bedroom") == [
        {"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"},
        {"frame": "ACCOMPANYING", "theme": "tracy", "goal": "bedroom"},
    ]
    assert frames_read(vocabulary, "go to the entrance and meet tracy") == [
        {"frame": "MOTION", "goal": "entrance_hall"},
        {"frame": "SEARCHING", "theme": "tracy", "ground": "entrance_hall"},
    ]


@pytest.mark.parametrize(
    ("text", "verb"),
    [("find tracy and follow her", "follow"), ("find tracy and thank her", "thank")],
)
def test_an_unknown_action_on_a_person_is_refused_by_name(
    vocabulary: Vocabulary, text: str, verb: str
) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames
    assert f"I cannot {verb}" in result.reason


def test_a_known_action_on_a_person_after_a_joiner_still_reads(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "find tracy and take her to the kitchen") == [
        {"frame": "SEARCHING", "theme": "tracy"},
        {"frame": "ACCOMPANYING", "theme": "tracy", "goal": "kitchen"},
    ]


@pytest.mark.parametrize("text", ["take tracy to annie", "lead tracy to annie", "bring jack to annie"])
def test_taking_someone_to_a_person_asks_the_room(vocabulary: Vocabulary, text: str) -> None:
    # where another person is, the reader does not know (the robot finds out): the room is asked
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames
    assert "I do not know where annie is" in result.question


def test_an_unknown_action_on_a_named_person_is_refused_by_name(vocabulary: Vocabulary) -> None:
    # it was a second place to go to: "Go where? the tracy is not a room or furniture"
    result = understand("go to the kitchen and tell tracy dinner is ready", vocabulary, speaker="annie")
    assert not result.accepted and "I cannot tell" in result.reason


@pytest.mark.parametrize(
    "text",
    ["find tracy and ask her to follow you to the kitchen", "find tracy and tell her to go to the kitchen"],
)
def test_someone_asked_to_come_by_pronoun_is_taken_there(vocabulary: Vocabulary, text: str) -> None:
    assert frames_read(vocabulary, text) == [
        {"frame": "SEARCHING", "theme": "tracy"},
        {"frame": "ACCOMPANYING", "theme": "tracy", "goal": "kitchen"},
    ]
