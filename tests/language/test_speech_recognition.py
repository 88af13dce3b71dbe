"""Recognition of a few committed WAV files (few, for speed; the full set is a benchmark)."""

from __future__ import annotations

import pytest

from knic.language.speech import Recognizer
from knic.language.understanding import default_grammar, understand_transcript
from knic.language.vocabulary import Vocabulary

from .conftest import SPEECH_FIXTURES


@pytest.fixture(scope="module")
def recognizer(vocabulary: Vocabulary) -> Recognizer:
    return Recognizer(default_grammar(), vocabulary)


@pytest.mark.parametrize(
    ("name", "words", "goals"),
    [
        ("cmd_011.wav", "bring me my glasses", ["(has annie glasses)"]),
        ("cmd_036.wav", "switch on the left light", ["(light_on bedroom_left_light)"]),
        ("cmd_050.wav", "locate the tablet and bring it to me", ["(reported tablet)", "(has annie tablet)"]),
    ],
)
def test_commands_are_recognised_word_for_word(
    recognizer: Recognizer, vocabulary: Vocabulary, name: str, words: str, goals: list[str]
) -> None:
    transcript = recognizer.recognize(SPEECH_FIXTURES / name)
    assert transcript.text == words and transcript.in_grammar
    result = understand_transcript(transcript, vocabulary)
    assert result.accepted and [str(g) for g in result.goals] == goals


def test_speech_outside_the_grammar_is_rejected(recognizer: Recognizer, vocabulary: Vocabulary) -> None:
    transcript = recognizer.recognize(SPEECH_FIXTURES / "oog_063.wav")  # "what is the weather like today"
    result = understand_transcript(transcript, vocabulary)
    assert not result.accepted and result.goals == ()
    assert "matched no command" in result.reason or "understand" in result.reason


def test_decoding_does_not_depend_on_what_came_before(recognizer: Recognizer) -> None:
    first = recognizer.recognize(SPEECH_FIXTURES / "cmd_011.wav")
    recognizer.recognize(SPEECH_FIXTURES / "oog_063.wav")
    again = recognizer.recognize(SPEECH_FIXTURES / "cmd_011.wav")
    assert (first.text, first.score) == (again.text, again.score)


def test_the_recogniser_knows_every_word_of_the_grammar(recognizer: Recognizer) -> None:
    assert "public <utterance>" in recognizer.jsgf and "<filler>" in recognizer.jsgf
    assert "glasses" in recognizer.graph.words()
    assert all(" " not in w for w in recognizer.unknown_words)
