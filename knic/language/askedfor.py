"""Requests said the long way round, put as the plain request (used by
:func:`knic.language.household.where_last` on a command's text, before it is cut into sentences):

* being shown a place is being taken there: "can you show me where the dining room is", "show me the way to
  the quiet room" are "take me to the dining room", "... to the quiet room";
* the speaker asking to be taken in the passive ("I should like to be taken to the garden room", "I'd like to
  be taken to my room", "could I be taken to the lounge"): "take me to ...";
* "where do you keep the sugar?" (as said by someone new to a house) asks where the sugar is, not to keep it
  anywhere;
* a place asked after and then gone to ("where's the assisted bathroom? can you take me there"): "take me to
  the assisted bathroom";
* who asked for the request, said after it ("bring the pill pot to Lionel, Fenella said to", "..., as mum
  said", "..., nan told me to"): left out, as the request is the same;
* whether someone is "still here" or "here" ("is Clementine still here?", "is jack here?"), one word for whom:
  where they are, as "is jack around" asks;
* a thing moved "off" one place "and onto" or ", to" another, often without a verb ("care folder off the
  filing cabinet and onto the desk", "pill pot off the trolley, to Wilfred"): "from" the one "to" the other,
  as "pill pot from the trolley to Wilfred" is read;
* what someone is due, said after a request ("thermometer to the lounge, Hortense is due her obs", "..., he's
  due a bath"), and what two people want to do ("put the jigsaw on the table, Gran and Mabel want to do it
  after lunch"): a reason, left out;
* someone said by who they are and then by name ("where's that nurse, Fenella?", "the lady, Mabel"): by
  name;
* a thing that "may remain where it is" (or "can stay there", "is to be left as it is"), said after a
  request ("I require the bible from the quiet room; the chess set may remain where it is"): asks nothing,
  left out.

And :func:`returned_read`, on the command's text with the world's names (from
:func:`knic.language.understanding.understand`): a thing "returned to" a piece of furniture ("be so good as to
return the poetry book to the bookshelf", "return the walking stick to the armchair") is put back on it, as
a thing returned to a person is given and one returned to a room brought there.
"""

from __future__ import annotations

import re
from functools import lru_cache

from knic.language.vocabulary import Vocabulary

#: "show me where the dining room is", "show me the way to the lounge"
_SHOWN = re.compile(
    r"\bshow me (?:where (?P<place>(?:the|my|your|our) [a-z' ]+?) (?:is|are)\b|the way (?:to|into) )",
    re.IGNORECASE,
)
#: "I should like to be taken to", "I'd like to be taken to", "could I be taken to"
_TAKEN = re.compile(
    r"\b(?:i(?:'d| should| would| want to| need to| wish to)? (?:like |love )?to be|(?:can|could|may) i be)"
    r" (?:taken|brought|walked|shown) (?:to|into|back to)\b",
    re.IGNORECASE,
)
#: "where do you keep the sugar", "where do we keep the towels"
_KEPT = re.compile(
    r"\bwhere do (?:you|we|they|people|the staff) (?:usually |normally )?keep\b", re.IGNORECASE
)
#: "where's the assisted bathroom? can you take me there"
_THERE = re.compile(
    r"\bwhere(?:'s| is) (?P<place>(?:the|my) [a-z' ]+?)\s*\?\s*(?:(?:can|could|would|will) you )?"
    r"(?:please )?(?P<verb>take|bring|walk) me there\b",
    re.IGNORECASE,
)
#: "..., Fenella said to", "..., as mum said", "..., nan told me to": who asked for it, said last
_ASKED_BY = re.compile(
    r",\s*(?:as |like )?[a-z]+ (?:said(?: to| so)?|says(?: to| so)?|told me(?: to)?|asked me(?: to)?|asked"
    r"(?: for it)?)\s*[.!]?\s*$",
    re.IGNORECASE,
)
#: "is Clementine still here", "is jack here": one word for whom, then a question's end
_STILL_HERE = re.compile(r"\bis (?P<who>[a-z]+) (?:still )?here\b(?=\s*(?:[?.!,;]|$))", re.IGNORECASE)
#: words that are not someone asked after ("is it here", "is everyone here")
_NOT_WHOM = frozenset(
    {"it", "this", "that", "there", "everyone", "everybody", "anyone", "anybody", "he", "she"}
)


#: "off the trolley, to Wilfred", "off the filing cabinet and onto the desk"
_OFF_ONTO = re.compile(
    r"\boff (?P<source>(?:the|my|his|her|their|your) [a-z' ]+?)(?:,\s*|\s+and\s+)(?:on)?to"
    r" (?P<goal>(?:the|my|his|her|their|your|me|him)\b|[A-Z])"
)
#: ", Hortense is due her obs", ", he's due a bath": said last
_DUE = re.compile(
    r",\s*(?:[a-z]+ is|he's|she's|they're|they are|he is|she is) (?:now |also )?(?:over)?due\b"
    r"[^,.;?!]*[.!]?\s*$",
    re.IGNORECASE,
)

#: ", Gran and Mabel want to do it after lunch": two people's purpose, said last
_THEY_WANT = re.compile(
    r",\s*[a-z]+ and [a-z]+ (?:want|need|would like|'d like|are going) to\b[^.;?!]*[.!]?\s*$", re.IGNORECASE
)
#: "that nurse, Fenella": who someone is, said before their name (a capital: the name as written)
_ROLE_THEN_NAME = re.compile(
    r"\b(?:[Tt]hat|[Tt]he|[Tt]his|[Oo]ur|[Mm]y) (?:nurse|carer|doctor|lady|man|woman|gentleman|girl|boy|lad"
    r"|chap|fellow|cleaner|visitor|resident|neighbour|neighbor),\s+(?=[A-Z])"
)

#: "; the chess set may remain where it is", ", the rest can stay there": said last
_LEFT_BE = re.compile(
    r"[;,.]\s*(?:the|my|his|her|their|your|that|this) [a-z' ]+? (?:may|can|should|will|is to|are to) "
    r"(?:remain|stay|be left|rest)(?: where it is| where they are| there| as it is| as they are)\s*[.!]?\s*$",
    re.IGNORECASE,
)


def asked_for_read(text: str) -> str:
    """``text`` with the requests of the module docstring said plainly; else ``text``."""
    text = _THERE.sub(lambda m: f"{m.group('verb')} me to {m.group('place')}", text)
    text = _SHOWN.sub(lambda m: f"take me to {m.group('place')}" if m.group("place") else "take me to ", text)
    text = _TAKEN.sub("take me to", text)
    text = _KEPT.sub("where is", text)
    text = _THEY_WANT.sub("", _DUE.sub("", _ASKED_BY.sub("", _ROLE_THEN_NAME.sub("", text))))
    text = _LEFT_BE.sub("", text)
    text = _OFF_ONTO.sub(lambda m: f"from {m.group('source')} to {m.group('goal')}", text)
    who = _STILL_HERE.search(text)
    if who is None or who.group("who").lower() in _NOT_WHOM:
        return text
    return f"{text[: who.start()]}is {who.group('who')} around{text[who.end() :]}"


#: "return the poetry book to the bookshelf": the thing, then where to
_RETURNED = re.compile(
    r"\breturn (?P<thing>(?:the|my|his|her|their|your|this|that) [a-z' ]+?) (?:back )?to "
    r"(?P<det>the|my|his|her|their|your) (?P<place>[a-z' ]+?)"
    r"(?=\s*(?:[,.;!?]|$)| (?:in|on|by|and|then|please)\b)",
    re.IGNORECASE,
)


def returned_read(text: str, vocabulary: Vocabulary) -> str:
    """ "return X to the <furniture>" -> "put X back on the <furniture>"; else ``text``."""
    if "return" not in text.lower():
        return text
    furniture = _furniture_said(vocabulary)

    def put(match: re.Match[str]) -> str:
        if match.group("place").lower() not in furniture:
            return match.group(0)
        return f"put {match.group('thing')} back on {match.group('det')} {match.group('place')}"

    return _RETURNED.sub(put, text)


@lru_cache(maxsize=16)
def _furniture_said(vocabulary: Vocabulary) -> frozenset[str]:
    """What the world's furniture is called (whole names and their synonyms), once per vocabulary."""
    return frozenset(t.phrase for t in vocabulary.terms if vocabulary.is_subtype(t.type, "furniture"))
