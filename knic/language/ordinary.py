"""Turns of phrase of ordinary native speakers that say less, or other, than their words (people32, a family
house where British, Irish, American and Australian speakers of fifteen to eighty-three asked for things):

* "go on" said alone before a request, as encouragement ("ah go on, put the heating on there", "go on then,
  bring me a biscuit"): no going; the request is what is asked (a thing the house lacks in it is named, not
  "go where?"). "Go on to the kitchen", "go on and fetch it" keep their words;
* a wish to go somewhere and then "take me" with no place ("I'd like to go to the kitchen, would you take
  me", "I need to go to the bathroom, can you take me there?"): the speaker is taken there, one action,
  not the robot going there alone;
* "off the floor", "from the floor", "off the ground": where a thing lies that is no place of the world
  ("pick up the cushion off the floor and put it on the armchair"): the taking has no source, where the
  reader would refuse the floor.

Each works on the text as said, before it is split into stretches (:func:`ordinary_read`).
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
    r"i(?:'d|\s+would)?\s+(?:like|want|need|wanna|have)(?:\s+to)?\s+(?:go|get)\s+"
    r"(?P<way>(?:(?:up|down|over|back|through|across)\s+)?(?:to|into|in\s+to)\s+[^.,;!?]+?)\s*[.,;!?]+\s*"
    r"(?:(?:so|and|then)\s+)?(?:(?:would|could|can|will)\s+you\s+)?(?:please\s+)?take\s+me"
    r"(?:[\s,]+there)?(?:[\s,]+please)?\s*[.?!]*\s*$",
    re.IGNORECASE,
)

#: where a thing lies that is no place of any world: the floor, the ground
_OFF_THE_FLOOR = re.compile(r"\s+(?:off\s+of|off|from)\s+the\s+(?:floor|ground)\b", re.IGNORECASE)


def ordinary_read(text: str) -> str:
    """``text`` with the turns of phrase of this module put plainly: "go on, " before a request dropped, a
    wish to go and "take me" said as "take me to ...", "off the floor" dropped."""
    if (encouraged := _ENCOURAGED.match(text)) is not None:
        text = text[encouraged.end() :]
    if (wish := _TAKE_ME_ALONG.match(text)) is not None:
        text = f"{wish.group('before')}take me {wish.group('way')}"
    return _OFF_THE_FLOOR.sub("", text)


__all__ = ["ordinary_read"]
