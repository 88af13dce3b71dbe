"""What the sentences of a command say of each other, read before its words are (used by
:class:`knic.language.reader.Reader` on the command's stretches between stops and commas):

* A sentence after a request that says something the world has no device for is on or off ("shut the porch
  light off, the Sox game's on") or how someone is ("Marnie's asleep"): a remark, dropped
  (:func:`_remarks_dropped`).
* A sentence after a request that gives its reason ("..., as I wish to inspect the washing line",
  "..., because I'm cold"), or a reason said on in the request's sentence ("take me to the lounge so that I
  can watch tv"), or says what someone else means to do ("where did the jigsaw go? Colby wants to finish
  it"), asks nothing more: dropped (:func:`reasons_dropped`).
* What someone did with a thing said before ("do you happen to know where the headphones are? jas borrowed
  them"): a sentence of a person, a past verb the command language lacks and no thing named, said beside a
  request, is talk (:func:`done_dropped`): jas is no one to look for.
* "together" (or "at once", "in one go") said last says how, not what: dropped; a sentence then left with a
  verb and "it" or "them" only, after a sentence that named them ("bring me the milk and the butter, could
  you take them together"), asks nothing more (:func:`together_dropped`).
* An aside after a request that tells who or what was meant in words the world lacks, naming only a place
  ("find Imogen for me. Imogen! The young lady from the bluebell room."): dropped (:func:`_asides_dropped`).
* A request that names only a thing the world lacks, with talk beside it ("can you turn on the aircon, it's
  so hot here in the laundry"): read without the talk, so that what is lacking is named
  (:func:`_lacking_first`).
* Who a thing is for, said last after where it goes, when the world knows no such one ("put the walking map
  on the coffee table for the guests"): says why, dropped (:func:`_for_unknown_dropped`).
* A terse sentence of a device and its state beside a sentence of another kind ("travel mug to kitchen,
  landing light off", "bring the mug to the kitchen, landing light off"): the device's is said with "turn",
  and a terse one of things and where they go ("travel mug to kitchen") with "take", so that each is an
  action of its own (:func:`verbs_said`); a command of one kind only ("hall light on, landing light off";
  "take the sponge, the soap and the tissues to the bathroom") is read as said.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from knic.language.besides import besides_read
from knic.language.chunks import Chunk
from knic.language.vocabulary import Term

#: how things are carried, said last ("take them together")
_TOGETHER = (["all", "together"], ["together"], ["at", "once"], ["in", "one", "go"], ["in", "one", "trip"])
#: what a device's sentence may hold besides the device and its state
_WITH_STATE = frozenset({"det", "level", "number", "percent", "prep", "state", "quant"})


def sentences_read(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """The sentences with the rules of the module docstring applied (and of :mod:`knic.language.besides`)."""
    segments = reasons_dropped(together_dropped(besides_read(segments, chunks, is_a), chunks), chunks)
    segments = _remarks_dropped(segments, chunks, is_a)  # "..., the Sox game's on", "..., Marnie's asleep"
    segments = done_dropped(segments, chunks, lambda c: any(is_a(t, "person") for t in c.terms))
    segments = _lacking_first(_asides_dropped(segments, chunks, is_a), chunks)
    return verbs_said([_for_unknown_dropped(s, chunks) for s in segments], chunks, is_a)


def _lacking_first(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]]:
    """A request that names only a thing the world lacks ("can you turn on the aircon, it's so hot here in the
    laundry"; "bring me my knitting, it is in my bag"; a learner's "bring me bread, I make soup"), read
    without the sentences of talk beside it that have no verb or open with the speaker ("i make soup"): its
    refusal names what is lacking, not "here", "it" or the room the talk names."""
    said = [chunks(s) for s in segments]
    lacking = [
        n
        for n, c in enumerate(said)
        if any(x.kind == "verb" and not x.soft for x in c[:1] + c[1:2])  # "it's getting dark": no request
        and not any(x.kind in ("entity", "pronoun") for x in c)
        and any(c[i].kind in ("det", "me") and c[i + 1].kind == "unknown" for i in range(1, len(c) - 1))
    ]
    corrected = any(x.kind == "repair" for c in said for x in c)  # "go to the garage, no wait, the kitchen"
    if len(lacking) != 1 or len(segments) < 2 or corrected:
        return segments
    told = [
        n == lacking[0] or (any(x.kind == "verb" for x in c) and s[:1] not in _SPEAKER)
        for n, (s, c) in enumerate(zip(segments, said, strict=True))
    ]
    return [s for n, s in enumerate(segments) if told[n]]


#: what opens a sentence the speaker says of themselves ("i make soup", "we're eating")
_SPEAKER = (["i"], ["i'm"], ["we"], ["we're"])


def _asides_dropped(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """The sentences without an aside after a request that tells who or what was meant in words the world
    lacks, naming only a place ("find Imogen for me. Imogen! The young lady from the bluebell room."): the
    request said it already."""
    out: list[list[str]] = []
    for segment in segments:
        said = chunks(segment)
        named = [c for c in said if c.kind == "entity"]
        aside = (
            any(c.kind == "verb" for s in out for c in chunks(s))
            and not any(c.kind in ("verb", "me", "pronoun", "state", "level", "number") for c in said)
            and any(c.kind == "unknown" for c in said)
            and not (_SAYING_WHERE | {"one", "ones"}) & set(segment)  # "..., it's in the office": where it is
            and named
            and all(any(is_a(t, "room") or is_a(t, "furniture") for t in c.terms) for c in named)
        )
        if not aside:
            out.append(segment)
    return out


#: what says where a thing or someone is, not who or what is meant ("it's in the office", "i'm in bed")
_SAYING_WHERE = frozenset(
    {"it's", "they're", "he's", "she's", "he'll", "she'll", "it'll", "is", "are", "was", "were", "be", "i'm"}
    | {"i", "we", "we're", "you", "you're", "i'll", "we'll", "am"}
)
#: where a thing is put or taken, said before who it is for
_WHERE = frozenset({"on", "in", "into", "onto", "to", "at", "by", "next to", "on top of", "inside"})


def _for_unknown_dropped(segment: list[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> list[str]:
    """A sentence without who it is for, said last after where the thing goes, when the world knows no such
    one ("put the walking map on the coffee table for the guests", "... in the fridge for later"): whom the
    robot cannot hand a thing to says why, not where."""
    said = chunks(segment)
    at = next((i for i in range(len(said) - 1, 0, -1) if said[i].text == "for"), None)
    if at is None or not any(c.kind == "unknown" for c in said[at + 1 :]):
        return segment
    if any(c.kind not in ("det", "unknown") for c in said[at + 1 :]):
        return segment
    placed = any(
        c.kind == "prep" and c.text in _WHERE and any(d.kind == "entity" for d in said[i + 1 : at])
        for i, c in enumerate(said[:at])
    )
    if not placed or not any(c.kind == "verb" for c in said[:at]):
        return segment
    return segment[: sum(len(c.text.split()) for c in said[:at])]


#: how a sentence giving the reason for a request opens ("..., as I wish to inspect the washing line")
_REASONS = (
    ["because"],
    ["cos"],
    ["coz"],
    ["cause"],
    ["'cause"],
    ["since"],
    ["so", "that"],
    *([w, s] for w in ("as", "so") for s in ("i", "we", "it", "he", "she", "they", "i'm", "i've", "it's")),
    # what the speaker has to do themself, said after the request ("..., gotta ask priya something", "where
    # is bronte? i must give her the sun hat", "switch on the geyser, i want to bath")
    ["got", "to"],
    ["i've", "got", "to"],
    ["i", "have", "to"],
    ["i", "must"],
    ["i", "need", "to"],
    ["i", "want", "to"],
    ["we", "have", "to"],
)


#: what someone else means to do, said after a request ("where did the jigsaw go? Colby wants to finish it")
_MEANS_TO = (["wants", "to"], ["needs", "to"], ["has", "to"], ["is", "going", "to"])


def _wish_of_another(segment: list[str], chunks: Callable[[Sequence[str]], list[Chunk]]) -> bool:
    """Whether a sentence says what someone else means to do, with a verb that is no action of the robot's
    ("Colby wants to finish it", "she needs to practise"; not "Colby wants to go to the kitchen"): a
    reason; so is the speaker's own "i want read newspaper" (a learner's, with no "to")."""
    if segment[:2] in (["i", "want"], ["i", "need"]) and len(segment) > 3:
        then = chunks(segment[2:3])
        return bool(then) and then[0].kind == "unknown"
    for at in (1, 2, 3):
        said = next((m for m in _MEANS_TO if segment[at : at + len(m)] == m), None)
        if said is not None:
            then = chunks(segment[at + len(said) : at + len(said) + 1])
            return bool(then) and then[0].kind != "verb"
    return False


#: a reason said on in the sentence of the request, with no stop before it
_SAID_ON = (["because"], ["cos"], ["coz"], ["so", "that"], ["so", "i", "can"], ["so", "we", "can"])


def _remarks_dropped(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """The sentences without the remarks after a request: that something the world has no device for is on
    or off ("shut the porch light off, the Sox game's on", "..., the kettle is on", "..., the telly's off"),
    not the state the request asks for; how someone is, in words that name nothing of the world ("turn off
    the fairy lights? Marnie's asleep", "..., Brendan is still asleep", "..., Tracy's a bit tired"), not a
    person to operate or to look for."""
    out: list[list[str]] = []
    for segment in segments:
        acted = any(c.kind == "verb" for s in out for c in chunks(s))
        said = chunks(segment)
        if acted and (_on_said_of_others(segment, said, is_a) or _how_someone_is(said, is_a)):
            continue
        out.append(segment)
    return out


def _on_said_of_others(segment: list[str], said: list[Chunk], is_a: Callable[[Term, str], bool]) -> bool:
    on = len(segment) > 2 and segment[-1] in ("on", "off") and segment[0] not in ("and", "then")
    be = on and (segment[-2].endswith("'s") or segment[-2] in ("is", "are", "was"))
    return be and not any(c.kind == "verb" or any(is_a(t, "device") for t in c.terms) for c in said)


def _how_someone_is(said: list[Chunk], is_a: Callable[[Term, str], bool]) -> bool:
    person = len(said) > 2 and said[0].kind == "entity" and any(is_a(t, "person") for t in said[0].terms)
    rest = said[2:]
    return (
        person
        and said[1].text in ("is", "was")
        and all(c.kind in ("unknown", "vague", "det") for c in rest)
        and any(c.kind == "unknown" for c in rest)
    )


def reasons_dropped(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]]:
    """The sentences without those after a request that give its reason ("..., as I wish to inspect the
    washing line", "..., because I want to see the garden"): a reason asks for nothing more."""
    out: list[list[str]] = []
    for segment in segments:
        acted = any(c.kind == "verb" for s in out for c in chunks(s))
        if acted and (any(segment[: len(r)] == r for r in _REASONS) or _wish_of_another(segment, chunks)):
            continue
        # said on in the same sentence ("take me to the lounge so that I can watch tv"): cut there
        at = next(
            (i for i in range(1, len(segment)) if any(segment[i : i + len(r)] == r for r in _SAID_ON)), None
        )
        if at is not None and any(c.kind == "verb" for c in chunks(segment[:at])):
            # up to a request said after it ("... because i'm cold and then turn the dimmer down")
            on = (j for j in range(at + 1, len(segment)) if segment[j] in ("and", "then"))
            end = next((j for j in on if any(c.kind == "verb" for c in chunks(segment[j:]))), len(segment))
            segment = segment[:at] + segment[end:]
        out.append(segment)
    return out


def done_dropped(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_person: Callable[[Chunk], bool],
) -> list[list[str]]:
    """The sentences without those saying what someone did to a thing said before (see the module
    docstring), when a sentence with a verb is left; else all."""
    kept = [s for s in segments if not _done(chunks(s), is_person)]
    acts = any(c.kind == "verb" for s in kept for c in chunks(s))
    return kept if acts and len(kept) < len(segments) else segments


#: pasts that are no "-ed" word, of what happens to someone ("tobias cut his finger", "she hurt her knee")
_HAPPENED = frozenset({"cut", "hurt", "broke", "fell", "lost", "left", "spilt", "burnt", "bumped", "banged"})


def _done(said: list[Chunk], is_person: Callable[[Chunk], bool]) -> bool:
    """Whether a sentence is a person, a word in "-ed" the tables do not know (or a past of what happens to
    someone, :data:`_HAPPENED`), and no name after it."""
    if len(said) < 2 or said[0].kind != "entity" or not is_person(said[0]):
        return False
    past = said[1].kind == "unknown" and said[1].text.endswith("ed")
    if not past and said[1].text not in _HAPPENED:  # "tobias cut his finger": "cut" is also the robot's verb
        return False
    return not any(c.terms or c.kind in ("verb", "me") for c in said[2:])


def together_dropped(
    segments: list[list[str]], chunks: Callable[[Sequence[str]], list[Chunk]]
) -> list[list[str]]:
    """The sentences without "together" said last, and without a sentence then left as a verb and a pronoun
    after another sentence (see the module docstring)."""
    out: list[list[str]] = []
    for segment in segments:
        how = next((t for t in _TOGETHER if len(segment) > len(t) and segment[-len(t) :] == t), None)
        if how is None:
            out.append(segment)
            continue
        said = chunks(segment[: -len(how)])
        if out and [c.kind for c in said if c.kind != "quant"] == ["verb", "pronoun"]:
            continue  # "..., could you take them together": the things said before, carried as said
        out.append(segment[: -len(how)])
    return out


def verbs_said(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """The sentences with the verb a terse sentence leaves unsaid, in a command of terse sentences of two
    kinds or of a terse one beside one with a verb (see the module docstring); else as said."""
    if len(segments) < 2:
        return segments
    kinds = [_terse_kind(chunks(s), is_a) for s in segments]
    if "device" not in kinds or len({k or "said" for k in kinds}) < 2:
        return segments  # things listed after a verb ("take the sponge, the soap and the tissues to ...")
    out: list[list[str]] = []
    for segment, kind in zip(segments, kinds, strict=True):
        if kind is None:
            out.append(segment)
            continue
        joined = 0
        while joined < len(segment) and [c.kind for c in chunks(segment[: joined + 1])] == ["join"]:
            joined += 1  # "..., then landing light off": the verb after "then"
        verb = "turn" if kind == "device" else "take"
        out.append([*segment[:joined], verb, *segment[joined:]])
    return out


def _terse_kind(said: list[Chunk], is_a: Callable[[Term, str], bool]) -> str | None:
    """ "device": a sentence of devices and a state or level only ("landing light off"); "carry": of things
    and where they go only ("travel mug to kitchen"); else None."""
    said = [c for c in said if c.kind != "join"]
    if not said or any(c.kind in ("verb", "unknown", "pronoun") for c in said):
        return None
    named = [c for c in said if c.kind == "entity"]
    if not named:
        return None
    if all(is_a(t, "device") for c in named for t in c.terms) and any(
        c.kind in ("state", "level", "number") or (c.kind == "prep" and c.state) for c in said
    ):
        return "device" if all(c.kind in _WITH_STATE or c.kind == "entity" for c in said) else None
    goal = next((i for i, c in enumerate(said) if c.kind == "prep" and c.role == "goal"), None)
    if goal is None or goal == 0 or goal + 1 >= len(said):
        return None
    things = [c for c in said[:goal] if c.kind == "entity"]
    where = said[goal + 1 :]
    placed = all(
        c.kind in ("det", "me") or (c.kind == "entity" and any(is_a(t, k) for t in c.terms for k in _PLACES))
        for c in where
    )
    carried = bool(things) and all(is_a(t, "item") for c in things for t in c.terms)
    return (
        "carry"
        if carried and placed and all(c.kind in ("det", "entity", "join") for c in said[:goal])
        else None
    )


#: where a thing said tersely may go
_PLACES = ("room", "furniture", "person")
