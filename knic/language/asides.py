"""What a speaker says to others, or about others, around a request to the robot:

* a stretch set off by a pair of dashes in the middle of a sentence, where the sentence broke off (after an
  article, a possessive or a preposition: "bring me the — Tobi, leave that! — the palm oil", "switch off
  the — hold on, I'm on the phone — the store light"), that exclaims or asks ("... on the shoe rack — Tobi,
  wear your shoes! — by the door") or that calls someone by name ("— Tobi, stop jumping on the sofa —") is
  an interruption, said to someone else or to no one:
  dropped, and the sentence read on where it broke off (a signer's "ice pack — freezer take — Ottavio give"
  stays). Kept are a description
  of the thing ("the tea — the green one — from the kitchen") and a correction ("the plastic cup in the —
  sorry, the enamel cup — in the sink"): what opens with an article or a possessive, after any word of
  repair (:func:`dashed_asides_dropped`, on the text);
* a title said before a person's name ("Mama Adunni", "Oga Olumide", "Aunty Funmilayo", "Pastor Ikenna",
  "my sister Funmilayo") is dropped: the name says who (:func:`spoken_to`);
* a stretch that calls someone by name or waits ("wait", "hold on", "hello"), cutting into a sentence broken
  off after an article or a preposition that goes on after it ("put the mug on the, Jack stop it, on the
  dining table"), is dropped too (:func:`spoken_to`);
* "Jack said the hallway light should be off", said last: what Jack said, passed on, is the request
  (:func:`spoken_to`);
* a person's name said alone, then a question to "you" ("Ese, have you seen it? Robbie, find it"), is said
  to that person, when the command goes on to ask the robot something: dropped (:func:`spoken_to`);
* "what is inside the deep freezer? check if the chicken is there", "the deep freezer, is the chicken
  there?": "there" is the place asked about or named alone just before (:func:`spoken_to`);
* "why is the X (still) off?" before a request says what is wrong, as "the X is still off" does ("why is
  the security light still off? put it on"): read so (:func:`spoken_to`).
"""

from __future__ import annotations

import re
from functools import lru_cache

from knic.language.kinds import phrases_of
from knic.language.vocabulary import Vocabulary

#: a pair of dashes (typographic, or a hyphen with spaces around it) and what they set off
_DASHED = re.compile(r"\s*(?:—|–|\s-{1,2}\s|--)\s*([^—–]+?)\s*(?:—|–|\s-{1,2}\s|--)\s*(?=\S)")
#: words that open a correction
_REPAIR = r"(?:sorry|no|i mean|actually|rather|or rather|i meant|er|um)"
#: what a kept aside opens with, after any word of repair: a description of a thing
_DESCRIBES = re.compile(
    rf"^(?:{_REPAIR}\W+)*(?:the|a|an|my|your|his|her|their|our|this|that|these|those|one)\b", re.IGNORECASE
)
#: words a sentence breaks off after, to be taken up again after the interruption
_BROKEN_AFTER = frozenset(
    {
        "the",
        "a",
        "an",
        "my",
        "your",
        "his",
        "her",
        "our",
        "their",
        "to",
        "on",
        "in",
        "into",
        "at",
        "from",
        "of",
    }
    | {"for", "and", "with", "off", "by", "some", "this", "that"}
)
#: a name called at the start of an aside, written with its capital ("Tobi, stop jumping on the sofa")
_CALLED = re.compile(r"^[A-Z][a-z]+,")
#: words that open a stretch cutting into a sentence to wait or to answer someone
_WAITING = frozenset({"wait", "hold", "hang", "hello", "hi", "yes", "coming"})
#: titles said before a name
_TITLES = frozenset(
    {"mr", "mrs", "miss", "ms", "dr", "aunty", "auntie", "aunt", "uncle", "mama", "papa", "mummy", "daddy"}
    | {"madam", "madame", "oga", "pastor", "reverend", "rev", "father", "sister", "brother", "grandma"}
    | {"grandpa", "granny", "baba", "iya", "alhaji", "alhaja", "chief", "prof", "professor", "doctor"}
    | {"cousin", "nanny", "sir", "ma", "mummy's", "lady", "mister", "brother's", "sister's"}
)
#: questions said to someone else after their name ("Ese, have you seen it?")
_ASKED = frozenset({("have", "you"), ("did", "you"), ("do", "you"), ("are", "you"), ("were", "you")})
_STATES = frozenset({"on", "off", "open", "closed", "shut", "up", "down"})


def dashed_asides_dropped(text: str) -> str:
    """``text`` without the interruptions set off by dashes (see the module docstring)."""

    def aside(match: re.Match[str]) -> str:
        said = match.group(1)
        before = text[: match.start()].split()[-1:]
        broken = before and before[0].lower() in _BROKEN_AFTER  # "bring me the — ..."
        # "— Tobi, wear your shoes! —", "— hello? yes, I'm here —", "— Tobi, stop that —"
        called = "!" in said or "?" in said or _CALLED.match(said) is not None
        if _DESCRIBES.match(said) or "." in said or not (broken or called):
            return match.group(0)
        return " "

    return _DASHED.sub(aside, text)


def spoken_to(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """The sentences without titles before names, questions to other people and with "why is X off" read
    as a complaint (see the module docstring)."""
    people = [phrase.split() for phrase in phrases_of(vocabulary, "person")]
    firsts = {words[0] for words in people} | {words[0] + "'s" for words in people}
    out = segments
    kept: list[list[str]] = []
    skip = False
    for i, segment in enumerate(out):
        if skip:
            skip = False
            continue
        if _cut_in(out, i, kept, firsts):  # "put the mug on the, Jack stop it, on the dining table"
            continue
        nxt = out[i + 1] if i + 1 < len(out) else []
        named = len(segment) == 1 and segment[0] in firsts
        if named and tuple(nxt[:2]) in _ASKED and i + 2 < len(out):
            # "Ese, have you seen it?": said to Ese; "Jack, have you seen the remote? ..., find it": the
            # question names what "it" is, and stays
            skip = not {"the", "my", "a", "an", "your", "his", "her"} & set(nxt[2:])
            continue
        kept.append(_why_said(segment) if i + 1 < len(out) else _told(segment, firsts))
    return _there_said(kept or out, vocabulary)


def _told(words: list[str], firsts: set[str]) -> list[str]:
    """ "Jack said the hallway light should be off": what Jack said is asked of the robot, passed on; the
    words after "said" are the request (only where they open with "the": "her laptop" needs who said it)."""
    rest = words[3:] if words[2:3] == ["that"] else words[2:]
    if words[:1] and words[0] in firsts and words[1:2] in (["said"], ["says"]) and rest[:1] == ["the"]:
        return rest
    return words


def _cut_in(segments: list[list[str]], i: int, kept: list[list[str]], firsts: set[str]) -> bool:
    """Whether the stretch at ``i`` cuts into a sentence broken off after an article or a preposition, to call
    someone or to wait ("put the mug on the, Jack stop it, on the dining table", "switch on the, wait, Tobi
    come here, switch on the chandelier"), the sentence going on after it."""
    if not kept or not kept[-1] or kept[-1][-1] not in _BROKEN_AFTER or i + 1 >= len(segments):
        return False
    said = segments[i]
    return bool(said) and ((said[0] in firsts and not said[0].endswith("'s")) or said[0] in _WAITING)


def _there_said(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """ "what is inside the deep freezer? check if the chicken is there", "the deep freezer, is the chicken
    there?": "there" is the place the sentence before asked about or named alone, said in full ("... is in
    the deep freezer"); the sentence before only pointed at it."""
    places = phrases_of(vocabulary, "furniture", "room")
    for i, segment in enumerate(segments[:-1]):
        later = segments[i + 1]
        if "there" not in later or "in" in later[later.index("there") - 1 : later.index("there")]:
            continue
        asked = segment[:3] in (["what", "is", "in"], ["what", "is", "inside"], ["what", "is", "on"])
        place = segment[3:] if asked else segment
        said = place[1:] if place[:1] in (["the"], ["my"]) else place
        if said and " ".join(said) in places and (asked or len(segments) == 2):
            at = later.index("there")
            told = ["on" if segment[2:3] == ["on"] and asked else "in", *place]
            return [*segments[:i], [*later[:at], *told, *later[at + 1 :]], *segments[i + 2 :]]
    return segments


def titles_dropped(text: str, vocabulary: Vocabulary) -> str:
    """``text`` without a title said before a person's name ("Mama Adunni's room": "Adunni's room")."""
    said = _titled(vocabulary)
    return said.sub("", text) if said is not None else text


@lru_cache(maxsize=16)
def _titled(vocabulary: Vocabulary) -> re.Pattern[str] | None:
    """A title before one of the world's people's first names (None: the world has no people); built once
    per vocabulary."""
    people = {phrase.split()[0] for phrase in phrases_of(vocabulary, "person")}
    if not people:
        return None
    names = "|".join(re.escape(p) for p in sorted(people, key=len, reverse=True))
    titles = "|".join(re.escape(t) for t in sorted(_TITLES, key=len, reverse=True))
    said = rf"\b(?:(?:my|our)\s+(?=(?:{titles})\s+(?:{names})\b(?!')))?(?:{titles})\.?\s+(?=(?:{names})\b)"
    return re.compile(said, re.IGNORECASE)


def _why_said(words: list[str]) -> list[str]:
    """ "why is the x still off" -> "the x is still off": a complaint before a request."""
    if words[:2] not in (["why", "is"], ["why", "are"]) or words[-1:] == [] or words[-1] not in _STATES:
        return words
    return (
        [*words[2:-1], words[1], words[-1]] if words[-2] != "still" else [*words[2:-2], words[1], *words[-2:]]
    )
