"""A thing said as "the one" where it is ("bring me the one on the coffee table", "the cup, bring me the one
on the dining table"), which the reader took for the speaker ("me") taken to the table:

* a kind of thing or device said before it ("the cup, ... the one on the dining table", "all the lights but
  the one in the hallway"): that kind, where it is said to be ("the cup on the dining table"), which the
  reader narrows as any thing said with its place;
* else the one thing the world places there ("the one on the coffee table": the remote, where the remote is
  the only thing the world puts on it);
* else a question: which of the things there, or, where the world places nothing there (the robot does not
  know where things are until it has looked), which thing it is.

A place said with "on", "in", "inside", "from" or "at" is where a thing is; "by", "near" or "beside" a place
("the one by the sofa") only says what it is near, so no thing the world places is taken for it.
"""

from __future__ import annotations

from functools import lru_cache

from knic.language.chains import AmbiguityError
from knic.language.vocabulary import Vocabulary

#: prepositions that say where a thing is, after "the one", and those that say only what it is near
_WHERE = frozenset({"on", "in", "inside", "from", "at"})
_NEAR = frozenset({"by", "near", "beside"})
#: words that leave out the one said after them ("all the lights but the one in the hallway")
_LEFT_OUT = frozenset({"but", "except", "apart", "besides", "excluding", "not"})
_DETERMINERS = frozenset({"the", "my", "our", "your", "that"})


@lru_cache(maxsize=16)
def _names(vocabulary: Vocabulary) -> tuple[dict[str, str], dict[str, str], dict[str, list[str]]]:
    """(place phrase -> symbol, the last word of a thing's or a device's name and its plural -> that word,
    place symbol -> items placed there) of a world, read once per vocabulary."""
    places: dict[str, str] = {}
    heads: dict[str, str] = {}
    for term in vocabulary.terms:
        if term.is_group:
            continue
        if vocabulary.is_subtype(term.type, "furniture") or vocabulary.is_subtype(term.type, "room"):
            places.setdefault(term.phrase, term.symbol)
        elif vocabulary.is_subtype(term.type, "item") or vocabulary.is_subtype(term.type, "device"):
            head = term.phrase.split()[-1]  # "the lights but the one in the hallway": the light
            heads.update({head: head, **({} if head.endswith("s") else {head + "s": head})})
    there: dict[str, list[str]] = {}
    for symbol, where in vocabulary.locations.items():
        if vocabulary.is_of(symbol, "item"):
            for place in where:
                there.setdefault(place, []).append(symbol)
    return places, heads, there


def ones_placed(words: list[str], said: list[str], vocabulary: Vocabulary) -> list[str]:
    """``words`` with "the one on/in/from/at <place>" put as the thing meant (see the module docstring);
    ``said``: the words of the sentences before.

    Raises:
        AmbiguityError: several things, or none the world knows of, are there and no kind was said.
    """
    places, heads, there = _names(vocabulary)
    for i in range(1, len(words) - 2):
        if words[i] != "one" or words[i - 1] not in _DETERMINERS or words[i + 1] not in _WHERE | _NEAR:
            continue
        if _LEFT_OUT & set(words[max(0, i - 4) : i - 1]):
            continue  # "all the lights but the one in the hallway": what is left out (selecting.py)
        at = i + 2 + (words[i + 2] in _DETERMINERS)
        said_at = [" ".join(words[at:end]) for end in range(len(words), at, -1)]
        place = next((p for p in said_at if p in places), None)
        if place is None:
            continue
        kinds = [heads[w] for w in said + words[: i - 1] if w in heads]
        if kinds:  # "the cup, bring me the one on the dining table"
            return [*words[:i], kinds[-1], *words[i + 1 :]]
        things = sorted(set(there.get(places[place], []))) if words[i + 1] in _WHERE else []
        if len(things) == 1:
            return [*words[:i], *vocabulary.phrase_of(things[0]).split(), *words[i + 1 :]]
        if things:
            named = [f"the {vocabulary.phrase_of(t)}" for t in things]
            listed = ", ".join(named[:-1]) + f" or {named[-1]}"
            raise AmbiguityError(f"which one {words[i + 1]} the {place} do you mean: {listed}?")
        raise AmbiguityError(f"which thing {words[i + 1]} the {place} do you mean? Name it, please")
    return words
