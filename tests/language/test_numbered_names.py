"""Names as PDDL problems written elsewhere give them (``tests/fixtures/language/numbered/numbered.pddl``, no
lexicon): digits run together with a name are said apart ("cup1" is "cup one"), so "the cup" asks which of
the numbered cups, "the second cup" and "cup1" name one, and "the cups" are both; ordinals written with
digits are words ("the 2nd lamp") (``knic.language.decimals.digits_apart``)."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary, normalize
from knic.language.world import read_vocabulary

from .conftest import frames_read

PROBLEM = "tests/fixtures/language/numbered/numbered.pddl"


@pytest.fixture(scope="module")
def numbered() -> Vocabulary:
    return read_vocabulary(problem=PROBLEM)


@pytest.mark.parametrize(
    ("typed", "read"),
    [
        ("cup1", "cup one"),
        ("bring me sofa2", "bring me sofa two"),
        ("the 2nd lamp", "the second lamp"),
        ("the 3RD cup", "the third cup"),
        ("dim it to 0.5", "dim it to fifty percent"),
        ("room 101", "room 101"),
    ],
)
def test_digits_run_together_with_letters_are_said_apart(typed: str, read: str) -> None:
    assert normalize(typed) == read


def test_a_numbered_things_kind_asks_which(numbered: Vocabulary) -> None:
    result = understand("bring me the cup", numbered, speaker="alice")
    assert not result.accepted and "cup one" in result.question and "cup two" in result.question


@pytest.mark.parametrize(
    ("text", "theme"),
    [("bring me cup1", "cup1"), ("bring me cup 2", "cup2"), ("bring me the second cup", "cup2")],
)
def test_a_numbered_thing_said_by_its_number_is_that_one(numbered: Vocabulary, text: str, theme: str) -> None:
    assert frames_read(numbered, text, "alice") == [
        {"frame": "BRINGING", "theme": theme, "beneficiary": "me"}
    ]


def test_numbered_things_in_the_plural_are_all_of_them(numbered: Vocabulary) -> None:
    frames = frames_read(numbered, "bring me the cups", "alice")
    assert sorted(f["theme"] for f in frames) == ["cup1", "cup2"]


def test_other_names_of_the_problem_are_read_as_said(numbered: Vocabulary) -> None:
    assert frames_read(numbered, "turn on the 2nd lamp", "alice") == [
        {"frame": "OPERATING", "device": "lamp_02", "state": "on"}
    ]
    assert frames_read(numbered, "go to sofa 2", "alice") == [{"frame": "MOTION", "goal": "sofa2"}]
    assert frames_read(numbered, "put the red mug on the kitchen table", "alice") == [
        {"frame": "PLACING", "theme": "red-mug", "goal": "kitchen-table"}
    ]
    assert frames_read(numbered, "set the dimmer to half", "alice") == [
        {"frame": "OPERATING", "device": "dimmer-1", "state": "50"}
    ]


@pytest.mark.parametrize(
    ("text", "frame"),
    [
        ("go to the living room", {"frame": "MOTION", "goal": "livingroom"}),
        ("go to the livingroom", {"frame": "MOTION", "goal": "livingroom"}),
        ("bring me the blue bottle", {"frame": "BRINGING", "theme": "bluebottle", "beneficiary": "me"}),
        (
            "put the red mug on the kitchen counter",
            {"frame": "PLACING", "theme": "red-mug", "goal": "kitchencounter"},
        ),
    ],
)
def test_camel_cased_symbols_are_said_as_words(
    numbered: Vocabulary, text: str, frame: dict[str, str]
) -> None:
    assert frames_read(numbered, text, "alice") == [frame]


def test_the_knowledge_bases_vocabulary_says_them_as_words_too() -> None:
    from knic.language.world import load_world

    _, vocabulary = load_world(problem=PROBLEM)
    assert {"living room", "blue bottle", "ceiling light"} <= {t.phrase for t in vocabulary.terms}
    assert frames_read(vocabulary, "turn on the ceiling light", "alice") == [
        {"frame": "OPERATING", "device": "ceilinglight", "state": "on"}
    ]
