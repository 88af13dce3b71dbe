"""Spoken yes/no answers (the semi-autonomous role's confirmation) and the answer grammar."""

from __future__ import annotations

from pathlib import Path

import pytest

from knic.language.fsg import answer_graph
from knic.language.speech import AnswerRecognizer

ANSWERS = Path(__file__).resolve().parents[1] / "fixtures" / "speech_answers"


@pytest.fixture(scope="module")
def recognizer() -> AnswerRecognizer:
    return AnswerRecognizer()


@pytest.mark.parametrize(
    ("name", "heard"),
    [
        ("answer_001.wav", "yes"),  # "yes"
        ("answer_015.wav", "yes please"),
        ("answer_029.wav", "no"),  # "nope"
        ("answer_050.wav", "negative"),
        ("answer_064.wav", ""),  # "what is the time": not an answer
        ("answer_071.wav", ""),  # "bring me the cup"
    ],
)
def test_answers_are_heard_and_other_speech_is_no_answer(
    recognizer: AnswerRecognizer, name: str, heard: str
) -> None:
    assert recognizer.recognize(ANSWERS / name) == heard


def test_the_answer_graph_has_no_empty_path_and_fillers_need_three_words() -> None:
    graph = answer_graph(["yes", "no"], ["tea", "cup"], 0.001)
    text = graph.to_fsg("answer")
    assert "NUM_STATES 7" in text and "FINAL_STATE 3" in text
    into_final = {(s, w) for s, d, _, w in graph.transitions if d == graph.final}
    assert (graph.start, "yes") in into_final and (graph.start, "tea") not in into_final
    filler_states = {d for s, d, _, w in graph.transitions if w == "tea" and s == graph.start}
    assert not any(s in filler_states and d == graph.final for s, d, _, _ in graph.transitions)
    assert all(w for _, _, _, w in graph.transitions)  # epsilon-free


def test_an_answer_is_heard_whatever_came_before(recognizer: AnswerRecognizer) -> None:
    fixtures = Path(__file__).resolve().parents[1] / "integration" / "fixtures"
    yes, no = fixtures / "answer_yes.wav", fixtures / "answer_no.wav"
    assert [recognizer.recognize(f) for f in (yes, yes, no, yes, yes)] == ["yes", "yes", "no", "yes", "yes"]
