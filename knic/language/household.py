"""What family members and carers say around a request in a busy household, tidied before it is read (used
by :class:`knic.language.reader.Reader`: :func:`words_tidied` and :func:`ones_named` on the words of each
sentence, :func:`other_one` and :func:`said_around` on the chunks, between the passes of
:mod:`knic.language.tidy`).

* "bin the pizza box": thrown away (:func:`binned`);
* a thing said, then "where" alone ("chopsticks, where?"): where it is (:func:`where_last`);
* hesitations inside a phrase ("when you um get a minute"), and "you're" after "when" or "once" ("when
  you're done": when you are done), in the words (:func:`words_tidied`);
* what a device is said or asked to be before the request about it ("is the hallway light on? turn it
  off", "the blinds are stuck halfway, open them all the way", "if the hallway light is on again, turn it
  off"): the device is said, its state is not asked;
* what someone is doing, said before or after the request ("jack's waiting in the hall, bring him the
  water", "bring maria her laptop, she's working in the study"), or where someone given a thing is ("give
  dai his glasses, he's in the office"): talk; the person stays said for "him"; likewise whether someone is
  about, asked before the request ("is bethan here yet? find her");
* who left a thing where ("the tissues that grandma left on the sofa"): the place says where it is;
* "on" before a place after a device's state was said ("turn off the lamp on the desk"): where, not on;
* where a thing should go ("grandma's glasses need to go on her bedside table"): put it there;
* a thing to take along where the robot goes ("go to the bedroom and don't forget the glasses", "... and
  take the glasses with you"): the thing is taken there first;
* "the other one" in a correction ("switch on the left lamp, no wait, the other one"): the other of a pair;
  "the right one" after "the left lamp": the right lamp (:func:`ones_named`);
* "my room", "her room": the bedroom, where the world has one;
* a place said again at once as another before the action goes on ("bring the cup from the kitchen table um
  the counter to tracy"): the second is meant.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import replace
from functools import lru_cache

from knic.language.askedfor import asked_for_read
from knic.language.chunks import Chunk, Chunker, past_determiners, singulars
from knic.language.clerical import clerical_read
from knic.language.contracted import contracted
from knic.language.dialects import dialect_words
from knic.language.gathered import gathered
from knic.language.gathered import gathered_up as gathered_up  # for the reader, whose module is full
from knic.language.ordinary import ordinary_read, side_ones
from knic.language.pidgin import pidgin_words
from knic.language.placedones import ones_placed
from knic.language.plainorder import asked_plainly
from knic.language.procedure import procedure_read
from knic.language.regional import regional_words
from knic.language.registers import register_words
from knic.language.restating import restated
from knic.language.trailing import restarts_read
from knic.language.twice import asked_twice
from knic.language.vocabulary import Vocabulary

#: hesitations, dropped even inside a phrase (they are fillers wherever they stand)
HESITATIONS = frozenset({"um", "umm", "uh", "uhh", "uhm", "er", "erm", "hmm"})
#: words after which "you're" opens a clause of time ("when you're done", "once you're finished")
_TIME_WORDS = frozenset({"when", "once", "after", "until", "till"})
_CONTRACTED = {"you're": ["you", "are"]}
#: what says a device's state is a condition of the request after it ("if the hallway light is on, ...")
_IF = frozenset({"if", "when", "whenever"})
#: what a device is said to be before its state ("the blinds are still shut", "are stuck halfway", "is
#: switched on")
_STATE_WORDS = frozenset(
    {"is", "are", "still", "already", "stuck", "left", "now", "all", "fully", "switched", "turned"}
)
#: subjects said with "be" contracted ("she's working in the study")
_CONTRACTED_DOERS = frozenset({"i'm", "we're", "they're", "he's", "she's", "you're"})
#: words that ask whether someone is about ("is bethan here yet", "is rhys up yet", "is dai back")
_ABOUT = frozenset({"yet", "back", "home", "around", "about", "awake", "up", "in", "still", "already", "now"})
#: what may stand between a thing and "go" when the speaker says where it should go
_SHOULD = frozenset({"need", "needs", "to", "should", "must", "has", "have", "can", "could", "ought", "is"})


#: articles a thing said again after a hesitation starts with ("a cup of tea, er, a cup")
_ARTICLES = frozenset({"a", "an", "the", "my", "some", "your"})
#: what "bin" is a noun after ("in the bin the ...", "the kitchen bin")
_NOT_BINNED = frozenset({"a", "an", "the", "my", "your", "our", "in", "into", "to", "from", "by", "near"})
#: words after which a hesitation before an article is no correction ("bring me uh the mug", "to uh the")
_NOT_ENDING_A_THING = frozenset(
    {"me", "him", "her", "us", "them", "it", "and", "or", "then", "to", "from", "of", "on", "in", "at", "for"}
    | {"with", "into", "onto", "off", "is", "are", "please", "also", "too", "by", "near", "next", "under"}
)


#: what a thing did that asks where it is now ("where did my phone go", "where has the hairbrush gone")
_GONE = ("go", "gone", "went", "disappeared", "vanished", "got")
#: question words, and what stresses them without adding a word of meaning ("where tf is", "where on earth")
_WH = frozenset({"where", "what", "who", "how", "why", "which"})
_WH_STRESSED = (
    ["tf"],
    ["the", "hell"],
    ["the", "heck"],
    ["on", "earth"],
    ["the", "fuck"],
    ["in", "the", "world"],
)
#: what, said before a last "where", asks something else ("do you know where", "i wonder where")
_NOT_A_THING = frozenset(
    {"know", "wonder", "see", "is", "are", "put", "left", "go", "went", "did", "i", "you"}
)
_WHERE_LAST = re.compile(r"^\s*(?P<thing>[a-z' ]+?)\s*[,.]?\s+where\s*\??\s*$")


def where_last(text: str) -> str:
    """ "chopsticks, where?", "my keys where", "annie is where?": a thing said, then "where" alone (said by
    learners and tired people, or asked back): where the thing is ("where is my keys"); else ``text``, with
    questions said in another order put back (:mod:`knic.language.plainorder`)."""
    # "ah go on, ...", "off the floor" (ordinary.py); "to my location", "is to be brought" (procedure.py);
    # "in here... in the nursery", "... no, leave it. ..." (trailing.py)
    text = asked_plainly(ordinary_read(procedure_read(clerical_read(restarts_read(asked_for_read(text))))))
    match = _WHERE_LAST.match(text.lower())
    words = match.group("thing").split() if match else []
    if len(words) > 1 and words[-1] in ("is", "are"):  # "annie is where?", "the keys are where?": asked back
        words = words[:-1]
    if not words or len(words) > 4 or "where" in words or _NOT_A_THING & set(words):
        return text
    return f"where is {' '.join(words)}"


#: who may be asked where they put a thing, as the command language says it ("where did you put")
_ASKERS = frozenset({"you", "i", "we"})
#: what someone did with a thing that asks where it is now ("where did emeka put the calpol")
_PUT_AWAY = frozenset({"put", "leave", "left", "hide", "hid", "hidden", "move", "moved", "stash", "stashed"})


def gone_asked(tokens: list[str]) -> list[str]:
    """ "where did my phone go", "where has the hairbrush gone", "where'd the keys go", "where has the rota
    got to": where the thing is; "where tf is", "where on earth are": where."""
    for i in range(len(tokens) - 1, 0, -1):
        for said in _WH_STRESSED:
            if tokens[i - 1] in _WH and tokens[i : i + len(said)] == said:
                tokens = [*tokens[:i], *tokens[i + len(said) :]]
    for i, token in enumerate(tokens[:-2]):
        if token not in ("where", "where'd", "where's") or (
            token == "where" and tokens[i + 1] not in ("did", "has", "have")
        ):
            continue
        start = i + 1 if token in ("where'd", "where's") else i + 2  # "where's the remote gone?"
        if tokens[start] not in _ASKERS and tokens[start + 1 : start + 2] and tokens[start + 1] in _PUT_AWAY:
            # "where did emeka put the calpol", "where has tyler left my keys": where the thing is
            return [*tokens[:i], "where", "is", *tokens[start + 2 :]]
        if tokens[start] in ("you", "i", "we", "he", "she"):  # "where did you go": no thing asked for
            continue
        if tokens[start : start + 2] in (["it", "go"], ["they", "go"], ["it", "gone"], ["they", "gone"]):
            # "my slippers, where did they go": where a thing said before is
            copula = "is" if tokens[start] == "it" else "are"
            return [*tokens[:i], "where", copula, tokens[start], *tokens[start + 2 :]]
        for end in range(start + 1, min(start + 6, len(tokens))):
            if tokens[end] in _GONE:
                after = end + 1 + (tokens[end + 1 : end + 2] == ["to"])
                return [*tokens[:i], "where", "is", *tokens[start:end], *tokens[after:]]
    return tokens


def binned(tokens: list[str]) -> list[str]:
    """ "bin the pizza box": "bin" said as a verb, right before a determiner and after none, throws the thing
    away; so do "dispose of", "get rid of" and "throw out" before one ("dispose of the cardboard box")."""
    for i, token in enumerate(tokens[:-1]):
        if token == "bin" and tokens[i + 1] in _ARTICLES and (i == 0 or tokens[i - 1] not in _NOT_BINNED):
            return [*tokens[:i], "toss", "away", *tokens[i + 1 :]]
        said = next((n for n in (2, 3) if tokens[i : i + n] in _RID), 0)
        if said and tokens[i + said : i + said + 1] and tokens[i + said] in _ARTICLES:
            return [*tokens[:i], "toss", "away", *tokens[i + said :]]
    return tokens


#: what throws a thing away, said before it ("get rid of the tissues")
_RID = (["dispose", "of"], ["get", "rid", "of"], ["throw", "out"])


def words_tidied(tokens: list[str]) -> list[str]:
    """The words without hesitations, in plain English (:mod:`knic.language.dialects`), with "you're" spelled
    out after a word of time and "me" said again for "my" ("bring me me glasses", as said in Britain and
    Ireland). A hesitation between a thing said after an article and the same article said again ("get me a
    cup of tea er a cup") is the speaker correcting the thing: it is read as "i mean"."""
    out: list[str] = []
    tokens = gathered(
        binned(gone_asked(contracted(dialect_words(regional_words(pidgin_words(register_words(tokens)))))))
    )
    for i, token in enumerate(tokens):
        if token in HESITATIONS:
            nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
            if (
                nxt in _ARTICLES
                and out
                and out[-1] not in _ARTICLES | _NOT_ENDING_A_THING | HESITATIONS
                and nxt in out[:-1]
            ):
                out += ["i", "mean"]
            continue
        if token in _CONTRACTED and out and out[-1] in _TIME_WORDS:
            out += _CONTRACTED[token]
            continue
        if token == "me" and out[-1:] == ["me"] and i + 1 < len(tokens):  # "fetch me me slippers": my
            token = "my"
        out.append(token)
    return out


def said_around(chunks: list[Chunk], vocabulary: Vocabulary, chunker: Chunker) -> list[Chunk]:
    """``chunks`` with what is said around the request tidied (see the module docstring); ``chunker`` gives
    the verbs a thing's destination is read with ("put", "take")."""

    def is_a(chunk: Chunk, category: str) -> bool:
        return any(vocabulary.is_subtype(t.type, category) for t in chunk.terms)

    chunks = _state_said(_own_room(_restated_before(chunks, is_a), vocabulary), is_a)
    chunks = _doings(_person_asked(chunks, is_a), is_a)
    chunks = _placed_on(_left_by(_one_of(chunks), is_a), is_a)
    put, take = (chunker.chunks([verb])[0] for verb in ("put", "take"))
    return _taken_along(_should_go(chunks, is_a, put), is_a, take)


def _one_of(chunks: list[Chunk]) -> list[Chunk]:
    """ "grab one of the mugs": one thing of those the plural names, said as "the mug" (asked which where
    several fit), not all of them."""
    out = list(chunks)
    for i in range(len(out) - 3, -1, -1):
        if len(out[i : i + 4]) < 4:
            continue
        one, of, the, things = out[i : i + 4]
        if (one.text, of.text, the.kind, things.kind, things.role) == (
            "one",
            "of",
            "det",
            "entity",
            "plural",
        ):
            *_, last = things.text.split()
            one_said = (singulars(last) or [last[:-1] if last.endswith("s") else last])[0]
            text = " ".join([*things.text.split()[:-1], one_said])
            out[i : i + 4] = [the, replace(things, text=text, role="")]
    return out


def _next_verb(chunks: Sequence[Chunk], start: int) -> int | None:
    """The index of the first verb said as a command from ``start`` (past joiners only), else None."""
    at = start
    while at < len(chunks) and chunks[at].kind == "join":
        at += 1
    return at if at < len(chunks) and chunks[at].kind == "verb" and not chunks[at].soft else None


def _state_said(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """A device's state said or asked before the first action ("is the hallway light on?", "the study blinds
    are open", "the blinds are stuck halfway") with an action after it: the state is dropped, the device
    stays said (for "it" or "them")."""
    asked = chunks and chunks[0].kind == "verb" and chunks[0].text in ("is", "are")
    start = 1 if asked or (chunks and chunks[0].kind == "unknown" and chunks[0].text in _IF) else 0
    at = past_determiners(chunks, start)
    if at >= len(chunks) or chunks[at].kind != "entity" or not is_a(chunks[at], "device"):
        return chunks
    device = at
    at += 1
    while at < len(chunks) and chunks[at].kind == "unknown" and chunks[at].text in _STATE_WORDS:
        at += 1
    if not start and at == device + 1:
        return chunks  # "the lights off": a command
    stated = at < len(chunks) and (
        chunks[at].kind in ("state", "level", "number") or chunks[at].state is not None
    )
    if not stated or _next_verb(chunks, at + 1) is None:
        return chunks
    return chunks[start : device + 1] + chunks[at + 1 :]


def _person_asked(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """Whether someone is about, asked before a request ("is bethan here yet? find her", "is rhys up yet?
    bring him his hoodie"): the question is dropped, the person stays said for "her" or "him"."""
    if len(chunks) < 3 or chunks[0].text not in ("is", "are") or chunks[1].kind != "entity":
        return chunks
    if not is_a(chunks[1], "person"):
        return chunks
    at = 2
    while at < len(chunks) and (
        (chunks[at].kind == "me" and chunks[at].role == "here")
        or chunks[at].kind == "state"
        or (chunks[at].kind in ("unknown", "unsaid") and chunks[at].text in _ABOUT)
    ):
        at += 1
    return [chunks[1], *chunks[at:]] if at > 2 and _next_verb(chunks, at) is not None else chunks


def _doings(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """What someone is doing ("jack is waiting in the hall", "she's working in the study"): from "is" (or
    the contracted subject) up to the next action or joiner; a person said as the subject stays said."""
    out: list[Chunk] = []
    i = 0
    while i < len(chunks):
        chunk = chunks[i]
        subject = chunk.kind == "unknown" and chunk.text in _CONTRACTED_DOERS
        been = (
            chunk.text in ("has", "have", "had", "is")  # "rosa's been" is read "rosa is been"
            and chunks[i + 1 : i + 2] != []
            and chunks[i + 1].text == "been"
        )
        be = (
            chunk.kind == "unknown"
            and (chunk.text in ("is", "are") or been)
            and bool(out)
            and out[-1].kind == "entity"
            and is_a(out[-1], "person")
        )
        nxt = chunks[i + 1 + been] if i + 1 + been < len(chunks) else None
        doing = nxt is not None and (
            (nxt.kind == "verb" and nxt.soft) or (nxt.kind == "unknown" and nxt.text.endswith("ing"))
        )
        # "give dai his glasses, he's in the office": where he is, after no search ("find dai, he's in ...")
        doing = doing or (
            subject
            and nxt is not None
            and nxt.kind == "prep"
            and nxt.text in ("in", "at")
            and _given(out, is_a)
        )
        if not ((subject or be) and doing):
            out.append(chunk)
            i += 1
            continue
        end = i + 2
        while (
            end < len(chunks)
            and chunks[end].kind != "join"
            and (chunks[end].kind != "verb" or chunks[end].soft)
        ):
            end += 1
        if end == len(chunks) and not any(c.kind == "verb" and not c.soft for c in out):
            out.append(chunk)  # nothing asked besides: left as said
            i += 1
            continue
        # "rosa has been looking for the teddy, take it to her": the thing stays said for "it"
        out += [c for c in chunks[i:end] if c.kind == "entity" and is_a(c, "item")]
        i = end
    return out


def _given(said: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> bool:
    """Whether a person was named (or said as whose a thing is: "take Savitri's box to her") and no search
    was asked for in what was said."""
    person = any(c.kind == "owner" or (c.kind == "entity" and is_a(c, "person")) for c in said)
    return person and not any(c.kind == "verb" and c.frames[:1] == ("SEARCHING",) for c in said)


def _left_by(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """Drop "that grandma left" between a thing and where it is ("the tissues that grandma left on the
    sofa", "the stapler that oscar put on the desk"): the place says where the thing is."""
    for i in range(1, len(chunks) - 3):
        that, doer, doing, where = chunks[i : i + 4]
        if (
            chunks[i - 1].kind == "entity"
            and that.text in ("that", "which")
            and doer.kind == "entity"
            and is_a(doer, "person")
            and doing.kind in ("unknown", "verb")
            and where.kind == "prep"
        ):
            return chunks[:i] + chunks[i + 3 :]
    return chunks


def _placed_on(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """A state word said as a preposition before a place, once the action's state is said, after a name
    ("turn off the lamp on the desk"): where the device is, not a second state."""
    out = list(chunks)
    stated = False
    for i, chunk in enumerate(out):
        if chunk.kind == "verb":
            stated = chunk.state is not None
            continue
        place = next((c for c in out[i + 1 :] if c.kind != "det"), Chunk("unknown", ""))
        placed = place.kind == "entity" and (is_a(place, "furniture") or is_a(place, "room"))
        named = i > 0 and out[i - 1].kind == "entity"
        if chunk.kind == "prep" and chunk.state is not None and stated and placed and named:
            out[i] = Chunk("prep", chunk.text, role="place")
        elif chunk.kind == "state" or (chunk.kind == "prep" and chunk.state is not None):
            stated = True
    return out


def _should_go(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool], put: Chunk) -> list[Chunk]:
    """Where a thing should go, said before any action ("grandma's glasses need to go on her bedside table",
    "the laptop should go on the desk"): put the thing there."""
    thing = next((i for i, c in enumerate(chunks) if c.kind in ("entity", "verb")), None)
    if not thing or chunks[thing].kind != "entity" or not is_a(chunks[thing], "item"):
        return chunks
    if chunks[thing - 1].kind not in ("det", "owner"):
        return chunks  # "you can go in the dining room": no thing said ("can": the coke can)
    go = thing + 1
    while go < len(chunks) and chunks[go].text in _SHOULD:
        go += 1
    if go + 1 >= len(chunks) or chunks[go].frames != ("MOTION",) or chunks[go + 1].kind != "prep":
        return chunks
    start = thing
    while start > 0 and chunks[start - 1].kind in ("det", "owner"):
        start -= 1
    return [*chunks[:start], put, *chunks[start : thing + 1], *chunks[go + 1 :]]


#: the other side, for "the other one" said of a thing named by its side
_SIDE_SWAPPED = {"left": "right", "right": "left"}


def other_one(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "The other one" (or "the other light") in a correction: the other of the pair the thing said before
    belongs to ("switch on the left lamp, no wait, the other one": the right lamp), or the thing named by
    the other side ("the left shelf": the right shelf), or the one other thing of its type; of several
    others, those named by the same last word, asked about when more than one; left as said when none."""
    for i, chunk in enumerate(chunks[:-2]):
        if chunk.kind != "repair":
            continue
        at = past_determiners(chunks, i + 1)
        if at >= len(chunks) or chunks[at].text != "other":
            continue
        end = at + 1
        if end < len(chunks) and (chunks[end].text in ("one", "ones") or chunks[end].kind == "entity"):
            end += 1
        said = next((c for c in reversed(chunks[:i]) if c.kind == "entity" and len(c.terms) == 1), None)
        if said is None:
            continue
        symbol = said.terms[0].symbol
        pairs = [
            t.members for t in vocabulary.terms if t.is_group and len(t.members) == 2 and symbol in t.members
        ]
        others = [m for m in pairs[0] if m != symbol] if pairs else []
        words = said.terms[0].phrase.split()  # "the left shelf, no, the other one": the right shelf
        sided = (
            [" ".join(_SIDE_SWAPPED.get(w, w) for w in words)] if _SIDE_SWAPPED.keys() & set(words) else []
        )
        others = others or sorted({t.symbol for t in vocabulary.terms if t.phrase in sided} - {symbol})
        if not others:
            kind = vocabulary.type_of(symbol)
            others = list(
                {t.symbol for t in vocabulary.terms if not t.is_group and t.type == kind} - {symbol}
            )
        kind_word = words[-1]
        if len(others) > 1:  # "the kitchen blinds, no, the other ones": of those called blinds too
            others = sorted(o for o in others if vocabulary.phrase_of(o).split()[-1] == kind_word)
        # of several others, which is asked ("the blue cup, no, the other one": the pink or the white cup?)
        terms = tuple(next(t for t in vocabulary.terms if t.symbol == o) for o in others)
        if not terms:
            continue
        text = terms[0].phrase if len(terms) == 1 else kind_word
        return [*chunks[: i + 1], Chunk("entity", text, terms), *chunks[end:]]
    return chunks


#: words before "room" that make it someone's own room ("my room", "her room")
_OWNERS = frozenset({"my", "your", "his", "her", "our", "their"})


def _own_room(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "my room", "her room": the bedroom, where the world has exactly one room called so."""
    bedrooms = [
        t for t in vocabulary.terms if t.phrase.endswith("bedroom") and vocabulary.is_subtype(t.type, "room")
    ]
    if len({t.symbol for t in bedrooms}) != 1:
        return chunks
    return [
        Chunk("entity", bedrooms[0].phrase, (bedrooms[0],), role=c.role)
        if c.kind == "entity" and c.text == "room" and i and chunks[i - 1].text in _OWNERS
        else c
        for i, c in enumerate(chunks)
    ]


def _restated_before(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool]) -> list[Chunk]:
    """A place a preposition governs, said again at once as another with its determiner and followed by
    another preposition ("from the kitchen table um the counter to tracy"): the first is dropped."""

    def place(at: int) -> bool:
        return (
            at < len(chunks)
            and chunks[at].kind == "entity"
            and (is_a(chunks[at], "furniture") or is_a(chunks[at], "room"))
        )

    for i, chunk in enumerate(chunks[:-4]):
        first = past_determiners(chunks, i + 1)
        again = past_determiners(chunks, first + 1)
        said_again = again > first + 1 and place(first) and place(again)
        if (
            chunk.kind == "prep"
            and said_again
            and again + 1 < len(chunks)
            and chunks[again + 1].kind == "prep"
        ):
            return [*chunks[: i + 1], *chunks[first + 1 :]]
    return chunks


def ones_named(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """ "the right one" said after "the left lamp": "the right lamp", where the world has a thing called so
    (the last word of a name said before, with the word said before "one"); then what is said again more
    exactly is put where it was said (:mod:`knic.language.restating`: "I want the light off. The hallway
    one.")."""
    names, sided = _two_word_names(vocabulary)
    said: list[str] = []
    out: list[list[str]] = []
    for segment in segments:
        kept = side_ones(list(segment), said, sided)  # "the shelf, the one on the left" (ordinary.py)
        kept = ones_placed(kept, said, vocabulary)  # "the one on the coffee table" (placedones.py)
        for i in range(1, len(kept)):
            heads = [w for w in said + kept[:i] if f"{kept[i - 1]} {w}" in names]
            if kept[i] == "one" and heads:
                kept[i] = heads[-1]
        said += kept
        out.append(kept)
    return restated(asked_twice(out), vocabulary)  # "bring my gita, bring it" (twice.py)


#: what says a thing is to be taken along ("don't forget the glasses", "do not forget", "remember the keys")
_NOT_FORGOTTEN = (("don't", "forget"), ("dont", "forget"), ("do", "not", "forget"), ("remember",))


@lru_cache(maxsize=16)
def _two_word_names(vocabulary: Vocabulary) -> tuple[frozenset[str], dict[str, str]]:
    """The world's names of two words, and the symbol of each that names one thing (once per vocabulary)."""
    names = frozenset(t.phrase for t in vocabulary.terms if len(t.phrase.split()) == 2)
    return names, {t.phrase: t.symbol for t in vocabulary.terms if t.phrase in names and not t.is_group}


def _taken_along(chunks: list[Chunk], is_a: Callable[[Chunk, str], bool], take: Chunk) -> list[Chunk]:
    """A thing to take along where a motion goes, said after it ("go to the bedroom and don't forget the
    glasses", "go to the study and take the laptop with you"): the thing is taken there, then the robot
    goes there (it ends where it was sent, with the thing)."""
    if not chunks or chunks[0].kind != "verb" or chunks[0].frames != ("MOTION",):
        return chunks
    end = next((i for i, c in enumerate(chunks) if i and c.kind in ("join", "verb", "unknown")), len(chunks))
    motion = chunks[:end]
    if not any(c.kind == "entity" and (is_a(c, "room") or is_a(c, "furniture")) for c in motion):
        return chunks
    at = end + (end < len(chunks) and chunks[end].kind == "join")
    words = [c.text for c in chunks[at : at + 3]]
    said = next((n for n in map(len, _NOT_FORGOTTEN) if tuple(words[:n]) in _NOT_FORGOTTEN), 0)
    along = not said and at < len(chunks) and chunks[at].kind == "verb" and chunks[at].text == take.text
    start = at + (said or along)
    thing = past_determiners(chunks, start)
    if not (said or along) or thing >= len(chunks) or not is_a(chunks[thing], "item"):
        return chunks
    rest = chunks[thing + 1 :]
    if along and [c.text for c in rest[:2]] == ["with", "you"]:
        rest = rest[2:]
    elif along or (rest and rest[0].kind != "join"):
        return chunks
    return [take, *chunks[start : thing + 1], *motion[1:], Chunk("join", "and"), *motion, *rest]
