"""Terse commands as people say them to smart speakers and voice assistants, and task descriptions that
say where a thing is and where it goes in one breath:

* a room said alone, with nothing else asked ("ok robot, dining room", "to the kitchen please"): go there;
* a room switched on or off ("turn the hallway off", "switch the garage on"): the room's lights (its one
  light or dimmer, else the group of them);
* a thing put from one piece of furniture onto another ("put the mug that's on the counter on the dining
  table"): the first is where it is taken from, the second where it goes, when the first is not in the
  second.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise

from knic.language.chunks import Chunk, Chunker
from knic.language.clauses import Arg
from knic.language.vocabulary import Term, Vocabulary

#: states a room's lights are switched to
_SWITCHED = ("on", "off")


def room_alone(chunks: list[Chunk], vocabulary: Vocabulary, chunker: Chunker) -> list[Chunk]:
    """A command that only names one room (with "to" and determiners at most) is a going there."""
    names = [c for c in chunks if c.kind == "entity"]
    rest = [c for c in chunks if c.kind != "entity"]
    if len(names) != 1 or not names[0].terms:
        return chunks
    if not all(vocabulary.is_subtype(t.type, "room") for t in names[0].terms):
        return chunks
    if any(c.kind not in ("det", "prep") or (c.kind == "prep" and c.role != "goal") for c in rest):
        return chunks
    go = [c for c in chunker.chunks(["go"]) if c.kind == "verb" and "MOTION" in c.frames]
    return [*go[:1], *chunks] if go else chunks


def room_lights(vocabulary: Vocabulary, rooms: Sequence[Term], state: str | None) -> list[str]:
    """The lights (and dimmers) of the rooms when they are switched on or off; [] for any other state."""
    if state not in _SWITCHED:
        return []
    found = [
        t.symbol
        for t in vocabulary.terms
        if not t.is_group
        and (vocabulary.is_subtype(t.type, "light") or vocabulary.is_subtype(t.type, "dimmer"))
        and any(_within(vocabulary, t, r) for r in rooms)
    ]
    symbols = list(dict.fromkeys(found))
    group = vocabulary.group_of(symbols) if len(symbols) > 1 else None
    return [group] if group is not None else symbols


def _within(vocabulary: Vocabulary, device: Term, room: Term) -> bool:
    if room.symbol in vocabulary.locations.get(device.symbol, ()):
        return True
    return room.symbol in device.symbol or room.phrase in device.phrase


def taken_from_first(vocabulary: Vocabulary, args: list[Arg]) -> None:
    """Of two pieces of furniture said one after the other, each with its own preposition, where the first
    is not in the second ("the cup on the tv table in the cabinet"): the first is where the thing is taken
    from. Changes ``args`` in place."""

    def furniture(arg: Arg) -> bool:
        terms = arg.chunk.terms
        return (
            arg.chunk.kind == "entity"
            and bool(terms)
            and all(vocabulary.is_subtype(t.type, "furniture") for t in terms)
        )

    for first, second in pairwise(args):
        if first.prep != "place" or second.prep not in ("place", "goal") or second.joined:
            continue
        if not (furniture(first) and furniture(second)) or first.consumed or second.consumed:
            continue
        inside = any(
            s.symbol in vocabulary.locations.get(f.symbol, ())
            for f in first.chunk.terms
            for s in second.chunk.terms
        )
        if not inside:
            first.prep, second.prep = "source", "goal"
            return


def placed_from(vocabulary: Vocabulary, args: list[Arg]) -> None:
    """In a placing with a destination said after "to" ("move the stapler on the desk to the workbench"),
    the places said before it with "on" or "in" are where the thing is taken from. Changes ``args``."""

    def place(arg: Arg) -> bool:
        terms = arg.chunk.terms
        kinds = ("room", "furniture")
        return (
            arg.chunk.kind == "entity"
            and bool(terms)
            and all(any(vocabulary.is_subtype(t.type, k) for k in kinds) for t in terms)
        )

    last = max((i for i, a in enumerate(args) if a.prep == "goal" and place(a)), default=0)
    for arg in args[:last]:
        if arg.prep == "place" and not arg.consumed and place(arg):
            arg.prep = "source"
