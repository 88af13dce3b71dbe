"""A room's light that is a dimmer, levels the world lacks named, and "come to me" asked back."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("dim the living room light to twenty five percent", "(device_level living_room_dimmer l25)"),
        ("turn on the light in the living room", "(device_level living_room_dimmer l100)"),
        ("set the living room light to half", "(device_level living_room_dimmer l50)"),
    ],
)
def test_a_room_light_may_be_its_dimmer(vocabulary: Vocabulary, text: str, goal: str) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == [goal]


def test_what_the_world_lacks_is_named(vocabulary: Vocabulary) -> None:
    result = understand("turn off the kitchen light", vocabulary)
    assert not result.accepted and "no light in the kitchen" in result.reason


@pytest.mark.parametrize(
    ("text", "level"),
    [
        ("dim the living room light to thirty percent", "living_room_dimmer l25"),
        ("set the dimmer to 40%", "living_room_dimmer l50"),
        ("lower the blinds to 10 percent", "bedroom_blinds l25"),  # a little open, not shut
        ("open the blinds to 95 percent", "bedroom_blinds l75"),
        ("set the dimmer to 3 percent", "living_room_dimmer l25"),
    ],
)
def test_a_level_the_world_lacks_goes_to_the_nearest_with_a_note(
    vocabulary: Vocabulary, text: str, level: str
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == [f"(device_level {level})"]
    said = result.frames[0]["state"]
    assert len(result.notes) == 1 and f"nearest level to {said}" in result.notes[0]
    assert result.to_dict()["notes"] == list(result.notes)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("set the dimmer to 0.5", "(device_level living_room_dimmer l50)"),  # a share: half
        ("Put the blinds at 0.75.", "(device_level bedroom_blinds l75)"),
        ("dim the living room light to 1.0", "(device_level living_room_dimmer l100)"),
        ("open the blinds to 74.6%", "(device_level bedroom_blinds l75)"),  # not 746, nor 74 then 6
    ],
)
def test_a_decimal_level_is_one_level_not_two_numbers(vocabulary: Vocabulary, text: str, goal: str) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == [goal]


@pytest.mark.parametrize("text", ["come to me", "take the mug to the kitchen and then come back to me"])
def test_coming_to_the_speaker_asks_where_they_are(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and result.question == "Where are you: in which room?"


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("I\u2019d like the cup please", "(has annie cup)"),  # was "i d like ...": no action
        ("could you find annie\u2019s glasses", "(reported glasses)"),  # was "annies": not an object
        ("br\u00edng me the c\u00fcp", "(has annie cup)"),
    ],
)
def test_typographic_marks_and_accents_read_as_typed_plainly(
    vocabulary: Vocabulary, text: str, goal: str
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert str(result.goals[0]).startswith(goal)
