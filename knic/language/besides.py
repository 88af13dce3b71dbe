"""What people say around a request that asks nothing of the robot, and a few words of theirs read as they
mean them (used by :func:`knic.language.sentences.sentences_read` on a command's sentences; people35):

* "nothing" after a verb of seeing or hearing ("turn the light all the way up, I can't see nothing", the
  double negative of many Englishes) is "anything": no level of nothing.
* A sentence after a request saying what someone has just done, in the perfect of Newfoundland and Irish
  English ("where's the game controller? Abdi's after hiding it"): talk, dropped; Abdi is no one to look
  for. Said first ("I'm after losing me glasses, where are they?") it stays: the request's "they" needs it.
* A sentence after a request opening with the speaker, or someone and the speaker, doing what is no action
  of the robot's ("take the baklava to the card table, Eleni and I play cards there", "..., we eat there"):
  talk, dropped; the cards they play are nothing to carry.
* A sentence after a request that already says where the thing goes, saying someone wants some of it
  ("take the baklava to the sunroom, Eleni wants some"): the reason, dropped; Eleni is not given it as well.
* "both" said last after a state ("the bathroom light and the landing light, put off both"): "them".
* A piece of furniture said alone, then "go there" with only politeness beside it ("my desk, please go
  there"): "go to my desk", as a room said so already is.
* "have it at" (or "them") a level ("the sunroom blinds, we'll have them at seventy percent"): "set it to"
  that level, as "have the blinds at seventy" already is; "have them on" (or off): "turn them on".
* "we need", "we'll need", "we're going to need" (or "want") opening a command: "i need" (a nurse's or a
  parent's "we"; "we're going to need the towels from the linen closet", "we'll want the bedsheets").
* "is" opening a sentence before "too", "so", "very" or "much" (a learner's dropped "it", as Greek, Spanish,
  Italian and Persian speakers leave it out: "is too much light, close the blinds of the sunroom"): "it's".
* "do a sweep (or pass, search, scan, check) of (or through, around) the rec room for the controller":
  "search the rec room for the controller".
* A sentence after a request saying where a thing is not ("where is the knitting bag? It's not on the rocking
  chair", "..., they're not on the hall bench", a learner's "is not on the rocking chair"): dropped; it is
  looked for everywhere, not there.
* "put" or "get" before devices each with its own level or state ("can we get the bedroom blinds halfway and
  the bedroom light at ten", "get the desk lamp to twenty and the office light off"): "set", so that each
  keeps its own, as after "set" or "turn" (the last level was read for both).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from knic.language.chunks import Chunk
from knic.language.vocabulary import Term

#: verbs of perceiving before a double negative's "nothing"
_PERCEIVING = frozenset({"see", "hear", "find", "feel", "read", "say"})
#: what says someone is (or was) "after" doing a thing
_BE = frozenset(
    {"is", "was", "am", "are", "'s", "i'm", "he's", "she's", "we're", "they're", "you're", "been"}
)
#: the speaker and others as a subject ("i" alone opens too much that matters: "i mean the juice")
_WE = (["we"], ["you", "and", "i"], ["me", "and", "you"])
#: what the speaker says of their thinking, losing or wanting: no talk to drop ("we think it's in the study")
_NOT_DOING = frozenset(
    {"think", "mean", "meant", "thought", "left", "lost", "put", "need", "want", "know", "said"}
)
#: verbs of wanting said of a third person ("eleni wants some")
_WANTS = frozenset({"wants", "needs", "would like", "likes"})
#: what a third person wants said of a thing named before
_SOME = frozenset({"some", "it", "them", "em", "one", "a bit", "a piece", "too", "as well"})
_STATES = frozenset({"on", "off", "out", "open", "closed", "shut"})
#: the speaker's "we" wishing for a thing
_WE_NEED = tuple(
    [*we, wish]
    for wish in ("need", "want")
    for we in (["we're", "going", "to"], ["we", "are", "going", "to"], ["we'll"], ["we", "will"], ["we"])
)
#: what a learner's "is" without its "it" comes before ("is too much light")
_HOW_MUCH = frozenset({"too", "so", "very", "much", "really", "quite"})
#: a going-over of a place said as a noun ("do a quick sweep of the basement")
_SWEEPS = frozenset({"sweep", "pass", "search", "scan", "check", "recce"})
_OVER = frozenset({"of", "through", "around", "round", "in"})
#: what a thing's sentence opens with, and its "not", before where it is not
_IT = frozenset({"it", "they", "he", "she", "it's", "its", "they're", "he's", "she's", "that's"})
_NOT = frozenset({"not", "isn't", "aren't", "wasn't", "weren't", "ain't"})
_WHERE = frozenset({"on", "in", "at", "under", "inside", "by", "near", "behind", "there", "here"})
#: verbs that put a thing somewhere, said of devices and their levels
_PUT = frozenset({"put", "get", "pop", "stick"})


def _swept(words: list[str]) -> list[str]:
    """ "do a pass through the rec room for the controller" -> "search the rec room for the controller"."""
    for i in range(len(words) - 3):
        if words[i] in ("do", "have", "make") and words[i + 1] in ("a", "an"):
            at = i + 3 if words[i + 2] in ("quick", "fast", "proper", "good") else i + 2
            if (
                at + 1 < len(words)
                and words[at] in _SWEEPS
                and words[at + 1] in _OVER
                and "for" in words[at:]
            ):
                return [*words[:i], "search", *words[at + 2 :]]
    return words


def _set_said(
    words: list[str], chunks: Callable[[Sequence[str]], list[Chunk]], is_a: Callable[[Term, str], bool]
) -> list[str]:
    """ "get the blinds halfway and the light at ten" -> "set the blinds halfway and the light at ten"."""
    said = chunks(words)
    verb = next((i for i, c in enumerate(said) if c.kind == "verb"), None)
    if verb is None or said[verb].text not in _PUT or said[verb].text not in words:
        return words
    rest = said[verb + 1 :]
    things = [i for i, c in enumerate(rest) if c.kind == "entity"]
    devices = [i for i in things if all(is_a(t, "device") for t in rest[i].terms)]
    leveled = [i for i in devices if any(c.kind in ("level", "number") for c in rest[i + 1 : i + 3])]
    stated = [i for i in devices if any(c.kind == "state" or c.text in _STATES for c in rest[i + 1 : i + 2])]
    if len(things) < 2 or not leveled or len(set(leveled) | set(stated)) != len(things):
        return words
    at = words.index(said[verb].text)
    return [*words[:at], "set", *words[at + 1 :]]


def _had_at(words: list[str]) -> list[str]:
    """ "have them at seventy" -> "set them to seventy"; "have it on" -> "turn it on"."""
    out = list(words)
    for i in range(len(words) - 2):
        if words[i] == "have" and words[i + 1] in ("it", "them", "em"):
            if words[i + 2] == "at":
                out[i], out[i + 2] = "set", "to"
            elif words[i + 2] in _STATES and i + 3 == len(words):
                out[i] = "turn"
    return out


def besides_read(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """The sentences with the rules of the module docstring applied."""
    segments = [_set_said(_swept(_had_at(_anything_seen(s))), chunks, is_a) for s in segments]
    segments = [["it's", *s[1:]] if s[:1] == ["is"] and s[1:2] and s[1] in _HOW_MUCH else s for s in segments]
    for we in _WE_NEED:
        if segments and segments[0][: len(we)] == we:
            segments = [["i", "need", *segments[0][len(we) :]], *segments[1:]]
    segments = [
        [*s[:-1], "them"] if len(s) > 2 and s[-1] == "both" and s[-2] in _STATES else s for s in segments
    ]
    segments = _there_named(segments, chunks, is_a)
    if len(segments) < 2:
        return segments
    kept = [segments[0]]
    for segment in segments[1:]:
        if not (
            _after_done(segment)
            or _not_there(segment)
            or _we_do(segment, chunks, is_a)
            or _wanted(segment, kept, chunks, is_a)
        ):
            kept.append(segment)
    return kept


def _anything_seen(words: list[str]) -> list[str]:
    """ "i can't see nothing" -> "i can't see anything"."""
    return [
        "anything" if w == "nothing" and i and words[i - 1] in _PERCEIVING else w for i, w in enumerate(words)
    ]


def _not_there(words: list[str]) -> bool:
    """Whether a sentence says where a thing is not ("it's not on the rocking chair", "isn't in there")."""
    at = 1 if words[:1] and words[0] in _IT else 0
    at += 1 if words[at : at + 1] and words[at] in _BE else 0
    at += 1 if words[at : at + 1] and words[at] in _NOT else 0
    return 0 < at < len(words) and words[at - 1] in _NOT and words[at] in _WHERE


def _after_done(words: list[str]) -> bool:
    """Whether a sentence says what someone is after doing ("abdi's after hiding it")."""
    return any(
        words[i] == "after"
        and words[i + 1].endswith("ing")
        and (words[i - 1] in _BE or words[i - 1].endswith("'s"))
        for i in range(1, len(words) - 1)
    )


def _person(said: list[Chunk], is_a: Callable[[Term, str], bool]) -> bool:
    """Whether chunks are one person's name."""
    return len(said) == 1 and said[0].kind == "entity" and all(is_a(t, "person") for t in said[0].terms)


def _we_do(
    words: list[str], chunks: Callable[[Sequence[str]], list[Chunk]], is_a: Callable[[Term, str], bool]
) -> bool:
    """Whether a sentence opens with the speaker (and others) doing what is no action ("we play cards
    there", "eleni and i play cards there")."""
    rest: list[str] | None = None
    for we in _WE:
        if words[: len(we)] == we:
            rest = words[len(we) :]
    for i in range(1, min(len(words) - 2, 4)):
        if words[i : i + 2] == ["and", "i"] and _person(chunks(words[:i]), is_a):
            rest = words[i + 2 :]
    if not rest or rest[0] in _NOT_DOING:
        return False
    said = chunks(rest[:1])
    return len(said) == 1 and said[0].kind == "unknown" and said[0].text == rest[0] and rest[0].isalpha()


def _wanted(
    words: list[str],
    before: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> bool:
    """Whether a sentence says a person wants some of what a request before it sends somewhere ("eleni wants
    some" after "take the baklava to the sunroom")."""
    if not any("to" in s for s in before):
        return False
    for i in range(1, len(words)):
        for wants in _WANTS:
            n = len(wants.split())
            if words[i : i + n] == wants.split() and " ".join(words[i + n :]) in _SOME:
                return _person(chunks(words[:i]), is_a)
    return False


def _there_named(
    segments: list[list[str]],
    chunks: Callable[[Sequence[str]], list[Chunk]],
    is_a: Callable[[Term, str], bool],
) -> list[list[str]]:
    """ "my desk", "please go there" -> "go to my desk"."""
    out: list[list[str]] = []
    n = 0
    while n < len(segments):
        said = chunks(segments[n])
        place = [c for c in said if c.kind != "det"]
        alone = (
            len(place) == 1
            and place[0].kind == "entity"
            and all(is_a(t, "furniture") for t in place[0].terms)
        )
        after = [c.text for c in chunks(segments[n + 1])] if n + 1 < len(segments) else []
        if alone and place[0].terms and after == ["go", "there"]:
            out.append(["go", "to", *segments[n]])
            n += 2
            continue
        out.append(segments[n])
        n += 1
    return out
