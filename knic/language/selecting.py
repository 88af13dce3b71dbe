"""Things picked out by what is said of them rather than by their names, read in the words of each sentence
before they are cut into chunks (by :class:`knic.language.reader.Reader`, after
:func:`knic.language.household.ones_named`):

* a request said again with "i said", "like i said", "i told you": the request ("i said the bedroom");
* "the ones" set apart after a thing, as "the one" ("my glasses, the ones on the nightstand");
* a side said of a thing ("the lamp on the left side of the bed", "the light to the right"): the thing of
  that side, where the world has one called so ("left lamp");
* two sides said of one noun ("the left and the right lamp"): both names said whole;
* a kind of thing said for its use ("something to drink", "something to eat", "a cold drink", "a piece of
  fruit", "a snack"): the one thing of the world of that kind, or a question which of them (none: the word
  is refused as unknown);
* "all of them", "both of them" after the things ("the lights, all of them, off"): said already;
* a room said before the name of a device or piece of furniture after "and" ("the hallway light and the
  bedroom lamps"): where that one is, not where the first one is;
* a thing said by a landmark the world does not know ("the light by the door") where the thing's name fits
  several: the landmark cannot tell them apart, so the reader asks which;
* "put it back" after a thing is said to have fallen or been knocked from a place ("the candle fell off the
  shelf, put it back"): back on that place;
* "from the coffee table on the tv table": from the one onto the other, not the coffee table that is on the
  tv table (nor the one in a room it is not in);
* one of two things "whichever" ("the mug or the cup, whichever is closer") or "either ... or": the robot
  cannot tell which; it asks;
* a size said of a thing where the world names one of its kind small ("mini_fridge" beside "fridge"): "the
  small fridge" is the mini fridge, "the big fridge" the fridge; where one of its kind is named big ("double
  bed", "master bedroom") "the big bed", "the big bedroom" is that one;
* a place said alone before a sentence that says "in there" or "on there" ("the fridge, is the butter in
  there?"): that place.
"""

from __future__ import annotations

from collections.abc import Sequence

from knic.language.chains import AmbiguityError
from knic.language.frames import CommandFrame
from knic.language.quantified import all_of_them
from knic.language.shortnames import containers
from knic.language.vocabulary import Term, Vocabulary
from knic.language.wherefromto import onto_joined

#: what says a request is said again ("i said the bedroom", "like i said, the hallway light")
_SAID_AGAIN = (
    ("like", "i", "said"),
    ("as", "i", "said"),
    ("i", "already", "said"),
    ("i", "already", "told", "you"),
    ("i", "told", "you", "to"),
    ("i", "told", "you"),
    ("i", "said"),
)
_SIDES = frozenset({"left", "right"})
_SIDE_PREPS = frozenset({"on", "to", "at"})
_DETERMINERS = frozenset({"the", "a", "an", "my", "your", "his", "her", "our", "their", "this", "that"})
#: what things of a kind are called, for a kind said by its use ("something to drink")
_KINDS = {
    "drink": frozenset(
        {"coke", "cola", "soda", "water", "juice", "milk", "tea", "coffee", "beer", "wine", "lemonade"}
    ),
    "fruit": frozenset({"apple", "lemon", "banana", "orange", "pear", "peach", "plum", "grapes", "lime"}),
    "food": frozenset(
        {"apple", "lemon", "banana", "orange", "pear", "peach", "plum", "grapes", "lime", "bread", "biscuit"}
        | {"biscuits", "cake", "sandwich", "cookie", "cookies", "crackers", "cheese", "chocolate", "yogurt"}
        | {"yoghurt", "popcorn", "eggs", "egg", "crisps", "nuts", "jam", "cereal", "soup", "noodles", "pizza"}
    ),
}
#: words before a kind that mean every thing of it ("all the fruit", "every drink")
_EVERY = frozenset({"all", "every", "each"})
_KIND_WORDS = {
    "drink": "drink",
    "drinks": "drink",
    "beverage": "drink",
    "fruit": "fruit",
    "fruits": "fruit",
    "eat": "food",  # only "something to eat" (a verb otherwise)
    "snack": "food",
}
#: how the robot asks which thing of a kind, where "which <kind> do you mean" would not do
_ASK = {"food": "what would you like to eat"}
_SAID_OF_KIND = frozenset(
    {
        "cold",
        "hot",
        "cool",
        "warm",
        "fresh",
        "nice",
        "little",
        "piece",
        "of",
        "another",
        "sweet",
        "tasty",
        "healthy",
    }
)


def described(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """The sentences with things said by description put as their names (see the module docstring).

    Raises:
        AmbiguityError: a kind of thing fits several things, or "whichever" of two is asked for.
    """
    phrases = {t.phrase: t for t in vocabulary.terms if t.type != "level"}
    heads = {p.split()[-1] for p in phrases}  # the last words of the names ("lamp", "table")
    out: list[list[str]] = []
    for segment in onto_joined(segments):  # "oats from larder, on island put"
        words = all_of_them(_said_again(segment, len(segments) > 1), out[-1] if out else [], heads)
        words = [
            "one" if w == "ones" and i and words[i - 1] in _DETERMINERS | {"these", "those"} else w
            for i, w in enumerate(words)
        ]
        words = _sides(_two_sides(words, phrases), phrases)
        words = _kind(words, vocabulary)
        words = _room_first(_landmark_unknown(words, phrases, heads), vocabulary, phrases)
        words = _sized(_from_onto(words, vocabulary, phrases), phrases)
        if words:
            out.append(words)
    _whichever([w for words in out for w in words], phrases)  # "the mug or the cup, whichever is closer"
    return _fell_from(_there_named(out, vocabulary, phrases), vocabulary, phrases)


#: words that say a thing is the small one of its kind, in what is said and in the world's names
_SMALL = frozenset({"small", "little", "mini", "tiny", "compact", "smaller"})
#: words that say a thing is the big one of its kind
_BIG = frozenset({"big", "large", "bigger", "larger", "main"})
#: the words of size ("the big one in the kitchen": plainspoken.py)
SIZES = _SMALL | _BIG
#: words of the world's names that say a thing is the big one of its kind ("double bed", "master bedroom")
_BIG_NAMES = frozenset({"big", "large", "double", "king", "master", "main"})


def _sized(words: list[str], phrases: dict[str, Term]) -> list[str]:
    """ "the small fridge" where the world has a fridge and a mini fridge: the mini fridge (the one whose name
    says it is small); "the big fridge" there: the fridge (the one whose name does not). Else as said."""
    out = list(words)
    for i, word in enumerate(words[:-1]):
        noun = words[i + 1]
        if word not in _SMALL | _BIG or f"{word} {noun}" in phrases:
            continue
        big = [p for p in phrases if p.endswith(f" {noun}") and p.split()[-2] in _BIG_NAMES]
        if word in _BIG and len({phrases[p].symbol for p in big}) == 1:  # "the big bed": the double bed
            out[i] = big[0].rsplit(" ", 1)[0]
            continue
        small = [p for p in phrases if p.endswith(f" {noun}") and p.split()[-2] in _SMALL]
        if len(small) != 1 or noun not in phrases:  # "the big fridge" beside the mini fridge: the fridge
            continue
        out[i] = small[0].rsplit(" ", 1)[0] if word in _SMALL else ""
    return [w for w in out if w]


def _there_named(
    segments: list[list[str]], vocabulary: Vocabulary, phrases: dict[str, Term]
) -> list[list[str]]:
    """ "the big fridge, is the butter in there?": a place said alone in a sentence before one that says "in
    there" (or "on there") is that place; the sentence of it alone is dropped."""
    out: list[list[str]] = []
    for segment in segments:
        said = out[-1] if out else []
        name = " ".join(said[1:] if said[:1] == ["the"] else said)
        places = ("room", "furniture")
        place = phrases.get(name)
        at = next(
            (
                i
                for i in range(1, len(segment))
                if segment[i - 1 : i + 1] in (["in", "there"], ["on", "there"])
            ),
            0,
        )
        if at and place is not None and any(vocabulary.is_subtype(place.type, k) for k in places):
            out[-1] = [*segment[:at], "the", *name.split(), *segment[at + 1 :]]
            continue
        out.append(segment)
    return out


def _said_again(words: list[str], others: bool) -> list[str]:
    """Without "i said" and the like opening the sentence (alone, only when other sentences are said)."""
    for said in _SAID_AGAIN:
        if tuple(words[: len(said)]) == said and (len(words) > len(said) or others):
            return words[len(said) :]
    return words


def _two_sides(words: list[str], phrases: dict[str, Term]) -> list[str]:
    """ "the left and the right lamp": "the left lamp and the right lamp", both names of the world."""
    for i, word in enumerate(words):
        if word != "and" or i < 1 or i + 2 >= len(words):
            continue
        first = words[i - 1]
        at = i + 1 + (words[i + 1] in _DETERMINERS)
        if at + 1 >= len(words):
            continue
        second, noun = words[at], _singular(words[at + 1], phrases, words[at])
        if first in phrases or f"{second} {noun}" not in phrases or f"{first} {noun}" not in phrases:
            continue
        if first == second:  # "my laptop and the laptop charger": a thing, then another named after it
            continue
        return [*words[:i], noun, "and", *words[i + 1 : at], second, noun, *words[at + 2 :]]
    return words


def _singular(noun: str, phrases: dict[str, Term], before: str) -> str:
    if f"{before} {noun}" in phrases or not noun.endswith("s"):
        return noun
    return noun[:-1]


def _sides(words: list[str], phrases: dict[str, Term]) -> list[str]:
    """ "the lamp on the left side of the bed": "the left lamp", where the world has one called so."""
    for i in range(3, len(words)):
        side, noun = words[i], words[i - 3]
        if side not in _SIDES or words[i - 1] != "the" or words[i - 2] not in _SIDE_PREPS:
            continue
        if f"{side} {noun}" not in phrases:
            continue
        end = i + 1
        for extra in ("hand", "side"):
            if end < len(words) and words[end] == extra:
                end += 1
        if end < len(words) and words[end] == "of":  # the landmark: "of the bed", "of the kitchen table"
            landmark, stop = _name_at(words, end + 1, phrases)
            if landmark is not None:
                end = stop
        return [*words[: i - 3], side, noun, *words[end:]]
    return words


def _heads(phrase: str) -> set[str]:
    """The words that say what kind of thing a name names: its last ("orange juice": juice; a "tea towel" is
    no tea), and before a container of a two-word name what it holds ("water bottle": water; a "hot water
    bottle" holds no drink)."""
    words = phrase.split()
    return {words[-1], *(words[-2:-1] if words[-1] in containers() and len(words) == 2 else ())}


def _kind(words: list[str], vocabulary: Vocabulary) -> list[str]:
    """ "something to drink", "a cold drink": the one thing of the world of that kind."""
    for i, word in enumerate(words):
        kind = _KIND_WORDS.get(word)
        if kind is None or not i or _name_starts(words[i : i + 2], vocabulary):
            continue  # "the snack bar", "the drinks cabinet": a name of the world, no kind of thing
        start = i
        if words[i - 1] == "to":  # "something (cold) to drink"; "i want to drink": a verb
            start = i - 2
            while start >= 0 and words[start] in _SAID_OF_KIND:
                start -= 1
            if start < 0 or words[start] not in ("something", "anything"):
                continue
        else:
            while start and (
                words[start - 1] in _SAID_OF_KIND or words[start - 1] in _DETERMINERS | {"some"}
            ):
                start -= 1
            if (start == i and words[i - 1] not in _EVERY) or word == "eat":
                continue  # "drink" said as a verb
        things = {
            t.symbol: t
            for t in vocabulary.terms
            if not t.is_group and vocabulary.is_subtype(t.type, "item") and _heads(t.phrase) & _KINDS[kind]
        }
        if not things:
            return words
        names = [vocabulary.phrase_of(s) for s in sorted(things)]
        every = (bool(start) and words[start - 1] in _EVERY) or words[start - 2 : start] == ["all", "of"]
        if len(things) > 1 and every:  # "bring me all the fruit": each of them, one after the other
            said = " and ".join(f"the {n}" for n in names).split()
            return [*words[: start - 1 - (words[start - 1] == "of")], *said, *words[i + 1 :]]
        if len(things) > 1:
            listed = ", ".join(f"the {n}" for n in names[:-1]) + f" or the {names[-1]}"
            raise AmbiguityError(f"{_ASK.get(kind, f'which {kind} do you mean')}: {listed}?")
        symbol = next(iter(things))
        return [*words[:start], "the", *vocabulary.phrase_of(symbol).split(), *words[i + 1 :]]
    return words


def _name_starts(words: list[str], vocabulary: Vocabulary) -> bool:
    """Whether two words said together start a name of the world ("snack bar", "fruit bowl")."""
    said = " ".join(words)
    return len(words) == 2 and any(f"{t.phrase} ".startswith(f"{said} ") for t in vocabulary.terms)


def _whichever(words: list[str], phrases: dict[str, Term]) -> None:
    """ "the mug or the cup, whichever is closer", "either the mug or the cup": ask which."""
    if "or" not in words or not ({"whichever", "either"} & set(words)):
        return
    at = words.index("or")
    before = [w for w in words[:at] if w not in _DETERMINERS]
    after = [w for w in words[at + 1 :] if w not in _DETERMINERS]
    first = next((" ".join(before[-n:]) for n in (3, 2, 1) if " ".join(before[-n:]) in phrases), None)
    second = next((" ".join(after[:n]) for n in (3, 2, 1) if " ".join(after[:n]) in phrases), None)
    if first is None or second is None or phrases[first].symbol == phrases[second].symbol:
        return
    tail = " ".join(words[words.index("whichever") :]) if "whichever" in words else ""
    judged = f" I cannot judge '{tail}' myself." if tail else ""
    raise AmbiguityError(f"which one, the {first} or the {second}?{judged}")


def came_from(previous: Sequence[CommandFrame], theme: str) -> str | None:
    """Where a thing put "back" came from: the source of the latest earlier action on it ("take the cup
    from the table and then put it back": the table), else None."""
    for frame in reversed(previous):
        if frame.get("theme") == theme and frame.get("source"):
            return frame.get("source")
    return None


_LANDMARKS = (("next", "to"), ("close", "to"), ("by",), ("near",), ("beside",))
#: words after a landmark that end its name: the state said last ("turn the lamp near the recliner on")
_AFTER_LANDMARK = frozenset({"on", "off", "out", "up", "down", "open", "shut", "closed", "please", "now"})
#: what "by" says of a change rather than of a place ("by half", "by a third", "by one quarter")
_BY_HOW_MUCH = frozenset({"half", "third", "thirds", "quarter", "quarters", "percent", "much", "notch"})


def _landmark_unknown(words: list[str], phrases: dict[str, Term], heads: set[str]) -> list[str]:
    """ "the light by the door" where no door is known and several lights: the landmark left out, so that
    the reader asks which light (``heads``: the last words of the names)."""
    for i in range(1, len(words)):
        landmark = next((m for m in _LANDMARKS if tuple(words[i : i + len(m)]) == m), None)
        if landmark is None:
            continue
        noun = words[i - 1][:-1] if words[i - 1].endswith("s") else words[i - 1]
        fitting = {t.symbol for p, t in phrases.items() if noun in (p.split()[-1], t.type) and not t.is_group}
        at = i + len(landmark)
        while at < len(words) and words[at] in _DETERMINERS:
            at += 1
        said = words[at:]
        while said and said[-1] in _AFTER_LANDMARK:
            said = said[:-1]
        if len(fitting) < 2 or not said or len(said) > 2 or " ".join(said) in phrases:
            continue
        if landmark == ("by",) and (set(said) & _BY_HOW_MUCH or said[0].isdigit()):
            continue  # "close the blind by half", "dim it by 20 percent": how much, no landmark
        if said[-1] in heads or said[-1][:-1] in heads:
            continue
        return words[:i]
    return words


def _room_first(words: list[str], vocabulary: Vocabulary, phrases: dict[str, Term]) -> list[str]:
    """After "and", "the bedroom lamps": "the lamps in the bedroom" (a room said before the name of a device
    or piece of furniture, which the reader narrows down by the place said right after it)."""
    for i, word in enumerate(words):
        if word != "and":
            continue
        at = i + 1
        while at < len(words) and words[at] in _DETERMINERS | {"both", "all"}:
            at += 1
        size = next((n for n in (2, 1) if " ".join(words[at : at + n]) in phrases), 0)
        room = phrases.get(" ".join(words[at : at + size]))
        if not size or room is None or not vocabulary.is_subtype(room.type, "room"):
            continue
        noun = words[at + size : at + size + 1]
        if not noun or " ".join(words[at : at + size + 1]) in phrases:
            continue
        single = noun[0][:-1] if noun[0].endswith("s") else noun[0]
        narrowed = ("device", "furniture")  # what a place narrows down; things said with it share it
        lasts = {
            p.split()[-1]
            for p, t in phrases.items()
            if any(vocabulary.is_subtype(t.type, k) for k in narrowed)
        }
        if noun[0] not in lasts and single not in lasts:
            continue
        return [*words[:at], noun[0], "in", "the", *words[at : at + size], *words[at + size + 1 :]]
    return words


#: what says a thing left a place by accident ("fell off the shelf", "got knocked out of the crib")
_FELL = frozenset({"fell", "dropped", "slipped", "rolled", "tumbled", "knocked", "blown", "blew"})
_FROM = (("out", "of"), ("off", "of"), ("off",), ("from",))


def _fell_from(
    segments: list[list[str]], vocabulary: Vocabulary, phrases: dict[str, Term]
) -> list[list[str]]:
    """ "the teddy fell out of the crib, put it back": "put it back in the crib" (a later "back" with no
    place said after it is where the thing fell from)."""
    place: list[str] = []
    out = []
    for words in segments:
        kept = list(words)
        for i, word in enumerate(kept):
            if (
                word == "back"
                and place
                and (i + 1 == len(kept) or kept[i + 1] not in ("in", "on", "to", "into"))
            ):
                kept[i + 1 : i + 1] = ["in", "the", *place]
                place = []
                break
            if word not in _FELL:
                continue
            rest = kept[i + 1 :]
            skip = next((j for j in range(5) if any(tuple(rest[j : j + len(f)]) == f for f in _FROM)), 0)
            rest = rest[skip:]  # "i dropped the sponge off the counter"
            said = next((len(f) for f in _FROM if tuple(rest[: len(f)]) == f), 0)
            term = _name_at(rest, said, phrases)[0] if said else None
            if term is not None and any(vocabulary.is_subtype(term.type, k) for k in ("furniture", "room")):
                place = term.phrase.split()
        out.append(kept)
    return out


_ONTO = frozenset({"on", "onto", "in", "into", "inside"})


def _name_at(words: list[str], at: int, phrases: dict[str, Term]) -> tuple[Term | None, int]:
    """The thing named from ``at`` (past one determiner; the longest name of up to three words) and where its
    name ends, else None and where it would start."""
    at += at < len(words) and words[at] in _DETERMINERS
    size = next((n for n in (3, 2, 1) if " ".join(words[at : at + n]) in phrases), 0)
    return (phrases[" ".join(words[at : at + size])], at + size) if size else (None, at)


def _from_onto(words: list[str], vocabulary: Vocabulary, phrases: dict[str, Term]) -> list[str]:
    """ "put the mug from the coffee table on the tv table": "put the mug on the tv table from the coffee
    table" (the second place is where the thing goes: a piece of furniture, or a room the first is not in)."""
    for i, word in enumerate(words):
        if word != "from":
            continue
        source, end = _name_at(words, i + 1, phrases)
        if source is None or not vocabulary.is_subtype(source.type, "furniture") or end >= len(words):
            continue
        if words[end] not in _ONTO:
            continue
        goal, stop = _name_at(words, end + 1, phrases)
        if goal is None or goal.symbol == source.symbol:
            continue
        room = vocabulary.is_subtype(goal.type, "room")
        inside = goal.symbol in vocabulary.locations.get(source.symbol, ())
        # "from the desk in the den": the den's writing desk, though the box room has a "desk"
        inside = inside or (
            words[end - 2] in (*_DETERMINERS, "from")  # said by one word
            and any(
                t.phrase.split()[-1] == words[end - 1]
                and goal.symbol in vocabulary.locations.get(t.symbol, ())
                for t in phrases.values()
                if vocabulary.is_subtype(t.type, "furniture")
            )
        )
        if not (vocabulary.is_subtype(goal.type, "furniture") or (room and not inside)):
            continue
        return [*words[:i], *words[end:stop], *words[i:end], *words[stop:]]
    return words
