"""Where sentences start in a command said without punctuation (speech transcripts), found from its words.

Typed commands separate the request from the talk around it with commas and full stops ("bring me the
sponge, love, I want to wipe up a spill"); a recogniser gives lowercase words only. When a stretch of words
cannot be read as one command, :class:`knic.language.reader.Reader` reads it again cut where a sentence
starts (:func:`sentence_starts`), and a command that points at a thing first ("see that candle put it on
the nightstand") with the pointing taken as the thing said (:func:`pointed`).

A cut never splits a phrase the chunker reads as one ("where did i leave" stays whole) and is made only:

* after an address word ("dear", "love": a speaker addresses the robot at the end or the start of a
  sentence);
* before a contraction that opens a statement ("i'm", "it's", "i've", "they're");
* before a bare subject pronoun ("i", "it", "they", ...) or "let" that no verb, preposition or determiner
  governs ("bring me the remote i want to watch the news": after a noun phrase);
* before "not" after a noun phrase, a level or a state ("a quarter of the way not too much").
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from itertools import pairwise

from knic.language.apologies import (
    adds,
    directions_read,
    guessed_where,
    hedged_asked,
    late_marker_placed,
    narrowed,
    or_dropped,
    suggested,
    where_it_is,
)
from knic.language.chunks import Chunk

#: words a speaker addresses the robot with; a sentence ends or starts next to them
ADDRESS = frozenset(
    {"dear", "love", "darling", "sweetie", "honey", "sweetheart", "robot", "buddy", "mate", "pal"}
)
#: contractions that open a statement ("i'm off to bed", "it's too bright")
OPENING_CONTRACTIONS = frozenset(
    {
        "i'm",
        "i've",
        "i'd",
        "i'll",
        "it's",
        "it'll",
        "that's",
        "they're",
        "they've",
        "we're",
        "we've",
        "you're",
        "he's",
        "she's",
        "there's",
        "let's",
    }
)
#: subject pronouns and "let": a sentence starts at them unless a verb, preposition or determiner governs them
SUBJECTS = frozenset({"i", "it", "they", "we", "he", "she", "let", "not"})
#: what, said last before a subject pronoun, makes the pronoun its object ("put it", "for her")
_GOVERNING = frozenset({"verb", "prep", "det", "join", "partitive", "quant", "percent", "repair", "owner"})
#: what "see" points with ("see that candle?"): a determiner right after it
_POINTING = frozenset({"that", "this", "those", "these", "the"})


def sentence_starts(tokens: Sequence[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> list[int]:
    """The indices (> 0) of ``tokens`` where a new sentence starts, by the rules of the module docstring;
    ``chunks`` cuts tokens into chunks (:meth:`knic.language.reader.Reader.chunks`)."""
    starts: list[int] = []
    whole = _kinds(chunks(tokens))
    for i in range(1, len(tokens)):
        word, before = tokens[i], tokens[i - 1]
        if not (before in ADDRESS or word in OPENING_CONTRACTIONS or word in SUBJECTS):
            continue
        left, right = chunks(tokens[:i]), chunks(tokens[i:])
        if _kinds(left) + _kinds(right) != whole:
            continue  # the cut splits a phrase ("where did i leave", "i think")
        if before in ADDRESS or word in OPENING_CONTRACTIONS:
            starts.append(i)
            continue
        last = _last_said(tokens[:i], left, chunks)
        if word == "not":
            if last in ("entity", "level", "number", "percent", "state", "me", "pronoun"):
                starts.append(i)
        elif last not in _GOVERNING:
            starts.append(i)
    return starts


def _kinds(chunks: list[Chunk]) -> list[tuple[str, str]]:
    return [(c.kind, c.text) for c in chunks]


def _last_said(
    tokens: Sequence[str], left: list[Chunk], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> str:
    """The kind of the last chunk before a cut; "filler" when the last word is dropped as politeness or
    nothing is said before."""
    if not left or not chunks(tokens[-1:]):
        return "filler"
    return left[-1].kind


def cut(segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]) -> list[list[str]]:
    """Each segment cut where a sentence starts in it (:func:`sentence_starts`)."""
    out: list[list[str]] = []
    for segment in segments:
        at = [0, *sentence_starts(segment, chunks), len(segment)]
        out += [segment[a:b] for a, b in pairwise(at) if b > a]
    return out


def statements_dropped(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]] | None:
    """The segments without those that state something rather than ask ("turn the lights off i'm going to
    bed": a segment opened by a subject and no verb of the command language; "the sun is in my eyes, pull
    the blinds down": no verb, and something the world has no name for said to be somewhere or something);
    None when none is dropped or nothing would be left. A statement "it" may point back to stays ("the
    newspaper is on the table, bring it to me": the newspaper is refused)."""
    referred = any(c.kind == "pronoun" for segment in segments for c in chunks(segment))
    kept = [
        segment
        for segment in segments
        if not (
            (segment[0] in OPENING_CONTRACTIONS or segment[0] in SUBJECTS)
            and (said := chunks(segment))
            and said[0].kind != "verb"
        )
        and not (_stated(chunks(segment)) and not referred)
    ]
    return kept if kept and len(kept) < len(segments) else None


def _stated(said: list[Chunk]) -> bool:
    """Whether a segment says something unknown is somewhere or something ("the sun is in my eyes"), or where
    or how a person is ("take the cooler to the den, keoni is sleeping on the chaise lounge", "..., mateo is
    in the kitchen"), and asks for nothing."""
    if any(c.kind == "verb" for c in said):
        return False
    person = bool(said) and said[0].kind == "entity" and all(t.type == "person" for t in said[0].terms)
    if person and len(said) > 1 and said[1].kind == "unknown" and said[1].text in _COPULAS:
        return True
    return any(a.kind == "unknown" and b.kind == "unknown" and b.text in _COPULAS for a, b in pairwise(said))


def operates_it(segment: Sequence[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> bool:
    """Whether a stretch of a command switches or sets "it" or "them" ("turn it off", "open them"): a verb
    that only operates devices, first, and a pronoun; such a stretch is the request, never talk around it."""
    said = chunks(segment)
    said = said[next((i for i, c in enumerate(said) if c.kind != "join"), len(said)) :]  # "then close it"
    operates = bool(said) and said[0].kind == "verb" and said[0].frames == ("OPERATING",)
    return operates and any(c.kind == "pronoun" for c in said)


def pointed(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]] | None:
    """The segments with a leading "see" that points at a thing dropped ("see that candle put it on the
    nightstand": that candle, then the action on it); None when the command starts otherwise, or when what
    is seen has a state or a copula ("see that the lights are off": make sure they are) or no action
    follows it."""
    first = segments[0]
    at = 1 if first[:1] == ["see"] else 2 if first[:2] == ["you", "see"] else 0
    if not at or len(first) <= at + 1 or first[at] not in _POINTING:
        return None
    rest = [first[at:], *segments[1:]]
    said = chunks([t for segment in rest for t in segment])
    verb = next((i for i, c in enumerate(said) if c.kind == "verb"), None)
    if verb is None or any(c.kind in _SAID_OF or c.text in _COPULAS for c in said[:verb]):
        return None
    return rest


#: what makes "see that ..." a wish for a state rather than pointing
_SAID_OF = frozenset({"state", "level", "number"})
_COPULAS = frozenset({"is", "are", "be", "gets", "stays", "isn't", "aren't"})


def sorry_repairs(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]]:
    """The segments with a bare "sorry" read as the repair "sorry i meant" when it stands between an
    action and what corrects it ("bring me the cup sorry the mug"): after a verb, and followed by a name, a
    level or a state before any word the tables do not know. "sorry, can you ..." and "sorry to bother you"
    stay politeness, and so does "sorry" in a list that goes on ("the kitchen light and, sorry, the lights
    under the cabinets too"); "or" and a late "i mean" around the correction are read with it
    (:mod:`knic.language.apologies`)."""
    # "i don't suppose the ice cream is in the freezer, is it?", "where'd i leave my keys, the kitchen?"
    segments = guessed_where(hedged_asked(suggested(directions_read(segments))), chunks)  # "why you don't"
    segments = where_it_is(segments, chunks)  # "give the football to colby, i found it on the landing"
    words = [t for segment in segments for t in segment]
    out: list[list[str]] = []
    at = 0
    for segment in segments:
        kept: list[str] = []
        for token in segment:
            if (
                token == "sorry"
                and not adds(words[:at], words[at + 1 :])
                and _corrects(words[:at], words[at + 1 :], chunks)
            ):
                kept += [token, "i", "meant"]
            else:
                kept.append(token)
            at += 1
        out.append(kept)
    return narrowed(late_marker_placed(or_dropped(out, chunks), chunks), chunks)


#: what a speaker says alone between an action and what corrects it ("..., wait, the box room")
_PAUSES = (
    ["wait"],
    ["hang", "on"],
    ["hold", "on"],
    ["no", "hang", "on"],
    ["no", "hold", "on"],
    ["oh", "wait"],
)
#: what a speaker says after the thing that corrects what they said ("..., the lounge light I mean")
_LATE_REPAIRS = (["actually"], ["i", "mean"], ["i", "meant"], ["rather"])


def late_repairs(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]]:
    """The segments with a repair said last in a sentence after an action ("switch on the floor lamp, er,
    the lounge light I mean", "get my laptop, well, the laptop charger actually") said first in it, as
    "i mean the lounge light": the thing corrects what the action said. A sentence with a verb of its own
    ("..., actually make it 60") is left as said. "Wait", "hang on" or "hold on" said alone between an
    action and what corrects it ("..., wait, the box room") is "no wait"."""
    out: list[list[str]] = []
    for at, segment in enumerate(segments):
        after = segments[at + 1] if at + 1 < len(segments) else []
        if segment in _PAUSES and out and _corrects([t for s in out for t in s], after, chunks):
            out.append(["no", "wait"])  # "take the towels to the bathroom, wait, the box room"
            continue
        marker = next((m for m in _LATE_REPAIRS if len(segment) > len(m) and segment[-len(m) :] == m), None)
        said = chunks(segment[: -len(marker)]) if marker else []
        if (
            marker is not None
            and any(c.kind == "verb" for s in out for c in chunks(s))
            and not any(c.kind in ("verb", "repair") for c in said)
            and any(c.kind in ("entity", "me", "number", "level", "state") for c in said)
        ):
            segment = ["i", "mean", *segment[: -len(marker)]]
        out.append(segment)
    return out


def _corrects(before: list[str], after: list[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> bool:
    if not any(c.kind == "verb" for c in chunks(before)):
        return False
    for chunk in chunks(after):
        if chunk.kind in ("entity", "me", "number", "level", "state"):
            return True
        if chunk.kind not in ("det", "prep") and not (chunk.kind == "pronoun" and chunk.text in _OWNERS):
            return False  # "..., sorry, her bed": "her" says whose, as "the" would
    return False


#: pronouns that say whose a thing is, read before a name as a determiner would be
_OWNERS = frozenset({"her", "his", "their"})


#: a subject with "be" before an "-ing" verb: what someone is doing, not what the robot is asked to do
_DOING = frozenset({"i'm", "we're", "they're", "he's", "she's", "it's", "am"})


def doings_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop what the speaker says someone is doing ("switch off the lights i'm going to bed"): a subject
    with "be" right before an "-ing" verb, up to the next verb said as a command or a joiner."""

    def starts(out: list[Chunk], chunk: Chunk, nxt: Chunk | None) -> bool:
        # said first, the clause is talk the reader already skips
        doing = chunk.kind == "unknown" and chunk.text in _DOING
        return doing and nxt is not None and nxt.kind == "verb" and nxt.soft and bool(out)

    return _talk_dropped(chunks, starts)


def _talk_dropped(
    chunks: list[Chunk], starts: Callable[[list[Chunk], Chunk, Chunk | None], bool]
) -> list[Chunk]:
    """``chunks`` without each stretch from a chunk where ``starts(kept so far, chunk, next chunk)`` up to
    the next verb said as a command or a joiner."""
    out: list[Chunk] = []
    skipping = False
    for i, chunk in enumerate(chunks):
        nxt = chunks[i + 1] if i + 1 < len(chunks) else None
        if starts(out, chunk, nxt):
            skipping = True
        elif skipping and (chunk.kind == "join" or (chunk.kind == "verb" and not chunk.soft)):
            skipping = False
        if not skipping:
            out.append(chunk)
    return out


#: what a name said as a subject is followed by when the speaker says something about it, not to the robot
#: ("find the teddy bear, oscar can't sleep without it")
_SAYS = frozenset(
    {
        "can't",
        "cannot",
        "won't",
        "wouldn't",
        "couldn't",
        "doesn't",
        "didn't",
        "isn't",
        "hasn't",
        "needs",
        "wants",
        "likes",
        "loves",
        "hates",
        "misses",
        "has",
        "will",
        "must",
        "should",
        "always",
        "never",
    }
)


def sayings_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop what the speaker says about someone or something after an action ("find the teddy bear, oscar
    can't sleep without it"): a name no verb, preposition or determiner governs, right before one of
    :data:`_SAYS`, up to the next verb said as a command or a joiner."""

    def starts(out: list[Chunk], chunk: Chunk, nxt: Chunk | None) -> bool:
        saying = chunk.kind == "entity" and nxt is not None and nxt.kind == "unknown" and nxt.text in _SAYS
        return saying and any(c.kind == "verb" for c in out) and out[-1].kind not in _GOVERNING

    return _talk_dropped(_wishes_dropped(_done_said(chunks)), starts)


def _done_said(chunks: list[Chunk]) -> list[Chunk]:
    """ "fetch the first aid kit, tom's cut his finger": what someone has done, said after an action, is a
    saying about them (the verb after "has" or "is" is no action of the robot's)."""
    out = list(chunks)
    for i in range(1, len(out) - 2):
        name, have, done = out[i : i + 3]
        if (
            name.kind == "entity"
            and have.kind == "unknown"
            and have.text in ("has", "had", "is", "was")
            and done.kind == "verb"
            and any(c.kind == "verb" for c in out[:i])
        ):
            out[i + 1 : i + 3] = [Chunk("unknown", "has"), replace(done, soft=True)]
    return out


def _wishes_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop why the speaker asks, said after an action ("take me to the parlour, I want to play the piano"):
    "i want to" (or the like) before a word the language does not know, up to the next verb said as a
    command or a joiner."""
    out: list[Chunk] = []
    skipping = False
    for i, chunk in enumerate(chunks):
        after = chunks[i + 1 : i + 3]
        if (
            chunk.kind == "verb"
            and chunk.text.split()[0] == "i"
            and any(c.kind == "verb" for c in out)
            and [c.kind for c in after] == ["prep", "unknown"]
            and after[0].text == "to"
        ):
            skipping = True
        elif skipping and (chunk.kind == "join" or (chunk.kind == "verb" and not chunk.soft)):
            skipping = False
        if not skipping:
            out.append(chunk)
    return out
