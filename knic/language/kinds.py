"""The kinds of thing commands name (rooms, furniture, items, people, devices) and the robot, under the names
other domains give them.

The reader and the goals ask whether a symbol is a ``room``, an ``item`` or a ``person``: the ERL domain's
type names. A domain written elsewhere may call its rooms ``location`` and its people ``human``; without this
its every place was "not a room or a piece of furniture". :func:`aliased` puts the kind above such a type when
the domain declares no type of the kind's own name, so the domain's types and predicates stay as written.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import lru_cache
from typing import Any, Protocol

#: each kind a command names, and the type names other domains give it (in the order tried)
ALIASES: dict[str, tuple[str, ...]] = {
    "room": ("location", "place", "area", "zone", "waypoint"),
    "person": ("human", "people", "guest", "resident", "customer"),
    "item": ("thing", "obj", "physobj", "graspable", "pickable", "movable", "portable"),
    "furniture": ("surface", "furnishing"),
    "device": ("appliance", "switchable"),
    "robot": ("bot", "mobile_robot", "mobile_base"),
}


def aliased(types: Mapping[str, str | None]) -> dict[str, str | None]:
    """``{type: parent type}`` with each kind of :data:`ALIASES` the domain lacks by name put between the
    domain's types of its other names and their parent (``location - object`` becomes ``location - room``,
    ``room - object``); a type below another of the same kind's names keeps its parent (``waypoint -
    location`` stays). Unchanged when the domain names each kind itself or none otherwise."""
    out = dict(types)
    for kind, names in ALIASES.items():
        found = [name for name in names if name in out]
        if kind in out or not found:
            continue
        tops = [name for name in found if not _below(out, name, set(found) - {name})]
        out[kind] = out[tops[0]]
        for name in tops:
            out[name] = kind
    return out


def is_subtype(types: Mapping[str, str | None], type_name: str, ancestor: str) -> bool:
    """Whether ``type_name`` is ``ancestor`` or derives from it in ``{type: parent type}`` (every type derives
    from ``object``; a cycle of parents ends the walk)."""
    current: str | None = type_name
    for _ in range(len(types) + 1):  # longer than any chain of parents
        if current is None or current == ancestor:
            break
        current = types.get(current)
    return current == ancestor or ancestor == "object"


def _below(types: Mapping[str, str | None], name: str, others: set[str]) -> bool:
    """Whether ``name`` derives from one of ``others``."""
    parent = types.get(name)
    return parent is not None and any(is_subtype(types, parent, other) for other in others)


class Kinded(Protocol):
    """What :func:`phrases_of` needs of a vocabulary (:class:`~knic.language.vocabulary.Vocabulary`, which
    imports this module)."""

    @property
    def terms(self) -> Sequence[Any]: ...

    def is_subtype(self, type_name: str, ancestor: str) -> bool: ...


@lru_cache(maxsize=64)
def phrases_of(vocabulary: Kinded, *kinds: str) -> frozenset[str]:
    """The phrases of a vocabulary that name things of any of ``kinds`` (``"person"``; ``"furniture",
    "room"``), found once per vocabulary: the reader's rules ask on every read, and the vocabulary does not
    change."""
    kind_of = vocabulary.is_subtype
    return frozenset(t.phrase for t in vocabulary.terms if any(kind_of(t.type, k) for k in kinds))
