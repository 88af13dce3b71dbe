"""Phrasings from the people21 development set (a ground-floor, wheelchair-accessible flat the reader was
never tuned on, ``tests/fixtures/language/people21/accessible_flat.yaml``) the reader first got wrong:

* Scottish and texting spellings (``commands.yaml`` spellings): "fae" from, "tae" to, "aff" off, "gie" give,
  "ma" my, "n" and, "gonnae" (would you), "pleas" please; "keep" a thing somewhere is to put it there (Indian
  English, "keep the saucepan on the hob"); "is possible to" and "it is possible to" are politeness, as "is it
  possible to" is.
"""

from __future__ import annotations

from typing import Any

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read

FLAT = "tests/fixtures/language/people21/accessible_flat.yaml"


def _world(file: str) -> Vocabulary:
    """A world file's vocabulary, as the language bench and ``knic goal --world`` read it."""
    from pathlib import Path

    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    path = Path(__file__).resolve().parents[2] / file
    vocabulary: Any = world_vocabulary(str(path), DEFAULT_DOMAIN, None)[0]
    return vocabulary


@pytest.fixture(scope="module")
def flat() -> Vocabulary:
    """The accessible flat's vocabulary."""
    return _world(FLAT)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "gonnae bring us ma headphones fae the study",
            [{"frame": "BRINGING", "theme": "headphones", "source": "study", "beneficiary": "me"}],
        ),
        (
            "turn the bedroom light aff n the hall light on",
            [
                {"frame": "OPERATING", "device": "bedroom_light", "state": "off"},
                {"frame": "OPERATING", "device": "hall_light", "state": "on"},
            ],
        ),
        (
            "get the toolbox fae the shelves n gie it tae tomasz",
            [
                {"frame": "TAKING", "theme": "toolbox", "source": "utility_shelves"},
                {
                    "frame": "BRINGING",
                    "theme": "toolbox",
                    "source": "utility_shelves",
                    "beneficiary": "tomasz",
                },
            ],
        ),
        ("take the laptop tae dawn", [{"frame": "BRINGING", "theme": "laptop", "beneficiary": "dawn"}]),
        ("keep the saucepan on the hob", [{"frame": "PLACING", "theme": "saucepan", "goal": "hob"}]),
        (
            "take the eggs out of the fridge and keep them on the worktop",
            [
                {"frame": "TAKING", "theme": "eggs", "source": "fridge_freezer"},
                {"frame": "PLACING", "theme": "eggs", "goal": "low_worktop"},
            ],
        ),
    ],
)
def test_scots_and_texting_spellings_and_keep(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "callum") == frames


@pytest.mark.parametrize(
    ("text", "word"),
    [("is possible to bring ladder", "ladder"), ("bring me ma phone charger", "phone charger")],
)
def test_learners_politeness_leaves_the_missing_thing_named(flat: Vocabulary, text: str, word: str) -> None:
    result = understand(text, flat, speaker="tomasz")
    assert not result.accepted
    assert f"no '{word}'" in result.reason
