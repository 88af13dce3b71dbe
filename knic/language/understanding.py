"""Text to understanding: read the command (:mod:`knic.language.reader`), derive and check goals.

:func:`understand` never raises for what a user says: a command it cannot take comes back with
``accepted=False``, no goals and a ``reason`` that says what was not understood. Nothing is written anywhere;
adding the goals to a knowledge base is the caller's step (:func:`knic.language.goals.add_goals`), after a
confirmation when the robot's role asks for one (:mod:`knic.language.dialogue`).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from core.errors import LanguageError
from knic.language.askedfor import returned_read
from knic.language.commands import command_grammar
from knic.language.complaints import dark_read
from knic.language.frames import CommandFrame
from knic.language.goals import frames_to_goals, hints
from knic.language.grammar import Grammar
from knic.language.mixed import mixed_said
from knic.language.owned import owned_read
from knic.language.plainspoken import lacked, plainly_said
from knic.language.reader import AmbiguityError, Reader
from knic.language.roundabout import roundabout_said
from knic.language.vocabulary import Vocabulary
from knowledge_base import Fact

if TYPE_CHECKING:
    from knic.language.audio import Transcript

DEFAULT_SPEAKER = "annie"
#: the most words of one command that are read: the longest of the text dev sets' 4,900 commands has 44, and a
#: command of thousands of words (pasted text, a runaway recogniser) would take the reader minutes
MAX_WORDS = 150
#: a number said below zero ("set the dimmer to -10", "minus twenty"): no level, and its digits alone would
#: be read as one (10); a dash with a space after it is a dash ("bench lamp 2 - 35%"); the weather said
#: beside a request ("..., it's minus twenty out", "-5 degrees outside") is no level
NEGATIVE = re.compile(
    r"(?:(?<![\w.-])-(?=\d)|\b(?:minus|negative)\s+)(\d+|one|two|three|four|five|six|seven|eight|nine|ten|"
    r"eleven|twelve|fifteen|twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred)\b"
    r"(?!\s+(?:degrees|out|outside|today|tonight|this\s+morning|with\s+the\s+wind\s+chill)\b)",
    re.IGNORECASE,
)


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
        question: for an ambiguous command, the question to ask back ("which table do you mean: ...?").
        hints: where the command says things are, as ``possibly_at`` assumptions for the planner's search
            (see :func:`knic.language.goals.hints`); not goals.
        notes: what the goals do differently from what was said, to tell the speaker (a level the world
            lacks set to the nearest one it has).
    """

    text: str
    frames: tuple[CommandFrame, ...] = ()
    goals: tuple[Fact, ...] = ()
    accepted: bool = False
    reason: str = ""
    speaker: str = DEFAULT_SPEAKER
    extra: dict[str, Any] = field(default_factory=dict, compare=False)
    question: str = ""
    hints: tuple[Fact, ...] = ()
    notes: tuple[str, ...] = ()

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
        if self.question:
            data["question"] = self.question
        if self.hints:
            data["hints"] = [str(h) for h in self.hints]
        if self.notes:
            data["notes"] = list(self.notes)
        data.update(self.extra)
        return data


@lru_cache(maxsize=4)
def default_grammar() -> Grammar:
    """The ERL command grammar (built once)."""
    return command_grammar()


@lru_cache(maxsize=8)
def reader_for(vocabulary: Vocabulary) -> Reader:
    """The reader of a vocabulary (built once per vocabulary object)."""
    return Reader(vocabulary)


def reading_of(reader: Reader) -> Callable[[str], object]:
    """What a reader reads a text as (its frames as data; None when it does not read it, or finds it
    ambiguous)."""

    def reading(text: str) -> object:
        try:
            return [frame.to_dict() for frame in reader.read(text).frames]
        except LanguageError:
            return None

    return reading


#: texts a :func:`reader_check` remembers whether it read (then it forgets them all and starts again)
READS_KEPT = 4096


def reader_check(reader: Reader) -> Callable[[str], bool]:
    """Whether a reader reads a text, or understands it up to a question back. Each text's answer is
    remembered (reading depends on the text and the world only): a spoken command's recogniser asks of the
    same transcript several times (its n-best list, Whisper's beam, the candidates judged: on
    ``speech_people3/dev`` 14 readings per utterance, 3.7 ms each, of which 39% had been read already)."""
    known: dict[str, bool] = {}

    def reads(text: str) -> bool:
        if text in known:
            return known[text]
        if len(known) >= READS_KEPT:
            known.clear()
        try:
            reader.read(text)
            found = True
        except AmbiguityError:
            found = True
        except LanguageError:
            found = False
        known[text] = found
        return found

    return reads


def understand(
    text: str, vocabulary: Vocabulary, *, speaker: str = DEFAULT_SPEAKER, grammar: Grammar | None = None
) -> Understanding:
    """Understand one command (up to three chained actions) against a world's vocabulary.

    Args:
        text: the command, typed or recognised ("Could you please bring me my glasses?").
        vocabulary: the world's spoken names (see :meth:`Vocabulary.from_knowledge_base`).
        speaker: the person symbol that "me" stands for.
        grammar: unused (the reader reads the command language's phrase tables); kept for callers.

    Returns:
        An :class:`Understanding`; rejected commands have ``accepted=False`` and a ``reason``; ambiguous ones
        also a ``question``.
    """
    del grammar
    if len(text.split()) > MAX_WORDS:
        reason = f"the command is {len(text.split())} words long: I read at most {MAX_WORDS}; say it in parts"
        return Understanding(text, reason=reason, speaker=speaker)
    if negative := NEGATIVE.search(text):
        reason = f"'{negative.group(0)}' is below zero: a level goes from 0 to 100 percent"
        return Understanding(text, reason=reason, speaker=speaker)
    reader = reader_for(vocabulary)

    def unknown(word: str) -> bool:  # a word neither the world nor the command language knows
        return [c.kind for c in reader.chunks([word])] == ["unknown"]

    try:
        # "... light period", "mis espejuelos", "86 the light": said in English first (mixed.py); "it's dark
        # in the study": its lights; "hoodie from my bed": the bed in the speaker's own room; "three zero
        # percent", "do the light out": said plainly (plainspoken.py); "below in the boot room", "can I get
        # the lamp on", "the bedroom of Tadhg" (roundabout.py)
        said = returned_read(mixed_said(text, reader.language, vocabulary), vocabulary)  # askedfor.py
        said = plainly_said(roundabout_said(said, vocabulary, unknown), vocabulary, unknown)
        reading = reader.read(dark_read(owned_read(said, vocabulary, speaker)))
    except AmbiguityError as exc:
        question = str(exc)[:1].upper() + str(exc)[1:]
        return Understanding(text, reason=f"ambiguous: {exc}", speaker=speaker, question=question)
    except LanguageError as exc:
        word = lacked(text, lambda w: next((c.kind for c in reader.chunks([w])), ""))
        if word is not None and " what? I heard no " in str(exc):  # "bring me a pop": 'pop' is no thing here
            reason = f"there is no '{word}' here: this world has nothing called that"
            return Understanding(text, reason=reason, speaker=speaker)
        return Understanding(text, reason=str(exc), speaker=speaker)
    frames = tuple(reading.frames)
    notes: list[str] = [
        f"the {vocabulary.phrase_of(frames[i]['goal'])} on the way is no goal I can keep: I go to the "
        f"{vocabulary.phrase_of(frames[i + 1]['goal'])}"
        for i in sorted(reading.waypoints)
        if i + 1 < len(frames) and frames[i].kind == frames[i + 1].kind == "MOTION"
    ]
    try:
        goals = frames_to_goals(frames, vocabulary, speaker=speaker, waypoints=reading.waypoints, notes=notes)
    except LanguageError as exc:
        return Understanding(text, frames, reason=str(exc), speaker=speaker)
    if not goals:
        return Understanding(text, frames, reason="the command asks for nothing to achieve", speaker=speaker)
    return Understanding(
        text,
        frames,
        tuple(goals),
        accepted=True,
        speaker=speaker,
        hints=tuple(hints(frames, vocabulary)),
        notes=tuple(notes),
    )


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
        if transcript.text:  # what the reader finds wrong with the words heard, when it refuses them too
            read = understand(transcript.text, vocabulary, speaker=speaker, grammar=grammar)
            if not read.accepted and not read.question and read.reason:
                heard = f" (heard: '{transcript.text}'; {read.reason})"
        reason = f"the speech matched no command{heard}"
        return Understanding(transcript.text, reason=reason, speaker=speaker, extra=extra)
    result = understand(transcript.text, vocabulary, speaker=speaker, grammar=grammar)
    return Understanding(
        result.text,
        result.frames,
        result.goals,
        result.accepted,
        result.reason,
        result.speaker,
        extra,
        result.question,
        result.hints,
    )
