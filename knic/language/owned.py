"""A speaker's and a person's own things and furniture, for :func:`knic.language.understanding.understand`.

* Where the speaker has a room named after them ("rhys_bedroom"), "my bed" is the bed in that room, when the
  world has several beds and one of them is there ("hoodie from my bed": rhys's single bed, not the double bed
  or the camp bed). A person's room is the usual sign of whose a piece of furniture is. So too for a device
  ("open my blind", "my room light off": the one in that room; "my big light": the big light there), and "my
  room" or "my bedroom" (or "me room", as said in Newfoundland, Ireland and the north of England) is that
  room; "the laptop of me" (a learner's "of" for whose) is "my laptop"; with no room named after them, the
  room of the furniture named after them ("joy_bed": "my bedroom" said by joy is the room her bed stands
  in). "His desk", "her room" are so of the person named last before them ("is finn's laptop on his desk":
  finn's desk), and "mei's lamp", "sol's blind" of the person named; "go to finn's" is to finn's room.
* Where a thing's or a piece of furniture's name holds a person's name ("kerry_keys", "maisie_lunchbox",
  "joy_bed"), "my keys" (or "my bed") said by kerry, "kerry's keys", "kerrys keys" (typed without the
  apostrophe) and "her keys" once kerry was named are that thing: the world names its owner. Said by someone
  who owns none of them, "my keys" still asks which. Where the words after the owner are the whole name of
  another thing ("dariush's laptop charger" beside "dariush_laptop" and "laptop_charger"), they name that
  thing, not the owner's laptop and then a charger.
* A person's name with an "s" and no apostrophe before a word ("get tylers basketball") is said as the
  owner ("tyler's"), not as the one to give it to.
* Things given to several people ("give tyler and maisie the lunchboxes", "... their lunchboxes") where each
  of them owns one of the things by its name go each to its owner, not every thing to every one of them
  (:func:`own_pairs`).
"""

from __future__ import annotations

import re
from functools import lru_cache

from knic.language.asides import titles_dropped
from knic.language.frames import CommandFrame
from knic.language.regional import FOR_WHOM
from knic.language.shortnames import contains
from knic.language.vocabulary import Vocabulary

_MY = re.compile(r"\b(my|ma|his|her|their) ([a-z]+(?: [a-z]+)?)\b", re.IGNORECASE)
_WORD = re.compile(r"[a-z']+")
_SPEAKERS = ("my", "ma", "mine")
_OTHERS = ("his", "her", "their")
_ROOMS = ("room", "bedroom")  # "my room": the speaker's own
_TITLES = r"(?:mr|mrs|miss|ms|mx|dr|master)\.?"  # said before a name ("Miss Mei's room")
#: what may follow a person's name said as an owner of no thing ("go to finn's", "... to finn's and then ...")
_SAID_ALONE = r"\s*(?:$|[,.!?;]|\s(?:and|then|to|for|please|now)\b)"


def own_room(vocabulary: Vocabulary, speaker: str) -> str | None:
    """The one room named after the speaker (its name has the speaker's name as whole words), else None."""
    said = speaker.split("_")
    rooms = [
        symbol
        for symbol, kind in vocabulary.instances.items()
        if vocabulary.is_subtype(kind, "room") and contains(symbol.split("_"), said) and symbol != speaker
    ]
    if rooms:
        return rooms[0] if len(rooms) == 1 else None
    # none named after them: the room of the furniture that is ("joy_bed" in the annexe bedroom)
    theirs = {
        room
        for symbol, kind in vocabulary.instances.items()
        if vocabulary.is_subtype(kind, "furniture") and contains(symbol.split("_"), said)
        for room in vocabulary.locations.get(symbol, ())
        if vocabulary.is_subtype(vocabulary.instances.get(room, ""), "room")
    }
    return theirs.pop() if len(theirs) == 1 else None


def owned_read(text: str, vocabulary: Vocabulary, speaker: str) -> str:
    """``text`` with a person's own things said by their names, and "my <furniture>" said as "the
    <furniture> in <the speaker's room>" where that tells one of several pieces of furniture of that name (see
    the module docstring); "his" or "her" likewise of the person named last before it; else ``text``."""
    text = titles_dropped(text, vocabulary)  # "Mama Adunni's room" (asides.py)
    text = _ME_ROOM.sub(_my_room, _things_read(_OF_ME.sub(r"my \1", text), vocabulary, speaker))
    people = {t.phrase: t.symbol for t in vocabulary.terms if vocabulary.is_subtype(t.type, "person")}

    def owner(match: re.Match[str]) -> str | None:
        said = match.group(1).lower()
        if said in _SPEAKERS:
            return speaker
        if said not in _OTHERS:  # "mei's lamp": the person named
            return people.get(said.removesuffix("'s").removesuffix("'"))
        before = text[: match.start()].lower()
        named = [
            (m.end(), symbol)
            for p, symbol in people.items()
            for m in re.finditer(rf"\b{re.escape(p)}\b", before)
        ]
        return max(named)[1] if named else None

    def mine(match: re.Match[str]) -> str:
        whose = owner(match)
        room = own_room(vocabulary, whose) if whose else None
        if room is None:
            return match.group(0)
        where = vocabulary.phrase_of(room)
        for said in (match.group(2), match.group(2).split()[0]):
            rest = match.group(2)[len(said) :]
            if said.lower() in _ROOMS:  # "bring it to my room": the room named after the speaker
                return f"the {where}{rest}"
            named = _placed_named(vocabulary, said.lower())
            there = [s for s in named if room in vocabulary.locations.get(s, ())]
            if len(named) > 1 and len(there) == 1:
                return f"the {said} in the {where}{rest}"
        head = match.group(2).split()[-1].lower()
        if len(match.group(2).split()) > 1 and not _placed_named(vocabulary, match.group(2).lower()):
            # "my big light": a word of its own before a name's last word; the one of the room, if any there
            there = [s for s in _placed_named(vocabulary, head) if room in vocabulary.locations.get(s, ())]
            if there:
                return f"the {match.group(2)} in the {where}"
        return match.group(0)

    def theirs(match: re.Match[str]) -> str:  # "go to finn's": the room named after finn
        room = own_room(vocabulary, people[match.group(1).lower()])
        return f"the {vocabulary.phrase_of(room)}" if room else match.group(0)

    text = _MY.sub(mine, text)
    names = "|".join(re.escape(p) for p in sorted(people, key=len, reverse=True))
    if not names:
        return text
    text = re.sub(rf"\b(?:{_TITLES}\s+)?({names})'s(?={_SAID_ALONE})", theirs, text, flags=re.IGNORECASE)
    owner_then = rf"\b(?:{_TITLES}\s+)?((?:{names})(?:'s|'))\s+([a-z]+(?: [a-z]+)?)\b"
    return re.sub(owner_then, mine, text, flags=re.IGNORECASE)


#: a learner's "the laptop of me" (Persian, Greek and Romance "of" for whose): "my laptop"
_OF_ME = re.compile(r"\bthe ((?:[a-z]+ ){0,2}[a-z]+) of (?:me|mine)\b", re.IGNORECASE)
#: "me" before "room" (Newfoundland, Irish and Northern English "the light in me room"), with the word before
_ME_ROOM = re.compile(r"(?:\b([a-z']+)\s+)?\bme (?=(?:room|bedroom)\b)", re.IGNORECASE)


def _my_room(match: re.Match[str]) -> str:
    """ "in me room", "to me room" -> "in my room", "to my room"; not after a verb that takes whom for ("show
    me room 4" stays)."""
    before = match.group(1) or ""
    if before.lower() in FOR_WHOM - {"to", "for", "with"}:
        return match.group(0)
    return f"{before} my " if before else "my "


def _placed_named(vocabulary: Vocabulary, said: str) -> list[str]:
    """The furniture and devices whose name is ``said`` or ends with it (devices are in rooms too: "my
    blind", "my room light")."""
    found = {
        t.symbol
        for t in vocabulary.terms
        if not t.is_group
        and (vocabulary.is_subtype(t.type, "furniture") or vocabulary.is_subtype(t.type, "device"))
        and any(t.phrase == s or t.phrase.endswith(" " + s) for s in _numbers(said))
    }
    return sorted(found)


def _numbers(said: str) -> tuple[str, ...]:
    """``said`` and its last word in the other number: "my blind" is one of the "... blinds" as well."""
    return (said, said.removesuffix("s")) if said.endswith("s") else (said, f"{said}s")


@lru_cache(maxsize=16)
def _owned(vocabulary: Vocabulary) -> tuple[tuple[str, ...], dict[tuple[str, str], str]]:
    """The people's names, and (owner, the rest of a thing's name) -> the thing's name, for the things whose
    names hold a person's name ("kerry keys": ("kerry", "keys"))."""
    people = sorted(
        {t.phrase for t in vocabulary.terms if vocabulary.is_subtype(t.type, "person")}, key=lambda p: -len(p)
    )
    owned: dict[tuple[str, str], str] = {}
    for term in vocabulary.terms:
        if not (vocabulary.is_subtype(term.type, "item") or vocabulary.is_subtype(term.type, "furniture")):
            continue
        words = term.phrase.split()
        for person in people:
            said = person.split()
            at = next((i for i in range(len(words)) if words[i : i + len(said)] == said), None)
            rest = words[:at] + words[at + len(said) :] if at is not None else []
            if rest:
                owned.setdefault((person, " ".join(rest)), term.phrase)
                break
    return tuple(people), owned


def _me_for_my(words: list[str], i: int, owned: dict[tuple[str, str], str], me: str) -> bool:
    """Whether "me" at ``i`` is "my" before a thing the speaker owns ("fetch us me mug", Yorkshire and Irish
    English), not whom a thing is for after a verb ("bring me mug"; :mod:`knic.language.regional`)."""
    if words[i] != "me" or (i and words[i - 1] in FOR_WHOM):
        return False
    return _owned_thing(owned, me, words[i + 1 : i + 3]) is not None


def _things_read(text: str, vocabulary: Vocabulary, speaker: str) -> str:
    """``text`` with the owned things of the module docstring said by their names (the rest kept as said)."""
    people, owned = _owned(vocabulary)
    if not people:
        return text
    spans = list(_WORD.finditer(text.lower()))
    words = [m.group(0) for m in spans]
    me = vocabulary.phrase_of(speaker)
    last = ""  # the person named latest, whom "his" or "her" means
    changes: list[tuple[int, int, str]] = []  # (first word, word after the last, said instead)
    i = 0
    while i < len(words):
        owner, end = _owner_at(words, i, people)
        if owner is None and (words[i] in _SPEAKERS or _me_for_my(words, i, owned, me)):
            owner, end = me, i + 1
        elif owner is None and words[i] in _OTHERS and last:
            owner, end = last, i + 1
        elif owner is None:
            last = next((p for p in people if words[i : i + len(p.split())] == p.split()), None) or last
            i += 1
            continue
        if words[i] not in _SPEAKERS + _OTHERS:
            last = owner
        thing = _owned_thing(owned, owner, words[end : end + 2])
        if thing is not None and thing[1] == 1 and _named_whole(vocabulary, words[end : end + 2]):
            # "dariush's laptop charger": the laptop charger, not dariush's laptop and a charger
            changes.append((i, end, "my" if words[i] in (*_SPEAKERS, "me") else "the"))
            i = end
            continue
        if thing is not None:
            # the owner stays said: "grab my keys" is still for the speaker, and "fetch maisie's lunchbox and
            # give it to her" names maisie for "her"
            said = (
                "my" if words[i] in (*_SPEAKERS, "me") else words[i] if words[i] in _OTHERS else f"{owner}'s"
            )
            changes.append((i, end + thing[1], f"{said} {thing[0]}"))
            i = end + thing[1]
            continue
        if words[end - 1] == owner.split()[-1] + "s":  # "tylers basketball"
            changes.append((end - 1, end, owner.split()[-1] + "'s"))
        i = end
    for first, after, said in reversed(changes):
        text = text[: spans[first].start()] + said + text[spans[after - 1].end() :]
    return text


def _owner_at(words: list[str], i: int, people: tuple[str, ...]) -> tuple[str | None, int]:
    """The person said as an owner at ``words[i]`` ("kerry's", "kerrys", "james'") and where that ends."""
    for person in people:
        said = person.split()
        end = i + len(said)
        if end > len(words) or words[i : end - 1] != said[:-1]:
            continue
        last = said[-1]
        forms = (last + "'s", last + "'") + ((last + "s",) if not last.endswith("s") else ())
        if words[end - 1] in forms and end < len(words):
            return person, end
    return None, i


@lru_cache(maxsize=16)
def _phrases(vocabulary: Vocabulary) -> frozenset[str]:
    """The world's phrases of things and furniture (read once per vocabulary)."""
    kinds = ("item", "furniture")
    return frozenset(
        t.phrase for t in vocabulary.terms if any(vocabulary.is_subtype(t.type, k) for k in kinds)
    )


def _named_whole(vocabulary: Vocabulary, after: list[str]) -> bool:
    """Whether two words said after an owner are a thing's whole name ("laptop charger")."""
    return len(after) == 2 and " ".join(after) in _phrases(vocabulary)


def _owned_thing(owned: dict[tuple[str, str], str], owner: str, after: list[str]) -> tuple[str, int] | None:
    """The name of ``owner``'s thing said by the (one or two) words ``after``, and how many words it took."""
    for n in (2, 1):
        said = " ".join(after[:n])
        if len(after) < n:
            continue
        forms = (said, said + "s", said[:-1] if said.endswith("s") else said)
        name = next((owned[(owner, f)] for f in forms if (owner, f) in owned), None)
        if name is not None:
            return name, n
    return None


def own_pairs(frames: list[CommandFrame]) -> list[CommandFrame]:
    """The frames with each thing given to its owner only, where things are given to several people and each
    of them owns exactly one of the things by its name (see the module docstring); else ``frames``."""
    given = [f for f in frames if f.kind == "BRINGING" and f.get("beneficiary") and f.get("theme")]
    people = list(dict.fromkeys(str(f.get("beneficiary")) for f in given))
    things = list(dict.fromkeys(str(f.get("theme")) for f in given))
    if len(people) < 2 or len(given) != len(people) * len(things):
        return frames
    owners = {p: [t for t in things if contains(t.split("_"), p.split("_"))] for p in people}
    if any(len(owned) != 1 for owned in owners.values()):
        return frames
    return [f for f in frames if f not in given or owners[str(f.get("beneficiary"))] == [f.get("theme")]]
