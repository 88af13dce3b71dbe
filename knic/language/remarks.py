"""Remarks: what a speaker says of how something is or was, with no request in it, for
:class:`knic.language.reader.Reader` (refused: no action for the robot).

* A sentence that says what something was, did or has been doing ("the landing light has been flickering all
  week", "shift was brutal", "students kept their houses tidy"): words, then a past or perfect "be", "have"
  or "keep" before any verb of the command language, and no request after it; a thing "left" so ("the
  garage light has been left on again") is a complaint that asks for the other state, no remark. A command
  of such sentences and talk naming nothing of the world ("in my day, ...") is a remark; a request said
  with one ("the post was delivered, bring it to me") is read as said.
* A sentence with no verb of the command language that says how something is ("the kitchen's a mess again",
  "the porch light is broken", "the lounge is so cold") is a remark too.
* A question tag or talk said after the one sentence of a command ("is it going to be sunny tomorrow, do you
  think?") leaves that sentence alone for :func:`knic.language.reader.not_request`.
* "all" before a word of time ("leave the porch light on all night", "flickering all week") is a time, not
  every device: it is dropped (:func:`times_dropped`); "it would be nice if" before how a thing should be
  ("... if the reading lamp was off") only wishes it so (:func:`plain_words`).
* "set an alarm (a timer, a reminder) for half six": no action the robot has (:func:`undoable`).
* A later action of a chain the robot has no verb for ("bring me the cup and wash it", "... then polish the
  mug", "... and water the plant"): refused by name (:func:`unknown_action`), not dropped.
* A request taken back in a sentence of its own said last ("take the rugby ball to the garden, actually no,
  leave it", "bring me the kettle, oh never mind"): no action.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

from core.errors import LanguageError
from knic.language.chunks import Chunk
from knic.language.tidy import unplaced

#: a past or perfect "be", "have" or "keep" that says what something was or did
_PAST = (("has", "been"), ("have", "been"), ("had", "been"), ("was",), ("were",), ("kept",), ("used", "to"))
#: what nearly happened ("the breakfast rush nearly killed me", "I almost forgot"): said of the past, the verb
#: right after is no request
_NEARLY = (("nearly",), ("almost",))
#: words a sentence asking something opens with: no remark
_ASKING = frozenset({"where", "what", "who", "which", "how", "why", "when", "is", "are", "did", "do", "can"})
#: what is said right before a past "be" of a thing ("the mug that was ...": the thing is described)
_DESCRIBING = frozenset({"that", "which", "who", "what", "it", "there"})
#: states a device said to have been in (perfect) is complained of ("the lamp has been on all day": asks it
#: off); "the lamp was on" is a remark
_STATES = (["on"], ["off"], ["open"], ["closed"], ["shut"])
#: "be" said of how a thing is ("the lounge is a tip"), words of degree after it, and what a thing said to
#: be so is looked for, not remarked on; sentences opening so are asked or meant otherwise
_COPULAS = frozenset({"is", "are", "am"})
_DEGREES = frozenset({"so", "too", "very", "really", "such", "quite", "pretty", "well", "totally", "all"})
_LOST = frozenset({"lost", "missing", "gone", "nowhere"})
_NOT_SUBJECTS = frozenset({"let's", "here's", "where's", "what's", "who's", "how's"})
#: words that make what follows a wish ("it'd be great if the light was off", "i wish the blinds were shut")
_WISHING = frozenset({"if", "wish", "rather"})
#: words of time "all" goes before ("all week"); "all the time", "all along"
_TIMES = frozenset(
    {"week", "day", "night", "morning", "afternoon", "evening", "year", "month", "weekend", "along", "summer"}
    | {"winter", "autumn", "spring", "today", "yesterday", "weekend", "term", "semester"}
)
#: what a sentence that names nothing of the world may hold and still be talk
_TALK = frozenset({"unknown", "det", "prep", "join", "pronoun", "noun", "owner"})


def refused(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> str | None:
    """Why a command of remarks, or one asking to set an alarm, is refused (see the module docstring); else
    None."""
    lacking = told_there(segments, chunks)
    if lacking:  # "there's a parcel at the door, can you get it": the world has no parcel
        return f"there is no '{lacking}' here: this world has nothing called that"
    stated = remark(segments, chunks)
    if stated:
        return f"'{stated}' says how something is or was: no request, no action for me"
    if len(segments) > 1 and _taken_back(
        segments[-1]
    ):  # "take the ball to the garden, actually no, leave it"
        return "you took the request back: no action for me"
    timed = (undoable(segments) or "").removesuffix("s")
    article = "an" if timed[:1] in ("a", "e", "i", "o", "u") else "a"
    return f"setting {article} {timed} is no action for me" if timed else None


def told_there(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> str | None:
    """The word for a thing said to be there ("there is a parcel at the door", "there's a spider in the bath")
    that names nothing of the world, when the command then acts on "it" or "them" and names no other thing
    but places, or for one said alone before such a request (:func:`_said_alone`); else None."""
    words = [t for segment in segments for t in segment]
    said = chunks(words)
    for i, chunk in enumerate(said[:-2]):
        opens = chunk.text == "there's" or (chunk.text == "there" and said[i + 1].text in ("is", "are"))
        at = i + 1 + (chunk.text == "there")
        if not opens or at + 1 >= len(said) or said[at].kind != "det" or said[at + 1].kind != "unknown":
            continue
        rest = said[at + 2 :]
        if any(c.kind == "pronoun" for c in rest) and not unplaced(said):  # places may be said
            return said[at + 1].text
    return _said_alone(segments, chunks)


def _said_alone(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> str | None:
    """The word for a thing said alone first ("the television, switch it on", "the fan, turn it on") that
    names nothing of the world, when the next sentence acts on "it" or "them" before it names a thing of the
    world ("your mission: find Ines and guide her to the exit": "her" is Ines, the mission only a label);
    else None."""
    if len(segments) < 2:
        return None
    first, then = chunks(segments[0]), chunks(segments[1])
    if len(first) < 2 or first[0].kind != "det" or any(c.kind != "unknown" for c in first[1:]):
        return _said_of(first, then)
    return " ".join(c.text for c in first[1:]) if _acts_on_it(then) else None


def _said_of(first: list[Chunk], then: list[Chunk]) -> str | None:
    """The word for a thing a sentence that names nothing of the world says how it is ("the heating is on far
    too high, turn it down", "you have the heating up too high, turn it down"), when the next one acts on
    "it" or "them" before naming a thing; else None."""
    if any(c.kind == "entity" and c.terms for c in first):
        return None
    thing = next(
        (k + 1 for k, c in enumerate(first[:-1]) if c.kind == "det" and first[k + 1].kind == "unknown"), 0
    )
    return first[thing].text if thing and _acts_on_it(then) else None


def _acts_on_it(then: list[Chunk]) -> bool:
    """Whether a sentence acts on "it" or "them" before it names a thing of the world."""
    pronoun = next((k for k, c in enumerate(then) if c.kind == "pronoun"), None)
    named = next((k for k, c in enumerate(then) if c.kind == "entity" and c.terms), len(then))
    return any(c.kind == "verb" for c in then) and pronoun is not None and pronoun < named


#: what takes a request back when said last in a sentence of its own, after words of repair
_TAKEN_BACK = (
    ["leave", "it"],
    ["forget", "it"],
    ["forget", "that"],
    ["never", "mind"],
    ["nevermind"],
    ["don't", "bother"],
    ["dont", "bother"],
    ["no", "need"],
    ["cancel", "that"],
    ["cancel", "it"],
    ["scratch", "that"],
    ["leave", "them"],
)
_REPAIRING = frozenset(
    {"actually", "no", "wait", "sorry", "oh", "on", "second", "thought", "thoughts", "just"}
)


def _taken_back(segment: list[str]) -> bool:
    """Whether a sentence only takes back what was asked ("actually no, leave it", "oh never mind")."""
    start = 0
    while start < len(segment) and segment[start] in _REPAIRING:
        start += 1
    return segment[start:] in _TAKEN_BACK


def remark(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> str | None:
    """The sentence a command of remarks says (see the module docstring), else None."""
    stated: list[str] | None = None
    for segment in segments:
        said = chunks(segment)
        if not said:
            continue
        if _states(segment, chunks) or _described(segment, chunks):
            stated = stated or segment
            continue
        if not all(c.kind in _TALK and not c.terms for c in said):
            return None
    return " ".join(stated) if stated else None


def _states(segment: list[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> bool:
    """Whether a sentence says what something was or did (see the module docstring)."""
    if not segment or segment[0] in _ASKING:
        return False
    for at in range(1, len(segment)):
        marker = next((p for p in _PAST + _NEARLY if tuple(segment[at : at + len(p)]) == p), None)
        if marker is None:
            continue
        if marker in _NEARLY:
            marker = (*marker, segment[at + 1] if at + 1 < len(segment) else "")  # and what nearly happened
        before = chunks(segment[:at])
        # a verb with more said after it asks ("bring me the mug that was ..."); one said right before the
        # "be" is a noun ("shift was brutal")
        if segment[at - 1] in _DESCRIBING or any(c.kind == "verb" for c in before[:-1]):
            return False
        if _WISHING & set(segment[:at]):  # "it'd be great if the landing light was off": a wish
            return False
        said = segment[at + len(marker) : at + len(marker) + 1]
        if said == ["left"] or (marker[-1:] == ("been",) and said in _STATES):
            return False  # "the garage light has been left on again": a complaint that asks it off
        after = chunks(segment[at + len(marker) :])
        # "... tidy" said last is what was kept so; a verb with more after it asks ("the light was on all
        # night turn it off")
        return not any(c.kind == "verb" for c in after[:-1])
    return False


def _described(segment: list[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> bool:
    """Whether a sentence with no verb of the command language says how something is ("the kitchen's a mess
    again", "the porch light is broken", "the lounge is so cold"): a subject, "is" (or "'s", "are"), then a
    word the tables do not know, after articles and words of degree only. A thing said to be lost or missing
    ("my glasses are missing") is no remark."""
    if len(segment) < 2 or segment[0] in _ASKING or _LOST & set(segment):
        return False
    at = next((i + 1 for i, w in enumerate(segment) if w in _COPULAS and i > 0), None)  # "the laptop is dead"
    at = at or next(
        (i + 1 for i, w in enumerate(segment) if w.endswith("'s") and w[:-2]), None
    )  # "kitchen's"
    if at is None or at >= len(segment) or segment[0] in _NOT_SUBJECTS:
        return False
    said = chunks(segment)
    if any(c.kind == "verb" and not c.soft for c in said):
        return False
    after = [c for c in chunks(segment[at:]) if c.kind != "det" and c.text not in _DEGREES]
    if any(c.kind in ("state", "level", "number", "entity") or c.state for c in after):
        return False  # "the hallway light is still on": a complaint; "... is stuck on the shelf": where
    return bool(after) and (after[0].kind == "unknown" or (after[0].kind == "verb" and after[0].soft))


def tagged(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> list[list[str]]:
    """The first sentence alone when the others are talk naming nothing ("..., do you think?"), else all."""
    rest = [chunks(s) for s in segments[1:]]
    if rest and all(all(c.kind in _TALK and not c.terms for c in said) for said in rest):
        return segments[:1]
    return segments


#: openings of a wish about how a thing should be ("it would be nice if the lamp was off")
_WISH_OPENINGS = (
    ["it", "would", "be"],
    ["it'd", "be"],
    ["would", "be"],
    ["it", "will", "be"],
    ["it'll", "be"],
)


def plain_words(tokens: list[str]) -> list[str]:
    """The words without "all" before a word of time (:func:`times_dropped`) and without the opening of a
    wish about how a thing should be ("it would be nice if the reading lamp was off": the lamp off), when
    what follows "if" is no "you" ("... if you brought me the paper" is read with its verb)."""
    tokens = times_dropped(tokens)
    for opening in _WISH_OPENINGS:
        end = len(opening) + 1  # the opening, a word ("nice"), "if", and no "you" after it
        said = tokens[: len(opening)] == opening and tokens[end : end + 1] == ["if"]
        if said and tokens[end + 1 : end + 2] and tokens[end + 1] not in ("you", "u"):
            return [t for t in tokens[end + 1 :] if t not in ("was", "were")]  # the thing, how it should be
    return tokens


def times_dropped(tokens: list[str]) -> list[str]:
    """The words without "all" before a word of time ("all week", "all the time")."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        if tokens[i] == "all" and i + 1 < len(tokens):
            if tokens[i + 1] in _TIMES:
                i += 2
                continue
            if tokens[i + 1 : i + 3] == ["the", "time"]:
                i += 3
                continue
        out.append(tokens[i])
        i += 1
    return out


#: what "set" asks that no robot's action does ("set an alarm for half six")
_TIMED = frozenset({"alarm", "alarms", "timer", "timers", "reminder", "reminders"})


def undoable(segments: list[list[str]]) -> str | None:
    """What a command asks to set that no action of the robot does ("an alarm"), else None."""
    for segment in segments:
        for i, word in enumerate(segment):
            timed = next((w for w in segment[i + 1 : i + 4] if w in _TIMED), None)
            if word == "set" and timed is not None and "clock" not in segment[i + 1 : i + 5]:
                return timed
    return None


#: words that may stand between a joiner and what it joins without being a verb ("and maybe the mug")
_NOT_VERBS = frozenset(
    {"maybe", "perhaps", "possibly", "probably", "even", "just", "only", "especially", "also"}
)


class NoSuchAction(LanguageError):
    """A command asks for an action the robot has not (:func:`unknown_action`): refused whichever way the
    rest of it could be read."""


def unknown_action(chunks: Sequence[Chunk], kind_of: Callable[[Chunk], str]) -> str | None:
    """The verb of a later action of a chain that is no action of the robot's: a word the command language
    does not know ("... and wash it", "... then polish the mug") before an object (a pronoun of one said last
    or before a preposition or a joiner, or a determiner and its name; ``kind_of``: what a chunk names,
    "object" for a thing), or an object's name said as a verb before a determiner and anything named but a
    person ("... and water the plant"), right after a joiner; else None.
    An unknown word before a place is left out as before ("go and answer the door": the robot goes there)."""
    for at, (joiner, word) in enumerate(itertools.pairwise(chunks)):
        if joiner.kind != "join" or word.kind not in ("unknown", "entity") or word.text in _NOT_VERBS:
            continue
        after = chunks[at + 2 : at + 4]
        # "wash it", "wash them in the sink"; not "..., they are in the shed" (the subject of what follows)
        # and "follow her", "thank him" (a person said as the object, not "they" said as a subject)
        pronoun = [c.kind for c in after[:1]] == ["pronoun"] and (
            after[0].role != "person" or after[0].text in ("her", "him")
        )
        acted_on = kind_of(after[1]) if [c.kind for c in after] == ["det", "entity"] else ""
        if word.kind == "entity":  # an object's name before what it is done to: "water the plant"
            if kind_of(word) == "object" and acted_on not in ("", "person"):
                return word.text
        elif pronoun and after[1:2] and after[1].kind not in ("prep", "join"):
            continue
        elif (pronoun or acted_on == "object") and not word.text.endswith("ly"):
            return word.text
        elif after[:1] and after[0].kind == "entity" and kind_of(after[0]) == "person":
            return word.text  # "... and tell tracy dinner is ready": no going to tracy
    return None
