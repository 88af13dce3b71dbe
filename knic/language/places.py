"""Where things are, for the reader (:class:`Places`, a part of :class:`knic.language.reader.Reader`): a
piece of furniture or a device narrowed by the place said with it ("the table in the kitchen", "the left
light in the bedroom"), the devices a command most likely means (those that take a level, those where the
command went), and the dimmers and blinds of rooms.
"""

from __future__ import annotations

from collections.abc import Sequence

from core.errors import LanguageError
from knic.language.chunks import Chunk, Chunker
from knic.language.clauses import Arg
from knic.language.commands import CommandLanguage
from knic.language.naming import called_so, named_after
from knic.language.placenames import beside_named, named_in_part
from knic.language.shortnames import contains
from knic.language.vocabulary import Term, Vocabulary


class Places:
    """The reader's knowledge of where things are (see the module docstring)."""

    vocabulary: Vocabulary
    language: CommandLanguage
    chunker: Chunker

    def is_a(self, term: Term, category: str) -> bool:
        """Whether a name's type is ``category`` or a subtype of it."""
        return self.vocabulary.is_subtype(term.type, category)

    def narrow(self, args: list[Arg]) -> None:
        """Narrow furniture and devices by the place said right after them ("the table in the kitchen",
        "the left light in the bedroom") or before them ("the kitchen table" said as two names)."""
        for index in range(1, len(args)):
            head, place = args[index - 1], args[index]
            if self._room_first(head, place):
                continue
            if (
                place.prep not in ("place", None)
                or place.chunk.kind != "entity"
                or head.chunk.kind != "entity"
            ):
                continue
            swapped = place.prep is None and not place.joined
            if swapped:
                head, place = place, head  # "kitchen light": the room said first
                if not any(self.is_a(t, "room") for t in place.chunk.terms):
                    continue
            rooms = [t for t in place.chunk.terms if self.is_a(t, "room") or self.is_a(t, "furniture")]
            narrowable = [t for t in head.chunk.terms if self.is_a(t, "furniture") or self.is_a(t, "device")]
            if rooms and narrowable and len(narrowable) != len(head.chunk.terms):
                # "the light in the study" where a "torchlight" is a light too: the robot knows where
                # furniture and devices are, not where things lie, so the place tells the study's light
                inside = [t for t in narrowable if any(self._within(t, r) for r in rooms)]
                if not inside and all(self.is_a(t, "light") for t in narrowable):
                    inside = list(self._dimmers_in(rooms))  # "the light in the dining room": its chandelier
                if not inside or any(t.is_group for t in head.chunk.terms):
                    continue
                head.chunk = Chunk("entity", head.chunk.text, tuple(narrowable), role=head.chunk.role)
            if not rooms or not narrowable:
                continue
            grouped = any(t.is_group for t in head.chunk.terms)
            candidates = self._members(head.chunk.terms) if grouped else head.chunk.terms
            kept = tuple(t for t in candidates if any(self._within(t, r) for r in rooms))
            if not kept and place.prep is not None and place.prep_text not in self.language.containment:
                kept = self._near(candidates, rooms)  # "the bedside table next to the bed"
                kept = beside_named(kept, rooms, self.vocabulary)  # "the lamp by the bed": the bedside lamp
                kept = named_after(kept, rooms, self.vocabulary)  # "the light over the dining table"
                if all(self.is_a(t, "light") for t in candidates):
                    # "the light above the island": the island lights, a dimmer of its room named after it
                    around = {p for r in rooms for p in self.vocabulary.locations.get(r.symbol, ())}
                    located = self.vocabulary.locations
                    dimmers = [t for t in self._dimmers_in(()) if around & set(located.get(t.symbol, ()))]
                    named = named_after((*kept, *dimmers), rooms, self.vocabulary)
                    kept = named if len(named) == 1 and dimmers else kept
            if (
                not kept
                and all(self.is_a(t, "device") for t in candidates)
                and all(self.is_a(t, "furniture") for t in rooms)
            ):  # "the lamp on my desk": a device is in a room, not on furniture; the one in the desk's room
                kept = self._near(candidates, self._in_next_room(rooms, args, index))
                kept = beside_named(kept, rooms, self.vocabulary)
            if not kept and all(self.is_a(t, "light") for t in candidates):
                kept = self._dimmers_in(rooms)  # "the living room light" where a dimmer is the room's light
            elif grouped and self._all_said(head) and all(self.is_a(t, "light") for t in candidates):
                # "all the lights in the bedroom": its bedside lamp too, a dimmer being a light that dims
                kept += tuple(t for t in self._dimmers_in(rooms) if t.symbol not in {k.symbol for k in kept})
            if not kept:  # "the desk in the den": the writing desk there, though the box room has a "desk"
                also = self.chunker.also_named(head.chunk.text)
                kept = tuple(t for t in also if any(self._within(t, r) for r in rooms))
            if not kept:
                where = self.vocabulary.phrase_of(rooms[0].symbol)
                plural = grouped or head.chunk.role == "plural"
                there = "there are no" if plural else "there is no"  # "there are no lights in the nursery"
                by = "in" if all(self.is_a(r, "room") for r in rooms) else place.prep_text or "by"
                raise LanguageError(f"{there} {head.chunk.text} {by} the {where} in this world")
            kept = named_in_part(kept, head.chunk.text, place.chunk.text, rooms, self.vocabulary)  # open plan
            said_in = place.chunk.text if all(self.is_a(r, "room") for r in rooms) else ""  # not on a desk
            kept = called_so(kept, head.chunk.text, self.vocabulary, said_in)  # "the light in the attic"
            head.chunk = Chunk("entity", head.chunk.text, kept, role=head.chunk.role)
            if swapped:  # "to the hallway table": the table, where the preposition before the room says
                head.prep, head.prep_text = place.prep, place.prep_text
            if grouped:  # "the lights in the bedroom": those of the group that are there
                head.quantity = head.quantity or "all"
            place.consumed = True

    def prefer_devices(self, arg: Arg, wants_level: bool, places: Sequence[str]) -> None:
        """Of the several devices one name fits, keep those that can do what is asked and are where the
        command went: with a level asked for, the dimmers and blinds ("turn the lamp up to half"); then those
        in the room of the latest place said before ("go to the living room and switch on the lamp"), where
        a dimmer may be the room's light. Nothing changes when no device fits these. A plural said alone ("go
        to the bedroom and close the blinds") is narrowed by the room only: those of the room gone to."""
        chunk = arg.chunk
        terms = tuple(t for t in chunk.terms if self.is_a(t, "device"))
        if chunk.kind != "entity" or (arg.quantity and not arg.plural) or len({t.symbol for t in terms}) < 2:
            return
        if wants_level and not arg.plural:
            levelled = tuple(t for t in terms if self.is_a(t, "dimmer") or self.is_a(t, "blinds"))
            if not levelled and all(self.is_a(t, "light") for t in terms):
                levelled = self._dimmers_in(tuple(t for t in self.vocabulary.terms if self.is_a(t, "room")))
            terms = levelled or terms
        for place in places:
            rooms = [t for t in self.vocabulary.terms if t.symbol == place and self.is_a(t, "room")]
            rooms += [
                t
                for t in self.vocabulary.terms
                if t.symbol in self.vocabulary.locations.get(place, ()) and self.is_a(t, "room")
            ]
            if not rooms:
                continue
            there = tuple(t for t in terms if any(self._within(t, r) for r in rooms))
            if not there and all(self.is_a(t, "light") for t in terms):
                there = self._dimmers_in(rooms)
            terms = there or terms
            break
        if len({t.symbol for t in terms}) < len({t.symbol for t in chunk.terms}):
            arg.chunk = Chunk("entity", chunk.text, terms, role=chunk.role)

    def levelled_in(self, rooms: Sequence[Term]) -> list[str]:
        """The dimmers and blinds in the rooms ("dim the lounge to 40": the lounge's dimmer)."""
        levelled = (t for t in self.vocabulary.terms if self.is_a(t, "dimmer") or self.is_a(t, "blinds"))
        return list(
            dict.fromkeys(
                t.symbol for t in levelled if not t.is_group and any(self._within(t, r) for r in rooms)
            )
        )

    def _dimmers_in(self, rooms: Sequence[Term]) -> tuple[Term, ...]:
        """The dimmers (dimmable lights) in the rooms, one term each; with no rooms, all of them."""
        found = {t.symbol: t for t in self.vocabulary.terms if self.is_a(t, "dimmer") and not t.is_group}
        return tuple(t for t in found.values() if not rooms or any(self._within(t, r) for r in rooms))

    def _room_first(self, room: Arg, place: Arg) -> bool:
        """ "put the soap in the downstairs toilet on the basin": a room said with "in" right before a piece
        of furniture of a name that fits several narrows it to the one there (the room is then said)."""
        if (
            room.prep != "place"
            or room.prep_text not in ("in", "inside")
            or place.prep not in ("place", "goal")
        ):
            return False
        rooms = [t for t in room.chunk.terms if self.is_a(t, "room")]
        pieces = [t for t in place.chunk.terms if self.is_a(t, "furniture")]
        if not rooms or len(rooms) != len(room.chunk.terms) or len(pieces) != len(place.chunk.terms):
            return False
        kept = tuple(t for t in pieces if any(self._within(t, r) for r in rooms))
        if not kept or len({t.symbol for t in pieces}) < 2:
            return False
        place.chunk = Chunk("entity", place.chunk.text, kept, role=place.chunk.role)
        room.consumed = True
        return True

    def _in_next_room(self, pieces: Sequence[Term], args: list[Arg], index: int) -> Sequence[Term]:
        """The pieces of furniture in the room said right after them ("the desk in mei's room"), else all."""
        after = args[index + 1] if index + 1 < len(args) else None
        if after is None or after.prep != "place" or after.chunk.kind != "entity":
            return pieces
        rooms = [t for t in after.chunk.terms if self.is_a(t, "room")]
        return [t for t in pieces if any(self._within(t, r) for r in rooms)] or pieces

    @staticmethod
    def _all_said(arg: Arg) -> bool:
        """Whether "all" was said of the argument ("all the lights", as one name or as a quantity)."""
        return arg.quantity == "all" or arg.chunk.text.split()[:1] == ["all"]

    def _near(self, candidates: Sequence[Term], landmarks: Sequence[Term]) -> tuple[Term, ...]:
        """Of the candidates said with a landmark ("next to the bed"), those in the landmark's room; a lone
        candidate stays whatever the world says of its room."""
        rooms = {r.symbol for r in landmarks if self.is_a(r, "room")}
        rooms |= {p for r in landmarks for p in self.vocabulary.locations.get(r.symbol, ())}
        others = [t for t in candidates if t.symbol not in {r.symbol for r in landmarks}]
        kept = tuple(t for t in others if rooms & set(self.vocabulary.locations.get(t.symbol, ())))
        if not kept:  # devices the world places nowhere are where their names say ("the light by the bed")
            said = [t for t in self.vocabulary.terms if t.symbol in rooms]
            kept = tuple(
                t for t in others if self.is_a(t, "device") and any(self._within(t, r) for r in said)
            )
        return kept or (tuple(candidates) if len(candidates) == 1 else ())

    def _members(self, terms: Sequence[Term]) -> tuple[Term, ...]:
        """The terms of every member of the groups among ``terms`` (one term per member symbol)."""
        symbols = {m for t in terms for m in t.members}
        firsts = {t.symbol: t for t in reversed(self.vocabulary.terms) if t.symbol in symbols}
        return tuple(firsts[s] for s in sorted(firsts))

    def _within(self, term: Term, place: Term) -> bool:
        if place.symbol in self.vocabulary.locations.get(term.symbol, ()):
            return True
        if self.is_a(term, "device") and not (
            self.vocabulary.locations.get(term.symbol) and self.is_a(place, "room")
        ):
            # a device is where its name says (whole words: the den's lamp is no "garden room reading lamp"),
            # unless the world places it in another room (the top landing's light is not on the landing)
            return contains(term.symbol.split("_"), place.symbol.split("_")) or contains(
                term.phrase.split(), place.phrase.split()
            )
        return False
