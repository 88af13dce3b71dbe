"""Phrasings from the people17 development set (Granny Annie's requests in the ERL apartment) the reader first
got wrong:

* "something to eat", "a snack": a kind of thing said by its use, as "something to drink" is: the one thing to
  eat, or a question which of them;
* a verb's word after "my", "your", "our", "their" or "the" names a thing ("my walking stick", "the dancing
  shoes"): a thing the world lacks is refused by that name, not read as a second action;
* a thing said with what it holds ("a glass of milk") is corrected whole ("no, a cup");
* a hesitation between a thing and the same article said again ("the banana, uh, the apple") is the
  speaker correcting the thing.
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read


@pytest.mark.parametrize(
    "text",
    ["could you get me something to eat", "fetch me a snack", "I'd love something sweet to eat"],
)
def test_something_to_eat_asks_which_food(vocabulary: Vocabulary, text: str) -> None:
    assert_asked(vocabulary, text, "eat")
    assert "apple" in understand(text, vocabulary).question


def test_to_eat_said_as_a_verb_is_no_kind(vocabulary: Vocabulary) -> None:
    result = understand("I want to eat", vocabulary)
    assert not result.accepted
    assert not result.reason.startswith("ambiguous")


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("please fetch my walking frame", "walking frame"),
        ("hand me your stick", "stick"),
        ("bring me the dancing shoes from the closet", "dancing shoes"),
    ],
)
def test_a_verbs_word_after_my_or_the_names_a_missing_thing(
    vocabulary: Vocabulary, text: str, word: str
) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted
    assert f"'{word}'" in result.reason, result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("have a look for my glasses", [{"frame": "SEARCHING", "theme": "glasses"}]),
        ("take the mug to the kitchen", [{"frame": "BRINGING", "theme": "mug", "goal": "kitchen"}]),
    ],
)
def test_verbs_after_other_words_stay_verbs(vocabulary: Vocabulary, text: str, frames: object) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "fetch me a mug of cocoa no wait a glass",
            [{"frame": "BRINGING", "theme": "glass", "beneficiary": "me"}],
        ),
        (
            "could you get a glass of lemonade sorry a mug",
            [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}],
        ),
    ],
)
def test_a_thing_said_with_what_it_holds_is_corrected_whole(
    vocabulary: Vocabulary, text: str, frames: object
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("hand me the pear um the lemon", [{"frame": "BRINGING", "theme": "lemon", "beneficiary": "me"}]),
        ("fetch a mug of cocoa uh a mug", [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}]),
        ("walk over to the bathroom er the bedroom", [{"frame": "MOTION", "goal": "bedroom"}]),
    ],
)
def test_a_hesitation_before_the_same_article_corrects_the_thing(
    vocabulary: Vocabulary, text: str, frames: object
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("fetch me uh the candle", [{"frame": "BRINGING", "theme": "candle", "beneficiary": "me"}]),
        (
            "get the soap and um the sponge",
            [
                {"frame": "BRINGING", "theme": "soap", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "sponge", "beneficiary": "me"},
            ],
        ),
    ],
)
def test_a_hesitation_after_no_thing_is_only_dropped(
    vocabulary: Vocabulary, text: str, frames: object
) -> None:
    assert frames_read(vocabulary, text) == frames
