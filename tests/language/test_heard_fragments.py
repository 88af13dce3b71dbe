"""Fragments a recogniser makes of other speech are not read as terse commands: a room said with "a" is no
room of the house to go to ("i would love a holiday by the sea", heard "i would love a hall it ...")."""

from __future__ import annotations

import pytest

from knic.language.understanding import understand
from knic.language.vocabulary import Vocabulary


@pytest.mark.parametrize("text", ["a hall", "an office please", "i would love a hall it that my the seek"])
def test_a_room_said_with_a_is_no_trip(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and result.goals == ()


@pytest.mark.parametrize(
    ("text", "goal"), [("the hall please", "(robot_at r2d2 hallway)"), ("kitchen", "(robot_at r2d2 kitchen)")]
)
def test_a_room_said_alone_is_still_a_trip(vocabulary: Vocabulary, text: str, goal: str) -> None:
    result = understand(text, vocabulary)
    assert result.accepted and [str(g) for g in result.goals] == [goal]
