"""Terse commands as people say them to smart speakers and voice assistants, and task descriptions read in
the third person (used by :class:`knic.language.reader.Reader` and :mod:`knic.language.roles`):

* a room said alone ("ok robot, dining room", "to the kitchen please"): go there; with a level ("living room
  to 30 percent"): its dimmer or blinds;
* a room switched on or off ("turn the hallway off", "switch the garage on"): the room's lights (its one
  light or dimmer, else the group of them); a level asked of a room's on/off lights is refused;
* a thing put from one piece of furniture onto another ("put the mug that's on the counter on the dining
  table"), or from a place to a "to" destination: the first is where it is taken from;
* a request told of someone ("tracy asks the robot to fetch her glasses", "annie asks for the tablet"): that
  action, for her where it would be for the speaker;
* verbs said of the robot in the third person ("the robot goes to the bedroom, then it finds the glasses");
* a person described before what they want ("annie, who is sitting on the sofa, wants the remote"): for her;
* a request quoted ("oscar says bring me the bottle"): "me" is the one quoted;
* the robot called by its name ("tiago, lounge dimmer to 30"): address.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import replace
from itertools import pairwise

from core.errors import LanguageError
from knic.language.chains import Reading
from knic.language.chunks import Chunk, Chunker, past_determiners
from knic.language.clauses import Arg, Clause
from knic.language.frames import SPEAKER, CommandFrame
from knic.language.vocabulary import Term, Vocabulary

#: states a room's lights are switched to
_SWITCHED = ("on", "off")
#: what a room said alone may come with: determiners, and a level
_LEVELLED = ("det", "level", "number", "percent")


def room_alone(chunks: list[Chunk], vocabulary: Vocabulary, chunker: Chunker) -> list[Chunk]:
    """A command that only names one room (with "to" and determiners at most) is a going there; with a level
    ("living room to 30 percent", "lounge at half") it is a setting of the room's dimmer or blinds; with "on"
    or "off" alone ("hallway on") a switching of its lights."""
    names = [c for c in chunks if c.kind == "entity"]
    rest = [c for c in chunks if c.kind != "entity"]
    if len(names) != 1 or not _names_only(vocabulary, names[0], ("room",)):
        return chunks
    if any(c.kind == "det" and c.text in ("a", "an") for c in rest):  # "a hall": no room of the house
        return chunks
    levelled = any(c.kind in ("level", "number") for c in rest)
    switched = [c for c in rest if c.state in _SWITCHED and c.kind in ("state", "prep")]
    roles = ("goal", "place", "level") if levelled else ("goal",)
    rest = [c for c in rest if c not in switched]
    if any(c.kind not in (*_LEVELLED, "prep") or (c.kind == "prep" and c.role not in roles) for c in rest):
        return chunks
    said = [c for c in rest if c.kind != "det"]
    if (not levelled and any(c.kind in _LEVELLED[1:] for c in rest)) or (switched and (levelled or said)):
        return chunks
    verb, frame = (
        ("set", "OPERATING") if levelled else ("turn", "OPERATING") if switched else ("go", "MOTION")
    )
    verbs = [c for c in chunker.chunks([verb]) if c.kind == "verb" and frame in c.frames]
    return [*verbs[:1], *chunks] if verbs else chunks


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


def devices_named_in(vocabulary: Vocabulary, rooms: Sequence[Term], said: str) -> list[str]:
    """The devices in the rooms whose own names end in the word a device was said by before ("close the
    curtains in the bedroom and the back room": the back room curtains), else []."""
    word = said.split()[-1] if said.split() else ""
    forms = {word, word + "s", word[:-1] if word.endswith("s") else word}
    found = [
        t.symbol
        for t in vocabulary.terms
        if word
        and not t.is_group
        and not t.given
        and vocabulary.is_subtype(t.type, "device")
        and t.phrase.split()[-1] in forms
        and any(_within(vocabulary, t, r) for r in rooms)
    ]
    return list(dict.fromkeys(found))


def _within(vocabulary: Vocabulary, device: Term, room: Term) -> bool:
    if room.symbol in vocabulary.locations.get(device.symbol, ()):
        return True
    return room.symbol in device.symbol or room.phrase in device.phrase


def taken_from_first(vocabulary: Vocabulary, args: list[Arg]) -> None:
    """Of two pieces of furniture said one after the other, each with its own preposition, where the first
    is not in the second ("the cup on the tv table in the cabinet"): the first is where the thing is taken
    from. Changes ``args`` in place."""
    for first, second in pairwise(args):
        if first.prep != "place" or second.prep not in ("place", "goal") or second.joined:
            continue
        furniture = all(_names_only(vocabulary, a.chunk, ("furniture",)) for a in (first, second))
        if not furniture or first.consumed or second.consumed:
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
        return _names_only(vocabulary, arg.chunk, ("room", "furniture"))

    last = max((i for i, a in enumerate(args) if a.prep == "goal" and place(a)), default=0)
    for arg in args[:last]:
        if arg.prep == "place" and not arg.consumed and place(arg):
            arg.prep = "source"


#: words that tell who asked for the action, between the person and "to" ("tracy asks the robot to ...",
#: "annie has told you to ...", "tracy would like the robot to ...")
_REPORTING = frozenset(
    {"asks", "asked", "has", "have", "had", "tells", "told", "orders", "ordered", "instructs", "instructed"}
    | {"requests", "requested", "commands", "commanded", "expects", "wishes", "wants", "needs", "would like"}
    | {"would", "like", "you", "says", "said"}
)
#: what quotes the request itself ("oscar says bring me the bottle", "maria tells the robot: go to the study")
_QUOTING = frozenset({"says", "said", "tells", "told"})
#: what asks for a thing ("annie asks for the tablet")
_ASKING_FOR = frozenset({"asks", "asked"})


def reported(
    chunks: list[Chunk], vocabulary: Vocabulary, bare_verb: Chunk | None
) -> tuple[list[Chunk], str | None]:
    """A request told of someone, as a task description says it ("tracy asks the robot to fetch her glasses",
    "annie wants the robot to close the blinds", "annie asks for the tablet"): the action as if she said it,
    and who asked (the one it is for where the speaker would be), else the chunks as they are and None."""
    if len(chunks) < 3 or not _names_only(vocabulary, chunks[0], ("person",)):
        return chunks, None
    people = {t.symbol for t in chunks[0].terms}
    i = 1
    while (
        i < len(chunks) and chunks[i].kind in ("unknown", "verb", "pronoun") and chunks[i].text in _REPORTING
    ):
        i += 1
    if i == 1 or i >= len(chunks) or len(people) != 1:
        return chunks, None
    asker = people.pop()
    if chunks[i].kind == "prep" and chunks[i].text == "for" and chunks[i - 1].text in _ASKING_FOR:
        return ([chunks[0], bare_verb, *chunks[i + 1 :]], asker) if bare_verb is not None else (chunks, None)
    quoted = chunks[i - 1].text in _QUOTING
    i = past_determiners(chunks, i)
    if quoted and i < len(chunks) and chunks[i].kind == "verb":  # "oscar says bring me the bottle": oscar
        return [chunks[0], *chunks[i:]], asker
    to = i + 1 < len(chunks) and chunks[i].kind == "prep" and chunks[i].text == "to"
    if (
        to
        and chunks[i + 1].kind in ("verb", "unknown")
        and chunks[i + 2 : i + 3]
        and chunks[i + 2].kind == "verb"
    ):
        # "hugo wants to leave, guide him to the exit", "annie wants to sleep, close the blinds": what the
        # person will do, said as the reason for the request (the person stays said, for "him" or "her")
        return [chunks[0], *chunks[i + 2 :]], None
    if to and chunks[i + 1].kind == "verb":
        return [chunks[0], *chunks[i + 1 :]], asker
    return chunks, None


def for_asker(reading: Reading, asker: str | None) -> Reading:
    """The frames of a request told of someone, with what was for the speaker for the one who asked."""
    if asker is None:
        return reading
    frames = [
        CommandFrame(f.kind, {**f.args, "beneficiary": asker}) if f.get("beneficiary") == SPEAKER else f
        for f in reading.frames
    ]
    return Reading(frames, reading.waypoints)


#: subjects said before a verb in a task description ("then it finds the glasses")
_SUBJECTS = frozenset({"it", "he", "she"})


def third_person_read(tokens: list[str], chunker: Chunker) -> list[str]:
    """Verbs said of the robot in the third person, as task descriptions say them ("the robot goes to the
    bedroom, then it finds the glasses", "picks up the apple and carries it to tracy"): read as the verb;
    "it", "he" or "she" right before such a verb is its subject and dropped. Words the reader knows stay, and
    so does a comparison's verb ("as bright as it goes")."""
    out: list[str] = []
    for token in tokens:
        base = _verb_of(token, chunker) if len(token) > 3 and token.endswith("s") else None
        if base is None or (out[-2:-1] == ["as"] and out[-1] in _SUBJECTS):  # "as bright as it goes"
            out.append(token)
            continue
        if out and out[-1] in _SUBJECTS:
            out.pop()
        out.append(base)
    return out


def _verb_of(word: str, chunker: Chunker) -> str | None:
    said = chunker.chunks([word])
    if not said or said[0].kind != "unknown":
        return None
    for base in (word[:-3] + "y" if word.endswith("ies") else "", word[:-2], word[:-1]):
        read = chunker.chunks([base]) if base else []
        if len(read) == 1 and read[0].kind == "verb":
            return base
    return None


def switched_only(vocabulary: Vocabulary, arg: Arg, args: list[Arg], levelled: bool) -> None:
    """A level asked of lights said with their room ("set the bedroom light to 40", "turn the light in the
    bedroom up a bit") where only a dimmer elsewhere could take one: refused, not another room's dimmer.
    The lights of a room said together where the room has a dimmer ("dim the lights in the lounge to 30"):
    its dimmer.

    Raises:
        LanguageError: the room's lights named can only be switched on or off.
    """
    terms = arg.chunk.terms
    dims = [vocabulary.is_subtype(t.type, "dimmer") for t in terms]
    lit = [d or vocabulary.is_subtype(t.type, "light") for d, t in zip(dims, terms, strict=True)]
    if not levelled or not terms or not all(lit) or all(dims):  # lights, or a room's lights and dimmers
        return
    rooms = [
        a
        for a in args
        if a.consumed and a.chunk.terms and all(vocabulary.is_subtype(t.type, "room") for t in a.chunk.terms)
    ]
    said = {t.symbol for a in rooms for t in a.chunk.terms}
    dimmers = {
        t.symbol: t
        for t in vocabulary.terms
        if vocabulary.is_subtype(t.type, "dimmer")
        and not t.is_group
        and said & set(vocabulary.locations.get(t.symbol, ()))
    }
    if rooms and dimmers and arg.quantity == "all":  # the room's lights said together: its dimmers
        arg.chunk = replace(arg.chunk, terms=tuple(dimmers.values()))
        arg.quantity = None if len(dimmers) == 1 else arg.quantity
    elif rooms:
        raise LanguageError(
            f"the {rooms[0].chunk.text} {arg.chunk.text} can only be switched on or off: say on or off"
        )


def told_read(tokens: list[str], chunker: Chunker, vocabulary: Vocabulary) -> tuple[list[Chunk], str | None]:
    """The chunks of a command with the readings of this module that come before all others (verbs in the
    third person, the robot's name as address, a person described before what
    they want, a request told of someone), and who asked (else None)."""
    chunks = chunker.chunks(third_person_read(tokens, chunker))
    chunks = robot_unnamed(chunks, vocabulary)
    return reported(described_subject(chunks, vocabulary), vocabulary, chunker.bare_verb)


#: what may stand between a person and what they want, describing where they are ("annie, who is sitting
#: on the sofa, wants the remote", "tracy is in the kitchen and needs a glass")
_DESCRIBING = ("unknown", "prep", "det", "join", "entity", "state")


def described_subject(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """A person said first, then where they are or what they do, then a verb whose subject is who it is for
    ("needs", "wants"): the person is that subject; the words between are dropped. Anything else stays."""
    verb = next((i for i, c in enumerate(chunks) if c.kind == "verb"), None)
    if verb is None or verb < 2 or chunks[verb].beneficiary != "subject":
        return chunks
    first, between = chunks[0], chunks[1:verb]
    if not _names_only(vocabulary, first, ("person",)):
        return chunks
    if any(c.kind not in _DESCRIBING for c in between):
        return chunks
    before = [c for c in between if c.kind != "det"]
    if before[-1:] and before[-1].kind == "entity" and (len(before) < 2 or before[-2].kind != "prep"):
        return chunks  # "annie said the kitchen needs the sponge": the kitchen is the subject
    if any(
        c.kind == "entity" and not all(_is(vocabulary, t, ("room", "furniture")) for t in c.terms)
        for c in between
    ):
        return chunks
    return [first, *chunks[verb:]]


def _is(vocabulary: Vocabulary, term: Term, kinds: Sequence[str]) -> bool:
    return any(vocabulary.is_subtype(term.type, k) for k in kinds)


def _names_only(vocabulary: Vocabulary, chunk: Chunk, kinds: Sequence[str]) -> bool:
    """Whether ``chunk`` names things of the world, every one of one of ``kinds`` ("room", "person")."""
    return (
        chunk.kind == "entity" and bool(chunk.terms) and all(_is(vocabulary, t, kinds) for t in chunk.terms)
    )


def robot_unnamed(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """The robot called by its name at the start or the end of a command ("tiago, lounge dimmer to 30",
    "bring me the keys r2d2"): address, dropped."""

    def robot(chunk: Chunk) -> bool:
        return _names_only(vocabulary, chunk, ("robot",))

    start, end = 0, len(chunks)
    while start < end and robot(chunks[start]):
        start += 1
    while end > start and robot(chunks[end - 1]):
        end -= 1
    return chunks[start:end] if (start, end) != (0, len(chunks)) else chunks


def wished_first(
    clause: Clause, first: list[list[CommandFrame]], frames: list[CommandFrame], wishes: Collection[str]
) -> int:
    """How many actions the command opens with that only say what the speaker wants ("i need the spare duvet
    from the airing cupboard", a verb of ``wishes``) when it then sends each of those things elsewhere ("bring
    it to the back bedroom", "put them on the table") or asks for a search ("i need my glasses, could you
    find them"): the wish says what and where from, the later action what to do, with no bringing of its own
    to the speaker; else 0. A wish said with where it should go, or
    followed by a bringing to the speaker, is left as said."""
    group = first[0] if clause.verb is not None and clause.verb.text in wishes and len(first) == 1 else []
    if (
        not group
        or frames[: len(group)] != group
        or any(f.kind != "BRINGING" or f.get("goal") for f in group)
    ):
        return 0
    later = {
        f.get("theme")
        for f in frames[len(group) :]
        if f.kind in ("PLACING", "SEARCHING")
        or (f.kind == "BRINGING" and (f.get("goal") or f.get("beneficiary") != SPEAKER))
    }
    return len(group) if all(f.get("theme") in later for f in group) else 0
