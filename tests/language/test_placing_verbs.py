"""A verb that places things first ("tidy", "clear", "arrange") said of a room is refused naming the room,
not read as setting the room's only dimmer (``knic.language.roles``); verbs of devices still set it."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize(
    "text", ["tidy the living room", "tidy up the living room", "arrange the living room"]
)
def test_a_placing_verb_said_of_a_room_names_the_room(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.question and not result.frames
    assert "living room" in result.reason


def test_a_device_verb_said_of_a_room_still_sets_its_dimmer(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "put the living room on") == [
        {"frame": "OPERATING", "device": "living_room_dimmer", "state": "on"}
    ]
    assert "how far" in understand("dim the living room", vocabulary, speaker="annie").question.lower()
