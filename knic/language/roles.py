"""Roles of a clause's arguments, one interpreter per frame kind.

Each interpreter takes a clause as heard and gives the frames it means, or raises
:class:`~core.errors.LanguageError` when the arguments do not fit the kind (the reader then tries the verb's
next kind: "take Tracy to the bedroom" is not a TAKING of an object, so it is an ACCOMPANYING). Prepositions
give roles ("from": source, "to": goal, "in"/"on"/"near": source, ground or goal by kind); a person said first
is who a carry is for ("bring me the glasses"); a place said right after furniture or a device narrows it down
(:meth:`Resolver.narrow`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Sequence
from typing import Protocol

from core.errors import LanguageError
from knic.language.chains import AmbiguityError, referent
from knic.language.chunks import Chunk
from knic.language.clauses import Arg, Clause, names_of
from knic.language.commands import CommandLanguage
from knic.language.frames import SPEAKER, CommandFrame
from knic.language.selecting import came_from
from knic.language.terse import devices_named_in, placed_from, room_lights, switched_only, taken_from_first
from knic.language.vocabulary import Term, Vocabulary, level_percent

Frames = list[CommandFrame]


class Resolver(Protocol):
    """What the interpreters ask of the reader (:class:`knic.language.reader.Reader`)."""

    vocabulary: Vocabulary
    language: CommandLanguage

    def is_a(self, term: Term, category: str) -> bool:
        """Whether a name's type is ``category`` or a subtype of it."""

    def resolve(
        self, arg: Arg, categories: Sequence[str], previous: Frames, groups: list[Frames]
    ) -> list[str]:
        """The symbols an argument names, of one of ``categories``."""

    def narrow(self, args: list[Arg]) -> None:
        """Narrow furniture and devices by the place said next to them."""

    def prefer_devices(self, arg: Arg, wants_level: bool, places: Sequence[str]) -> None:
        """Of the devices a name fits, keep those that can take a level and are where the command went."""

    def levelled_in(self, rooms: Sequence[Term]) -> list[str]:
        """The dimmers and blinds in the rooms."""


def _bringing(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "BRINGING")


def _taking(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "TAKING")


def _placing(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    return _carry(reader, clause, previous, groups, "PLACING")


def _carry(
    reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames], kind: str
) -> list[CommandFrame]:
    args = list(clause.args)
    try:
        reader.narrow(args)
    except AmbiguityError:
        raise
    except LanguageError:  # "put the cup that's on the tv table in the cabinet": from the one to the other
        taken_from_first(reader.vocabulary, args)
        reader.narrow(args)
    if kind == "PLACING":  # "move the stapler on the desk to the workbench": from the desk
        placed_from(reader.vocabulary, args)
    _landmarks_passed(reader, args, beside=kind != "PLACING")
    themes: list[str] = []
    roles: dict[str, str] = {}
    # where each object is taken from: "the remote from the living room and the glasses from the bedroom"
    sources: dict[str, str] = {}
    said_from: set[str] = set()  # objects whose source a "from" said (a bare "in"/"on" yields to it)
    goals: dict[str, str] = {}  # "the mug to the kitchen and the glass to the dining room"
    bare = [a for a in args if a.prep is None and not a.consumed]

    def person(arg: Arg) -> bool:
        chunk = arg.chunk
        return (
            chunk.kind == "me"
            or (chunk.kind == "pronoun" and chunk.role == "person")
            or (bool(chunk.terms) and all(reader.is_a(t, "person") for t in chunk.terms))
        )

    first_is_person = bare and person(bare[0])
    # "bring tom and nadia a water bottle": each of the people first said is given one
    also: list[Arg] = []
    while first_is_person and len(bare) > len(also) + 2 and bare[len(also) + 1].joined:
        if not person(bare[len(also) + 1]):
            break
        also.append(bare[len(also) + 1])
    for arg in also:
        bare.remove(arg)
    if (len(bare) >= 2 and not bare[1].joined) or (len(bare) == 1 and first_is_person and kind != "TAKING"):
        # "bring me the glasses", "give Tracy the cup": a person first is who it is for
        try:
            roles["beneficiary"] = reader.resolve(bare[0], ("person",), previous, groups)[0]
            for arg in (bare[0], *also):
                arg.consumed = True
        except LanguageError:
            pass
    to_person = False  # the latest argument said whom the thing goes to ("to granny in the living room")
    for arg in args:
        if arg.consumed:
            continue
        after_person, to_person = to_person, False
        if arg.prep == "place" and after_person and themes and _names_only_places(reader, arg):
            # "bring the juice to granny in the living room": where she is, so where the juice goes
            roles["goal"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
        elif arg.prep is None and themes and kind != "TAKING" and _names_only_places(reader, arg):
            # said without "to" ("put mug kitchen table"): where the objects go
            roles["goal"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
            for theme in themes:
                goals.setdefault(theme, roles["goal"])
        elif arg.prep is None or (arg.prep == "companion" and themes and _names_only(reader, arg, "item")):
            # "bring me the stamps along with the envelopes": one more thing
            themes += reader.resolve(arg, ("item",), previous, groups)
        elif arg.prep == "beneficiary" and kind == "BRINGING" and themes and _names_only_places(reader, arg):
            # "i'm needing the sponge for the kitchen", "the towels for the bathroom": where it goes
            roles["goal"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
        elif arg.prep == "beneficiary":
            roles["beneficiary"] = reader.resolve(arg, ("person",), previous, groups)[0]
            if themes and (kind == "PLACING" or (kind == "TAKING" and roles["beneficiary"] == SPEAKER)):
                # "pick up the blanket for me", "pop the remote on the footstool for me": a favour, not
                # where it goes; "take for me the slippers", said before the thing as "get me the slippers"
                # is, is whom it is for
                del roles["beneficiary"]
        elif arg.prep == "source":
            where = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
            for theme in themes or [""]:
                if theme not in said_from:
                    sources[theme] = where
                    said_from.add(theme)
        elif arg.prep == "goal" or (arg.prep in ("place", "level") and kind == "PLACING"):
            if arg.prep == "level" and arg.prep_text not in ("to",):
                continue
            if arg.prep == "place" and arg.chunk.kind == "me":
                continue  # "put it next to me on the couch": where it goes, by the speaker, not given them
            if (
                arg.chunk.kind == "me"
                or any(reader.is_a(t, "person") for t in arg.chunk.terms)
                or (arg.chunk.kind == "pronoun" and arg.chunk.role == "person")
            ):
                roles["beneficiary"] = reader.resolve(arg, ("person",), previous, groups)[0]
                # "to granny in the living room", "to me in the lounge" (not "here"): where they are
                to_person = roles["beneficiary"] != SPEAKER or arg.chunk.role != "here"
            else:
                roles["goal"] = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
                for theme in themes:
                    goals.setdefault(theme, roles["goal"])
        elif arg.prep == "place":
            if not themes:
                raise LanguageError(f"'{arg.prep_text} {arg.chunk.text}' but no object to {kind.lower()}")
            where = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
            if _carried_in(reader, clause, arg, roles):  # "bring the egg basket in the kitchen": into it
                roles["goal"] = where
                continue
            for theme in themes:
                sources.setdefault(theme, where)
    if not themes:
        themes = _implicit(clause, groups, reader.vocabulary, "item", "object")
    discarded = _discarded_into(reader, clause) if kind == "PLACING" and "goal" not in roles else None
    if discarded is not None:  # "throw the tissues away": into the bin
        roles["goal"] = discarded
    back = came_from(previous, themes[0]) if kind == "PLACING" and clause.unsaid_goal else None
    if back is not None and "goal" not in roles:  # "take the cup from the table, then put it back"
        roles["goal"] = back
    if kind == "PLACING" and "goal" not in roles and clause.unsaid_goal:  # "put the mug back"
        thing = reader.vocabulary.phrase_of(themes[0])
        raise AmbiguityError(f"where should I put the {thing}: on which piece of furniture or in which room?")
    if kind == "PLACING" and "goal" not in roles:
        thing = reader.vocabulary.phrase_of(themes[0])
        raise LanguageError(f"{_verb(clause)} the {thing} where? I heard no place")
    if kind == "TAKING" and ("goal" in roles or "beneficiary" in roles):
        kind = "BRINGING"
    if clause.verb is not None and clause.verb.beneficiary == "me" and "goal" not in roles:
        roles.setdefault("beneficiary", SPEAKER)
    if kind == "BRINGING" and "goal" not in roles and "beneficiary" not in roles:
        # "fetch the book": no one and nowhere said; a later "put it in the lounge" says where it goes,
        # else chain() makes it a BRINGING to the speaker
        kind = "TAKING"
    before = sources.pop("", None)  # "from the kitchen" said before the object ("get from the kitchen ...")
    frames = []
    for theme in dict.fromkeys(themes):
        source = sources.get(theme, before)
        own = {"goal": goals[theme]} if theme in goals else {}
        own.update({"source": source} if source else {})
        frames.append(CommandFrame(kind, {"theme": theme, **roles, **own}))
    for arg in also if "beneficiary" in roles else ():
        who = reader.resolve(arg, ("person",), previous, groups)[0]
        frames += [
            CommandFrame(f.kind, {**f.args, "beneficiary": who}) for f in frames if f.kind == "BRINGING"
        ]
    return frames


#: verbs that carry a thing somewhere: "in" a room said last after them, with no one and nowhere else said, is
#: where it goes, as a learner says "into" ("bring the egg basket in the kitchen"); after "fetch" or "get" (go
#: and get) or "take" (also to pick up: "take the laptop, the one in the study") it is where the thing is
_CARRY_VERBS = frozenset({"bring", "carry"})


def _carried_in(reader: Resolver, clause: Clause, arg: Arg, roles: dict[str, str]) -> bool:
    """Whether a room said with "in" last in a clause of a carrying verb is where the thing goes."""
    last = [a for a in clause.args if not a.consumed][-1:]
    return (
        clause.verb is not None
        and clause.verb.text in _CARRY_VERBS
        and arg.prep_text == "in"
        and last == [arg]
        and not ({"goal", "beneficiary"} & set(roles))
        and all(reader.is_a(t, "room") for t in arg.chunk.terms)
    )


def _discarded_into(reader: Resolver, clause: Clause) -> str | None:
    """The world's one bin when a thing is thrown away ("throw the tissues away"; commands.yaml's
    ``discard_verbs`` and ``discard_places``), else None."""
    language = reader.language
    if clause.verb is None or clause.verb.text not in language.discard_verbs or clause.unsaid_text != "away":
        return None
    bins = {
        t.symbol for t in reader.vocabulary.terms_of(("furniture",)) if t.phrase in language.discard_places
    }
    return bins.pop() if len(bins) == 1 else None


def _verb(clause: Clause) -> str:
    return clause.verb.text.capitalize() if clause.verb is not None else "Do"


def _searching(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    _landmarks_passed(reader, args, beside=True)
    themes: list[str] = []
    ground: str | None = None
    # "check the kitchen for the lemon": the thing looked for after "for", the place said bare
    sought = any(a.prep == "beneficiary" and a.chunk.kind != "me" for a in args)
    bare = [a for a in args if a.prep is None]  # "find the glasses for tracy", "find for him": for whom
    found = all(names_of(a, "item", reader.is_a) for a in bare) if bare else _sought_just_before(groups)
    for index, arg in enumerate(args):
        if arg.consumed or (arg.prep == "beneficiary" and found and names_of(arg, "person", reader.is_a)):
            continue
        if arg.chunk.kind == "me" and arg.prep is None and any(a.prep is None for a in args[index + 1 :]):
            continue  # "find me the stapler": for the speaker, not the speaker sought
        if arg.prep is None and sought and _names_only_places(reader, arg):
            ground = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
        elif arg.prep is None or (arg.prep == "beneficiary" and arg.chunk.kind != "me"):
            themes += reader.resolve(arg, ("item", "person"), previous, groups)
        elif arg.prep in ("place", "source") or (arg.prep == "goal" and arg.prep_text not in DESTINATIONS):
            ground = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]  # "look into the den"
        elif arg.prep == "goal":  # "find the mug and to the kitchen": no search takes anything anywhere
            raise LanguageError(
                f"'{arg.prep_text} the {arg.chunk.text}' after {_verb(clause).lower()}: should something go"
                " there? Say what to do there"
            )
    if not themes and clause.unknown:  # "go find mommy": someone the world has no name for
        raise LanguageError(f"there is no '{clause.unknown[0]}' here: this world has nothing called that")
    if not themes:  # "where are my glasses? have a look by the sofa": what was just asked about
        themes = _sought_just_before(groups)
    if not themes:
        raise LanguageError(f"{_verb(clause)} what? I heard no object or person of this world")
    extra = {"ground": ground} if ground else {}
    return [CommandFrame("SEARCHING", {"theme": t, **extra}) for t in dict.fromkeys(themes)]


#: words that send something to a place (a search sends nothing anywhere: one said with them is asked about)
DESTINATIONS = frozenset({"to", "towards", "toward"})


def _sought_just_before(groups: list[Frames]) -> list[str]:
    """The things the latest group of frames looks for, when it only looks for things (a question such as
    "where are my glasses", or things only mentioned: "the keys are in the garage, can you look")."""
    latest = next((group for group in reversed(groups) if group), [])
    if not latest or any(frame.kind != "SEARCHING" for frame in latest):
        return []
    return [str(frame.get("theme")) for frame in latest if frame.get("theme")]


def _landmarks_passed(reader: Resolver, args: list[Arg], *, beside: bool) -> None:
    """Objects said only to show where, before or after the place they stand on ("put the stapler beside the
    laptop on the desk", "on the desk beside the laptop"): the place said with them is meant. With ``beside``,
    an object said only beside another with no place after ("the crossword next to the magnifying glass") says
    no place (not where a thing is put: "put the stapler beside the laptop" is still refused)."""
    for index, arg in enumerate(args):
        terms = arg.chunk.terms
        if (
            arg.prep == "place"
            and not arg.consumed
            and terms
            and all(reader.is_a(t, "item") for t in terms)
            and (
                any(
                    a.prep in ("place", "goal", "source") and _names_only_places(reader, a)
                    for a in args  # before or after it ("put the magazine on the table next to the remote")
                )
                or (
                    beside
                    and arg.prep_text not in reader.language.containment
                    and any(a.prep is None and not a.consumed for a in args[:index])
                )
            )
        ):
            arg.consumed = True


def _names_only(reader: Resolver, arg: Arg, kind: str) -> bool:
    """Whether an argument names things of one kind ("item": things to carry, "person") and nothing else."""
    terms = arg.chunk.terms
    return arg.chunk.kind == "entity" and bool(terms) and all(reader.is_a(t, kind) for t in terms)


def _names_only_places(reader: Resolver, arg: Arg) -> bool:
    terms = arg.chunk.terms
    return bool(terms) and all(reader.is_a(t, "room") or reader.is_a(t, "furniture") for t in terms)


def _accompanying(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    people: list[str] = []
    goal: str | None = None
    for arg in args:
        if arg.consumed:
            continue
        if arg.prep is None and people == [SPEAKER] and _names_only(reader, arg, "room"):  # "take me roof":
            goal = reader.resolve(arg, ("room",), previous, groups)[0]  # a learner's "to" left out
        elif arg.prep is None:
            people += reader.resolve(arg, ("person",), previous, groups)
        elif arg.prep in ("goal", "place", "level") and (
            arg.chunk.kind == "me" or _names_only(reader, arg, "person")  # "take tracy to me", "... to annie"
        ):
            if not people:  # "take this to tracy", "bring that to me": what is not said
                raise LanguageError(f"{_verb(clause)} what? I heard no object or person of this world")
            who = reader.vocabulary.phrase_of(people[0])
            whose = "you are" if arg.chunk.kind == "me" else f"{arg.chunk.text} is"
            raise AmbiguityError(f"where should I take {who}? Say the room: I do not know where {whose}")
        elif arg.prep in ("goal", "place", "level"):
            goal = reader.resolve(arg, ("room", "furniture"), previous, groups)[0]
    if not people:
        raise LanguageError(f"{_verb(clause)} whom? I heard no person of this world")
    if goal is None and SPEAKER in people:
        raise LanguageError(f"{_verb(clause)} {people[0]} where? I heard no room")
    # no room said ("fetch tracy"): a later action may say where (else the chain asks)
    where = {"goal": goal} if goal is not None else {}
    return [CommandFrame("ACCOMPANYING", {"theme": p, **where}) for p in dict.fromkeys(people)]


def _motion(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    for arg in args:
        if not arg.consumed and arg.prep is None and arg.chunk.kind != "entity":
            raise LanguageError(f"{_verb(clause)} where? '{arg.chunk.text}' is not a place")
        if (
            not arg.consumed
            and arg.prep is None
            and not any(reader.is_a(t, "room") or reader.is_a(t, "furniture") for t in arg.chunk.terms)
        ):
            raise LanguageError(f"{_verb(clause)} where? the {arg.chunk.text} is not a room or furniture")
    places = [a for a in args if not a.consumed and a.prep in ("goal", "place", "level", None)]
    way = [w for w in (*clause.unknown, *clause.missing) if w in _FLOORS]
    if not places and way:  # "go upstairs": a world file says no floors
        raise LanguageError(f"{_verb(clause)} {way[0]} to which room? I do not know what is {way[0]} here")
    if not places:
        raise LanguageError(f"{_verb(clause)} where? I heard no room or furniture of this world")
    carries = clause.verb is not None and {"PLACING", "BRINGING"} & set(clause.verb.frames)
    if carries and places[0].prep is None and any(a.prep == "goal" for a in places[1:]):
        # "move the sofa to the bedroom": a thing to move, not where to go ("go down the hall to the study")
        raise LanguageError(
            f"I cannot {_verb(clause)} the {places[0].chunk.text}: it is no object I can carry"
        )
    target = places[-1]
    # "go to tracy": to where a person is (said with a preposition; "come to me" asks which room)
    person = (
        target.prep is not None
        and target.chunk.kind == "entity"
        and bool(target.chunk.terms)
        and all(reader.is_a(t, "person") for t in target.chunk.terms)
    )
    goal = reader.resolve(target, ("person",) if person else ("room", "furniture"), previous, groups)[0]
    # "go with tracy to the kitchen": she goes too; "come with me to the kitchen": the robot goes
    others = [
        p
        for a in args
        if a.prep == "companion" and not a.consumed
        for p in reader.resolve(a, ("person",), previous, groups)
        if p != SPEAKER
    ]
    if others:
        return [CommandFrame("ACCOMPANYING", {"theme": p, "goal": goal}) for p in dict.fromkeys(others)]
    return [CommandFrame("MOTION", {"goal": goal})]


#: words of another floor, said where a room is meant
_FLOORS = frozenset({"upstairs", "downstairs"})


def _operating(reader: Resolver, clause: Clause, previous: Frames, groups: list[Frames]) -> Frames:
    args = list(clause.args)
    reader.narrow(args)
    devices: list[str] = []
    named = ""  # the word the latest device was said by ("curtains")
    for index, arg in enumerate(args):
        if arg.consumed or arg.prep == "beneficiary":  # "close the blinds for me"
            continue
        # "lights off in the scullery and the boot room", "... in the kitchen and in the scullery": more rooms
        more = arg.joined or (arg.prep == "place" and index > 0 and args[index - 1].consumed)
        if arg.chunk.kind == "entity" and not any(reader.is_a(t, "device") for t in arg.chunk.terms):
            rooms = [t for t in arg.chunk.terms if reader.is_a(t, "room")]
            # "switch on the study and the landing lights": "on" is the state, and the study's lights meant
            stated = arg.prep is None or (index == 0 and arg.prep_text in clause.states)
            again = devices_named_in(reader.vocabulary, rooms, named) if more and devices else []
            if again:  # "close the curtains in the bedroom and the back room": the back room's too
                devices += again
                continue
            # "dim the lounge to 40": the room's only dimmer; "dim the lounge": how far is then asked
            # (not by a verb that places things first: "tidy the living room" is no setting of its dimmer)
            operates = clause.verb is None or clause.verb.frames[:1] == ("OPERATING",)
            stateless = not clause.states and operates and (clause.verb is None or clause.verb.state is None)
            own = reader.levelled_in(rooms) if clause.levels or clause.vague or stateless else []
            said = clause.states[-1] if clause.states else clause.verb.state if clause.verb else None
            own = own or room_lights(reader.vocabulary, rooms, said)  # "turn the hallway off"
            after = args[index + 1] if index + 1 < len(args) else None  # "the study and landing lights"
            lights = after is not None and after.joined and after.chunk.text.endswith("lights")
            take = (arg.prep is None and len(own) == 1) or (stated and lights and bool(own))
            if take or (more and devices and own):
                devices += own
            elif stated and (arg.prep is None or not arg.modifiers):  # "switch off the telly": named
                raise LanguageError(f"'{arg.chunk.text}' is not a device I can operate")
            continue
        places = [f.get(r) or "" for f in reversed(previous) for r in ("goal", "ground") if f.get(r)]
        switched_only(
            reader.vocabulary, arg, args, bool(clause.levels or clause.vague)
        )  # "bedroom light to 40"
        reader.prefer_devices(arg, bool(clause.levels or clause.vague), places)
        devices += reader.resolve(arg, ("device",), previous, groups)
        named = arg.chunk.text
    if not devices:
        devices = _implicit(clause, groups, reader.vocabulary, "device", "light, dimmer or blinds")
    bells = [d for d in devices if _all_are(reader.vocabulary, list(reader.vocabulary.members(d)), "bell")]
    if bells:  # "ring the bell": a door bell is heard, not worked (no action of the domain sets it)
        raise LanguageError(f"I cannot work the {reader.vocabulary.phrase_of(bells[0])}: I can only hear it")
    way = [w for w in (*clause.unknown, *clause.missing) if w in _FLOORS]
    if way and len({m for d in devices for m in reader.vocabulary.members(d)}) > 1:  # "the lights downstairs"
        raise AmbiguityError(f"which rooms are {way[0]}? This world does not say: name the rooms, please")
    if clause.vague and not clause.levels:
        _ask_level(reader.vocabulary, list(dict.fromkeys(devices)))
    state = clause.verb.state if clause.verb is not None else None
    if clause.levels:
        level = clause.levels[-1]
        downward = state == "closed" or clause.states[-1:] == ["closed"]
        if downward and clause.level_in_words:  # "close the blinds fully", "the dimmer all the way down"
            level = 100 - level
        state = str(level)
    elif clause.states:
        state = clause.states[-1]
    members = [m for d in devices for m in reader.vocabulary.members(d)]
    kinds = [reader.vocabulary.type_of(m) or "" for m in members]
    is_light = [reader.vocabulary.is_subtype(k, "light") for k in kinds]
    lights = all(is_light)
    # "close all the lights": dimmers said with lights are switched as the lights are
    dimmed = all(
        lit or reader.vocabulary.is_subtype(k, "dimmer") for lit, k in zip(is_light, kinds, strict=True)
    )
    lit = lights or (any(is_light) and dimmed)
    if state == "closed" and dimmed:  # a dimmer alone: "close the desk lamp" (Hong Kong English) is off
        state = "off"  # ("turn the dimmer right up" stays full, not on)
    if state == "open" and dimmed and clause.verb is not None and clause.verb.text.startswith("open"):
        state = "on"  # "open the desk lamp", as "open the light": on
    if state in _LIGHT_STATES and lit:
        state = _LIGHT_STATES[state]  # "open the left light", "close all the lights" (dimmers too): on, off
    if state in _BLINDS_STATES and _all_are(reader.vocabulary, members, "blinds"):
        state = _BLINDS_STATES[state]  # "turn the blinds off": close them
    # "the lights please"; "dim the lounge", "set the dimmer": how far
    if state is None and (clause.verb is None or not lights):
        _ask_level(reader.vocabulary, list(dict.fromkeys(devices)))
    if state is None:
        named = " and the ".join(reader.vocabulary.phrase_of(d) for d in devices)
        raise LanguageError(f"{_verb(clause)} the {named} to what? Say on, off or a level")
    return [CommandFrame("OPERATING", {"device": d, "state": state}) for d in dict.fromkeys(devices)]


#: a light "opened" or "closed" is switched on or off (as several languages say it)
_LIGHT_STATES = {"open": "on", "closed": "off"}
#: blinds switched on or off are opened or closed (the level each means)
_BLINDS_STATES = {"on": "open", "off": "closed"}


def _all_are(vocabulary: Vocabulary, symbols: list[str], kind: str) -> bool:
    """Whether each of the symbols is of type ``kind`` (or a subtype)."""
    return all(vocabulary.is_of(s, kind) for s in symbols)


def _implicit(
    clause: Clause, groups: list[Frames], vocabulary: Vocabulary, category: str, what: str
) -> list[str]:
    """What an action said without its object is about: the thing of ``category`` said last before it
    ("the cup on the dining table, bring to me"; "mug is on the counter, take it and give to tracy"), as
    if "it" were said. A verb said alone takes nothing: in speech it is mostly a word heard in the silence
    after the command ("fetch me the mug pick").

    Raises:
        LanguageError: nothing of that kind was said before; a word the world does not know stood where the
            object goes ("bring me banana from kitchen") is named.
    """
    with contextlib.suppress(LanguageError):
        if clause.implicit and not clause.unknown and not clause.empty():  # a verb alone takes nothing
            # all the things said last ("apple and lemon, bring to me"), as if "them" were said
            return referent(Chunk("pronoun", "them", role=category), (category,), groups, vocabulary)
    if clause.unknown:
        raise LanguageError(f"there is no '{clause.unknown[0]}' here: this world has nothing called that")
    raise LanguageError(f"{_verb(clause)} what? I heard no {what} of this world")


def _ask_level(vocabulary: Vocabulary, devices: list[str]) -> None:
    """A level meant but not said ("turn the dimmer up a bit"): raise the question to ask back."""
    named = " and the ".join(vocabulary.phrase_of(d) for d in devices)
    members = [m for d in devices for m in vocabulary.members(d)]
    if all(vocabulary.is_of(m, "light") for m in members):
        raise AmbiguityError(f"the {named} can only be switched on or off: on or off?")
    levels = sorted(p for p in (level_percent(s) for s in vocabulary.instances) if p is not None)
    offered = ", ".join(str(p) for p in levels[:-1]) + f" or {levels[-1]}" if levels else "a level"
    raise AmbiguityError(f"how far should I set the {named}: {offered} percent?")


Interpreter = Callable[[Resolver, Clause, Frames, list[Frames]], Frames]
#: frame kind -> its interpreter
INTERPRETERS: dict[str, Interpreter] = {
    "BRINGING": _bringing,
    "TAKING": _taking,
    "PLACING": _placing,
    "SEARCHING": _searching,
    "ACCOMPANYING": _accompanying,
    "MOTION": _motion,
    "OPERATING": _operating,
}
