"""Turns of phrase of ordinary native speakers that say less, or other, than their words (people32, a family
house where British, Irish, American and Australian speakers of fifteen to eighty-three asked for things):

* "go on" said alone before a request, as encouragement ("ah go on, put the heating on there", "go on then,
  bring me a biscuit"): no going; the request is what is asked (a thing the house lacks in it is named, not
  "go where?"). "Go on to the kitchen", "go on and fetch it" keep their words;
* a wish to go somewhere and then "take me" with no place ("I'd like to go to the kitchen, would you take
  me", "I need to go to the bathroom, can you take me there?"; people33: "I wish to go up to the roof
  terrace; kindly accompany me", "escort me", "walk me"): the speaker is taken there, one action, not the
  robot going there alone;
* "off the floor", "from the floor", "off the ground": where a thing lies that is no place of the world
  ("pick up the cushion off the floor and put it on the armchair"): the taking has no source, where the
  reader would refuse the floor;
* "left-hand", "right hand" before a noun are "left", "right" ("the right-hand shelf", "the left hand lamp",
  "on the left-hand side of the bed"), where "hand" was an unknown word and "right-hand light" was read as
  any light;
* a correction to "the other one" said in a stretch of its own ("bring me the blue cup. no wait, the other
  one") is read with the request it corrects, so that of several others the robot asks which, where the
  stretch naming nothing was dropped as talk and the first thing done;
* a part of a piece of furniture said with "of" ("the top shelf of the fridge", "the bottom drawer of the
  chest of drawers"): the furniture, where "shelf" alone asked which of the home's shelves was meant;
* "the one on the left", "the right one" said without a name, or after the name alone ("put the magazine on
  the shelf, the one on the left", "turn on the left one"): the thing the world names by that side and the
  name said before, or the one thing it names by that side (:func:`side_ones`, for
  :func:`knic.language.household.ones_named`);
* "do we have any X?", "have we got any X?" (said of the household) ask as "is there any X?" does: a search
  for X, where "we have" was read as talk.

Each but the sides works on the text as said, before it is split into stretches (:func:`ordinary_read`).
"""

from __future__ import annotations

import re

#: "go on" said alone before a request, after an interjection or none ("ah go on, ...", "go on then, ...")
_ENCOURAGED = re.compile(
    r"^\s*(?:(?:ah|aw|oh|och|oi|well|sure|right)\s*,?\s+)*go\s+on(?:\s+(?:then|now|so|there))?\s*[,.!;:]+\s*(?=\S)",
    re.IGNORECASE,
)

#: a wish of the speaker's to go somewhere ("i'd like to go to the kitchen"), then "take me" with no place
_TAKE_ME_ALONG = re.compile(
    r"^\s*(?P<before>(?:\w+\s*,?\s+)??)"
    r"i(?:'d|\s+would)?\s+(?:like|want|need|wanna|have|wish)(?:\s+to)?\s+(?:go|get)\s+"
    r"(?P<way>(?:(?:up|down|over|back|through|across)\s+)?(?:to|into|in\s+to)\s+[^.,;!?]+?)\s*[.,;!?]+\s*"
    r"(?:(?:so|and|then)\s+)?(?:(?:would|could|can|will)\s+you\s+)?(?:(?:please|kindly)\s+)?"
    r"(?:take|accompany|escort|walk)\s+me"
    r"(?:[\s,]+there)?(?:[\s,]+please)?\s*[.?!]*\s*$",
    re.IGNORECASE,
)

#: "left-hand", "right hand" said before a noun: the side alone ("the right-hand shelf")
_HANDED = re.compile(r"\b(left|right)(?:-|\s+)?hand(?:ed)?(?=\s+[a-z])", re.IGNORECASE)

#: whether the household has a thing, asked ("do we have any milk?", "have we still got some batteries?")
_HAVE_WE = re.compile(
    r"(^|[.,;!?]\s*)(?:do\s+we\s+(?:still\s+)?have|have\s+we\s+(?:still\s+)?got)\s+(any|some|a|an)\b",
    re.IGNORECASE,
)

#: the stops before a correction to "the other one" ("..., no wait, the other one"), and within it
_OTHER_ONE = re.compile(
    r"[.,;!?]+\s*(?P<words>(?:(?:no|nope|sorry|wait|actually|oh|hang on|i mean|i meant)\b[\s,.!;]*)+)"
    r"(?=the\s+other\s+ones?\b)",
    re.IGNORECASE,
)

#: a part of a piece of furniture said before it with "of" ("the top shelf of the fridge")
_PART_OF = re.compile(
    r"\bthe\s+(?:(?:top|bottom|middle|lower|upper|front|back|first|second|third)\s+)+"
    r"(?:shelf|drawer|rack|compartment|section)\s+of\s+(?=the\s)",
    re.IGNORECASE,
)

#: where a thing lies that is no place of any world: the floor, the ground; not the first word of a thing's
#: name ("switch off the floor lamp", "take the rug from the ground floor"), so said last in its clause, or
#: before a word that carries the sentence on (a joiner, a preposition, a filler)
_OFF_THE_FLOOR = re.compile(
    r"\s+(?:off\s+of|off|from)\s+the\s+(?:floor|ground)\b"
    r"(?=\s*(?:$|[,.;:!?&]|(?:and|then|to|into|onto|on|in|by|near|next|under|over|for|please|now|too|first|so|"
    r"as|before|after|again|back|behind|beside|with|there|here|while|because|if|or|but|yeah|ok|okay|thanks|"
    r"thank)\b))",
    re.IGNORECASE,
)


def ordinary_read(text: str) -> str:
    """``text`` with the turns of phrase of this module put plainly: "go on, " before a request dropped, a
    wish to go and "take me" said as "take me to ...", "off the floor" dropped, "right-hand" said "right",
    "do we have any" said "is there any", "the top shelf of the fridge" said "the fridge"."""
    if (encouraged := _ENCOURAGED.match(text)) is not None:
        text = text[encouraged.end() :]
    if (wish := _TAKE_ME_ALONG.match(text)) is not None:
        text = f"{wish.group('before')}take me {wish.group('way')}"
    text = _OTHER_ONE.sub(lambda said: " " + re.sub(r"[\s,.!;]+", " ", said.group("words")), text)
    text = _PART_OF.sub("", text)
    text = _HAVE_WE.sub(lambda said: f"{said.group(1)}is there {said.group(2)}", text)
    return _HANDED.sub(lambda said: said.group(1), _OFF_THE_FLOOR.sub("", text))


def side_ones(words: list[str], said: list[str], names: dict[str, str]) -> list[str]:
    """``words`` with "one on the left" or "left one" put as "left X": X the last word said before (in
    ``said`` or ``words``) that ``names`` (two-word names of the world, to their things) has after the side,
    else the one thing named with that side ("turn on the left one": the left light); else as said."""
    for i, side in enumerate(words):
        if side not in ("left", "right"):
            continue
        if i >= 3 and words[i - 3 : i] in (["one", "on", "the"], ["one", "to", "the"]):
            start, end = i - 3, i + 1
        elif words[i + 1 : i + 2] == ["one"]:
            start, end = i, i + 2
        else:
            continue
        heads = [w for w in said + words[:start] if f"{side} {w}" in names]
        named = {thing for phrase, thing in names.items() if phrase.split()[0] == side}
        if not heads and len(named) == 1:
            heads = [next(p for p, t in names.items() if p.split()[0] == side).split()[1]]
        if heads:
            return [*words[:start], side, heads[-1], *words[end:]]
    return words


__all__ = ["ordinary_read", "side_ones"]
