"""Dialogue around a command: repeat back what was understood, ask for yes or no, speak or print.

ERL practice: the robot repeats the request and, in the semi-autonomous role, waits for a yes or no before
the goals reach the knowledge base. :class:`Dialogue` does that with two pluggable ends: a :class:`Voice` that
says things (:class:`EspeakVoice` when ``espeak-ng`` is installed, else :class:`PrintVoice`) and a listener
that returns the user's answer as text (typed, or a transcript from :mod:`knic.language.speech`; the module
provides :data:`YES_NO_GRAMMAR` for a recogniser restricted to answers).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from collections.abc import Callable
from typing import Protocol, TextIO

from knic.language.answers import NO_WORDS, YES_NO_GRAMMAR, YES_WORDS, parse_answer
from knic.language.frames import SPEAKER, CommandFrame
from knic.language.understanding import Understanding

__all__ = [
    "NO_WORDS",
    "YES_NO_GRAMMAR",
    "YES_WORDS",
    "Dialogue",
    "EspeakVoice",
    "PrintVoice",
    "Voice",
    "default_voice",
    "describe",
    "parse_answer",
    "repeat_back",
]
from knic.language.vocabulary import Vocabulary


class Voice(Protocol):
    """Something that says a sentence to the user; returns when it has been said."""

    def say(self, sentence: str) -> None:
        """Say one sentence."""


class PrintVoice:
    """Prints what the robot says, prefixed with ``robot:``, to a stream (default stdout)."""

    def __init__(self, stream: TextIO | None = None):
        self.stream = stream

    def say(self, sentence: str) -> None:
        """Print one sentence."""
        print(f"robot: {sentence}", file=self.stream or sys.stdout)


class EspeakVoice:
    """Speaks through the ``espeak-ng`` program (blocking until it finished); prints when it fails."""

    def __init__(self, executable: str, voice: str = "en-us", fallback: Voice | None = None):
        self.executable = executable
        self.voice = voice
        self.fallback = fallback or PrintVoice()

    def say(self, sentence: str) -> None:
        """Speak one sentence; on any espeak-ng failure print it instead."""
        try:
            subprocess.run(
                [self.executable, "-v", self.voice, sentence], check=True, capture_output=True, timeout=30
            )
        except (OSError, subprocess.SubprocessError):
            self.fallback.say(sentence)


def default_voice() -> Voice:
    """:class:`EspeakVoice` when ``espeak-ng`` is on PATH, else :class:`PrintVoice`."""
    executable = shutil.which("espeak-ng")
    return EspeakVoice(executable) if executable else PrintVoice()


def describe(frame: CommandFrame, vocabulary: Vocabulary | None = None) -> str:
    """One frame as an English clause for repeating back ("bring the reading glasses to you")."""

    def name(role: str) -> str:
        value = frame.get(role) or ""
        if value == SPEAKER:
            return "you"
        spoken = vocabulary.phrase_of(value) if vocabulary is not None else value.replace("_", " ")
        return spoken if frame.kind == "OPERATING" or role == "beneficiary" else f"the {spoken}"

    kind = frame.kind
    if kind == "SEARCHING":
        where = f" in {name('ground')}" if frame.get("ground") else ""
        return f"find {name('theme')}{where}"
    if kind in ("BRINGING", "PLACING"):
        verb = "bring" if kind == "BRINGING" else "put"
        source = f" from {name('source')}" if frame.get("source") else ""
        target = f"to {name('beneficiary')}" if frame.get("beneficiary") else f"to {name('goal')}"
        if kind == "PLACING":
            target = f"on {name('goal')}"
        return f"{verb} {name('theme')}{source} {target}"
    if kind == "TAKING":
        source = f" from {name('source')}" if frame.get("source") else ""
        return f"pick up {name('theme')}{source}"
    if kind == "ACCOMPANYING":
        return f"take {name('theme')} to {name('goal')}"
    if kind == "MOTION":
        return f"go to {name('goal')}"
    state = frame.get("state") or ""
    if state.isdigit():
        return f"set the {name('device')} to {state} percent"
    if state in ("on", "off"):
        return f"switch {state} the {name('device')}"
    verb = {"half-open": "half-open", "open": "open"}.get(state, "close")
    return f"{verb} the {name('device')}"


def repeat_back(understanding: Understanding, vocabulary: Vocabulary | None = None) -> str:
    """The sentence the robot says after a command: what it will do, or what it did not understand."""
    if understanding.question:
        return understanding.question
    if not understanding.accepted:
        return f"Sorry, I did not understand. {understanding.reason[:1].upper()}{understanding.reason[1:]}."
    clauses = [describe(f, vocabulary) for f in understanding.frames]
    said = clauses[0] if len(clauses) == 1 else ", ".join(clauses[:-1]) + " and then " + clauses[-1]
    return f"You asked me to {said}."


class Dialogue:
    """Repeats commands back and, when asked to, waits for a yes or no.

    Args:
        voice: how the robot speaks (default :func:`default_voice`).
        listen: returns the user's next answer as text (typed or recognised); None means no answer came.
        vocabulary: for spoken names in replies.
        max_asks: how often to ask again after an answer that is neither yes nor no.
    """

    def __init__(
        self,
        listen: Callable[[], str | None],
        *,
        voice: Voice | None = None,
        vocabulary: Vocabulary | None = None,
        max_asks: int = 2,
    ):
        self.listen = listen
        self.voice = voice or default_voice()
        self.vocabulary = vocabulary
        self.max_asks = max_asks

    def acknowledge(self, understanding: Understanding) -> None:
        """Say what was understood (or why not) without waiting for an answer (autonomous roles)."""
        self.voice.say(repeat_back(understanding, self.vocabulary))

    def confirm(self, understanding: Understanding) -> bool:
        """Repeat the command back and wait for yes or no (semi-autonomous role).

        Returns:
            True only for an accepted command confirmed with yes; False for no, for a rejected command, and
            when no clear answer came after ``max_asks`` questions (nothing is done without a clear yes).
        """
        if not understanding.accepted:
            self.acknowledge(understanding)
            return False
        return self.ask(repeat_back(understanding, self.vocabulary) + " Is that right?")

    def ask(self, question: str) -> bool:
        """Ask a yes/no question and wait for a clear answer, asking again up to ``max_asks`` times.

        Returns:
            True for yes; False for no, and when no clear answer came.
        """
        self.voice.say(question)
        for attempt in range(self.max_asks):
            answer = self.listen()
            verdict = parse_answer(answer) if answer else None
            if verdict is not None:
                self.voice.say("Okay, I will do it." if verdict else "Okay, I will not do it.")
                return verdict
            if attempt + 1 < self.max_asks:
                self.voice.say("Please answer yes or no.")
        self.voice.say("I did not get an answer, so I will not do it.")
        return False
