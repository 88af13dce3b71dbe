"""What a tired or distracted speaker trails off from and says again (people33's new mother, up since three,
who breaks off, loses the word and starts over):

* a request broken off and then called off in a sentence of its own ("Turn the night light... no, leave
  it. Turn the nursery light off.", "Bring me the muslin. Forget it. Pass me the dummy."): what was called
  off is left out, and the request after it stands, an "it" or "them" in it being what was called off
  ("Open the blinds... no, leave it. Close them."); "leave it" is a calling off only after "no" ("put
  the cup on the table, leave it. ..." and "leave it on the table" stay as said);
* a request broken off and started again with its verb and "it" ("dim the nursery light... dim it to
  twenty"): one request, where the first asked how far;
* a vague "here" said and then the place itself after trailing off or a repair ("turn the big light off in
  here... in the nursery", "dim the lights in here... the nursery light", "in here, I mean in the
  nursery"): the place or the thing said again, where "here" was read as the speaker;
* a word that stands in for a name the speaker cannot find ("the thing... the teething ring", "the
  whatsit, the baby monitor"): the name found, where "thing" was looked for in the world.

Each works on the text as said, before it is split into stretches (:func:`restarts_read`).
"""

from __future__ import annotations

import re

#: a stop or a trailing off: "...", "…", or a full stop, comma, semicolon, exclamation or question mark
_BREAK = r"(?:\.{2,}|…|[.,;!?])"
#: "here" said again: after trailing off, or after a comma and a repair ("in here, I mean in the nursery")
_SAID_AGAIN = r"(?:\.{2,}|…|,)\s*(?:(?:no|sorry|i\s+mean|i\s+meant)[\s,]+)*"

#: a request called off in a sentence of its own, with another said after it
_CALLED_OFF = re.compile(
    rf"^.*?{_BREAK}\s*(?:(?:no|oh|wait|actually|um|erm)[\s,]+)*"
    r"(?:(?<=no\s)leave\s+it|(?<=no,\s)leave\s+it|forget\s+it|never\s*mind|don't\s+bother|do\s+not\s+bother|"
    rf"scratch\s+that|forget\s+that|cancel\s+that)\s*{_BREAK}\s*(?=\S)",
    re.IGNORECASE,
)

#: "here" said vaguely, then where after trailing off ("in here... in the nursery")
_HERE_THEN_PLACE = re.compile(
    rf"\b(?:in|up|out|down|over)?\s*here\s*{_SAID_AGAIN}(?=(?:in|on|at|into|to|by)\s+(?:the|my|our|your)\s)",
    re.IGNORECASE,
)

#: a thing said with "here", then the thing itself ("the lights in here... the nursery light")
_HERE_THEN_THING = re.compile(
    rf"\b(?:the|my|our)\s+(?:[a-z]+\s+){{0,2}}?(?:in|up|out|down|over)\s+here\s*{_SAID_AGAIN}"
    r"(?=(?:the|my|our|your)\s)",
    re.IGNORECASE,
)

#: a word standing in for a name not found, then the name ("the thing... the teething ring")
_PLACEHOLDER = re.compile(
    r"\b(?:the|a|this|that)\s+(?:thing|thingy|thingie|thingamajig|thingummy|thingummyjig|whatsit|what's-it|"
    rf"doodah|doodad|whatchamacallit|gizmo)\s*(?:{_BREAK}|-+)\s*(?=(?:the|my|his|her|your|our|a|an)\s)",
    re.IGNORECASE,
)


#: the thing a request called off named, for an "it" or "them" of the request said after it
_NAMED = re.compile(
    r"\b(?:the|my|your|our|his|her)\s+[a-z' ]+?"
    r"(?=\s*(?:\.{2,}|…|[.,;!?]|\s(?:to|on|in|off|up|down|at|from|into)\b|$))",
    re.IGNORECASE,
)
_IT = re.compile(r"\b(?:it|them)\b", re.IGNORECASE)

#: a request broken off and started again with its verb and "it" ("dim the nursery light... dim it to twenty")
_SAME_VERB_AGAIN = re.compile(
    r"(?P<start>^|(?<=[.!?;])\s*)(?P<verb>[a-z]+)\s+(?P<thing>(?:the|my|your|our|his|her)\s[^.…,;!?]+?)\s*"
    r"(?:\.{2,}|…)\s*(?P=verb)\s+(?:it|them)\b",
    re.IGNORECASE,
)


def restarts_read(text: str) -> str:
    """``text`` with what the speaker trailed off from and said again left out (see the module docstring)."""
    if (called_off := _CALLED_OFF.match(text)) is not None:
        named, text = _NAMED.search(text[: called_off.end()]), text[called_off.end() :]
        if named is not None:  # "open the blinds... no, leave it. Close them.": the blinds
            text = _IT.sub(named.group(0), text, count=1)
    text = _SAME_VERB_AGAIN.sub(lambda m: f"{m.group('start')}{m.group('verb')} {m.group('thing')}", text)
    text = _HERE_THEN_THING.sub("", _HERE_THEN_PLACE.sub("", text))
    return _PLACEHOLDER.sub("", text)


__all__ = ["restarts_read"]
