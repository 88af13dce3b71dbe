"""Phrasings from the people30 development set (a semi-detached suburban house with a conservatory, a garage
converted to a workshop and a loft room the reader was never tuned on,
``tests/fixtures/language/people30/semi_house.yaml``) the reader first got wrong, each tried in the ERL
apartment as well:

* "report the location of", "tell me the location of" (an engineer's, a log's words) search; "teleport to"
  (a child's word from games) goes; a learner's "wait me there" is "wait for me there" (``commands.yaml``);
* "loft" is a word for a kind of room, so a "loft room" is also "the loft" (``synonyms.yaml``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

HOUSE = "tests/fixtures/language/people30/semi_house.yaml"
Frames = list[dict[str, str]]


@lru_cache(maxsize=1)
def _house() -> Vocabulary:
    return world_of(HOUSE)


def _said(erl_vocabulary: Vocabulary, erl: bool, text: str, speaker: str) -> Frames:
    """The frames ``text`` is read as in the ERL apartment (said by annie) or in the semi (by ``speaker``)."""
    return frames_read(erl_vocabulary if erl else _house(), text, "annie" if erl else speaker)


@pytest.mark.parametrize(
    ("erl", "text", "frames"),
    [
        (False, "Report the location of the spirit level", [{"frame": "SEARCHING", "theme": "spirit_level"}]),
        (False, "tell me the location of the drill", [{"frame": "SEARCHING", "theme": "drill"}]),
        (True, "report the location of the remote", [{"frame": "SEARCHING", "theme": "remote"}]),
        (True, "give me the location of the tablet", [{"frame": "SEARCHING", "theme": "tablet"}]),
        (False, "Teleport to the conservatory", [{"frame": "MOTION", "goal": "conservatory"}]),
        (True, "teleport to the kitchen please", [{"frame": "MOTION", "goal": "kitchen"}]),
        (False, "Go up to the loft and wait me there", [{"frame": "MOTION", "goal": "loft_room"}]),
        (True, "go in the bedroom and wait me there", [{"frame": "MOTION", "goal": "bedroom"}]),
        (True, "wait me in the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    ],
)
def test_words_for_search_go_and_wait(vocabulary: Vocabulary, erl: bool, text: str, frames: Frames) -> None:
    assert _said(vocabulary, erl, text, "hazem") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Put the controller on the beanbag in the loft",
            [{"frame": "PLACING", "theme": "controller", "goal": "beanbag"}],
        ),
        (
            "Sorry, is Hazem up in the loft, do you know?",
            [{"frame": "SEARCHING", "theme": "hazem", "ground": "loft_room"}],
        ),
        ("switch the loft light off", [{"frame": "OPERATING", "device": "loft_light", "state": "off"}]),
        ("take me up to the loft", [{"frame": "ACCOMPANYING", "theme": "me", "goal": "loft_room"}]),
    ],
)
def test_the_loft_is_the_loft_room(text: str, frames: Frames) -> None:
    assert frames_read(_house(), text, "philippa") == frames
