"""A device said where an action needs a thing, a person or a place is refused saying it is a device and
what can be done with it (``knic.language.frames.not_of_kinds``), not as "not an object"."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("is the hallway light on?", "the hallway light is a device"),
        ("bring me the dimmer", "the dimmer is a device"),
        ("are the blinds open?", "the blinds are devices"),
    ],
)
def test_a_device_said_as_a_thing_is_said_to_be_a_device(
    vocabulary: Vocabulary, text: str, said: str
) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames and not result.goals
    assert said in result.reason and "switch or set" in result.reason


def test_what_is_no_device_is_still_named_by_its_kind(vocabulary: Vocabulary) -> None:
    result = understand("bring the kitchen to me", vocabulary, speaker="annie")  # "bring me the kitchen": a
    # learner's "take me to the kitchen" (people33)
    assert not result.accepted and "'kitchen' is not" in result.reason
