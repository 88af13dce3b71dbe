"""Names that say where their thing is, for narrowing a name said with a place (used by
:meth:`knic.language.places.Places.narrow`).

* A device said with a part of a room's name, in a home whose rooms run into each other
  (:func:`named_in_part`). An open-plan "kitchen living room" is called "the kitchen" at one end and "the
  living room" at the other. "The light in the kitchen" and "the blinds in the living room" then name the
  device whose own name is the part said and the noun ("kitchen light", "living room blinds"), not every
  light or blind of the whole room; "the lights in the kitchen" where the room is called just "kitchen"
  stay all of its lights, as before; "the lamp on the desk" is said with no room and stays as it was.
* A thing said beside a piece of furniture whose own name says so ("the lamp by the bed", "the lamp next to
  the bed", a learner's "the lamp of the bed": the bedside lamp, not the desk lamp in the room of another
  bed; likewise "fireside", "poolside"): English compounds in "-side" name what is beside their first word
  (:func:`beside_named`).
"""

from __future__ import annotations

from collections.abc import Sequence

from knic.language.vocabulary import Term, Vocabulary


def named_in_part(
    terms: Sequence[Term], said: str, place: str, rooms: Sequence[Term], vocabulary: Vocabulary
) -> tuple[Term, ...]:
    """Of the devices ``terms`` (those of the room ``said`` with the ``place`` words), the one whose own name
    is ``place`` and ``said``'s noun, when ``place`` is only a part of the room's name; else ``terms``."""
    words = place.split()
    names = [vocabulary.phrase_of(r.symbol).split() for r in rooms]
    if not all(vocabulary.is_subtype(r.type, "room") for r in rooms):  # "the lamp on the desk": no room
        return tuple(terms)
    if not words or not names or any(n == words or not _part(words, n) for n in names):
        return tuple(terms)
    noun = said.split()[-1] if said.split() else ""
    # "the blind in the living room" may be its "living room blinds"; "the lights in the kitchen" are several,
    # not its "kitchen light" alone
    forms = {noun} if noun.endswith("s") else {noun, noun + "s"}
    own = {
        t.symbol
        for t in vocabulary.terms
        if t.symbol in {u.symbol for u in terms}
        and not t.given
        and t.phrase.split()[:-1] == words
        and t.phrase.split()[-1] in forms
    }
    return tuple(t for t in terms if t.symbol in own) if len(own) == 1 else tuple(terms)


def _part(words: list[str], name: list[str]) -> bool:
    """Whether ``words`` are said in ``name`` as a run of whole words."""
    return any(name[i : i + len(words)] == words for i in range(len(name) - len(words) + 1))


def beside_named(
    terms: Sequence[Term], landmarks: Sequence[Term], vocabulary: Vocabulary
) -> tuple[Term, ...]:
    """Of ``terms`` said beside ``landmarks``, those whose own name has the landmark's noun and "side" as one
    word ("bedside lamp" beside a bed); else ``terms``."""
    sides = {vocabulary.phrase_of(t.symbol).split()[-1] + "side" for t in landmarks}
    kept = tuple(t for t in terms if sides & set(vocabulary.phrase_of(t.symbol).split()))
    return kept or tuple(terms)
