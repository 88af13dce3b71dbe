"""Orders and shortcuts of speakers of English as a second language, and of elderly speakers, read as the
command they mean (used by :class:`knic.language.reader.Reader`): the verb said last ("to the bathroom go"),
where the speaker themself goes said before the request ("i go to bed now, switch off the lamp"), a room told
by what is in it ("go to the room where is the bed"), "give it me", "you" before the verb after the thing
("toolbox you take from shelf"), a place said before the thing there ("on my desk is calculator") and a thing
said before the verb that puts it ("the dumbbells put on the weights bench and the boots on the rack"), and
"on" or "off" said as a verb after "and" ("switch off the office light and on the desk lamp"), where from
said first ("from the kitchen island the fruit bowl bring to my room"), a thing thrown to a person and a
thing said first with a count of its container after ("soju bring me one bottle")."""

from __future__ import annotations

from knic.language.chunks import Chunk, past_determiners
from knic.language.stepwise import listed_unknown, steps_read
from knic.language.tidy import unplaced
from knic.language.vocabulary import Vocabulary


def learners_read(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """The chunks with the orders of this module put as a command says them."""
    said = listed_unknown(chunks, vocabulary)  # "the apple and the banana, bring them": no banana here
    said = source_first(thrown_to(state_as_verb(said, vocabulary), vocabulary), vocabulary)
    said = subject_dropped(appositions_dropped(helped_to(said), vocabulary))
    said = gapped_given(out_the(carried_in(said, vocabulary), vocabulary), vocabulary)
    said = verb_last_moved(own_going_dropped(own_doing_dropped(room_told(it_me(said), vocabulary))))
    said = at_person(object_first(place_first(said, vocabulary), vocabulary), vocabulary)
    return steps_read(topic_measured(said, vocabulary), vocabulary)  # stepwise.py


#: what a thing is counted in ("one bottle", "a glass"), said after the thing itself by a speaker who says the
#: topic first
_MEASURES = frozenset(
    {"bottle", "glass", "cup", "can", "bowl", "box", "packet", "piece", "slice", "plate", "mug", "jar", "tin"}
)


def topic_measured(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "soju bring me one bottle", "water, bring me a glass" (the topic said first, as Korean, Japanese and
    Chinese speakers say it): a thing said alone before a verb that carries to the speaker, then "one" or "a"
    and a container said last, is what the container holds: "bring me one bottle of soju" (a thing the world
    lacks is named, not the bottles asked about). A person said first is whom the speaker addresses."""
    kinds = [c.kind for c in chunks]
    if kinds[1:4] != ["verb", "me", "det"] or len(chunks) != 5 or chunks[3].text not in ("a", "an", "one"):
        return chunks
    topic, verb, _, _, container = chunks
    thing = topic.kind == "unknown" or _is(topic, vocabulary, "item")
    if not thing or "BRINGING" not in verb.frames or container.text.split()[-1] not in _MEASURES:
        return chunks
    return [*chunks[1:], Chunk("partitive", "of"), topic]


def at_person(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "bring the apple at Annie", "bring at me the glasses" (a learner's "at" for "to": Spanish and Italian
    "a", French "à"): "at" after a verb that gives or takes, right before a person or "me", is "to"; a thing
    is never at a person ("the coke at the kitchen table" stays where it is)."""
    out = list(chunks)
    giving = False
    for i, chunk in enumerate(out[:-1]):
        if chunk.kind == "verb":
            giving = bool({"BRINGING", "TAKING"} & set(chunk.frames))
        elif giving and chunk.kind == "prep" and chunk.text == "at" and _given_to(out[i + 1], vocabulary):
            out[i] = Chunk("prep", "to", role="goal")
    return out


def _given_to(chunk: Chunk, vocabulary: Vocabulary) -> bool:
    """Whether a chunk is "me" or names only people."""
    return chunk.kind == "me" or _is(chunk, vocabulary, "person")


def state_as_verb(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "switch off the office light and on the desk lamp" (Indian English says "on the light", "off the
    fan"): "on" or "off" right after "and" and before a device, once a verb was said, is that verb again with
    this state ("and switch on the desk lamp"), not the earlier device's state; after a verb that switches
    nothing ("go to kit's room and off his night light"), "switch". So too straight after a device, where
    a state was said before it ("off the kitchen light and the store light, on the security light": the
    comma is gone by now); "switch the landing light on the hallway light off" stays."""
    out: list[Chunk] = []
    switch = Chunk("verb", "switch", frames=("OPERATING",))
    verb: Chunk | None = None
    stated = False  # a state said since the verb, before the device ("off the kitchen light ...")
    if len(chunks) > 2 and _state_before_device(chunks, 0, vocabulary):  # "off the kitchen light and on ..."
        verb = switch
    for i, chunk in enumerate(chunks):
        out.append(chunk)
        if chunk.kind == "verb":
            verb, stated = (chunk if "OPERATING" in chunk.frames else switch), False
        stated = stated or (chunk.kind == "prep" and chunk.state in ("on", "off"))
        after_device = stated and chunk.kind == "entity" and _is(chunk, vocabulary, "device")
        again = chunk.kind == "join" or after_device
        if verb is not None and again and _state_before_device(chunks, i + 1, vocabulary):
            out.append(verb)
    return out


def _state_before_device(chunks: list[Chunk], at: int, vocabulary: Vocabulary) -> bool:
    """Whether "on" or "off" at ``at`` comes right before a device (after a determiner, if any)."""
    thing = at + 1 + (at + 1 < len(chunks) and chunks[at + 1].kind == "det")
    return (
        thing < len(chunks)
        and chunks[at].kind == "prep"
        and chunks[at].state in ("on", "off")
        and _is(chunks[thing], vocabulary, "device")
    )


def source_first(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "from the kitchen island the fruit bowl bring to my room" (a German speaker's order: where from, what,
    then the verb): the verb and the thing first, then where from, then the rest as said."""
    if len(chunks) < 4 or chunks[0].kind != "prep" or chunks[0].text != "from":
        return chunks
    place = 1 + (chunks[1].kind == "det")
    thing = place + 1 + (place + 1 < len(chunks) and chunks[place + 1].kind == "det")
    verb = thing + 1
    if verb >= len(chunks) or chunks[verb].kind != "verb" or chunks[verb].beneficiary == "subject":
        return chunks
    if not (_is(chunks[place], vocabulary, "room") or _is(chunks[place], vocabulary, "furniture")):
        return chunks
    if not _is(chunks[thing], vocabulary, "item"):
        return chunks
    me = verb + 1 + (verb + 1 < len(chunks) and chunks[verb + 1].kind == "me")  # "... bring me"
    return [*chunks[verb:me], *chunks[place + 1 : verb], *chunks[: place + 1], *chunks[me:]]


#: verbs of throwing: a thing thrown to a person is given to them
_THROWN = frozenset({"throw", "toss", "chuck", "lob", "bung", "hoy"})


def thrown_to(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "chuck the football back to arjun", "toss the keys to mark": a thing thrown "to" a person (not to a
    place) is given to them, as "chuck me the remote" is to the speaker, and so is one thrown "over here"
    ("chuck the cushion over here", where the robot asked where to)."""
    out = list(chunks)
    for i, chunk in enumerate(chunks):
        if chunk.kind != "verb" or chunk.text not in _THROWN:
            continue
        end = next((k for k in range(i + 1, len(chunks)) if chunks[k].kind in ("verb", "join")), len(chunks))
        to = [k for k in range(i + 1, end - 1) if chunks[k].kind == "prep" and chunks[k].text == "to"]
        if (to and _is(chunks[to[-1] + 1], vocabulary, "person")) or chunks[end - 1].kind == "me":
            out[i] = Chunk("verb", "give", frames=("BRINGING",))
    return out


#: what says where a thing is after the place said first ("on my desk is calculator")
_BE = frozenset({"is", "are", "lies", "sits", "stands"})
#: the place prepositions a learner opens with before saying what is there
_FIRST_PLACES = frozenset({"on", "in", "at", "under", "inside", "on top of", "next to", "by"})


def place_first(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "on my desk is calculator, bring it to the kitchen table" (a place said first, as Polish and German
    speakers may): the thing is said first, "calculator is on my desk, ...", so that the place says where it
    is."""
    if len(chunks) < 4 or chunks[0].kind != "prep" or chunks[0].text not in _FIRST_PLACES:
        return chunks
    at = next((i for i, c in enumerate(chunks) if c.kind in ("verb", "join") or c.text in _BE), None)
    if at is None or at < 2 or chunks[at].text not in _BE:
        return chunks
    thing = at + 1 + (chunks[at + 1].kind == "det" if at + 1 < len(chunks) else 0)
    if thing >= len(chunks) or not _is(chunks[thing], vocabulary, "item"):
        return chunks
    return [*chunks[at + 1 : thing + 1], chunks[at], *chunks[:at], *chunks[thing + 1 :]]


def object_first(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "the dumbbells put on the weights bench and the work boots on the shoe rack": a thing said before a
    verb that carries or puts it, the verb followed by where: the thing is said after the verb ("put the
    dumbbells on ...") so that what follows "and" is read as more of the same."""
    start = 1 if chunks[:1] and chunks[0].kind == "det" else 0
    if len(chunks) < start + 3 or not _is(chunks[start], vocabulary, "item"):
        return chunks
    verb, after = chunks[start + 1], chunks[start + 2]
    carries = {"PLACING", "BRINGING"} & set(verb.frames)
    if verb.kind != "verb" or not carries or verb.beneficiary or after.kind != "prep":
        return chunks
    return [verb, *chunks[: start + 1], *chunks[start + 2 :]]


def _is(chunk: Chunk, vocabulary: Vocabulary, kind: str) -> bool:
    """Whether a chunk names only things of ``kind``."""
    return (
        chunk.kind == "entity"
        and bool(chunk.terms)
        and all(vocabulary.is_subtype(t.type, kind) for t in chunk.terms)
    )


def helped_to(chunks: list[Chunk]) -> list[Chunk]:
    """ "please help me to on the landing light", "kindly help me off the fan" (Nigerian English, where "on"
    and "off" are verbs): "help me (to)" before "on" or "off" is politeness; the switching is the request."""
    for i in range(len(chunks) - 2):
        if chunks[i].kind != "verb" or chunks[i].text != "help" or chunks[i + 1].kind != "me":
            continue
        at = i + 2 + (chunks[i + 2].text == "to")
        if (
            at + 1 < len(chunks)
            and chunks[at].text in ("on", "off")
            and chunks[at + 1].kind in ("det", "entity")
        ):
            return [*chunks[:i], *chunks[at:]]
    return chunks


def gapped_given(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "give tyler the headset and maisie the unicorn": after a verb that gives, a person and a thing, then
    "and" with another person and thing, the verb is said again for the second pair."""

    def person(chunk: Chunk) -> bool:
        return (
            chunk.kind == "entity"
            and bool(chunk.terms)
            and all(vocabulary.is_subtype(t.type, "person") for t in chunk.terms)
        )

    if len(chunks) < 6 or chunks[0].kind != "verb" or "BRINGING" not in chunks[0].frames:
        return chunks
    if not (person(chunks[1]) or chunks[1].kind == "me"):
        return chunks
    for i in range(2, len(chunks) - 2):
        thing = chunks[i - 1].kind == "entity" and not person(chunks[i - 1])
        if chunks[i].kind == "join" and person(chunks[i + 1]) and thing:
            after = past_determiners(chunks, i + 2)
            if after < len(chunks) and chunks[after].kind == "entity" and not person(chunks[after]):
                return [*chunks[: i + 1], chunks[0], *chunks[i + 1 :]]
    return chunks


def out_the(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "get the butter out the fridge" (American and British speech): "out" right before a determiner and a
    place, after a thing, is "out of" (where the thing is taken from), not the state "off"."""
    out = list(chunks)
    for i in range(1, len(out) - 2):
        if out[i].text != "out" or out[i].kind not in ("state", "prep") or out[i - 1].kind != "entity":
            continue
        at = past_determiners(out, i + 1)
        place = at < len(out) and at > i + 1 and out[at].kind == "entity" and out[at].terms
        rooms_or_furniture = ("room", "furniture")
        if place and all(
            any(vocabulary.is_subtype(t.type, k) for k in rooms_or_furniture) for t in out[at].terms
        ):
            out[i] = Chunk("prep", "out of", role="source")
    return out


def carried_in(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "bring me in the post", "bring in the washing": "in" right after a verb of carrying (and whom for)
    and before a thing, not a place, says only that it comes indoors."""
    out = list(chunks)
    for i in range(len(out) - 1, 0, -1):
        if out[i].kind != "prep" or out[i].text != "in":
            continue
        verb = i - 1 - (out[i - 1].kind in ("me", "entity") and i > 1 and out[i - 2].kind == "verb")
        if out[verb].kind != "verb" or "BRINGING" not in out[verb].frames:
            continue
        at = past_determiners(out, i + 1)
        thing = at < len(out) and out[at].kind == "entity" and out[at].terms
        if thing and all(vocabulary.is_subtype(t.type, "item") for t in out[at].terms):
            del out[i]
    return out


def appositions_dropped(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "find tomasz the handyman", "give it to bethan the nurse": what a person is, said after their name as
    "the" and a word the world has no name for, only says who they are."""
    out: list[Chunk] = []
    i = 0
    while i < len(chunks):
        chunk = chunks[i]
        out.append(chunk)
        i += 1
        person = chunk.kind == "entity" and any(vocabulary.is_subtype(t.type, "person") for t in chunk.terms)
        if person and i + 1 < len(chunks) and chunks[i].text == "the" and chunks[i + 1].kind == "unknown":
            end = i + 2
            if end == len(chunks) or chunks[end].kind in ("prep", "verb", "join"):
                i = end
    return out


def subject_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """ "toolbox you take from shelf and you put on workbench": "you" said right before a verb, after the
    thing or a joiner, is whom the speaker tells, not a thing of the world."""
    return [
        c
        for i, c in enumerate(chunks)
        if not (
            c.text == "you"
            and c.kind == "unknown"
            and 0 < i < len(chunks) - 1
            and chunks[i - 1].kind in ("entity", "join")
            and chunks[i + 1].kind == "verb"
        )
    ]


def it_me(chunks: list[Chunk]) -> list[Chunk]:
    """ "give it me", "bring them me" (British): "it" or "them" right after a verb, then "me", is to me; so is
    "me" said last after a thing ("bring apple me", a learner's order)."""
    out = list(chunks)
    for i in range(len(out) - 2, 0, -1):
        if out[i - 1].kind == "verb" and out[i].kind == "pronoun" and out[i + 1].kind == "me":
            out.insert(i + 1, Chunk("prep", "to", role="goal"))
    last = len(out) - 1
    if last >= 2 and out[last].kind == "me" and out[last - 1].kind == "entity":
        verb = past_determiners(out, 1) if out[0].kind == "verb" else 0
        if verb == last - 1:  # the verb, determiners, the thing, "me"
            out.insert(last, Chunk("prep", "to", role="goal"))
    return out


#: words that say what a room holds after "room": "where" (and the search verb "where is" a learner's order
#: makes of "where is the bed"), "with", "that has"
_HOLDING = frozenset({"where", "where is", "where are", "with", "that has", "which has"})
#: what may close the thing's name ("where the bed is")
_COPULAS = frozenset({"is", "are", "stands"})


def room_told(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "room", a word saying what it holds, and a thing the world places in exactly one room: that room
    ("go to the room where is the crib": the nursery). A thing in no room or in several leaves the words as
    said."""
    for i in range(len(chunks) - 2):
        if chunks[i].text not in ("room", "rooms") or chunks[i + 1].text not in _HOLDING:
            continue
        at = past_determiners(chunks, i + 2)
        if at >= len(chunks) or chunks[at].kind != "entity":
            continue
        rooms = {
            place
            for term in chunks[at].terms
            for place in vocabulary.locations.get(term.symbol, ())
            if _is_room(vocabulary, place)
        }
        if len(rooms) != 1:
            continue
        room = rooms.pop()
        terms = tuple(t for t in vocabulary.terms if t.symbol == room)[:1]
        end = at + 1
        if end < len(chunks) and chunks[end].kind == "unknown" and chunks[end].text in _COPULAS:
            end += 1
        return [*chunks[:i], Chunk("entity", terms[0].phrase, terms), *chunks[end:]]
    return chunks


def _is_room(vocabulary: Vocabulary, symbol: str) -> bool:
    return any(t.symbol == symbol and vocabulary.is_subtype(t.type, "room") for t in vocabulary.terms)


#: what may stand before a verb said last ("to the bathroom go", "the candle on the dining table put it",
#: "barley tea and rice cooker, kitchen island put")
_BEFORE_LAST_VERB = frozenset({"det", "entity", "prep", "me", "quant", "owner", "join"})
#: what may follow a verb said last, with it: how a device is set ("the blinds open halfway")
_SETTINGS = frozenset({"state", "level", "number", "percent", "vague"})


def verb_last_moved(chunks: list[Chunk]) -> list[Chunk]:
    """An action said with its verb last, as in the speaker's first language ("to the bathroom go please",
    "the candle on the dining table put it", "close the blinds and the desk lamp switch on"): the verb, with
    how a device is set said right after it, is put first, and an "it" or "them" right after it, for the
    thing said before, is dropped. Only where the action starts the command or follows a joiner, when names,
    determiners and prepositions alone come before the verb and nothing but a joiner or another action after
    it; a verb that takes its subject before it ("tracy needs") stays."""
    out = list(chunks)
    for start in range(len(out)):
        if start and out[start - 1].kind != "join":
            continue
        verb = next((i for i in range(start, len(out)) if out[i].kind == "verb"), None)
        if verb is None or verb == start or out[verb].beneficiary == "subject":
            continue
        before = out[start:verb]
        # how a device is set may come first too ("living room light little bit darker make")
        if any(c.kind not in _BEFORE_LAST_VERB | _SETTINGS for c in before) or not any(
            c.kind == "entity" for c in before
        ):
            continue
        after = verb + 1
        while after < len(out) and _setting(out, after):
            after += 1  # "switch on", "turn off", "open a little, like 10 percent"
        said = out[verb:after]
        if unplaced(before) and after < len(out) and out[after].kind == "pronoun":
            after += 1
            while after < len(out) and _setting(out, after):
                said.append(out[after])  # "the hall light, turn it off"
                after += 1
        if after < len(out) and out[after].kind not in ("join", "verb"):
            continue
        # how the device is set goes after it, as said in order: "hall light dim to 40 and floor lamp on" is
        # "dim hall light to 40 and ...", not a level the floor lamp shares
        out = [*out[:start], said[0], *before, *said[1:], *out[after:]]
    return out


def _setting(chunks: list[Chunk], at: int) -> bool:
    """Whether the chunk at ``at`` says how a device is set: a state, a level, a number, "percent", a vague
    amount, or a word the tables lack or a preposition right before a level ("like 10 percent", "around
    half")."""
    chunk = chunks[at]
    if chunk.kind in _SETTINGS or chunk.state is not None:
        return True
    hedged = at + 1 < len(chunks) and chunks[at + 1].kind in ("number", "level")
    return hedged and chunk.kind in ("unknown", "prep")


#: the speaker said as who does something ("i go to bed now", "i'm going out")
_SPEAKER_SUBJECTS = (("i",), ("we",), ("i'm",), ("im",), ("we're",), ("i", "am"), ("we", "are"))


#: the speaker said as who did something, before what they did ("i put", "i've put", "we have moved")
_DOERS = (("i",), ("we",), ("i've",), ("we've",), ("i", "have"), ("we", "have"))
#: what the speaker may say they did with a thing before asking something of it
_CARRIED = ("PLACING", "TAKING", "BRINGING")


def own_doing_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop what the speaker says they did with a thing before asking something ("i put the milk in the
    fridge, bring me the butter", "i've put my keys somewhere, can you find them"): "i" or "we" and a verb of
    carrying or putting, up to the next action; the things said stay, for a later "them". Said alone it is
    left to the reader (no request: ``not_requests``)."""
    said = [c.text if c.kind == "unknown" else "" for c in chunks[:2]]
    size = next((len(s) for s in sorted(_DOERS, key=len, reverse=True) if said[: len(s)] == list(s)), 0)
    if not size or len(chunks) < size + 2 or chunks[size].kind != "verb":
        return chunks
    if chunks[size].frames[:1] not in [(k,) for k in _CARRIED] or chunks[size].beneficiary is not None:
        return chunks
    nxt = next((i for i in range(size + 1, len(chunks)) if chunks[i].kind in ("verb", "join")), None)
    while nxt is not None and nxt < len(chunks) and chunks[nxt].kind == "join":
        nxt += 1
    if nxt is None or nxt >= len(chunks) or chunks[nxt].kind != "verb":
        return chunks
    return [*unplaced(chunks[size + 1 : nxt]), *chunks[nxt:]]


def own_going_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop where the speaker says they are going before asking something ("i go to bed now, switch off the
    lamp", "i'm going to the garden, close the blinds"): "i" or "we" and a verb of going only, up to the next
    action; said alone ("i go kitchen") it stays, as the request it may be, unless said as what the speaker
    is doing ("i'm going to bed": no request, nothing left to read)."""
    said = [c.text if c.kind == "unknown" else "" for c in chunks[:2]]
    size = next(
        (len(s) for s in sorted(_SPEAKER_SUBJECTS, key=len, reverse=True) if said[: len(s)] == list(s)), 0
    )
    if (
        not size
        or len(chunks) < size + 2
        or chunks[size].kind != "verb"
        or chunks[size].frames != ("MOTION",)
    ):
        return chunks
    nxt = next((i for i in range(size + 1, len(chunks)) if chunks[i].kind in ("verb", "join")), None)
    if nxt is None:
        return [] if size > 1 or said[0] in ("i'm", "im", "we're") else chunks
    while nxt < len(chunks) and (chunks[nxt].kind == "join" or chunks[nxt].text == "you"):
        nxt += 1
    return chunks[nxt:] if nxt < len(chunks) and chunks[nxt].kind == "verb" else chunks
