"""Shorter names people give a world's longer names (used by :mod:`knic.language.vocabulary`).

A world's symbol is spoken as its name ("kitchen_diner": "kitchen diner"), its lexicon phrases and their
common English synonyms. People in the house also say less:

* a numbered name by its ordinal: "bedroom_two" is "the second bedroom" or "bedroom number two" ("shelf_3":
  "the third shelf");
* a room by the kind of room one of its words names: "kitchen_diner" is "the kitchen", "bedroom_two" and
  "master_bedroom" are each "the bedroom" (two such rooms: the reader asks which), or its last two words
  before "room": "open_plan_living_room" is "the living room";
* a thing whose one-word name ends in a common noun by that noun: "newspaper" is "the paper", "armchair" "the
  chair", "hairbrush" "the brush";
* a container of a drink or food by what it holds: "water_bottle" is "some water", "milk_carton" "the milk";
* a piece of furniture made of several of a thing by them: "drawer_unit" and "chest_of_drawers" are each "the
  drawers" (both in one home: the reader asks which);
* a cupboard, closet or cabinet named after a kind of room by that word alone where no room has the word in
  its name: "pantry_cupboard" is "the pantry" ("bring me the olive oil from the pantry").

The kinds of room, the nouns, the containers and the units are general English, kept in ``synonyms.yaml``
(``room_words``, ``heads``, ``containers``, ``units``). A
short name that is already a name of the world is not given (the world's own names win: where "hall" names
the hallway, an "entrance_hall" is not also "the hall"); one short name of several things names them all.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from functools import lru_cache
from pathlib import Path
from typing import Protocol, TypeVar

from core.errors import LanguageError
from core.inputs import read_yaml

_FILE = Path(__file__).with_name("synonyms.yaml")
#: number words said last in a name, and the ordinal said before it instead
ORDINALS = {
    "one": "first",
    "two": "second",
    "three": "third",
    "four": "fourth",
    "five": "fifth",
    "six": "sixth",
    "seven": "seventh",
    "eight": "eighth",
    "nine": "ninth",
    "ten": "tenth",
}
#: the shortest a compound's first part may be ("teacup": "tea" + "cup"), so that "scup" gives no "cup"
_MIN_FIRST_PART = 3


class Named(Protocol):
    """What is read of a vocabulary term: its phrase and its type."""

    @property
    def phrase(self) -> str:
        """The spoken words."""

    @property
    def type(self) -> str:
        """The named symbol's type."""


N = TypeVar("N", bound=Named)


@lru_cache(maxsize=1)
def _word_lists() -> tuple[frozenset[str], tuple[str, ...], frozenset[str]]:
    """``room_words``, ``heads`` and ``containers`` of ``synonyms.yaml`` (read once).

    Raises:
        LanguageError: one is not a list of single words.
    """
    data = read_yaml(_FILE, "synonyms", LanguageError) or {}
    lists = []
    for key in ("room_words", "heads", "containers"):
        raw = data.get(key, []) if isinstance(data, dict) else []
        if not isinstance(raw, list) or not all(isinstance(w, str) and len(w.split()) == 1 for w in raw):
            raise LanguageError(f"{_FILE}: '{key}' is a list of single words")
        lists.append([w.lower() for w in raw])
    return frozenset(lists[0]), tuple(sorted(lists[1], key=len, reverse=True)), frozenset(lists[2])


def room_words() -> frozenset[str]:
    """The words that alone name a kind of room (``room_words`` of ``synonyms.yaml``: "cellar", "attic")."""
    return _word_lists()[0]


@lru_cache(maxsize=1)
def english_nearer() -> tuple[frozenset[str], ...]:
    """The nearer subsets of ``synonyms.yaml`` (``nearer``: the bathroom's words, the toilet's), read once.

    Raises:
        LanguageError: not a list of sets of phrases.
    """
    data = read_yaml(_FILE, "synonyms", LanguageError) or {}
    raw = data.get("nearer", []) if isinstance(data, dict) else []
    if not isinstance(raw, list) or not all(
        isinstance(group, list) and all(isinstance(p, str) and p.split() for p in group) for group in raw
    ):
        raise LanguageError(f"{_FILE}: 'nearer' is a list of sets of phrases")
    return tuple(frozenset(" ".join(p.lower().split()) for p in group) for group in raw)


@lru_cache(maxsize=1)
def english_opposites() -> dict[str, frozenset[str]]:
    """Each word of the ``opposites`` groups of ``synonyms.yaml`` -> the words opposite it (every other word
    of its group), read once.

    Raises:
        LanguageError: not a list of pairs of words.
    """
    data = read_yaml(_FILE, "synonyms", LanguageError) or {}
    raw = data.get("opposites", []) if isinstance(data, dict) else []
    if not isinstance(raw, list) or not all(
        isinstance(group, list)
        and len(group) >= 2
        and all(isinstance(w, str) and len(w.split()) == 1 for w in group)
        for group in raw
    ):
        raise LanguageError(f"{_FILE}: 'opposites' is a list of groups of two words or more")
    out: dict[str, set[str]] = {}
    for group in raw:
        words = {w.lower() for w in group}
        for word in words:
            out.setdefault(word, set()).update(words - {word})
    return {word: frozenset(others) for word, others in out.items()}


@lru_cache(maxsize=1)
def _units() -> dict[str, str]:
    """``units`` of ``synonyms.yaml``: a thing -> its plural, for furniture made of several of it.

    Raises:
        LanguageError: not a mapping of single words.
    """
    data = read_yaml(_FILE, "synonyms", LanguageError) or {}
    raw = data.get("units", {}) if isinstance(data, dict) else {}
    if not isinstance(raw, dict) or not all(
        isinstance(k, str) and isinstance(v, str) and len(k.split()) == len(v.split()) == 1
        for k, v in raw.items()
    ):
        raise LanguageError(f"{_FILE}: 'units' maps single words to their plurals")
    return {k.lower(): v.lower() for k, v in raw.items()}


def _made_of(words: list[str], units: dict[str, str]) -> list[str]:
    """What a piece of furniture made of several of a thing is called by them ("drawer unit", "chest of
    drawers" -> "drawers", "drawer")."""
    if len(words) == 2 and words[1] == "unit" and words[0] in units:
        return [units[words[0]], words[0]]
    one = {plural: thing for thing, plural in units.items()}
    if len(words) == 3 and words[0] in ("chest", "set", "bank") and words[1] == "of" and words[2] in one:
        return [words[2], one[words[2]]]
    return []


#: a cupboard called after the room it stands in for ("pantry cupboard", "utility cupboard")
_STORES = frozenset({"cupboard", "closet", "cabinet"})


def _store(words: list[str], room_words: frozenset[str], rooms: frozenset[str]) -> list[str]:
    """The kind of room a cupboard is named after ("pantry cupboard" -> "pantry"), unless a room of the world
    is called so ("bathroom cabinet" where there is a family bathroom: "the bathroom" is the room)."""
    named = len(words) == 2 and words[0] in room_words and words[1] in _STORES and words[0] not in rooms
    return [words[0]] if named else []


def contains(words: Sequence[str], part: Sequence[str]) -> bool:
    """Whether ``part`` is a run of whole words of ``words``."""
    return any(list(words[i : i + len(part)]) == list(part) for i in range(len(words) - len(part) + 1))


def containers() -> frozenset[str]:
    """The container words of ``synonyms.yaml`` ("bottle", "carton"): a name ending in one is what it
    holds."""
    return _word_lists()[2]


def _content(words: list[str], containers: frozenset[str]) -> list[str]:
    """What a container named by it holds ("water bottle" -> "water"; a "hot water bottle" holds no water)."""
    return [words[0]] if len(words) == 2 and words[-1] in containers else []


def _ordinal(words: list[str]) -> list[str]:
    """ "bedroom two" -> ["second bedroom", "bedroom number two"]."""
    if len(words) >= 2 and words[-1] in ORDINALS:
        return [" ".join([ORDINALS[words[-1]], *words[:-1]]), " ".join([*words[:-1], "number", words[-1]])]
    return []


def _room_kinds(words: list[str], room_words: frozenset[str]) -> list[str]:
    """The words of a longer room name that alone name a kind of room ("kitchen diner" -> kitchen, diner), and
    the kind of room it ends with ("open plan living room" -> living room)."""
    if len(words) < 2:
        return []
    ending = [" ".join(words[-2:])] if len(words) > 2 and words[-1] == "room" else []
    return [w for w in words if w in room_words] + ending


#: two-letter words of English, never read as a room's initials
_WORDS_OF_TWO = frozenset(
    {"am", "an", "as", "at", "be", "by", "do", "go", "he", "hi", "if", "in", "is"}
    | {"it", "me", "my", "no", "of", "oh", "ok", "on", "or", "so", "to", "up", "us"}
    | {"we", "ya", "ye", "yo", "ah", "eh", "er", "um", "uh", "hm", "mm", "ha"}
    # and what is written short in texts and before names ("bring me the hummus fr", "Dr", "St")
    | {"fr", "rn", "ty", "np", "ig", "tv", "pc", "dm", "gg", "bf", "gf", "bc", "pm", "ps", "mr", "ms"}
    | {"dr", "st"}
)


def _initials(words: list[str]) -> list[str]:
    """The initials of a two-word room name, as rooms are called in many homes ("the BQ", the boys' quarters
    of a Nigerian home; "the CR", a Filipino comfort room; "the LR"), unless they spell a word."""
    said = "".join(w[0] for w in words)
    return [said] if len(words) == 2 and said.isalpha() and said not in _WORDS_OF_TWO else []


def _head(words: list[str], heads: Sequence[str]) -> list[str]:
    """The common noun a one-word compound name ends in ("newspaper" -> "paper")."""
    if len(words) != 1:
        return []
    word = words[0]
    return [h for h in heads if word.endswith(h) and len(word) - len(h) >= _MIN_FIRST_PART][:1]


def short_names(
    terms: Iterable[N], is_room: Callable[[str], bool], *, exclude: Callable[[str], bool]
) -> list[tuple[str, N]]:
    """The short names of ``terms`` as (phrase, term said so), none of them a phrase of ``terms`` already.

    Args:
        terms: the world's names so far (symbols' names, lexicon phrases and synonyms).
        is_room: whether a type is a room.
        exclude: types that get no short names (people, levels).
    """
    terms = list(terms)
    room_words, heads, containers = _word_lists()
    units = _units()
    taken = {t.phrase for t in terms}
    said = frozenset(w for t in terms if is_room(t.type) for w in t.phrase.split())  # rooms' words
    names = {t.phrase.split()[0] for t in terms if exclude(t.type) and t.phrase}  # people's first names
    out: list[tuple[str, N]] = []
    seen: set[tuple[str, str]] = set()
    for term in terms:
        if exclude(term.type):
            continue
        words = term.phrase.split()
        phrases = _ordinal(words) + _head(words, heads)
        if is_room(term.type):
            # not a synonym's initials, nor those of a room named after someone ("finn room")
            own = term.phrase == getattr(term, "symbol", "").replace("_", " ") and words[0] not in names
            phrases += _room_kinds(words, room_words) + (_initials(words) if own else [])
        else:
            phrases += _content(words, containers) + _made_of(words, units) + _store(words, room_words, said)
        for phrase in phrases:
            key = (phrase, term.phrase)
            if phrase not in taken and key not in seen:
                seen.add(key)
                out.append((phrase, term))
    return out


def own_phrases(
    symbol: str, phrases: tuple[str, ...], instances: Mapping[str, str], room: bool
) -> tuple[str, ...]:
    """A symbol's phrases less each one-word phrase that ends the name of another thing of its type, unless
    the thing is a room: where a lexicon written for one home calls its ``bedroom_blinds`` "the blinds", a
    home with more blinds ("kitchen_blind", "study_blind") means them all, or asks which. A phrase that is
    another thing's own name is that thing's: where a home has a ``bedside_table`` and a ``night_stand``,
    "the night stand" is the night stand. The symbol's own name is always kept: where a home has a ``sofa``
    and a ``cinema_sofa``, "the sofa" is the sofa, not the cinema sofa by its last word."""
    kind = instances.get(symbol)
    if len(phrases) < 2:
        return phrases
    others = {o.replace("_", " ") for o in instances if o != symbol}
    phrases = tuple(p for p in phrases if p not in others) or phrases
    if room:
        return phrases
    ends = {o.replace("_", " ").split()[-1] for o, k in instances.items() if k == kind and o != symbol}
    ends |= {end[:-1] for end in ends if end.endswith("s")} | {end + "s" for end in ends}
    own = symbol.replace("_", " ")
    kept = tuple(p for p in phrases if " " in p or p not in ends or p == own)
    return kept or phrases
