"""Text to understanding: normalise, parse against the grammar, build frames, derive and check goals.

:func:`understand` never raises for what a user says: a command it cannot take comes back with
``accepted=False``, no goals and a ``reason`` that says what was not understood. Nothing is written anywhere;
adding the goals to a knowledge base is the caller's step (:func:`knic.language.goals.add_goals`), after a
confirmation when the robot's role asks for one (:mod:`knic.language.dialogue`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from core.errors import LanguageError
from knic.language.frames import CommandFrame, build_frames
from knic.language.goals import frames_to_goals
from knic.language.grammar import Grammar, command_grammar, grammar_words
from knic.language.parser import ParseFailure, Parser
from knic.language.vocabulary import Vocabulary, normalize
from knowledge_base import Fact

if TYPE_CHECKING:
    from knic.language.speech import Transcript

DEFAULT_SPEAKER = "annie"


@dataclass(frozen=True)
class Understanding:
    """What a command meant, or why it was not taken.

    Attributes:
        text: the command as given (typed or recognised).
        frames: the understood actions; empty when parsing failed.
        goals: the PDDL goals to add, already checked against the domain; empty when not accepted.
        accepted: True when the command parsed and every goal is valid.
        reason: for a rejected command, the one-line reply saying what was not understood; else "".
        speaker: the person symbol "me" stood for.
    """

    text: str
    frames: tuple[CommandFrame, ...] = ()
    goals: tuple[Fact, ...] = ()
    accepted: bool = False
    reason: str = ""
    speaker: str = DEFAULT_SPEAKER
    extra: dict[str, Any] = field(default_factory=dict, compare=False)

    def to_dict(self) -> dict[str, Any]:
        """The JSON form printed by ``knic goal --json``.

        Keys: text, frames, goals (PDDL strings), accepted, reason (only when rejected), and ``extra``'s keys.
        """
        data: dict[str, Any] = {
            "text": self.text,
            "frames": [f.to_dict() for f in self.frames],
            "goals": [str(g) for g in self.goals],
            "accepted": self.accepted,
        }
        if not self.accepted:
            data["reason"] = self.reason
        data.update(self.extra)
        return data


@lru_cache(maxsize=4)
def default_grammar() -> Grammar:
    """The ERL command grammar (built once)."""
    return command_grammar()


def understand(
    text: str, vocabulary: Vocabulary, *, speaker: str = DEFAULT_SPEAKER, grammar: Grammar | None = None
) -> Understanding:
    """Understand one command (up to three chained actions) against a world's vocabulary.

    Args:
        text: the command, typed or recognised ("Bring me my glasses, please").
        vocabulary: the world's spoken names (see :meth:`Vocabulary.from_knowledge_base`).
        speaker: the person symbol that "me" stands for.
        grammar: the command grammar; default :func:`default_grammar`.

    Returns:
        An :class:`Understanding`; rejected commands have ``accepted=False`` and a ``reason``.
    """
    grammar = grammar or default_grammar()
    tokens = normalize(text).split()
    parsed = Parser(grammar, vocabulary).parse(tokens)
    if isinstance(parsed, ParseFailure):
        reason = parsed.reason(vocabulary, grammar_words(grammar))
        return Understanding(text, reason=reason, speaker=speaker)
    try:
        frames = build_frames(parsed, vocabulary)
    except LanguageError as exc:
        return Understanding(text, reason=str(exc), speaker=speaker)
    try:
        goals = frames_to_goals(frames, vocabulary, speaker=speaker)
    except LanguageError as exc:
        return Understanding(text, tuple(frames), reason=str(exc), speaker=speaker)
    return Understanding(text, tuple(frames), tuple(goals), accepted=True, speaker=speaker)


def understand_transcript(
    transcript: Transcript,
    vocabulary: Vocabulary,
    *,
    speaker: str = DEFAULT_SPEAKER,
    grammar: Grammar | None = None,
) -> Understanding:
    """Understand what the recogniser heard; speech outside the grammar is rejected, never forced onto one.

    The result's ``extra`` carries ``transcript`` (the words heard) and ``audio`` (duration and decoding
    time), which appear in its JSON form.
    """
    extra = {
        "transcript": transcript.text,
        "audio": {"duration_s": round(transcript.duration, 3), "decode_ms": round(transcript.decode_ms, 1)},
    }
    if not transcript.text or not transcript.in_grammar:
        heard = f" (heard: '{transcript.text}')" if transcript.text else ""
        reason = f"the speech matched no command{heard}"
        return Understanding(transcript.text, reason=reason, speaker=speaker, extra=extra)
    result = understand(transcript.text, vocabulary, speaker=speaker, grammar=grammar)
    return Understanding(
        result.text, result.frames, result.goals, result.accepted, result.reason, result.speaker, extra
    )
