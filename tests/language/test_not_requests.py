"""What the speaker asks about, means to do themselves or does as a habit is no request (commands.yaml
``not_requests``): a question about how ("how do you spell kitchen"), the speaker's own plan ("i should water
the plants later") or habit ("i always keep the soap in the bathroom") is refused, even when misheard into
words that name the world; a request said that way is still read. So is what the robot cannot do or the world
lacks: a later action it has no verb for ("... and wash it"), furniture as the thing to move, a colour the
world's thing has not ("the white wine" beside a red one)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of


@pytest.mark.parametrize(
    "text",
    [
        "how do you spell kitchen",
        "how do you stay in the kitchen",  # "how do you spell kitchen" as a recogniser heard it
        "i should walk at the plant later",  # "i should water the plants later", heard so
        "How do I get to the kitchen?",
        "how does the dimmer work",
        "I ought to go to the bedroom",
        "i always keep the soap in the bathroom",  # a habit, heard word for word
        "We usually put the remote on the coffee table.",
        "i'll always keep the soap in the bathroom",  # as Whisper wrote it
    ],
)
def test_a_question_or_the_speakers_own_plan_is_refused(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and not result.frames
    assert "no request" in (result.reason or "")


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "I should like you to bring me the mug",
            [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}],
        ),
        (
            "how do you say, the remote, bring it to me",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
        (
            "I should water the plants later. Bring me the mug.",
            [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}],
        ),
        (
            "i always forget, bring me my glasses",
            [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}],
        ),
    ],
)
def test_a_request_said_around_such_words_is_read(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted and [f.to_dict() for f in result.frames] == frames


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("take the cup to the kitchen and wash it", "wash"),  # was the taking alone, the washing dropped
        ("fetch the mug then polish it", "polish"),
        ("bring me the cup and then dust the candle", "dust"),
        ("bring me the cup and water the plant", "water"),  # a thing's name said as a verb: not a bringing
    ],
)
def test_a_later_action_the_robot_has_not_is_refused_by_name(
    vocabulary: Vocabulary, text: str, verb: str
) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and not result.goals
    assert result.reason == f"I cannot {verb} things: '{verb}' is no action of mine"


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        ("bring me the cup and maybe the mug", ["(has annie cup)", "(has annie mug)"]),
        ("bring me the cup and the water", ["(has annie cup)", "(has annie water)"]),
    ],
)
def test_words_after_a_joiner_that_are_no_verb_still_read(
    vocabulary: Vocabulary, text: str, goals: list[str]
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals][: len(goals)] == goals


@pytest.mark.parametrize("text", ["move the sofa to the bedroom", "shift the armchair into the kitchen"])
def test_furniture_to_be_moved_is_refused_not_read_as_where_to_go(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)  # was a motion to the room, the sofa dropped
    assert not result.accepted and not result.goals and "is not an object" in result.reason


def test_a_way_said_before_where_to_go_is_still_a_motion(vocabulary: Vocabulary) -> None:
    result = understand("go down the hallway to the kitchen", vocabulary)
    assert [str(g) for g in result.goals] == ["(robot_at r2d2 kitchen)"]


def test_a_colour_the_worlds_thing_has_not_names_nothing() -> None:
    """The duplex has a red wine only: "the white wine" is not it (it was taken for the red one)."""
    duplex = world_of("tests/fixtures/language/people26/city_duplex.yaml")
    for text in ["bring me the white wine", "bring me a glass of white"]:
        result = understand(text, duplex, speaker="huiling")
        assert not result.accepted and "no 'white wine' here" in result.reason, text
    assert frames_read(duplex, "bring me the red wine", "huiling") == [
        {"frame": "BRINGING", "theme": "red_wine", "beneficiary": "me"}
    ]
