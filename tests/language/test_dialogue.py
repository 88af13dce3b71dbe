"""Dialogue: repeating back, yes/no confirmation, and its refusal to act without a clear yes."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from knic.language import understand
from knic.language.dialogue import YES_NO_GRAMMAR, Dialogue, PrintVoice, parse_answer, repeat_back
from knic.language.vocabulary import Vocabulary


class RecordingVoice:
    def __init__(self) -> None:
        self.said: list[str] = []

    def say(self, sentence: str) -> None:
        self.said.append(sentence)


def answers(*replies: str | None) -> Iterator[str | None]:
    yield from replies


def test_parse_answer() -> None:
    assert parse_answer("Yes, please") is True
    assert parse_answer("yeah do it") is True
    assert parse_answer("no") is False and parse_answer("nope, cancel that") is False
    assert parse_answer("maybe later") is None and parse_answer("yes no") is None
    assert "yes" in YES_NO_GRAMMAR and "public <answer>" in YES_NO_GRAMMAR


def test_repeat_back(vocabulary: Vocabulary) -> None:
    chained = understand("locate the tablet and bring it to me", vocabulary)
    assert (
        repeat_back(chained, vocabulary)
        == "You asked me to find the tablet and then bring the tablet to you."
    )
    lights = understand("turn off all the lights", vocabulary)
    assert repeat_back(lights, vocabulary) == "You asked me to switch off the lights."
    rejected = understand("bring me the banana", vocabulary)
    assert repeat_back(rejected, vocabulary).startswith(
        "Sorry, I did not understand. There is no 'banana' here"
    )


def test_an_ambiguous_command_is_answered_with_a_question(vocabulary: Vocabulary) -> None:
    result = understand("switch on the light", vocabulary)
    assert not result.accepted and result.goals == ()
    said = repeat_back(result, vocabulary)
    assert said.startswith("Which light do you mean:") and said.endswith("?")
    assert "left light" in said and "hallway light" in said


def test_confirmation_yes_no_and_silence(vocabulary: Vocabulary) -> None:
    command = understand("bring me my glasses", vocabulary)
    for replies, expected in [
        (("yes",), True),
        (("no",), False),
        (("hmm", "yes"), True),
        ((None, None), False),
    ]:
        voice = RecordingVoice()
        listen = answers(*replies).__next__
        assert Dialogue(listen, voice=voice, vocabulary=vocabulary).confirm(command) is expected
        assert voice.said[0] == "You asked me to bring the reading glasses to you. Is that right?"


def test_a_rejected_command_is_never_confirmed(vocabulary: Vocabulary) -> None:
    voice = RecordingVoice()
    asked: list[int] = []

    def listen() -> str:
        asked.append(1)
        return "yes"

    dialogue = Dialogue(listen, voice=voice)
    assert dialogue.confirm(understand("dance for me", vocabulary)) is False
    assert asked == [] and voice.said[0].startswith("Sorry")


def test_print_voice(capsys: pytest.CaptureFixture[str]) -> None:
    PrintVoice().say("Hello Annie.")
    assert capsys.readouterr().out == "robot: Hello Annie.\n"
