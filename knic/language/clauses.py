"""Clauses of a command: chunks split into one clause per action, each with its noun phrases and roles.

A new action starts at every verb (with or without "and" / "then" before it); "and" before a noun joins
several objects in one action. A verb right after a bare motion verb says what to do ("go get the cup"); a
verb that implies a state, said after the thing it is about, is that state ("i want the blinds open"). Words
before the first verb are a clause of their own when they make a device command ("lights off") or, when the
command has no verb at all, a request for the things they name ("the remote please"); otherwise they are
taken as address. A device named right after another device's state or level starts a new device action
("lights off, blinds down"). See :mod:`knic.language.reader` for the whole reading.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field, replace

from knic.language.chunks import Chunk
from knic.language.shortnames import containers
from knic.language.vocabulary import Term

_NOUNS = ("entity", "me", "pronoun", "everything", "there")
#: words that end a noun phrase the world has no name for ("the front door is open")
_LINKING = ("is", "are", "was", "were", "be")
#: words of a level said in words that say which way too ("all the way down", "as low as it goes"): a closing
#: verb does not turn them round, as it does "fully" ("close the blinds fully": closed)
_WAYS = frozenset(("up", "down", "low", "lowest", "high", "highest", "bright", "dim", "minimum", "maximum"))


@dataclass
class Arg:
    """A noun phrase of a clause with the preposition before it."""

    chunk: Chunk
    prep: str | None = None  # the preposition's role table ("source", "goal", "place", ...)
    prep_text: str = ""
    joined: bool = False  # "and" before it: the same role as the previous argument
    consumed: bool = False  # used to narrow down the previous argument
    quantity: str | None = None  # "all" or "both" said before it
    plural: bool = False  # its "all" is a plural said alone ("open the blinds"), not "all" said
    modifiers: tuple[str, ...] = ()  # unknown words before it ("the bedroom light" where there is none)


@dataclass
class Clause:
    """One action as said: its verb (None for a verbless device command) and what follows."""

    verb: Chunk | None
    args: list[Arg] = field(default_factory=list)
    states: list[str] = field(default_factory=list)
    levels: list[int] = field(default_factory=list)
    level_in_words: bool = False  # the last level said in words, not after "to" ("fully"): how far
    missing: list[str] = field(default_factory=list)  # unknown words where a name was expected
    unknown: list[str] = field(default_factory=list)  # other unknown words
    pending: list[str] = field(default_factory=list)  # unknown words since a noun phrase was expected
    vague: bool = False  # "a bit", "a little": a level meant but not said
    unsaid_goal: bool = False  # "away", "back": a destination meant but not said
    unsaid_text: str = ""  # the words that said so ("away")
    mine: bool = False  # "my" said: the speaker's own thing ("grab my glasses": for me)
    implicit: bool = False  # read with an unsaid object taken from before (the reader's second try)
    again: bool = False  # the verb before said again for another device ("the lamp off and the light too")

    def names_nothing(self) -> bool:
        """No noun phrase, state, level or missing name: only the verb and words not understood."""
        return not (self.args or self.states or self.levels or self.missing)

    def empty(self) -> bool:
        """Nothing said in the clause (besides its verb)."""
        return not (self.args or self.states or self.levels or self.missing or self.unknown)


@dataclass
class _Filling:
    """What the words read so far in a clause leave pending for the next one."""

    prep: Chunk | None = None
    joined: bool = False
    expecting: bool = False  # a noun phrase is expected (after a determiner or a preposition)
    quantity: Chunk | None = None
    after_prep: bool = False  # the chunk just before was a preposition
    article: str = ""  # the determiner just said, before a noun phrase
    indefinite: bool = False  # the latest noun phrase was said with "a", "an" or "one" ("one bottle")
    thing: str = ""  # the determiner of an object named by the chunk just before ("the" in "the candle")


#: words said right after a thing's name that are no noun of a longer name ("bring me the cup now")
_AFTER_A_THING = frozenset(
    {"now", "again", "too", "also", "first", "here", "there", "back", "soon", "instead", "already", "through"}
    | {"somewhere", "anywhere", "everywhere", "away", "over", "then", "today", "tonight", "you", "please"}
    | {"put", "left", "kept", "sent", "set", "done", "made", "got", "held", "laid", "sat", "stood", "found"}
    | {"lost", "fell", "hung", "stuck"}
    # the way it goes ("bring the cup round to tracy", "take the mug upstairs to the bedroom")
    | {
        "round",
        "around",
        "across",
        "along",
        "upstairs",
        "downstairs",
        "outside",
        "inside",
        "indoors",
        "outdoors",
    }
    # the way it goes on a boat ("take the tackle box aft to the stern", "bring the rope ashore")
    | {"aft", "astern", "ashore", "aboard"}
    | {"home", "together", "straight", "right", "quick", "fast", "asap", "later", "down", "up", "out", "in"}
    # whom it is said to ("fetch the mug mate", "bring the cup love to the kitchen")
    | {"mate", "buddy", "pal", "darling", "sweetie", "honey", "dear", "love", "sir", "madam", "robot"}
    | {
        "sweetheart",
        "pet",
        "hun",
        "lad",
        "son",
        "grandma",
        "granny",
        "gran",
        "nan",
        "nana",
        "grandad",
        "grandpa",
    }
    | {"mum", "mom", "dad", "auntie", "uncle"}
    # a word that joins what comes next, heard in the silence after a command ("bring me the remote but")
    | {
        "but",
        "and",
        "or",
        "nor",
        "so",
        "yet",
        "if",
        "because",
        "than",
        "that",
        "which",
        "who",
        "what",
        "when",
    }
    | {"where", "while", "though", "although", "unless", "until", "till", "like", "just", "not", "well"}
)
#: what may follow a longer name in an action
_GOES_ON = ("join", "prep", "verb")
#: endings of words that are no noun (participles, adverbs: "the lemon located on", "lying by", "quickly",
#: "the tablet brought to")
_NOT_NOUN_ENDINGS = ("ed", "en", "ing", "ly", "ght")


def _compound(
    clause: Clause, chunk: Chunk, nxt: Chunk | None, names_item: Callable[[Chunk], bool], article: str
) -> bool:
    """Whether an unknown word right after a thing's name said with a determiner, in an action, is the head of
    a longer name the world lacks ("bring me a candle holder" where the world has a candle: 'candle holder'
    is missing, the candle is not the argument). A container said after what it holds is that ("the water
    bottle": the water); a plural is the next thing of a list said without commas ("the mug, biscuits and
    the remote"); another thing's name too ("the mug, lemon and apple")."""
    if clause.verb is None or not clause.args or clause.args[-1].chunk.kind != "entity":
        return False  # "the teddy fell out of the crib": said of the thing, no name
    word = chunk.text
    if word in containers() or any(t.phrase.split()[-1] in containers() for t in chunk.terms):
        return False
    # the phrase goes on ("the candle holder from the kitchen"), or ends the command ("bring me a candle
    # holder", "the candle holder"; "fetch the mug quick", "the glasses mate": said to the robot)
    ended = (nxt is None and article in ("a", "an", "some", "the")) or (
        nxt is not None and nxt.kind in _GOES_ON
    )
    drawn_out = any(a == b == c for a, b, c in zip(word, word[1:], word[2:], strict=False))  # "pleeease"
    noun = (
        word.isalpha()
        and len(word) > 2
        and not (word.endswith("s") and not word.endswith("ss"))
        and not word.endswith(_NOT_NOUN_ENDINGS)
        and word not in _AFTER_A_THING | set(_LINKING)
        and not drawn_out
    )
    if chunk.kind != "unknown" or not ended or not noun:
        return False
    clause.missing.append(f"{clause.args.pop().chunk.text} {word}")
    return True


def _purpose(clause: Clause, chunk: Chunk, nxt: Chunk | None, filling: _Filling) -> bool:
    """Whether ``chunk`` is a word the world lacks said right after "for" at the end of an action whose
    person is already said ("bring me the remote for once", "get me an apple for breakfast"): what for, not
    for whom."""
    return (
        chunk.kind == "unknown"
        and filling.after_prep
        and filling.prep is not None
        and filling.prep.role == "beneficiary"
        and (nxt is None or nxt.kind in ("join", "verb"))
        and any(a.chunk.kind == "me" or a.prep == "beneficiary" for a in clause.args)
    )


#: determiners that make a thing the speaker's own
SPEAKERS_OWN = frozenset({"my", "our"})


def _subject(clause: Clause) -> Arg | None:
    """Take the noun phrase said last, with no preposition, from ``clause``: the subject of the verb that
    follows ("tracy needs the remote"); None when there is none."""
    if clause.args and clause.args[-1].prep is None and clause.args[-1].chunk.kind in ("entity", "pronoun"):
        return clause.args.pop()
    return None


def _before_verb(chunks: list[Chunk], index: int) -> list[Chunk]:
    """The chunk said right before the verb at ``index``, past a bare "to" ("help me to find it")."""
    before = chunks[max(index - 2, 0) : index]
    if len(before) == 2 and before[1].kind == "prep" and before[1].text == "to":
        return before[:1]
    return before[-1:]


def _given_to(chunks: list[Chunk], at: int, names_person: Callable[[Chunk], bool]) -> bool:
    """Whether "her" or "him" at ``at`` is whom a bringing verb right before it gives the thing after it to
    ("look for maria and bring her blanket": to maria, hers): a person is named earlier in the command and
    the action says no one else to give it to and nowhere to take it ("bring me her glasses", "bring her
    glasses to the kitchen" are possessives)."""
    verb = chunks[at - 1] if at else None
    if verb is None or verb.kind != "verb" or "BRINGING" not in verb.frames or verb.beneficiary is not None:
        return False
    if not any(c.kind in ("entity", "owner") and names_person(c) for c in chunks[: at - 1]):
        return False
    end = next((i for i in range(at + 1, len(chunks)) if chunks[i].kind in ("verb", "join")), len(chunks))
    return not any(c.kind == "me" or (c.kind == "prep" and c.role != "source") for c in chunks[at + 1 : end])


def _carried(clauses: list[Clause]) -> list[Clause]:
    """``clauses`` with a device said after another's state with the same verb and no state of its own ("turn
    the lamp off and the landing light too") put in that state."""
    for before, clause in itertools.pairwise(clauses):
        if clause.again and not (clause.states or clause.levels) and clause.args:
            clause.states, clause.levels = list(before.states), list(before.levels)
    return clauses


def split_clauses(
    chunks: list[Chunk],
    names_device: Callable[[Chunk], bool],
    names_item: Callable[[Chunk], bool] = lambda chunk: False,
    bare_verb: Chunk | None = None,
    context: list[Arg] | None = None,
    names_person: Callable[[Chunk], bool] = lambda chunk: False,
) -> list[Clause]:
    """Split chunks into clauses at verbs (a device said with the verb of the one before and no state of its
    own takes that one's state: :func:`_carried`).

    Args:
        chunks: the command's chunks (:class:`~knic.language.chunks.Chunker`).
        names_device: whether an entity chunk may name a device (for a verbless "lights off").
        names_item: whether an entity chunk may name an object (for a verbless "the remote please").
        bare_verb: the verb a command without any verb is read with when it names objects; None: refused.
        context: when given, receives the noun phrases said before the first verb that make no clause ("my
            glasses are in the bedroom, bring them to me": the glasses), for pronouns to refer to.
        names_person: whether an entity chunk names a person (for "find maria and bring her blanket").
    """
    chunks = [  # "her glasses": a possessive, not the pronoun
        Chunk("det", c.text)
        if c.kind == "pronoun"
        and c.role == "person"
        and i + 1 < len(chunks)
        and chunks[i + 1].kind == "entity"
        and not _given_to(chunks, i, names_person)
        else c
        for i, c in enumerate(chunks)
    ]
    for i, chunk in enumerate(chunks):  # "the light of the hallway": of a place is where it is
        after = next((c for c in chunks[i + 1 :] if c.kind != "det"), None)
        placed = after is not None and after.kind == "entity" and not names_item(after)
        if chunk.kind == "partitive" and placed:
            chunks[i] = Chunk("prep", chunk.text, role="place")
    preamble = Clause(None)
    clauses: list[Clause] = []
    current = preamble
    filling = _Filling()
    after_state = False  # the last word said a state ("switch the hallway light on")
    for index, chunk in enumerate(chunks):
        nxt = chunks[index + 1] if index + 1 < len(chunks) else None
        if (
            chunk.kind == "join"
            and after_state
            and current.verb is not None
            and nxt is not None
            and nxt.kind in ("det", "entity")
        ):
            # "switch the hallway light on and the bedroom lights off": the same verb again
            current = Clause(current.verb, again=True)
            clauses.append(current)
            filling, after_state = _Filling(), False
            continue
        ahead = next((c for c in chunks[index:] if c.kind not in ("det", "join")), None)
        if (
            (current.verb is None or current.verb.frames[0] == "OPERATING")
            and current.args
            and index > 0
            and (chunks[index - 1].kind in ("state", "level", "number", "percent") or after_state)
            and chunk.kind in ("entity", "det", "join")
            and ahead is not None
            and ahead.kind == "entity"
            and names_device(ahead)
        ):
            # "lights off, blinds down", "turn the lamp on, the blinds up": each device with its own state
            if current is preamble:
                clauses.append(preamble)
                preamble = Clause(None)
            current = Clause(current.verb, again=True)
            clauses.append(current)
            filling, after_state = _Filling(), False
            if chunk.kind == "join":
                continue
        after_state = chunk.kind == "state" or (chunk.kind == "prep" and chunk.state is not None)
        if chunk.kind == "verb":
            if current.verb is not None and not current.args and not current.states:
                if current.verb.frames == ("MOTION",):
                    current.verb = chunk  # "go get the cup": the second verb says what to do
                    continue
                if current.verb.frames == ("OPERATING",) and chunk.frames[0] == "OPERATING":
                    current.verb = chunk
                    continue
            if (
                current.verb is not None
                and current.verb.frames == ("ACCOMPANYING",)
                and len(current.args) == 1
                and current.args[0].prep is None
                and current.args[0].chunk in _before_verb(chunks, index)
                and current.args[0].chunk.kind in ("me", "entity")
                and not current.states
            ):
                # "help me find my glasses", "help oscar find his teddy bear": the second verb
                current.verb, current.args, filling = chunk, [], _Filling()
                continue
            if (
                chunk.state
                and current.args
                and not current.states
                and not current.levels
                and (
                    nxt is None
                    or nxt.kind in ("join", "verb")
                    or (nxt.kind in ("level", "number", "vague") and "OPERATING" in _frames(current))
                )
            ):
                # "i want the blinds open", "leave the lights on", "i'd like the blinds open halfway"
                current.states.append(chunk.state)
                continue
            # "the orchid needs water, take it to the kitchen": what a thing needs is said of it, no request
            of_thing = chunk.beneficiary == "subject" and bool(current.args) and current.args[-1].prep is None
            of_thing = of_thing and names_item(current.args[-1].chunk)
            subject = _subject(current) if chunk.beneficiary == "subject" and not of_thing else None
            unnamed = chunk.beneficiary == "subject" and index > 0 and chunks[index - 1].kind == "unknown"
            said = current.missing[-1:] if unnamed and subject is None else []
            current = Clause(replace(chunk, soft=True) if of_thing else chunk)
            if subject is not None:  # "tracy needs the remote": the remote is for tracy
                current.args.append(Arg(subject.chunk, "beneficiary", "for", False))
            current.missing.extend(said)  # "the kid wants the remote": no one the world knows
            clauses.append(current)
            filling = _Filling()
            continue
        _fill(current, chunk, nxt, filling, names_item)
    if preamble.empty():
        return _carried(clauses)
    devices = [a for a in preamble.args if names_device(a.chunk)]
    if devices and (preamble.states or preamble.levels or not clauses):
        clauses.insert(0, preamble)  # "lights off"; "the lights please" (the reader asks on or off)
    elif (
        not clauses
        and bare_verb is not None
        and not preamble.unknown
        and not preamble.states
        and not (len(chunks) > 1 and chunks[0].kind == "entity" and chunks[1].kind == "det")
        and (
            preamble.missing
            or any(a.chunk.kind == "everything" or names_item(a.chunk) for a in preamble.args)
        )
    ):
        # "the remote please": a request for it; a name said right before a determiner is a verb the robot
        # does not know ("water the plant")
        preamble.verb = bare_verb
        clauses.append(preamble)
    elif context is not None:
        context.extend(preamble.args)
    return _carried(clauses)


def _fill(
    clause: Clause,
    chunk: Chunk,
    nxt: Chunk | None,
    filling: _Filling,
    names_item: Callable[[Chunk], bool] = lambda chunk: False,
) -> None:
    """Add one chunk (not a verb) to a clause, updating what is pending for the next chunk."""
    after_thing, filling.thing = filling.thing, ""
    if (
        chunk.kind == "partitive"
        and clause.args
        and clause.args[-1].chunk.kind == "entity"
        and nxt is not None
        and (nxt.kind in ("entity", "det") or (nxt.kind == "unknown" and filling.indefinite))
    ):
        container = clause.args.pop()  # "a glass of water": the water is meant (not "me" in "hand me a ...")
        filling.prep = Chunk("prep", container.prep_text, role=container.prep) if container.prep else None
        filling.joined = container.joined
        # "a cup of tea": the tea, which the world may lack ("the remote of tv" stays the remote)
        filling.expecting = True
        return
    said_with = filling.article
    if chunk.kind == "det":
        filling.article = chunk.text
    elif chunk.kind in _NOUNS:
        filling.indefinite, filling.article = filling.article in ("a", "an", "one", "another"), ""
    if chunk.kind == "join":
        filling.joined = nxt is not None and nxt.kind in (*_NOUNS, "det", "unknown", "quant")
        last = clause.args[-1] if clause.args else None
        if filling.joined and last is not None and last.quantity == "both" and last.chunk.role != "plural":
            last.quantity = None  # "both the juice and the water": the two named, not two juices
        # "bring me juice and cookies": a plural after "and" joining things is one more thing, maybe missing
        thing = (
            last is not None and last.prep is None and last.chunk.kind == "entity" and names_item(last.chunk)
        )
        plural = nxt is not None and nxt.kind == "unknown" and nxt.text[-1:] == "s" and nxt.text[-2:] != "ss"
        filling.expecting = filling.expecting or (thing and plural)
        return
    if chunk.kind == "quant":
        if nxt is not None and nxt.kind in ("entity", "det"):
            filling.quantity = chunk  # "all the lights", "both lamps"
            return
        chunk = Chunk("everything", chunk.text)  # "turn off all": all of what is not said
    if chunk.kind == "vague":
        clause.vague = True
        return
    if chunk.kind == "det" and chunk.text in SPEAKERS_OWN:
        clause.mine = True
    if chunk.kind == "unsaid":
        clause.unsaid_goal = True
        clause.unsaid_text = chunk.text
        return
    if (
        chunk.kind == "pronoun"
        and chunk.role in ("item", "any")
        and filling.prep is None
        and any(a.prep is None and a.chunk.kind == "entity" and names_item(a.chunk) for a in clause.args)
    ):
        return  # "find the cup, it should be in the kitchen": the pronoun is the object just named
    if chunk.kind == "me" and chunk.role == "here" and filling.prep is None:
        filling.prep = Chunk("prep", "to", role="goal")  # "bring it here": to me
    if _purpose(clause, chunk, nxt, filling):
        clause.unknown.append(chunk.text)  # talk: refused only if the action names nothing else
        filling.prep, filling.expecting, filling.after_prep = None, False, False
        return
    if after_thing and _compound(clause, chunk, nxt, names_item, after_thing):
        return
    filling.thing = said_with if chunk.kind == "entity" and names_item(chunk) else ""
    filling.after_prep = chunk.kind == "prep"
    quantity = filling.quantity.role if filling.quantity is not None and chunk.kind == "entity" else None
    if quantity is None and chunk.kind == "entity" and chunk.role == "plural":
        quantity = "all"  # "turn on the lamps": every lamp
    add_to_clause(clause, chunk, nxt, filling.prep, filling.joined, filling.expecting)
    if quantity is not None:
        clause.args[-1].quantity = quantity
        clause.args[-1].plural = filling.quantity is None
    filling.expecting = chunk.kind in ("det", "prep") or (filling.expecting and chunk.kind == "unknown")
    if chunk.kind == "prep":
        filling.prep = chunk
    elif chunk.kind in _NOUNS:
        filling.prep, filling.joined, filling.quantity = None, False, None


def add_to_clause(
    clause: Clause,
    chunk: Chunk,
    nxt: Chunk | None,
    prep: Chunk | None,
    joined: bool,
    expecting: bool = False,
) -> None:
    """Add one chunk to a clause: a noun phrase as an argument, a state, a level, or an unknown word (a
    missing name when a noun phrase was expected and none follows)."""
    if chunk.kind == "there":  # a place: where an earlier action was (the reader resolves it)
        clause.args.append(Arg(chunk, prep.role if prep else "place", prep.text if prep else "in", joined))
    elif chunk.kind in _NOUNS:
        arg = Arg(chunk, prep.role if prep else None, prep.text if prep else "", joined)
        arg.modifiers = tuple(clause.pending)
        clause.args.append(arg)
    elif chunk.kind == "state" or (chunk.kind == "prep" and chunk.state):
        clause.states.append(chunk.state or "")
    elif chunk.kind in ("level", "number"):
        clause.levels.append(chunk.value or 0)
        # "to a quarter": where; "all the way down", "as low as it goes": which way is said too
        clause.level_in_words = chunk.kind == "level" and prep is None and not _WAYS & set(chunk.text.split())
    elif chunk.kind == "unknown":
        # a determiner after it starts the next noun phrase once an action is said ("bring my husband his
        # glasses": 'husband' is no one the world knows)
        ended = (
            nxt is None
            or nxt.kind in ("join", "prep", "verb")
            or (nxt.kind == "det" and clause.verb is not None)
        )
        # "give bethan the plasters", "take grandpa his ipad": a word between a verb that gives or takes and a
        # thing is whom it is for
        given_to = (
            clause.verb is not None
            and {"BRINGING", "TAKING"} & set(clause.verb.frames)
            and not (clause.args or clause.pending)
            and nxt is not None
            and nxt.kind == "det"
        )
        if (expecting and ended) or given_to:
            # the whole name not known ("the front door is open": 'front door'), not its last word
            phrase = [*clause.pending, chunk.text]
            while len(phrase) > 1 and phrase[-1] in _LINKING:
                phrase.pop()
            clause.missing.append(" ".join(phrase))
            clause.pending.clear()
        else:
            clause.unknown.append(chunk.text)
            if expecting:
                clause.pending.append(chunk.text)
    if chunk.kind != "unknown":
        clause.pending.clear()


def _frames(clause: Clause) -> tuple[str, ...]:
    """The frame kinds the clause's verb may start (none without a verb)."""
    return clause.verb.frames if clause.verb is not None else ()


def names_of(arg: Arg, kind: str, is_a: Callable[[Term, str], bool]) -> bool:
    """Whether an argument names a thing of ``kind`` ("item": "the glasses", "it", "them"; "person":
    "tracy", "him")."""
    said = arg.chunk
    if said.kind == "pronoun":
        return said.role in (kind, "any") if kind == "item" else said.role == kind
    return any(is_a(t, kind) for t in said.terms)
