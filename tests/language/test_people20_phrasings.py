"""Phrasings from the people20 development set (a two-storey hill farmhouse the reader was never tuned on,
``tests/fixtures/language/people20/farmhouse.yaml``) the reader first got wrong:

* general English names (``synonyms.yaml``): "the wireless" for a radio, "a band-aid" for the plasters, "the
  post" or "the mail" for letters, "a pill box" for a pill organiser, "a cookie" for a biscuit (and so the
  biscuit tin), "the den" for a snug; a cloakroom is a downstairs toilet, so "the loo" is the cloakroom where
  the bathroom is another room; a one-word compound name ending in "shelves", "shelf" or "basin" is said by
  that word ("the shelves" for the bookshelves, "the basin" for the washbasin).
"""

from __future__ import annotations

from typing import Any

import pytest

from knic.language.vocabulary import Vocabulary

from .conftest import frames_read

FARMHOUSE = "tests/fixtures/language/people20/farmhouse.yaml"


def _world(file: str) -> Vocabulary:
    """A world file's vocabulary, as the language bench and ``knic goal --world`` read it."""
    from pathlib import Path

    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    path = Path(__file__).resolve().parents[2] / file
    vocabulary: Any = world_vocabulary(str(path), DEFAULT_DOMAIN, None)[0]
    return vocabulary


@pytest.fixture(scope="module")
def farm() -> Vocabulary:
    """The farmhouse's vocabulary."""
    return _world(FARMHOUSE)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "put the wireless on the kitchen table",
            [{"frame": "PLACING", "theme": "radio", "goal": "kitchen_table"}],
        ),
        ("bring me a band-aid", [{"frame": "BRINGING", "theme": "plasters", "beneficiary": "me"}]),
        ("where's my pill box got to", [{"frame": "SEARCHING", "theme": "pill_organiser"}]),
        ("bring me a cookie", [{"frame": "BRINGING", "theme": "biscuit_tin", "beneficiary": "me"}]),
        ("bring me the post", [{"frame": "BRINGING", "theme": "letters", "beneficiary": "me"}]),
        ("turn on the lights in the den", [{"frame": "OPERATING", "device": "snug_lamp", "state": "on"}]),
        ("go to the loo", [{"frame": "MOTION", "goal": "cloakroom"}]),
        ("go to the bathroom", [{"frame": "MOTION", "goal": "bathroom"}]),
        (
            "grab the recipe book from the shelves in the snug",
            [{"frame": "TAKING", "theme": "recipe_book", "source": "bookshelves"}],
        ),
        (
            "fetch the hand soap from the basin",
            [{"frame": "BRINGING", "theme": "hand_soap", "source": "washbasin", "beneficiary": "me"}],
        ),
    ],
)
def test_general_english_names(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "ffion") == frames
