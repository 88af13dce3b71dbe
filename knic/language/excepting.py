"""Things left out of "all" ("turn off all the lights except the hallway one", "close every blind but the
bedroom ones", "bring me all the drinks apart from the juice").

The reader did not know "except": "close all the blinds except the ones in the study" closed only the
study's, "bring me all the drinks except the juice" brought the juice too. Now the command is read without
the exception, and what it names is taken out of what "all" named: the things left, as the group the world
names them by, else each alone. A thing is described when the words name it (a name of the world, or a
group of such), or when every word said of it ("hallway", "left", "bedroom") is a word of its name or of the
room the world places it in ("the one in the hallway": "hallway" names the room of the light). Words that
describe none of them are refused, naming them: the robot does not guess which to leave.

Called from :meth:`knic.language.reader.Reader.read` on a command's text; the words that mark an
exception are the command language's ``except_words`` (``commands.yaml``).
"""

from __future__ import annotations

from collections.abc import Callable

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
) -> tuple[str, list[str]] | None:
    """The command without its exception, and the excepted words, when an exception word follows a
    quantified phrase ("all the lights", "every blind") and a thing is said after it ("the", "my", or a name)
    before the next verb or "and"/"then"; None otherwise ("bring me the mug but first switch on the light"
    has no "all" before its "but", "all the lights, but first go to the kitchen" says no thing after it)."""
    said = text.split()
    words = [normalize(w) for w in said]
    quantified = {q.split()[0] for q in language.quantifiers.get("all", ())}
    phrases = sorted((e.split() for e in language.except_words), key=len, reverse=True)
    for at in range(1, len(words)):
        found = next((p for p in phrases if words[at : at + len(p)] == p), None)
        if found is None or not quantified & set(words[:at]):
            continue
        end = at + len(found)
        stop = next((i for i in range(end, len(words)) if words[i] in _REST or is_verb(words[i])), len(words))
        if stop == end or words[end] not in _THINGS:
            return None
        return " ".join([*said[:at], *said[stop:]]), " ".join(words[end:stop]).split()
    return None


def without(
    reading: Reading,
    words: list[str],
    vocabulary: Vocabulary,
    named: Callable[[list[str]], list[Chunk]],
) -> Reading:
    """The reading with the things ``words`` describe taken out of each frame's device or theme: the rest of
    a group it named, as the group the world names them by if there is one, else each alone (``named``: the
    chunks of some words, for the names they say).

    Raises:
        LanguageError: the words describe none of the things, or every one of them.
    """
    names = {m for c in named(words) for t in c.terms for m in (t.symbol, *vocabulary.members(t.symbol))}
    said = [w for w in words if w not in _EMPTY]
    frames: list[CommandFrame] = []
    waypoints: set[int] = set()
    left_out = False
    for index, frame in enumerate(reading.frames):
        role = next((r for r in _ROLES if frame.get(r)), None)
        if index in reading.waypoints:
            waypoints.add(len(frames))
        if role is None:
            frames.append(frame)
            continue
        members = vocabulary.members(frame.args[role])
        kept = [m for m in members if m not in names and not (said and _described(m, said, vocabulary))]
        left_out = left_out or len(kept) < len(members)
        group = vocabulary.group_of(kept) if len(kept) > 1 else None
        for member in [group] if group else kept:
            frames.append(CommandFrame(frame.kind, {**frame.args, role: member}))
    phrase = " ".join(words)
    if not left_out:
        raise LanguageError(f"'{phrase}' is none of the things you asked for: which should I leave out?")
    if not any(f.get(r) for f in frames for r in _ROLES):
        raise LanguageError(f"leaving out '{phrase}' leaves nothing to do")
    return Reading(frames, waypoints)


def _described(symbol: str, said: list[str], vocabulary: Vocabulary) -> bool:
    """Whether every word said is a word of the thing's name or of the room the world places it in."""
    words = {*vocabulary.phrase_of(symbol).split(), *symbol.split("_")}
    for place in vocabulary.locations.get(symbol, ()):
        words |= set(vocabulary.phrase_of(place).split())
    return all(w in words or w.rstrip("s") in words for w in said)
