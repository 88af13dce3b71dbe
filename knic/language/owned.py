"""A speaker's own furniture, for :func:`knic.language.understanding.understand`: where the speaker has a
room named after them ("rhys_bedroom"), "my bed" is the bed in that room, when the world has several beds and
one of them is there ("hoodie from my bed": rhys's single bed, not the double bed or the camp bed). The world
names no owners of furniture; a person's room is the one sign of whose a piece of it is.
"""

from __future__ import annotations

import re

from knic.language.shortnames import contains
from knic.language.vocabulary import Vocabulary

_MY = re.compile(r"\b(my|ma) ([a-z]+(?: [a-z]+)?)\b", re.IGNORECASE)


def own_room(vocabulary: Vocabulary, speaker: str) -> str | None:
    """The one room named after the speaker (its name has the speaker's name as whole words), else None."""
    said = speaker.split("_")
    rooms = [
        symbol
        for symbol, kind in vocabulary.instances.items()
        if vocabulary.is_subtype(kind, "room") and contains(symbol.split("_"), said) and symbol != speaker
    ]
    return rooms[0] if len(rooms) == 1 else None


def owned_read(text: str, vocabulary: Vocabulary, speaker: str) -> str:
    """``text`` with "my <furniture>" said as "the <furniture> in <the speaker's room>" where that tells one
    of several pieces of furniture of that name (see the module docstring); else ``text``."""
    room = own_room(vocabulary, speaker)
    if room is None:
        return text
    where = vocabulary.phrase_of(room)

    def mine(match: re.Match[str]) -> str:
        for said in (match.group(2), match.group(2).split()[0]):
            named = _furniture_named(vocabulary, said.lower())
            there = [s for s in named if room in vocabulary.locations.get(s, ())]
            if len(named) > 1 and len(there) == 1:
                rest = match.group(2)[len(said) :]
                return f"the {said} in the {where}{rest}"
        return match.group(0)

    return _MY.sub(mine, text)


def _furniture_named(vocabulary: Vocabulary, said: str) -> list[str]:
    """The furniture whose name is ``said`` or ends with it."""
    found = {
        t.symbol
        for t in vocabulary.terms
        if vocabulary.is_subtype(t.type, "furniture") and (t.phrase == said or t.phrase.endswith(" " + said))
    }
    return sorted(found)
