"""Reading commands as people say them: chunks, clauses, roles and frames from normalised text.

The reader is driven by the phrase tables of :mod:`knic.language.commands` (general English) and by a
world's :class:`~knic.language.vocabulary.Vocabulary` (its names). It is deliberately more forgiving than the
template grammar the speech decoder searches, and understands every sentence the templates admit.

Steps for one command:

1. **Chunks.** Left to right, the longest phrase at each position becomes one chunk: a world name (full
   phrase, else the last word of a longer name, else a plural: "table" may be any table, "cups" is "cup"),
   a verb, a preposition, a state, a level or number, a joiner, a determiner, a pronoun, "me"; fillers and
   politeness are dropped; anything else is an unknown word.
2. **Clauses.** A new action starts at every verb (with or without "and" / "then" before it); "and" before a
   noun joins several objects in one action. A clause without a verb is a device command when it names a
   device and a state ("lights off"), otherwise words before the first verb are taken as address.
3. **Frames.** The verb lists the frame kinds it may start; the first kind whose arguments fit by type wins
   ("take Tracy to the bedroom" is ACCOMPANYING, "take the cup to the kitchen" BRINGING). Prepositions give
   roles; a place right after a piece of furniture or a device narrows it down ("the table in the kitchen").
4. **Chains.** Pronouns take the previous action's referent; a TAKING followed by an action on the same
   object hands it its source; a MOTION followed by an action gives it its source or ground.

Errors are :class:`~core.errors.LanguageError` with one line for the user; an ambiguous name raises
:class:`AmbiguityError` whose message is the question to ask back.
"""

from __future__ import annotations

import copy
from collections.abc import Sequence
from dataclasses import dataclass, field

from core.errors import LanguageError
from knic.language.chunks import Chunk, Chunker
from knic.language.commands import CommandLanguage, command_language
from knic.language.frames import SPEAKER, CommandFrame
from knic.language.vocabulary import Term, Vocabulary, level_percent, normalize

MAX_ACTIONS = 3
Frames = list[CommandFrame]


class AmbiguityError(LanguageError):
    """A name fits several things; the message is the question to ask back."""


@dataclass
class Arg:
    """A noun phrase of a clause with the preposition before it."""

    chunk: Chunk
    prep: str | None = None  # the preposition's role table ("source", "goal", "place", ...)
    prep_text: str = ""
    joined: bool = False  # "and" before it: the same role as the previous argument
    consumed: bool = False  # used to narrow down the previous argument


@dataclass
class Clause:
    """One action as said: its verb (None for a verbless device command) and what follows."""

    verb: Chunk | None
    args: list[Arg] = field(default_factory=list)
    states: list[str] = field(default_factory=list)
    levels: list[int] = field(default_factory=list)
    missing: list[str] = field(default_factory=list)  # unknown words where a name was expected


@dataclass
class Reading:
    """Frames read from a command, before goals."""

    frames: list[CommandFrame]
    waypoints: set[int] = field(default_factory=set)  # indices of MOTION frames whose place went on


class Reader:
    """Reads normalised commands against one vocabulary (build once per vocabulary; :meth:`read` is pure)."""

    def __init__(self, vocabulary: Vocabulary, language: CommandLanguage | None = None):
        self.vocabulary = vocabulary
        self.language = language or command_language()
        self.chunker = Chunker(vocabulary, self.language)

    def chunks(self, tokens: Sequence[str]) -> list[Chunk]:
        """The chunks of a normalised token list (see :class:`~knic.language.chunks.Chunker`)."""
        return self.chunker.chunks(tokens)

    # ------------------------------------------------------------------ clauses

    def clauses(self, chunks: list[Chunk]) -> list[Clause]:
        """Split chunks into clauses at verbs; see the module docstring."""
        chunks = [  # "her glasses": a possessive, not the pronoun
            Chunk("det", c.text)
            if c.kind == "pronoun"
            and c.role == "person"
            and i + 1 < len(chunks)
            and chunks[i + 1].kind == "entity"
            else c
            for i, c in enumerate(chunks)
        ]
        clauses: list[Clause] = []
        current: Clause | None = None
        preamble: list[Chunk] = []
        pending_prep: Chunk | None = None
        joined = False
        expecting = False  # a noun phrase is expected (after a determiner or a preposition)
        for index, chunk in enumerate(chunks):
            nxt = chunks[index + 1] if index + 1 < len(chunks) else None
            if chunk.kind == "verb":
                if (
                    current is not None
                    and current.verb is not None
                    and not current.args
                    and not current.states
                ):
                    if "MOTION" in current.verb.frames and current.verb.frames == ("MOTION",):
                        current.verb = chunk  # "go get the cup": the second verb says what to do
                        continue
                    if current.verb.frames == ("OPERATING",) and chunk.frames[0] == "OPERATING":
                        current.verb = chunk
                        continue
                current = Clause(chunk)
                clauses.append(current)
                pending_prep, joined = None, False
                continue
            if current is None:
                preamble.append(chunk)
                continue
            if (
                chunk.kind == "partitive"
                and current.args
                and nxt is not None
                and nxt.kind in ("entity", "det")
            ):
                container = current.args.pop()  # "a glass of water": the water is meant
                pending_prep = (
                    Chunk("prep", container.prep_text, role=container.prep) if container.prep else None
                )
                joined = container.joined
                continue
            if chunk.kind == "join":
                joined = nxt is not None and nxt.kind in ("entity", "det", "pronoun", "me", "unknown")
                continue
            self._add_to_clause(current, chunk, nxt, pending_prep, joined, expecting)
            expecting = chunk.kind in ("det", "prep") or (expecting and chunk.kind == "unknown")
            if chunk.kind == "prep":
                pending_prep = chunk
            elif chunk.kind in ("entity", "pronoun", "me"):
                pending_prep, joined = None, False
        if preamble:
            verbless = self._verbless(preamble)
            if verbless is not None:
                clauses.insert(0, verbless)
        return clauses

    def _add_to_clause(
        self,
        clause: Clause,
        chunk: Chunk,
        nxt: Chunk | None,
        prep: Chunk | None,
        joined: bool,
        expecting: bool = False,
    ) -> None:
        if chunk.kind in ("entity", "me", "pronoun"):
            clause.args.append(Arg(chunk, prep.role if prep else None, prep.text if prep else "", joined))
        elif chunk.kind == "state" or (chunk.kind == "prep" and chunk.state):
            clause.states.append(chunk.state or "")
        elif chunk.kind in ("level", "number"):
            clause.levels.append(chunk.value or 0)
        elif chunk.kind == "unknown" and expecting and (nxt is None or nxt.kind in ("join", "prep", "verb")):
            clause.missing.append(chunk.text)

    def _verbless(self, preamble: list[Chunk]) -> Clause | None:
        clause = Clause(None)
        for index, chunk in enumerate(preamble):
            nxt = preamble[index + 1] if index + 1 < len(preamble) else None
            self._add_to_clause(clause, chunk, nxt, None, False)
        devices = [a for a in clause.args if any(self._is(t, "device") for t in a.chunk.terms)]
        if devices and (clause.states or clause.levels):
            return clause
        return None

    # ------------------------------------------------------------------ reading

    def read(self, text: str) -> Reading:
        """The frames of a command.

        Raises:
            AmbiguityError: a name fits several things (the message asks which).
            LanguageError: the command is not understood (the message says what is missing or unknown).
        """
        tokens = normalize(text).split()
        if not tokens:
            raise LanguageError("nothing to understand: the command is empty")
        chunks = self.chunks(tokens)
        clauses = self.clauses(chunks)
        if not clauses:
            unknown = [c.text for c in chunks if c.kind == "unknown"]
            if unknown:
                raise LanguageError(f"I do not know what to do: no action I know in '{' '.join(tokens)}'")
            raise LanguageError(f"no action in '{' '.join(tokens)}': say what to do, e.g. 'bring me ...'")
        if len(clauses) > MAX_ACTIONS:
            raise LanguageError(f"{len(clauses)} actions in one command; I take up to {MAX_ACTIONS} at once")
        frames: list[CommandFrame] = []
        groups: list[list[CommandFrame]] = []
        for clause in clauses:
            group = self._frames_of(clause, frames, groups)
            groups.append(group)
            frames.extend(group)
        return chain(frames, self.vocabulary)

    def _frames_of(
        self, clause: Clause, previous: list[CommandFrame], groups: list[list[CommandFrame]]
    ) -> list[CommandFrame]:
        if clause.missing:
            word = clause.missing[0]
            raise LanguageError(f"there is no '{word}' here: this world has nothing called that")
        kinds = clause.verb.frames if clause.verb is not None else ("OPERATING",)
        first_error: LanguageError | None = None
        for kind in kinds:
            try:
                # each reading starts from the clause as heard: an attempt marks arguments consumed
                found = _INTERPRETERS[kind](self, copy.deepcopy(clause), previous, groups)
            except AmbiguityError:
                raise
            except LanguageError as exc:
                first_error = first_error or exc
                continue
            if found:
                return found
        verb = clause.verb.text if clause.verb is not None else "the command"
        raise first_error or LanguageError(f"I do not know how to '{verb}' that")

    # ------------------------------------------------------------------ arguments

    def _is(self, term: Term, category: str) -> bool:
        return self.vocabulary.is_subtype(term.type, category)

    def resolve(
        self,
        arg: Arg,
        categories: Sequence[str],
        previous: list[CommandFrame],
        groups: list[list[CommandFrame]],
    ) -> list[str]:
        """The symbols an argument names (several for "them"), of one of ``categories``.

        Raises:
            LanguageError: the argument names nothing of those categories.
            AmbiguityError: it names several things.
        """
        chunk = arg.chunk
        if chunk.kind == "me":
            if "person" not in categories:
                raise LanguageError("'me' cannot be that")
            return [SPEAKER]
        if chunk.kind == "pronoun":
            return _referent(chunk, categories, previous, groups, self.vocabulary)
        terms = [t for t in chunk.terms if any(self._is(t, c) for c in categories)]
        if not terms:
            kinds = " or ".join(_NAMES.get(c, c) for c in categories)
            raise LanguageError(f"'{chunk.text}' is not {kinds}")
        symbols = list(dict.fromkeys(t.symbol for t in terms))
        if len(symbols) > 1:
            options = [self.vocabulary.phrase_of(s) for s in symbols]
            listed = ", ".join(f"the {o}" for o in options[:-1]) + f" or the {options[-1]}"
            raise AmbiguityError(f"which {chunk.text} do you mean: {listed}?")
        return symbols

    def narrow(self, args: list[Arg]) -> None:
        """Narrow furniture and devices by the place said right after them ("the table in the kitchen",
        "the left light in the bedroom") or before them ("the kitchen table" said as two names)."""
        for index in range(1, len(args)):
            head, place = args[index - 1], args[index]
            if (
                place.prep not in ("place", None)
                or place.chunk.kind != "entity"
                or head.chunk.kind != "entity"
            ):
                continue
            if place.prep is None and not place.joined:
                head, place = place, head  # "kitchen light": the room said first
                if not any(self._is(t, "room") for t in place.chunk.terms):
                    continue
            rooms = [t for t in place.chunk.terms if self._is(t, "room") or self._is(t, "furniture")]
            narrowable = [t for t in head.chunk.terms if self._is(t, "furniture") or self._is(t, "device")]
            if not rooms or not narrowable or len(narrowable) != len(head.chunk.terms):
                continue
            kept = tuple(t for t in head.chunk.terms if any(self._within(t, r) for r in rooms))
            if not kept:
                where = self.vocabulary.phrase_of(rooms[0].symbol)
                raise LanguageError(f"there is no {head.chunk.text} in the {where} in this world")
            head.chunk = Chunk("entity", head.chunk.text, kept)
            place.consumed = True

    def _within(self, term: Term, place: Term) -> bool:
        if place.symbol in self.vocabulary.locations.get(term.symbol, ()):
            return True
        if self._is(term, "device"):
            return place.symbol in term.symbol or place.phrase in term.phrase
        return False


_NAMES = {
    "item": "an object",
    "person": "a person",
    "room": "a room",
    "furniture": "a piece of furniture",
    "device": "a device",
    "light": "a light",
}


def _referent(
    chunk: Chunk,
    categories: Sequence[str],
    previous: list[CommandFrame],
    groups: list[list[CommandFrame]],
    vocabulary: Vocabulary,
) -> list[str]:
    wanted = chunk.role
    for group in reversed(groups):
        found: list[str] = []
        for frame in group:
            for role in ("theme", "beneficiary"):
                value = frame.get(role)
                if value is None or value == SPEAKER:
                    continue
                value_type = vocabulary.type_of(value) or ""
                fits = any(vocabulary.is_subtype(value_type, c) for c in categories)
                if (
                    fits
                    and (wanted == "any" or vocabulary.is_subtype(value_type, wanted))
                    and value not in found
                ):
                    found.append(value)
        if found:
            return found if chunk.text == "them" else found[-1:]
    thing = "an object" if wanted == "item" else "a person" if wanted == "person" else "anything"
    raise LanguageError(f"'{chunk.text}' does not refer to {thing} named earlier in the command")


def chain(frames: list[CommandFrame], vocabulary: Vocabulary) -> Reading:
    """Hand sources on along a chain; a TAKING that nothing carries on becomes a BRINGING to the speaker.

    A carry with no destination said ("fetch the book", "grab the cup") reads as a TAKING, so a destination
    said later for the same object ("... and put it in the lounge", "... then take it to the kitchen")
    replaces the speaker as where it ends.
    """
    out = list(frames)
    waypoints: set[int] = set()
    for index, frame in enumerate(out):
        later = out[index + 1 :]
        if frame.kind == "MOTION" and later:
            nxt = later[0]
            role = "ground" if nxt.kind == "SEARCHING" else "source"
            theme = nxt.get("theme")
            if nxt.kind in ("SEARCHING", "TAKING", "BRINGING") and nxt.get(role) is None and theme:
                out[index + 1] = CommandFrame(nxt.kind, {**nxt.args, role: frame["goal"]})
                waypoints.add(index)
        if frame.kind == "TAKING":
            carried = [  # a later carry of the same object, not one fetched again from elsewhere
                j
                for j in range(index + 1, len(out))
                if out[j].kind in ("BRINGING", "PLACING")
                and out[j].get("theme") == frame.get("theme")
                and out[j].get("source") in (None, frame.get("source"))
            ]
            if carried:
                j = carried[0]
                if out[j].get("source") is None and frame.get("source") is not None:
                    out[j] = CommandFrame(out[j].kind, {**out[j].args, "source": frame["source"]})
            else:
                out[index] = CommandFrame("BRINGING", {**frame.args, "beneficiary": SPEAKER})
    return Reading(out, waypoints)


# ---------------------------------------------------------------------- frame kinds


def _bringing(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "BRINGING")


def _taking(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "TAKING")


def _placing(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "PLACING")


def _carry(
    reader: Reader, clause: Clause, previous: list[CommandFrame], groups: list[list[CommandFrame]], kind: str
) -> list[CommandFrame]:
    args = list(clause.args)
    reader.narrow(args)
    themes: list[str] = []
    roles: dict[str, str] = {}
    bare = [a for a in args if a.prep is None and not a.consumed]
    first_is_person = bare and (
        bare[0].chunk.kind == "me"
        or (bare[0].chunk.kind == "pronoun" and bare[0].chunk.role == "person")
        or (bare[0].chunk.terms and all(reader._is(t, "person") for t in bare[0].chunk.terms))
    )
    if (len(bare) >= 2 and not bare[1].joined) or (len(bare) == 1 and first_is_person and kind != "TAKING"):
        # "bring me the glasses", "give Tracy the cup": a person first is who it is for
        try:
            roles["beneficiary"] = reader.resolve(bare[0], ("person",), previous, groups)[0]
            bare[0].consumed = True
        except LanguageError:
            pass
    for arg in args:
        if arg.consumed:
            continue
        if arg.prep is None:
            themes += reader.resolve(arg, ("item",), previous, groups)
        elif arg.prep == "beneficiary":
            roles["beneficiary"] = reader.resolve(arg, ("person",), previous, groups)[0]
        elif arg.prep == "source":
            roles["source"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
        elif arg.prep == "goal" or (arg.prep in ("place", "level") and kind == "PLACING"):
            if arg.prep == "level" and arg.prep_text not in ("to",):
                continue
            if (
                arg.chunk.kind == "me"
                or any(reader._is(t, "person") for t in arg.chunk.terms)
                or (arg.chunk.kind == "pronoun" and arg.chunk.role == "person")
            ):
                roles["beneficiary"] = reader.resolve(arg, ("person",), previous, groups)[0]
            else:
                roles["goal"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
        elif arg.prep == "place":
            if not themes:
                raise LanguageError(f"'{arg.prep_text} {arg.chunk.text}' but no object to {kind.lower()}")
            roles.setdefault("source", reader.resolve(arg, ("room", "furniture"), previous, groups)[0])
    if not themes:
        raise LanguageError(f"{_verb(clause)} what? I heard no object of this world")
    if kind == "PLACING" and "goal" not in roles:
        raise LanguageError(f"{_verb(clause)} the {themes[0]} where? I heard no place")
    if kind == "TAKING" and ("goal" in roles or "beneficiary" in roles):
        kind = "BRINGING"
    if clause.verb is not None and clause.verb.beneficiary and "goal" not in roles:
        roles.setdefault("beneficiary", SPEAKER)
    if kind == "BRINGING" and "goal" not in roles and "beneficiary" not in roles:
        # "fetch the book": no one and nowhere said; a later "put it in the lounge" says where it goes,
        # else chain() makes it a BRINGING to the speaker
        kind = "TAKING"
    return [CommandFrame(kind, {"theme": theme, **roles}) for theme in dict.fromkeys(themes)]


def _verb(clause: Clause) -> str:
    return clause.verb.text.capitalize() if clause.verb is not None else "Do"


def _searching(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    themes: list[str] = []
    ground: str | None = None
    for arg in args:
        if arg.consumed:
            continue
        if arg.prep is None:
            themes += reader.resolve(arg, ("item", "person"), previous, groups)
        elif arg.prep in ("place", "source"):
            ground = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
    if not themes:
        raise LanguageError(f"{_verb(clause)} what? I heard no object or person of this world")
    extra = {"ground": ground} if ground else {}
    return [CommandFrame("SEARCHING", {"theme": t, **extra}) for t in dict.fromkeys(themes)]


def _accompanying(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    people: list[str] = []
    goal: str | None = None
    for arg in args:
        if arg.consumed:
            continue
        if arg.prep is None:
            people += reader.resolve(arg, ("person",), previous, groups)
        elif arg.prep in ("goal", "place", "level"):
            goal = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
    if not people:
        raise LanguageError(f"{_verb(clause)} whom? I heard no person of this world")
    if goal is None:
        raise LanguageError(f"{_verb(clause)} {people[0]} where? I heard no room")
    return [CommandFrame("ACCOMPANYING", {"theme": p, "goal": goal}) for p in dict.fromkeys(people)]


def _motion(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    for arg in args:
        if not arg.consumed and arg.prep is None and arg.chunk.kind != "entity":
            raise LanguageError(f"{_verb(clause)} where? '{arg.chunk.text}' is not a place")
        if (
            not arg.consumed
            and arg.prep is None
            and not any(reader._is(t, "room") or reader._is(t, "furniture") for t in arg.chunk.terms)
        ):
            raise LanguageError(f"{_verb(clause)} where? the {arg.chunk.text} is not a room or furniture")
    places = [a for a in args if not a.consumed and a.prep in ("goal", "place", "level", None)]
    if not places:
        raise LanguageError(f"{_verb(clause)} where? I heard no room or furniture of this world")
    goal = reader.resolve(places[-1], ("room", "furniture"), previous, groups)[0]
    return [CommandFrame("MOTION", {"goal": goal})]


def _operating(reader: Reader, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    devices: list[str] = []
    for arg in args:
        if arg.consumed:
            continue
        if arg.chunk.kind == "entity" and not any(reader._is(t, "device") for t in arg.chunk.terms):
            if arg.prep is None:
                raise LanguageError(f"'{arg.chunk.text}' is not a device I can operate")
            continue
        devices += reader.resolve(arg, ("device",), previous, groups)
    if not devices:
        raise LanguageError(f"{_verb(clause)} what? I heard no light, dimmer or blinds of this world")
    state = clause.verb.state if clause.verb is not None else None
    if clause.levels:
        state = str(clause.levels[-1])
    elif clause.states:
        state = clause.states[-1]
    if state is None:
        raise LanguageError(f"{_verb(clause)} the {' and '.join(devices)} to what? Say on, off or a level")
    return [CommandFrame("OPERATING", {"device": d, "state": state}) for d in dict.fromkeys(devices)]


_INTERPRETERS = {
    "BRINGING": _bringing,
    "TAKING": _taking,
    "PLACING": _placing,
    "SEARCHING": _searching,
    "ACCOMPANYING": _accompanying,
    "MOTION": _motion,
    "OPERATING": _operating,
}

__all__ = ["AmbiguityError", "Reader", "Reading", "level_percent"]
