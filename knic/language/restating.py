"""What a speaker says again, more exactly, in a later stretch of the same command (used by
:func:`knic.language.household.ones_named` on the sentences of a command, with the world's names):

* a level said roughly and then exactly for the same device ("make the breakfast room light a bit brighter,
  put it to eighty percent", "turn the lamp up a little, set it at 60"): the exact level, said where the
  rough one was;
* a thing whose name starts with a word for the whole home ("the flat cap", "the house keys"): said without
  its article, so that "the flat" is not read as anywhere in the home;
* a thing said alone after a request about "it" that named nothing ("turn it up. The reading lamp. To
  seventy."): the thing, where "it" was said;
* a thing's name said again alone, longer ("turn on the lamp. The lamp. The standard lamp, next to me."; "put
  it on the table, the kitchen table"): the longer name where the shorter was said, and a name said again as
  it was, dropped; not right after a correction ("bring me the coke, no, the juice, no wait, the coke"), which
  the reader applies;
* a device named by its kind alone ("blind", "blinds", "lamp") after another device was named by its own
  name ("turn the breakfast room light down to ten and shut the blinds", "desk lamp to fifty, blind half
  open"): the one of that kind in the same room, where there is exactly one (a speaker names the room once);
* a piece of furniture named by one word after the robot is sent to a room ("go to the heather room and get
  my stick from the wardrobe"): the one of the room whose name ends so, where there is exactly one, even
  where another room's is called by that word alone (the owners' "wardrobe").
"""

from __future__ import annotations

from functools import lru_cache

from knic.language.commands import command_language
from knic.language.vocabulary import Vocabulary

#: verbs a level is said again with, of "it" or "them" ("put it to eighty percent")
_SETTING = frozenset({"put", "set", "turn", "make", "dim", "bring", "take"})
_IT = frozenset({"it", "them"})
#: what a sentence asking something opens with ("what is it called"): its "it" is no thing
_ASKING = frozenset({"what", "how", "where", "who", "which", "why", "when", "is", "was", "does", "do"})
_ARTICLES = frozenset({"the", "a", "an", "my", "that", "this", "your", "our"})
#: what says every thing of a kind is meant ("all the blinds", "both lamps")
_ALL = frozenset({"all", "both", "every", "each", "of", "two", "three"})
#: what a device's kind noun follows when it is said alone ("shut the blinds", "blind half open")
_ALONE_AFTER = _ARTICLES | {"", "and", "then", "open", "close", "shut", "raise", "lower", "draw"}


@lru_cache(maxsize=16)
def _devices(vocabulary: Vocabulary) -> tuple[tuple[str, str, str], ...]:
    """(phrase, symbol, room) of each device of the world with one room."""
    out = []
    for term in vocabulary.terms:
        rooms = vocabulary.locations.get(term.symbol, ())
        if vocabulary.is_subtype(term.type, "device") and len(rooms) == 1:
            out.append((term.phrase, term.symbol, rooms[0]))
    return tuple(out)


@lru_cache(maxsize=16)
def _phrases(vocabulary: Vocabulary) -> frozenset[str]:
    """The world's phrases, read once per vocabulary (not at every command)."""
    return frozenset(t.phrase for t in vocabulary.terms)


def restated(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """The sentences with what is said again more exactly put where it was first said (see the module
    docstring)."""
    segments = _level_restated([list(s) for s in segments])
    phrases = _phrases(vocabulary)
    segments = _name_restated(_home_named(segments, phrases), phrases)
    return _of_room_gone_to(_kind_in_room(segments, vocabulary), vocabulary)


def _home_named(segments: list[list[str]], phrases: frozenset[str]) -> list[list[str]]:
    home = [p.split() for p in command_language().anywhere if p.startswith("the ") and len(p.split()) == 2]
    out = []
    for segment in segments:
        words = list(segment)
        for i in range(len(words) - 2, -1, -1):
            if words[i : i + 2] in home and any(
                " ".join(words[i + 1 : i + 1 + n]) in phrases for n in range(2, 5) if i + n < len(words) + 1
            ):
                del words[i]  # "the flat cap": the cap called flat, not anywhere in the flat
        out.append(words)
    return out


def _level_restated(segments: list[list[str]]) -> list[list[str]]:
    vague = sorted((p.split() for p in command_language().vague_levels), key=len, reverse=True)
    for n in range(len(segments) - 1):
        later = segments[n + 1]
        if len(later) < 4 or later[0] not in _SETTING or later[1] not in _IT:
            continue
        at = next((i for i, w in enumerate(later) if w in ("to", "at")), None)
        if at is None or at + 1 >= len(later):
            continue
        words = segments[n]
        for phrase in vague:
            k = len(phrase)
            start = next((i for i in range(len(words) - k + 1) if words[i : i + k] == phrase), None)
            if start is not None:
                segments[n] = [*words[:start], *later[at:], *words[start + k :]]
                segments[n + 1] = []
                break
    return [s for s in segments if s]


def _name_restated(segments: list[list[str]], phrases: frozenset[str]) -> list[list[str]]:
    out: list[list[str]] = []
    repairs = {tuple(r.split()) for r in command_language().repairs}
    for segment in segments:
        if out and tuple(out[-1]) in repairs:  # "the coke, no, the juice, no wait, the coke": corrected back
            out.append(segment)
            continue
        name = segment[1:] if segment[:1] and segment[0] in _ARTICLES else segment
        said = " ".join(name)
        earlier = f" {' '.join(w for s in out for w in s)} "
        if len(segment) > 1 and segment[0] in _ARTICLES and f" {' '.join(segment)} " in earlier:
            continue  # "the lamp. The lamp.": said again as it was
        spot = _pronoun_before(out, phrases) if name and said in phrases else None
        if spot is not None:  # "turn it up. The reading lamp.": "it" is the lamp, said after
            out[spot[0]][spot[1] : spot[1] + 1] = name
            continue
        if not out or not name or said not in phrases:
            out.append(segment)
            continue
        last = name[-1]
        for s in reversed(out):
            spots = [i for i in range(1, len(s)) if s[i] == last and s[i - 1] in _ARTICLES]
            if spots:
                i = spots[-1]
                s[i : i + 1] = name
                break
        else:
            out.append(segment)
    return out


def _pronoun_before(out: list[list[str]], phrases: frozenset[str]) -> tuple[int, int] | None:
    """Where the last "it" or "them" stands in the sentences said so far, when they name nothing of the world
    (a thing said only after the request about it); else None."""
    words = [w for s in out for w in s]
    if any(" ".join(words[i : i + n]) in phrases for n in range(1, 5) for i in range(len(words))):
        return None
    spots = [
        (n, i)
        for n, s in enumerate(out)
        for i, w in enumerate(s)
        if w in _IT and i in (1, 2) and s[0] not in _ASKING  # "turn it up", not "what is it called"
    ]
    return spots[-1] if spots else None


def _kind_in_room(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    devices = _devices(vocabulary)
    if not devices:
        return segments
    kinds = {noun for nouns in command_language().type_nouns.values() for noun in nouns if " " not in noun}
    room: str | None = None
    out: list[list[str]] = []
    for segment in segments:
        words = list(segment)
        i = 0
        while i < len(words):
            named = _device_at(words, i, devices)
            if named is not None:
                room, size = named[2], len(named[0].split())
                i += size
                continue
            word = words[i]
            before = words[i - 1] if i else ""
            counted = set(words[max(0, i - 2) : i]) & _ALL  # "close all the blinds": every one
            if room is not None and word in kinds and before in _ALONE_AFTER and not counted:
                stem = word[:-1] if word.endswith("s") else word
                there = {d for p, d, r in devices if r == room and p.split()[-1] in (word, stem, stem + "s")}
                if len(there) == 1:
                    own = there.pop().replace("_", " ").split()  # the device's own name
                    words[i : i + 1] = own
                    i += len(own)
                    continue
            i += 1
        out.append(words)
    return out


def _device_at(
    words: list[str], at: int, devices: tuple[tuple[str, str, str], ...]
) -> tuple[str, str, str] | None:
    """The device whose whole phrase (of two words or more) is said from ``at``, the longest; else None."""
    best = None
    for device in devices:
        phrase = device[0].split()
        if (
            len(phrase) > 1
            and words[at : at + len(phrase)] == phrase
            and (best is None or len(phrase) > len(best[0].split()))
        ):
            best = device
    return best


#: verbs that send the robot to a room said after them ("go to the heather room")
_GOING = frozenset({"go", "head", "walk", "nip", "pop", "run", "drive", "come"})


@lru_cache(maxsize=16)
def _rooms_and_furniture(vocabulary: Vocabulary) -> tuple[dict[str, str], dict[str, tuple[str, str]]]:
    """The world's room phrases (-> symbol) and its furniture phrases (-> symbol, room)."""
    rooms: dict[str, str] = {}
    furniture: dict[str, tuple[str, str]] = {}
    for term in vocabulary.terms:
        where = vocabulary.locations.get(term.symbol, ())
        if vocabulary.is_subtype(term.type, "room"):
            rooms[term.phrase] = term.symbol
        elif vocabulary.is_subtype(term.type, "furniture") and len(where) == 1:
            furniture[term.phrase] = (term.symbol, where[0])
    return rooms, furniture


def _of_room_gone_to(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    rooms, furniture = _rooms_and_furniture(vocabulary)
    if not furniture:
        return segments
    room: str | None = None
    out: list[list[str]] = []
    for segment in segments:
        words = list(segment)
        for i, word in enumerate(words):
            if (
                i >= 2
                and words[i - 1] == "the"
                and words[i - 2] in ("to", "into")
                and _GOING & set(words[:i])
            ):
                said = next(
                    (rooms[p] for p in sorted(rooms, key=len, reverse=True) if _said_at(words, i, p)), None
                )
                room = said or room
                continue
            if room is None or i == 0 or words[i - 1] != "the" or word not in furniture:
                continue
            if i + 1 < len(words) and f"{word} {words[i + 1]}" in " ".join(furniture):
                continue  # a longer name said on
            symbol, where = furniture[word]
            ours = {
                s for p, (s, r) in furniture.items() if r == room and p.split()[-1] == word and s != symbol
            }
            if where != room and len(ours) == 1:
                words[i] = ours.pop().replace("_", " ")
        out.append(words)
    return out


def _said_at(words: list[str], at: int, phrase: str) -> bool:
    return words[at : at + len(phrase.split())] == phrase.split()
