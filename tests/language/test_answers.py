"""Spoken yes/no answers (the semi-autonomous role's confirmation) and the answer grammar."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from core.errors import LanguageError
from knic.language.answers import load_answer_phrases, parse_answer
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
    graph = answer_graph(["yes", "that's wrong"], ["tea", "cup"], 0.001, openers=["well"])
    into_final = {(s, w) for s, d, _, w in graph.transitions if d == graph.final}
    assert (graph.start, "yes") in into_final and (graph.start, "tea") not in into_final
    assert (graph.start, "well") not in into_final  # an opener alone is no answer
    filler_states = {d for s, d, _, w in graph.transitions if w == "tea" and s == graph.start}
    assert not any(s in filler_states and d == graph.final for s, d, _, _ in graph.transitions)
    assert all(w for _, _, _, w in graph.transitions)  # epsilon-free
    # a phrase of two words is a chain: "that's" leads to a state whose "wrong" ends the answer
    middle = {d for s, d, _, w in graph.transitions if s == graph.start and w == "that's"}
    assert any(s in middle and w == "wrong" and d == graph.final for s, d, _, w in graph.transitions)
    assert f"NUM_STATES {graph.num_states}" in graph.to_fsg("answer")


@pytest.mark.parametrize(
    ("text", "verdict"),
    [
        ("that's right", True),
        ("Yes, that is correct.", True),
        ("of course", True),
        ("well, sure", True),
        ("yes please, thank you", True),
        ("No, that's wrong.", False),
        ("not quite", False),
        ("that is not right", False),  # the longer phrase wins over "right"
        ("absolutely not", False),  # ... and over "absolutely"
        ("nope", False),
        ("I'm not sure", None),
        ("yes no", None),
        ("bring me the cup", None),
    ],
)
def test_general_affirmatives_and_negatives_are_read(text: str, verdict: bool | None) -> None:
    assert parse_answer(text) is verdict


def test_the_answer_lists_are_checked(tmp_path: Path) -> None:
    bad = tmp_path / "answers.yaml"
    bad.write_text('"yes": [sure]\n"no": [sure]\nunsure: []\nopeners: []\nclosers: []\n', encoding="utf-8")
    with pytest.raises(LanguageError, match="both yes and no: sure"):
        load_answer_phrases(bad)
    bad.write_text('"yes": true\n', encoding="utf-8")
    with pytest.raises(LanguageError, match="'yes' must be a list"):
        load_answer_phrases(bad)


def test_spoken_multi_word_answers_of_the_development_set(recognizer: AnswerRecognizer) -> None:
    folder = ANSWERS.parent / "speech_answers_dev"
    entries = json.loads((folder / "gold.json").read_text(encoding="utf-8"))["utterances"]
    got = {}
    for entry in entries:
        heard = recognizer.recognize(folder / entry["file"])
        verdict = parse_answer(heard) if heard else None
        got[entry["file"]] = None if verdict is None else ("yes" if verdict else "no")
    right = sum(got[e["file"]] == e["answer"] for e in entries)
    assert right >= len(entries) - 2, got


def test_an_answer_is_heard_whatever_came_before(recognizer: AnswerRecognizer) -> None:
    fixtures = Path(__file__).resolve().parents[1] / "integration" / "fixtures"
    yes, no = fixtures / "answer_yes.wav", fixtures / "answer_no.wav"
    assert [recognizer.recognize(f) for f in (yes, yes, no, yes, yes)] == ["yes", "yes", "no", "yes", "yes"]
