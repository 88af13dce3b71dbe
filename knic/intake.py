"""The goal intake: one door for goals, from text, speech, the command line, ROS 2 or the web view.

A submission is understood (English through :mod:`knic.language`, or PDDL atoms such as
``(object_at glasses bedroom)``), validated against the knowledge base's domain, confirmed when the role asks
for it, and then added in one batch: all of its goals or none. The intake works while the robot runs: it
never blocks. Under a role that confirms, :meth:`GoalIntake.submit` repeats the command back with a question
and returns at once; the answer arrives later through :meth:`GoalIntake.hear` (a recognised utterance, a typed
line, ``--confirm``), and only a clear yes adds the goals.

Lifecycle: construct with the knowledge base, the world's vocabulary and how the robot speaks; call
:meth:`submit`, :meth:`submit_audio` and :meth:`hear` from one thread (the run loop's); read
:attr:`history` for what was submitted and what became of it. Times are the knowledge base's clock
(simulated seconds in a run).
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from core.errors import KnicError, KnowledgeBaseError, LanguageError
from knowledge_base import Fact, KnowledgeBase

if TYPE_CHECKING:
    from knic.language.speech import AnswerRecognizer
    from knic.language.understanding import Understanding
    from knic.language.vocabulary import Vocabulary


class Outcome(enum.Enum):
    """What became of a submission (or of an answer)."""

    ADDED = "added"  # the goals are in the knowledge base
    ASKED = "asked"  # repeated back with a question; waiting for yes or no
    REFUSED = "refused"  # not understood, or invalid for this world; nothing added
    DECLINED = "declined"  # answered no, or no clear answer after asking again; nothing added
    ASKED_AGAIN = "asked_again"  # the answer was neither yes nor no


@dataclass(frozen=True)
class Submission:
    """One command as the intake understood it.

    Attributes:
        text: the command as given (typed, recognised, or PDDL).
        goals: the validated PDDL goals (empty when refused).
        speaker: the person "me" stands for.
        source: provenance source the goals are written with (``user``, ``operator``, ``speech``, ...).
        said: the sentence the robot repeats back ("You asked me to ...").
        understanding: the language result for an English command, None for PDDL.
    """

    text: str
    goals: tuple[Fact, ...]
    speaker: str
    source: str
    said: str
    understanding: Understanding | None = None


@dataclass(frozen=True)
class IntakeReply:
    """The result of :meth:`GoalIntake.submit`, :meth:`~GoalIntake.submit_audio` or :meth:`~GoalIntake.hear`.

    Attributes:
        outcome: see :class:`Outcome`.
        goals: the goals concerned, as PDDL strings.
        reply: what the robot said in response.
        reason: one line saying why, for REFUSED and DECLINED.
    """

    outcome: Outcome
    goals: tuple[str, ...] = ()
    reply: str = ""
    reason: str = ""

    def to_dict(self) -> dict[str, object]:
        """JSON form (for ``--json``, ROS 2 and the web view)."""
        return {
            "outcome": self.outcome.value,
            "goals": list(self.goals),
            "reply": self.reply,
            "reason": self.reason,
        }


@dataclass
class _Pending:
    submission: Submission
    asks: int = 1


@dataclass
class IntakeRecord:
    """One line of :attr:`GoalIntake.history`: a submission and its latest outcome at ``time``."""

    submission: Submission
    outcome: Outcome
    time: float
    reason: str = ""


Recognise = Callable[[str], str]


@dataclass
class GoalIntake:
    """Understands, validates, confirms and adds goals (see the module docstring).

    Attributes:
        kb: the knowledge base the goals go to.
        vocabulary: the world's spoken names (for English commands and replies).
        say: how the robot speaks (a run: the robot's speech through the seam).
        confirm: the role asks for a yes before acting (``Role.confirm_actions``).
        max_asks: how often a question is asked in all before the command is declined.
        recognise_command: WAV path -> transcript of a command (default: pocketsphinx with the n-gram model).
        recognise_answer: WAV path -> transcript of a yes/no answer (default: pocketsphinx answer grammar).
        recognise_plain_answer: the same after the robot asked "Please answer yes or no" (default: the answer
            grammar without its non-answer path; with only ``recognise_answer`` given, that one).
        on_added: called with each submission whose goals were added (after the batch committed).
    """

    kb: KnowledgeBase
    vocabulary: Vocabulary
    say: Callable[[str], None]
    confirm: bool = False
    max_asks: int = 2
    recognise_command: Recognise | None = None
    recognise_answer: Recognise | None = None
    recognise_plain_answer: Recognise | None = None
    on_added: Callable[[Submission], None] | None = None
    history: list[IntakeRecord] = field(default_factory=list)
    _pending: _Pending | None = None
    _model: AnswerRecognizer | None = None

    # ------------------------------------------------------------------ queries

    @property
    def awaiting_answer(self) -> Submission | None:
        """The submission waiting for yes or no, or None."""
        return self._pending.submission if self._pending is not None else None

    # ------------------------------------------------------------------ input

    def submit(self, text: str, *, speaker: str = "annie", source: str = "user") -> IntakeReply:
        """Take one command (English or PDDL atoms); see the module docstring.

        A new command while another waits for its answer replaces it (the old one is declined).
        """
        try:
            submission = self.understand(text, speaker=speaker, source=source)
        except KnicError as exc:
            reason = str(exc)
            reply = f"Sorry, I cannot do that: {reason}."
            self.say(reply)
            self._record(Submission(text, (), speaker, source, reply), Outcome.REFUSED, reason)
            return IntakeReply(Outcome.REFUSED, (), reply, reason)
        if self._pending is not None:
            self._record(self._pending.submission, Outcome.DECLINED, "replaced by a newer command")
            self._pending = None
        if self.confirm:
            question = f"{submission.said} Is that right?"
            self.say(question)
            self._pending = _Pending(submission)
            self._record(submission, Outcome.ASKED)
            return IntakeReply(Outcome.ASKED, _names(submission.goals), question)
        return self._add(submission, submission.said)

    def submit_audio(self, wav: str | Path, *, speaker: str = "annie", source: str = "speech") -> IntakeReply:
        """Recognise a spoken command (or, while a question is open, a spoken answer) and take it."""
        if self._pending is not None:
            # once asked to answer yes or no, the speaker is heard as saying one of the answers
            plain = self._pending.asks > 0
            recognise = self._plain_answer_recogniser() if plain else self._answer_recogniser()
            return self.hear(recognise(str(wav)))
        try:
            text = self._command_recogniser()(str(wav))
        except LanguageError as exc:
            reply = "Sorry, I did not understand."
            self.say(reply)
            return IntakeReply(Outcome.REFUSED, (), reply, str(exc))
        return self.submit(text, speaker=speaker, source=source)

    def hear(self, answer: str | None) -> IntakeReply:
        """An answer to the open question (None: no answer came). Without an open question, nothing."""
        from knic.language.dialogue import parse_answer

        pending = self._pending
        if pending is None:
            return IntakeReply(Outcome.REFUSED, (), "", "no question is open")
        verdict = parse_answer(answer) if answer else None
        if verdict is True:
            self._pending = None
            return self._add(pending.submission, "Okay, I will do it.")
        if verdict is None and pending.asks < self.max_asks:
            pending.asks += 1
            reply = "Please answer yes or no."
            self.say(reply)
            return IntakeReply(Outcome.ASKED_AGAIN, _names(pending.submission.goals), reply)
        self._pending = None
        reason = "answered no" if verdict is False else "no clear yes or no"
        reply = (
            "Okay, I will not do it." if verdict is False else "I did not get an answer, so I will not do it."
        )
        self.say(reply)
        self._record(pending.submission, Outcome.DECLINED, reason)
        return IntakeReply(Outcome.DECLINED, _names(pending.submission.goals), reply, reason)

    # ------------------------------------------------------------------ steps

    def understand(self, text: str, *, speaker: str = "annie", source: str = "user") -> Submission:
        """The validated :class:`Submission` of ``text``; adds nothing.

        Raises:
            LanguageError: an English command was not understood (the reason names what).
            KnowledgeBaseError: a PDDL atom is malformed or invalid for this domain.
        """
        stripped = text.strip()
        if not stripped:
            raise LanguageError("the command is empty")
        if stripped.startswith("("):
            goals = tuple(parse_goals(stripped))
            self.validate(goals)
            said = "You asked me to make " + " and ".join(str(g) for g in goals) + " true."
            return Submission(stripped, goals, speaker, source, said)
        from knic.language.dialogue import repeat_back
        from knic.language.understanding import understand

        result = understand(stripped, self.vocabulary, speaker=speaker)
        if not result.accepted:
            raise LanguageError(f'"{stripped}" not understood: {result.reason}')
        goals = tuple(result.goals) + tuple(g for g in source_goals(result, self.kb) if g not in result.goals)
        self.validate(goals)
        return Submission(stripped, goals, speaker, source, repeat_back(result, self.vocabulary), result)

    def validate(self, goals: tuple[Fact, ...]) -> None:
        """Check goals against the domain and instances without writing (a trial batch that is undone).

        Raises:
            KnowledgeBaseError: the first invalid goal and why.
        """
        try:
            with self.kb.batch():
                for goal in goals:
                    self.kb.add_goal(goal.predicate, *goal.args, source="intake.check")
                raise _Undo
        except _Undo:
            pass

    # ------------------------------------------------------------------ internals

    def _add(self, submission: Submission, reply: str) -> IntakeReply:
        with self.kb.batch():
            for goal in submission.goals:
                self.kb.add_goal(goal.predicate, *goal.args, source=submission.source)
        self.say(reply)
        self._record(submission, Outcome.ADDED)
        if self.on_added is not None:
            self.on_added(submission)
        return IntakeReply(Outcome.ADDED, _names(submission.goals), reply)

    def _record(self, submission: Submission, outcome: Outcome, reason: str = "") -> None:
        self.history.append(IntakeRecord(submission, outcome, self.kb.now(), reason))

    def _command_recogniser(self) -> Recognise:
        if self.recognise_command is None:
            from knic.language.lmspeech import command_recognizer

            recognizer = command_recognizer(self.vocabulary)

            def recognise(wav: str) -> str:
                transcript = recognizer.recognize(wav)
                if not transcript.text or not transcript.in_grammar:
                    heard = f' (heard "{transcript.text}")' if transcript.text else ""
                    raise LanguageError(f"{wav}: no command recognised{heard}")
                return str(transcript.text)

            self.recognise_command = recognise
        return self.recognise_command

    def _answer_recogniser(self) -> Recognise:
        if self.recognise_answer is None:
            recognizer = self._answer_model()
            self.recognise_answer = lambda wav: str(recognizer.recognize(wav))
        return self.recognise_answer

    def _plain_answer_recogniser(self) -> Recognise:
        if self.recognise_plain_answer is None:
            if self.recognise_answer is not None and self._model is None:
                return self.recognise_answer  # a recogniser of the caller's: it hears every answer
            recognizer = self._answer_model()
            self.recognise_plain_answer = lambda wav: str(recognizer.recognize(wav, closed=True))
        return self.recognise_plain_answer

    def _answer_model(self) -> AnswerRecognizer:
        if self._model is None:
            from knic.language.speech import AnswerRecognizer

            self._model = AnswerRecognizer()
        return self._model


def source_goals(understood: Understanding, kb: KnowledgeBase) -> list[Fact]:
    """Goals that keep where a command says to take things from: ``(taken_from ?o ?f)`` for each item to
    bring "from" a piece of furniture ("bring me an apple from the kitchen cabinet"), when the domain has
    ``taken_from``. A source that is a room adds nothing (the item is searched for there first, a hint)."""
    if "taken_from" not in kb.domain.predicates:
        return []
    out: list[Fact] = []
    for frame in understood.frames:
        theme, source = frame.get("theme"), frame.get("source")
        if frame.kind != "BRINGING" or not theme or not source:
            continue
        if kb.type_of(theme) == "item" and kb.type_of(source) == "furniture":
            fact = Fact("taken_from", (theme, source))
            if fact not in out:
                out.append(fact)
    return out


class _Undo(Exception):
    """Raised inside a trial batch to undo it."""


def parse_goals(text: str) -> list[Fact]:
    """PDDL atoms ``"(a x) (b y)"`` as facts.

    Raises:
        KnowledgeBaseError: the text is not one or more PDDL atoms.
    """
    facts: list[Fact] = []
    depth, start = 0, -1
    for i, ch in enumerate(text):
        if ch == "(":
            if depth == 0:
                start = i
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth < 0:
                break
            if depth == 0:
                facts.append(_parse_atom(text[start : i + 1]))
        elif depth == 0 and not ch.isspace():
            raise KnowledgeBaseError(f"goal {text!r}: unexpected {ch!r} at column {i + 1} outside an atom")
    if depth != 0 or not facts:
        raise KnowledgeBaseError(f"goal {text!r} is not a PDDL atom like (object_at glasses bedroom)")
    return facts


def _parse_atom(text: str) -> Fact:
    try:
        return Fact.parse(text)
    except (ValueError, KnicError) as exc:
        raise KnowledgeBaseError(
            f"goal {text!r} is not a PDDL atom like (object_at glasses bedroom): {exc}"
        ) from None


def _names(goals: tuple[Fact, ...]) -> tuple[str, ...]:
    return tuple(str(g) for g in goals)
