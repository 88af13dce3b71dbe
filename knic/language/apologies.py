"""Corrections said by a speaker who apologises and hedges as she goes: the words around the correction.

:func:`knic.language.segments.sorry_repairs` reads a bare "sorry" between an action and what corrects it as
"sorry i meant"; around it people also say:

* "or" opening the correction ("turn the landing light off? Or, sorry, the hallway light"; "... to Ottavia?
  Or, no, to the bathroom"; "or rather the kitchen"): the "or" is dropped, so that the repair is read as
  said (:func:`or_dropped`);
* the late marker said alone after the correction ("Or, sorry, the hallway light, I mean"; "sorry, her bed, I
  mean her bed" says it twice): said after a stretch a repair already opens, it adds nothing and is dropped;
  said after a stretch that only names things, after an action, it opens that stretch ("..., the hallway
  light, I mean" is "i mean the hallway light"; :func:`late_marker_placed`);
* "and, sorry, the under-cabinet lights too": an apology inside a list adds the thing, it corrects nothing
  (:func:`adds`).
* the thing said again more exactly, alone after the request ("could you bring me the glasses? The
  sunglasses, sorry"; "close the curtains? The bedroom ones"): in the request's place (:func:`narrowed`);
* a correction that opens with a preposition ("... to Ottavia? Or, no, to the bathroom") replaces what
  followed the same preposition (:func:`after_same_preposition`, for :func:`knic.language.tidy.repaired`).
* a hedged question about where a thing is ("I don't suppose the ice cream is in the chest freezer, is
  it?", "I wonder if the keys are on the hall table", "the ice cream isn't in the freezer, is it?"): asked
  plainly, "is the ice cream in the chest freezer" (:func:`hedged_asked`).
* a learner's "why you don't bring me the thermos?" is the suggestion "why don't you ...", not "you don't"
  that says not to (:func:`suggested`);
* the way there said as directions: "down cellar", "up attic" (no article before a kind of room) are "down
  to the cellar", so that the room is named where the home has none; "take a left into the kitchen" is "go
  into the kitchen"; a turn said alone is dropped (:func:`directions_read`);
* where the thing asked for is, said after the request ("give the football to Colby, I found it on the
  landing", "..., it is on the landing"): where to take it from, not where the person given it is
  (:func:`where_it_is`);
* a guess at where, a place said alone after a question of where a thing or person is ("where'd I leave my
  sunglasses, the conservatory?"): where to look (:func:`guessed_where`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from knic.language.chunks import Chunk
from knic.language.shortnames import room_words

Chunks = Callable[[Sequence[str]], list[Chunk]]
#: what a speaker says after the thing that corrects what they said (as knic.language.segments reads them)
_MARKERS = (["i", "mean"], ["i", "meant"], ["actually"], ["rather"])
#: words that end an addition ("..., and, sorry, the under-cabinet lights too")
_ADDING = (["too"], ["as", "well"], ["also"])


def _opens_repair(segment: Sequence[str], chunks: Chunks) -> bool:
    said = chunks(segment)
    return bool(said) and said[0].kind == "repair"


def or_dropped(segments: list[list[str]], chunks: Chunks) -> list[list[str]]:
    """The segments without an "or" that opens a correction: said alone before a stretch a repair opens
    ("..., or, sorry, the hallway light"), or first in such a stretch ("or no, the bathroom")."""
    out: list[list[str]] = []
    for at, segment in enumerate(segments):
        after = segments[at + 1] if at + 1 < len(segments) else []
        if segment == ["or"] and out and after and (_opens_repair(after, chunks) or after == ["sorry"]):
            continue
        if len(segment) > 1 and segment[0] == "or" and out and _opens_repair(segment[1:], chunks):
            segment = segment[1:]
        out.append(segment)
    return out


def late_marker_placed(segments: list[list[str]], chunks: Chunks) -> list[list[str]]:
    """The segments with a late marker said alone ("..., the hallway light, I mean") dropped after a
    stretch a repair opens, or put first in the stretch before it where that stretch only names things
    and an action was said before it."""
    out: list[list[str]] = []
    for segment in segments:
        if segment not in _MARKERS or len(out) < 2:
            out.append(segment)
            continue
        last = chunks(out[-1])
        if _opens_repair(out[-1], chunks) or (
            len(out) > 1 and [c.kind for c in chunks(out[-2])] == ["repair"]
        ):
            continue  # "sorry, the hallway light, i mean": said already
        named = any(c.kind in ("entity", "me", "number", "level", "state") for c in last)
        acted = any(c.kind == "verb" for s in out[:-1] for c in chunks(s))
        if named and acted and not any(c.kind in ("verb", "repair") for c in last):
            out[-1] = [*segment, *out[-1]]
            continue
        out.append(segment)
    return out


def adds(before: Sequence[str], after: Sequence[str]) -> bool:
    """Whether an apology between ``before`` and ``after`` stands inside a list that goes on: after "and"
    ("the kitchen light and, sorry, the under-cabinet lights"), or before words that end with "too", "as
    well" or "also"."""
    if before and before[-1] == "and":
        return True
    return any(len(after) >= len(end) and list(after[-len(end) :]) == end for end in _ADDING)


def after_same_preposition(before: Sequence[Chunk], replacement: Sequence[Chunk]) -> int | None:
    """Where the name a correction opening with a preposition replaces is, when an earlier stretch opens
    with the same preposition: the name after it, whatever it names ("bring the dressing gown to Ottavia?
    Or, no, to the bathroom": the bathroom, not Ottavia's place, is where it goes); else None."""
    if not replacement or replacement[0].kind != "prep":
        return None
    for at in range(len(before) - 1, -1, -1):
        if before[at].kind == "prep" and before[at].text == replacement[0].text:
            nxt = at + 1
            while nxt < len(before) and before[nxt].kind == "det":
                nxt += 1
            if nxt < len(before) and before[nxt].kind in ("entity", "me"):
                return nxt
            return None
    return None


#: words said around a thing said again that tell nothing of it ("the sunglasses, sorry")
_ASIDE = frozenset({"sorry", "please", "thanks", "i", "mean", "meant"})


def narrowed(segments: list[list[str]], chunks: Chunks) -> list[list[str]]:
    """The segments with a thing said again more exactly, alone after the request that named it, put in
    its place: "could you bring me the glasses? The sunglasses, sorry" is "... bring me the sunglasses",
    "would you close the curtains? The bedroom ones" is "... close the bedroom curtains" ("ones" and "one"
    stand for the word said before). The new words must end as the thing's did ("sunglasses" ends as
    "glasses" does, "bedroom curtains" as "curtains"), so a list ("the mug, the plate") is left alone."""
    out: list[list[str]] = []
    for segment in segments:
        words = [w for w in segment if w not in _ASIDE]
        said = chunks(words)
        if out and words and said and said[0].kind == "det":
            words, said = words[1:], said[1:]
        before = chunks(out[-1]) if out else []
        acted = any(c.kind == "verb" for s in out for c in chunks(s))
        last = before[-1] if before and before[-1].kind == "entity" else None
        if (
            last is None
            or not acted
            or not said
            or (said[-1].kind != "entity" and words[-1] not in ("ones", "one"))
            or any(c.kind not in ("entity", "unknown") for c in said)
            or out[-1][-len(last.text.split()) :] != last.text.split()
        ):
            out.append(segment)
            continue
        head = last.text.split()[-1]
        again = [*words[:-1], head] if words[-1] in ("ones", "one") else words
        if again == last.text.split() or not again[-1].endswith(head):
            out.append(segment)
            continue
        out[-1] = [*out[-1][: -len(last.text.split())], *again]
    return out


#: openings that hedge a question about where a thing is ("I don't suppose the ice cream is in the freezer?")
_HEDGES = (
    ["i", "don't", "suppose"],
    ["i", "do", "not", "suppose"],
    ["i", "wonder", "if"],
    ["i", "wonder", "whether"],
)
#: a question tag after a statement ("..., is it?", "..., aren't they?")
_TAGS = frozenset(
    {"is it", "isn't it", "are they", "aren't they", "is he", "is she", "isn't he", "isn't she"}
)
#: where a thing is said to be after "is" ("... is in the freezer", "... is on the table")
_WHERE = frozenset({"in", "on", "at", "inside", "under", "by", "near", "still"})


def hedged_asked(segments: list[list[str]]) -> list[list[str]]:
    """The segments with a hedged question about where a thing is asked plainly: "I don't suppose the ice
    cream is in the chest freezer, is it?", "I wonder if the keys are on the hall table", "the ice cream
    isn't in the freezer, is it?" are "is the ice cream in the chest freezer" (a search there); the tag said
    after it is dropped. A statement without a hedge or a tag ("the ice cream is in the freezer") is left."""
    out: list[list[str]] = []
    for at, segment in enumerate(segments):
        if " ".join(segment) in _TAGS and out and out[-1][:1] in (["is"], ["are"]):
            continue  # the tag of the question just put plainly
        tagged = at + 1 < len(segments) and " ".join(segments[at + 1]) in _TAGS
        hedge = next((h for h in _HEDGES if segment[: len(h)] == h), None)
        start = len(hedge) if hedge else 0
        be = next((i for i in range(start + 1, len(segment) - 1) if segment[i] in _BE), None)
        if (hedge or tagged) and be is not None and segment[be + 1] in _WHERE:
            segment = [_BE[segment[be]], *segment[start:be], *segment[be + 1 :]]
        out.append(segment)
    return out


#: "be" as said in the statement, and as it opens the question
_BE = {"is": "is", "are": "are", "isn't": "is", "aren't": "are"}


def guessed_where(segments: list[list[str]], chunks: Chunks) -> list[list[str]]:
    """The segments with a place said alone after a question of where a thing or person is ("where'd I
    leave my sunglasses, the conservatory?", "where's Colby, his room?") read as where to look: "... my
    sunglasses in the conservatory"."""
    out: list[list[str]] = []
    for segment in segments:
        said = [c for c in chunks(segment) if c.kind != "det"]
        place = len(said) == 1 and said[0].kind == "entity" and bool(said[0].terms)
        place = place and all(t.type in ("room", "furniture") for t in said[0].terms)
        before = chunks(out[-1]) if out else []
        asked = any(w.startswith("where") for w in out[-1]) if out else False
        last = before[-1] if before else None
        thing = (
            last is not None
            and last.kind == "entity"
            and any(t.type in ("item", "person") for t in last.terms)
        )
        if place and asked and thing:
            out[-1] = [*out[-1], "in", *segment]
            continue
        out.append(segment)
    return out


#: a learner's order of a suggestion ("why you don't bring me the thermos?"): "why don't you"
_WHY_YOU = (["why", "you", "don't"], ["why", "you", "do", "not"], ["why", "you", "not"])


def suggested(segments: list[list[str]]) -> list[list[str]]:
    """The segments with a learner's "why you don't ..." (Arabic, Persian and other speakers keep the
    statement's order in a question) said as "why don't you ...", a suggestion that asks for what follows,
    not "you don't" that says not to."""
    out = []
    for segment in segments:
        said = next((w for w in _WHY_YOU if segment[: len(w)] == w), None)
        out.append(["why", "don't", "you", *segment[len(said) :]] if said else segment)
    return out


#: where "down" or "up" goes to a kind of room said with no article ("go down cellar", "up attic")
_UP_DOWN = frozenset({"down", "up"})
#: a driver's turn said on the way ("take a left into the kitchen", "bang a u-ey"): how, not where
_TURNS = frozenset({"left", "right", "uey", "uie"})
_TURNING = frozenset({"take", "bang", "hang", "hook", "make", "do", "pull"})
_INTO = frozenset({"into", "in", "to", "through", "onto"})


def directions_read(segments: list[list[str]]) -> list[list[str]]:
    """The segments with the way there said as people give directions: "down cellar" and "up attic" (New
    England, and elsewhere, with no article before a kind of room) are "down to the cellar", "up to the
    attic", so that the room is named even where the home has none; "take a left into the kitchen", "bang a
    left into ..." (American) are "go into ..."; a turn said alone ("bang a u-ey and go back ...") is dropped.
    """
    rooms = room_words()
    out = []
    for segment in segments:
        words: list[str] = []
        i = 0
        while i < len(segment):
            token = segment[i]
            turn = segment[i : i + 3]
            if len(turn) == 3 and turn[0] in _TURNING and turn[1] == "a" and turn[2] in _TURNS:
                nxt = segment[i + 3] if i + 3 < len(segment) else ""
                words += ["go"] if nxt in _INTO else []
                i += 3
                continue
            words.append(token)
            if token in _UP_DOWN and i + 1 < len(segment) and segment[i + 1] in rooms:
                words += ["to", "the"]
            i += 1
        out.append(words)
    return out


#: what opens a sentence saying where the thing just asked for is ("it is on the landing", "I found it ...")
_IT_IS = (
    *([s, b] for s in ("it", "they") for b in ("is", "are", "was", "were", "'s")),
    *(["i", v, o] for v in ("found", "left", "saw", "put", "dropped") for o in ("it", "them")),
)
_ON = frozenset({"on", "in", "at", "under", "by", "inside", "near"})


def where_it_is(segments: list[list[str]], chunks: Chunks) -> list[list[str]]:
    """The segments with a sentence after a request that says where its thing is ("give the football to Colby,
    I found it on the landing", "..., it is on the landing") said as where to take it from ("... from the
    landing"): so it is not taken for where the person given it is."""
    out: list[list[str]] = []
    for segment in segments:
        opening = next((o for o in _IT_IS if segment[: len(o)] == o), None)
        acted = any(c.kind == "verb" for s in out for c in chunks(s))
        if (
            opening is None
            or not acted
            or len(segment) <= len(opening) + 1
            or segment[len(opening)] not in _ON
        ):
            out.append(segment)
            continue
        place = segment[len(opening) + 1 :]
        said = [c for c in chunks(place) if c.kind != "det"]
        placed = len(said) == 1 and said[0].kind == "entity" and bool(said[0].terms)
        if not placed or not all(t.type in ("room", "furniture") for t in said[0].terms) or "from" in out[-1]:
            out.append(segment)
            continue
        out[-1] = [*out[-1], "from", *place]
    return out
