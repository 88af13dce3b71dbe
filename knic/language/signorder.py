"""Requests typed in the order of a sign language, or of a learner whose language puts the verb last and says
no prepositions, put as English says them (used by :func:`knic.language.naming.said_named`, on the sentences
of a command with the world's names). British Sign Language, like Turkish, Japanese or Korean, gives the
topic first and the verb last, and a deaf person typing English often keeps that order and leaves out "to",
"from" and "on", setting the parts apart with commas or dashes:

* a place or person said straight before a verb said last takes the preposition the verb asks for ("Ice
  pack — freezer take — Ottavio give": from the freezer, to Ottavio; "sofa take, garden bench put": from the
  sofa, on the garden bench; "courtyard go": to the courtyard), and an action after another is joined to it
  by "and", so that the verb is put first as for other speakers
  (:func:`knic.language.learners.verb_last_moved`);
* a place said alone between the thing and the verb ("Plasters, cabinet wet room — Theo bring", "Watering
  can — planter — put back") is where from for a verb that carries and where to for one that puts or goes;
  "back" after it is then left out (the place is said);
* a place said alone before "go there" ("Sofa — go there"): go to that place;
* where a thing said before is, said as a place and "there" or whose ("Glasses Nan's — recliner there. Bring
  me", "Laptop Wanjiru — desk her. Bring me"): on that place ("on her desk"); a thing and "there" after a
  place said alone ("Fridge — milk there? Check"): whether the thing is in the place, "check" said after it
  being that question;
* a thing said first, perhaps where it is, then a verb of carrying and a person alone ("Car keys, hook —
  take Kieran"): the thing taken from there to the person, not the person taken along;
* a verb said before a place with no preposition ("toolbox bring kitchen", "bring dining table"): the
  preposition the verb asks for ("to", "on"), the thing said before the verb put after it; a piece of
  furniture said straight before a room ("cabinet wet room"): "in" the room;
* a two-word name said the other way round, its describing word last ("mug spotty", as BSL, French or
  Italian put it): the name;
* a person said alone, then a place alone, then "check" ("Tracy — kitchen? Check"): whether the person is
  there;
* a person said with where they are and nothing else ("Wanjiru in her room?", a signer's or a Caribbean
  speaker's question with "is" left out): whether they are there.

Nothing changes in a sentence with a preposition or a verb before the names, or with no world name.
"""

from __future__ import annotations

from functools import lru_cache

from knic.language.vocabulary import Vocabulary

#: verbs said last, and the preposition each asks of a place said before it (a person is given "to")
_PLACE_PREP = {
    "take": "from",
    "grab": "from",
    "fetch": "from",
    "bring": "from",
    "give": "from",
    "put": "on",
    "place": "on",
    "go": "to",
    "come": "to",
    "wait": "at",
}
#: verbs after which a person said before is who the thing goes to
_TO_PERSON = frozenset({"give", "bring", "take", "fetch"})
#: words said after a verb said last, with it
_AFTER_VERB = frozenset({"back", "please", "there", "now"})
#: words that show a sentence is said in English order already
_PREPOSITIONS = frozenset(
    {"to", "from", "on", "in", "into", "onto", "off", "at", "out", "by", "near", "under", "for", "with", "of"}
)
_PLACES = frozenset({"room", "furniture"})
#: verbs of going, which take a place said alone before them as where to
_GOING = frozenset({"go", "come", "wait"})
#: words that make a stretch an action of its own, before which a later one is joined with "and"
_VERBS = frozenset(_PLACE_PREP) | {"on", "off", "open", "close", "turn", "switch", "where", "check"}


def signed_read(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """``segments`` (the sentences and stretches of one command) with the orders of the module docstring put
    as English says them; else as they are."""
    names = _names(vocabulary)
    out = [_owner_after(_described_after(list(s), names), names) for s in segments]
    said = [list(s) for s in out]  # as said, before a preposition is put in
    for i, words in enumerate(out):
        checked = i + 2 == len(out) and set(out[i + 1]) <= {"check", "look", "please"}
        if i and checked and _only_names(out[i - 1], names) == "person" and _places(words, names):
            return [*out[: i - 1], ["is", *out[i - 1], "in", *words]]  # "tracy — kitchen? check"
        if i and _there_said(out, i, names):  # "glasses nan's — recliner there", "fridge — milk there?"
            continue
        if i and _given_after(out, i, names):  # "car keys, hook — take kieran"
            continue
        verb = _last_verb(words)
        if verb is None:
            out[i] = _to_place(_be_asked(words, names), names)  # "wanjiru in her room?", "bring kitchen"
            if out[i] != words and i > 1 and _places(out[i - 1], names) and out[i][0] in _TO_PERSON:
                out[i - 1] = ["from", *_room_after(out[i - 1], names)]  # "biscuit tin, sideboard — bring ..."
            if out[i] != words and any(_VERBS & set(s) for s in said[:i]) and out[i][:1] != ["and"]:
                out[i] = ["and", *out[i]]  # "storage room, go. toolbox bring kitchen"
            continue
        at, verb_said = verb
        before = words[:at]
        placed = i and _places(out[i - 1], names)
        if _PREPOSITIONS & set(before):
            continue
        kind, size = _name_before(before, names)
        if kind == "person" and verb_said in _TO_PERSON:
            before = [*before[: len(before) - size], "to", *before[len(before) - size :]]
        elif kind in _PLACES and verb_said in _PLACE_PREP:
            before = [*before[: len(before) - size], _PLACE_PREP[verb_said], *before[len(before) - size :]]
        elif before or not placed or verb_said not in _PLACE_PREP:
            continue
        elif verb_said in _GOING:  # "sofa — go there": go to the sofa
            out[i] = [verb_said, _PLACE_PREP[verb_said], *out[i - 1]]
            out[i - 1] = []
            continue
        if placed and i > 1 and verb_said in _PLACE_PREP:
            # "plasters, cabinet wet room — theo bring": the place said alone is where from or to
            out[i - 1] = [_PLACE_PREP[verb_said], *_room_after(out[i - 1], names)]
        words = [w for w in [*before, *words[at:]] if w not in ("back", "there")]
        if any(_VERBS & set(s) for s in said[:i]) and words[:1] != ["and"]:
            words = ["and", *words]  # an action after another ("courtyard light on, courtyard go, wait")
        out[i] = words
    return [s for s in out if s]


@lru_cache(maxsize=16)
def _names(vocabulary: Vocabulary) -> dict[tuple[str, ...], str]:
    """The world's phrases as word tuples, with what each names: person, room, furniture or thing."""
    found: dict[tuple[str, ...], str] = {}
    last: dict[tuple[str, ...], set[str]] = {}
    for term in vocabulary.terms:
        for kind in ("person", "room", "furniture", "item", "device"):
            if vocabulary.is_subtype(term.type, kind):
                words = tuple(term.phrase.split())
                found.setdefault(words, kind)
                last.setdefault(words[-1:], set()).add(kind)  # "freezer" of the "fridge freezer"
                break
    for word, kinds in last.items():
        if len(kinds) == 1 and word:
            found.setdefault(word, next(iter(kinds)))
    return found


def _last_verb(words: list[str]) -> tuple[int, str] | None:
    """Where the verb said last is and which it is ("freezer take", "put back"), else None."""
    end = len(words)
    while end and words[end - 1] in _AFTER_VERB:
        end -= 1
    if end and words[end - 1] in _PLACE_PREP and (end > 1 or len(words) > end):
        return end - 1, words[end - 1]
    if end == 1 and words[0] in _PLACE_PREP:
        return 0, words[0]
    return None


def _name_before(before: list[str], names: dict[tuple[str, ...], str]) -> tuple[str | None, int]:
    """What the name said last in ``before`` names, and its length in words (the longest that fits)."""
    for size in range(min(4, len(before)), 0, -1):
        kind = names.get(tuple(before[-size:]))
        if kind is not None:
            return kind, size
    return None, 0


def _places(words: list[str], names: dict[tuple[str, ...], str]) -> bool:
    """Whether ``words`` are only names of places ("sofa"; "cabinet wet room": the cabinet in the room)."""
    said = words[1:] if words[:1] and words[0] in ("the", "my", "your", "his", "her", "our") else words
    while said:
        size = next((n for n in range(min(4, len(said)), 0, -1) if names.get(tuple(said[:n])) in _PLACES), 0)
        if not size:
            return False
        said = said[size:]
    return bool(words)


def _owner_after(words: list[str], names: dict[tuple[str, ...], str]) -> list[str]:
    """A thing's name and then a person's, opening a stretch with no verb ("headphones theo", "laptop
    wanjiru", a signer's order for whose thing it is): "theo's headphones"."""
    for size in range(min(4, len(words) - 1), 0, -1):
        if names.get(tuple(words[:size])) != "item":
            continue
        rest = words[size:]
        person = next(
            (n for n in range(min(3, len(rest)), 0, -1) if names.get(tuple(rest[:n])) == "person"), 0
        )
        if person and not _VERBS & set(words):
            return [*rest[: person - 1], rest[person - 1] + "'s", *words[:size], *rest[person:]]
        break
    return words


def _be_asked(words: list[str], names: dict[tuple[str, ...], str]) -> list[str]:
    """A person's name, then "in", "on" or "at" and a place, nothing else: "is" before it."""
    size = next((n for n in range(min(3, len(words)), 0, -1) if names.get(tuple(words[:n])) == "person"), 0)
    rest = words[size:]
    if not size or rest[:1] not in (["in"], ["on"], ["at"]) or _VERBS & set(rest[1:]):
        return words
    place = rest[1:]
    while place[:1] and place[0] in ("the", "my", "his", "her", "their", "our", "your"):
        place = place[1:]
    return ["is", *words] if names.get(tuple(place)) in _PLACES or place[-1:] == ["room"] else words


#: words said after a place for where a thing is ("recliner there") or whose it is ("desk her", BSL order)
_WHOSE = {"there": "", "her": "her", "his": "his", "mine": "my", "their": "their", "theirs": "their"}


def _there_said(out: list[list[str]], i: int, names: dict[tuple[str, ...], str]) -> bool:
    """Put where a thing said before is as English says it (see the module docstring), in place; whether
    the stretch at ``i`` was one of these."""
    words, before = out[i], out[i - 1]
    if len(words) < 2 or words[-1] not in _WHOSE or _VERBS & set(before):
        return False
    said = words[:-1]
    whose = [_WHOSE[words[-1]]] if _WHOSE[words[-1]] else []
    if names.get(tuple(said)) in _PLACES and any(
        names.get(tuple(before[n:m])) == "item"
        for n in range(len(before))
        for m in range(n + 1, len(before) + 1)
    ):
        out[i] = ["on", *whose, *said]  # "glasses nan's — recliner there": on the recliner
        return True
    if words[-1] == "there" and names.get(tuple(said)) == "item" and _places(before, names):
        out[i] = ["is", *said, "in", *before]  # "fridge — milk there?": is the milk in the fridge
        out[i - 1] = []
        if i + 1 < len(out) and out[i + 1] and set(out[i + 1]) <= {"check", "look", "please"}:
            out[i + 1] = []  # "..., check": that question
        return True
    return False


def _to_place(words: list[str], names: dict[tuple[str, ...], str]) -> list[str]:
    """ "toolbox bring kitchen", "bring dining table": a verb, then a place last with no preposition, in a
    stretch with none: the verb first, the thing, then "to" or "on" and the place; "umbrella bring me": the
    verb, "me", the thing."""
    verb = next((i for i, w in enumerate(words) if w in _PLACE_PREP and w not in _GOING), None)
    if verb is None or _PREPOSITIONS & set(words) or _VERBS & set(words[:verb]):
        return words
    place = words[verb + 1 :]
    if (
        place in (["me"], ["us"])
        and words[verb] in _TO_PERSON
        and _name_before(words[:verb], names)[0] == "item"
    ):
        return [words[verb], "me", *words[:verb]]  # "umbrella bring me"
    if names.get(tuple(place)) not in _PLACES or (
        words[:verb] and _name_before(words[:verb], names)[0] != "item"
    ):
        return words
    prep = "on" if _PLACE_PREP[words[verb]] == "on" else "to"
    return [words[verb], *words[:verb], prep, *place]


def _room_after(words: list[str], names: dict[tuple[str, ...], str]) -> list[str]:
    """ "cabinet wet room": a piece of furniture and then a room, "in" between."""
    for n in range(1, len(words)):
        if names.get(tuple(words[:n])) == "furniture" and names.get(tuple(words[n:])) == "room":
            return [*words[:n], "in", *words[n:]]
    return words


def _described_after(words: list[str], names: dict[tuple[str, ...], str]) -> list[str]:
    """Two words whose other order is a world name and theirs is none ("mug spotty"): that name."""
    out = list(words)
    for i in range(len(out) - 1):
        pair = (out[i], out[i + 1])
        if pair not in names and (pair[1], pair[0]) in names and names[(pair[1], pair[0])] == "item":
            out[i], out[i + 1] = pair[1], pair[0]
    return out


def _only_names(words: list[str], names: dict[tuple[str, ...], str]) -> str | None:
    """What ``words`` name, when they are one name only."""
    return names.get(tuple(words))


def _given_after(out: list[list[str]], i: int, names: dict[tuple[str, ...], str]) -> bool:
    """ "car keys, hook — take kieran": put as "car keys from hook and take to kieran", in place; whether the
    stretch at ``i`` was so."""
    words = out[i]
    if len(words) < 2 or words[0] not in _TO_PERSON or names.get(tuple(words[1:])) != "person":
        return False
    kinds = [_only_names(s, names) or ("place" if _places(s, names) else None) for s in out[:i]]
    if "item" not in kinds or any(k not in ("item", "place", "room", "furniture") for k in kinds):
        return False
    if kinds[-1] != "item":
        out[i - 1] = ["from", *_room_after(out[i - 1], names)]
    out[i] = ["and", words[0], "to", *words[1:]]
    return True
