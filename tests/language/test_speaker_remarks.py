"""What the speaker says of their own going is no request of the robot (``knic.language.learners``), and a
question the request needs beats the talk's "no action" (``knic.language.reader``)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read


@pytest.mark.parametrize(
    "text",
    ["I'm going to bed", "im going to bed", "I am going to the kitchen", "we're heading to the bathroom"],
)
def test_the_speakers_own_going_said_alone_is_no_request(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.frames and not result.question
    assert "no action" in result.reason


def test_a_learners_plain_going_said_alone_stays_a_request(vocabulary: Vocabulary) -> None:
    # "i go kitchen": a learner's request as often as a statement (people11)
    assert frames_read(vocabulary, "i go kitchen") == [{"frame": "MOTION", "goal": "kitchen"}]


def test_the_request_after_the_speakers_going_is_read(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "I'm going to bed, turn the lights off") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"}
    ]


def test_a_question_the_request_needs_beats_the_talks_no_action(vocabulary: Vocabulary) -> None:
    result = understand("I'm going to bed, turn everything off", vocabulary, speaker="annie")
    assert not result.accepted and not result.frames
    assert "everything" in result.question


@pytest.mark.parametrize(
    "text", ["put the mug on the kitchen table, then close it", "go to the bedroom, then switch them on"]
)
def test_an_action_on_it_after_then_is_not_dropped_as_talk(vocabulary: Vocabulary, text: str) -> None:
    # "then close it" asks for an action: refused with the command, never left out of it (reader.py)
    result = understand(text, vocabulary, speaker="annie")
    assert not result.accepted and not result.goals
