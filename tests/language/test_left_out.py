"""Things left out of all of a kind, whichever word leaves them out: "except", "apart from", "excluding"."""

from __future__ import annotations

import pytest

from knic.language.understanding import understand
from knic.language.vocabulary import Vocabulary


@pytest.mark.parametrize("word", ["except", "apart from", "excluding", "other than"])
def test_the_one_left_out_stays_as_it_is(vocabulary: Vocabulary, word: str) -> None:
    result = understand(f"switch off all the lights {word} the hallway one", vocabulary)
    goals = [str(g) for g in result.goals]
    assert result.accepted and "(light_off bedroom_left_light)" in goals
    assert not any("hallway_light" in g for g in goals)
