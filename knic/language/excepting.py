"""Things left out of "all" ("turn off all the lights except the hallway one", "close every blind but the
bedroom ones", "bring me all the drinks apart from the juice").

The reader did not know "except" after "all" in many cases: "close all the blinds except the ones in the
study" closed only the study's, "bring me all the drinks except the juice" brought the juice too. Now the
command is read without the exception, and what it names is taken out of what "all" named: the things left,
as the group the world names them by, else each alone. A thing is described when the words name it (a name
of the world, or a group of such), or when every word said of it ("hallway", "left", "bedroom") is a word of
its name or of the room the world places it in ("the one in the hallway": "hallway" names the room of the
light); a name of one of them leaves out that one only ("the hallway light", not the porch light in the
hallway as well). A thing of the world that is none of them leaves them all ("all the lights except the
blinds": the blinds are no light); words that describe nothing are refused, naming them: the robot does not
guess which to leave. An exception belongs to the action it is said in ("turn off all the lights except the
hallway light, then close all the blinds except the kitchen ones").

Called from :meth:`knic.language.reader.Reader.read` on a command's text, before anything else reads it;
the words that mark an exception are the command language's ``except_words`` (``commands.yaml``). "But"
leaves out only after "all" ("bring me the mug but first ...", "take the apple but not the lemon to
tracy"); the others also after a group said without it ("lights off except for the left lamp": the lights
are every light). This module replaced two older leave-outs that read among the words and chunks (of
groups of devices only).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Sequence
from typing import Protocol

from core.errors import LanguageError
from knic.language.chains import Reading
from knic.language.chunks import Chunk
from knic.language.commands import CommandLanguage
from knic.language.frames import CommandFrame
from knic.language.vocabulary import Vocabulary, normalize

#: the roles a frame names the things "all" covers by
_ROLES = ("device", "theme")
#: words of the excepted phrase that describe nothing themselves
_EMPTY = frozenset(
    {"the", "a", "an", "one", "ones", "in", "on", "of", "at", "from", "for", "that", "which", "is"}
)
#: how the excepted thing is said first ("except the hallway one", "but my glasses", "apart from those two")
_THINGS = frozenset({"the", "my", "that", "those", "this", "these", "for", "his", "her", "our", "their"})
#: what may follow the excepted phrase, beginning the rest of the command ("..., and then go to the kitchen")
_REST = frozenset({"and", "then"})


def excepted(
    text: str, language: CommandLanguage, is_verb: Callable[[str], object]
) -> tuple[str, list[str], str, str] | None:
    """The command without its exception, the excepted words, what was said before them and before the
    action they belong to ("and" or "then" before it), when an exception word is said before more words, up
    to the next verb or "and"/"then"; a bare "but" only after a quantified phrase ("all the lights", "every
    blind") and before a thing ("the", "my"). None otherwise ("bring me the mug but first switch on the
    light" has no "all" before its "but", "all the lights, but first go to the kitchen" no thing after it)."""
    said = text.split()
    words = [normalize(w) for w in said]
    quantified = {q.split()[0] for q in language.quantifiers.get("all", ())}
    phrases = sorted((e.split() for e in language.except_words), key=len, reverse=True)
    for at in range(1, len(words)):
        found = next((p for p in phrases if words[at : at + len(p)] == p), None)
        if found is None or (found[0] == "but" and not quantified & set(words[:at])):
            continue  # "bring me the mug but first ...", "... but not the lemon": "but" only after "all"
        end = at + len(found)
        stop = next((i for i in range(end, len(words)) if words[i] in _REST or is_verb(words[i])), len(words))
        if stop == end or (found == ["but"] and words[end] not in _THINGS):
            return None
        head = " ".join([*said[:at], *said[stop:]])
        quantifier = max((i for i in range(at) if words[i] in quantified), default=at)
        lead = max((i for i in range(quantifier) if words[i] in _REST), default=0)
        return head, " ".join(words[end:stop]).split(), " ".join(said[:at]), " ".join(said[:lead])
    return None


class Reads(Protocol):
    """What :func:`read_excepting` reads with (:class:`knic.language.reader.Reader`)."""

    vocabulary: Vocabulary
    language: CommandLanguage

    def read(self, text: str) -> Reading: ...

    def chunks(self, tokens: Sequence[str]) -> list[Chunk]: ...


def read_excepting(text: str, reader: Reads, is_verb: Callable[[str], object]) -> Reading | None:
    """The reading of a command that leaves things out of "all" (None: it leaves none out). When more is said
    after the exception ("... except the hallway light, and then close all the blinds"), only the actions said
    before it lose the things, if they read the same alone.

    Raises:
        LanguageError: as :func:`without`, or the command without its exception is not understood.
    """
    split = excepted(text, reader.language, is_verb)
    if split is None:
        return None
    head, words, before, lead = split
    whole = reader.read(head)
    span = range(_said_first(reader, lead, whole), len(whole.frames))
    if head.strip() != before.strip():
        span = range(span.start, _said_first(reader, before, whole) or span.stop)
    return without(whole, words, reader.vocabulary, reader.chunks, span)


def _said_first(reader: Reads, text: str, whole: Reading) -> int:
    """How many of the whole command's frames ``text`` (its beginning) reads as, when they are the same
    (0: it reads as none of them, or as others)."""
    if not text.strip():
        return 0
    with contextlib.suppress(LanguageError):
        first = list(reader.read(text).frames)
        return len(first) if list(whole.frames[: len(first)]) == first else 0
    return 0


def without(
    reading: Reading,
    words: list[str],
    vocabulary: Vocabulary,
    named: Callable[[list[str]], list[Chunk]],
    span: range | None = None,
) -> Reading:
    """The reading with the things ``words`` describe taken out of each frame's device or theme (of the
    frames in ``span``; all by default): the rest of a group it named, as the group the world names them
    by if there is one, else each alone (``named``: the chunks of some words, for the names they say).

    Raises:
        LanguageError: the words describe none of the things, or every one of them.
    """
    names = {m for c in named(words) for t in c.terms for m in (t.symbol, *vocabulary.members(t.symbol))}
    said = [w for w in words if w not in _EMPTY]
    acted_on = [(i, f) for i, f in enumerate(reading.frames) if span is None or i in span]
    covered = {m for _, f in acted_on for r in _ROLES if f.get(r) for m in vocabulary.members(f.args[r])}
    if names & covered:  # "the hallway light" names it: not the porch light in the hallway as well
        said = []
    frames: list[CommandFrame] = []
    waypoints: set[int] = set()
    left_out, acted = False, False
    for index, frame in enumerate(reading.frames):
        role = next((r for r in _ROLES if frame.get(r)), None)
        if index in reading.waypoints:
            waypoints.add(len(frames))
        if role is None or (span is not None and index not in span):
            frames.append(frame)
            continue
        members = vocabulary.members(frame.args[role])
        kept = [m for m in members if m not in names and not (said and _described(m, said, vocabulary))]
        left_out = left_out or len(kept) < len(members)
        group = vocabulary.group_of(kept) if len(kept) > 1 else None
        acted = acted or bool(kept)
        for member in [group] if group else kept:
            frames.append(CommandFrame(frame.kind, {**frame.args, role: member}))
    phrase = " ".join(words)
    if not left_out and names:  # "all the lights except the blinds": the blinds are none of them anyway
        return reading
    if not left_out:
        raise LanguageError(f"'{phrase}' is none of the things you asked for: which should I leave out?")
    if not acted:
        raise LanguageError(f"leaving out '{phrase}' leaves nothing to do")
    return Reading(frames, waypoints)


def _described(symbol: str, said: list[str], vocabulary: Vocabulary) -> bool:
    """Whether every word said is a word of one of the thing's names ("second" of "cup2", said "cup two" and
    "the second cup") or of the room the world places it in."""
    words = {w for t in vocabulary.terms if t.symbol == symbol for w in t.phrase.split()} | set(
        symbol.split("_")
    )
    for place in vocabulary.locations.get(symbol, ()):
        words |= set(vocabulary.phrase_of(place).split())
    return all(w in words or w.rstrip("s") in words for w in said)
