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
    result = understand("dim the living room light to thirty percent", vocabulary)
    assert not result.accepted and "no level of 30 percent (it has 0, 25, 50, 75, 100)" in result.reason


@pytest.mark.parametrize("text", ["come to me", "take the mug to the kitchen and then come back to me"])
def test_coming_to_the_speaker_asks_where_they_are(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and result.question == "Where are you: in which room?"
