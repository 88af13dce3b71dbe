"""A complaint that a room is dark, said as the whole command, read as the request it makes.

"It's far too dark in the study" asks for the study's lights: the whole command is read as "turn on the
lights in the study" (the room's light, its group of lights, or a question which). A complaint about "here" or
"there" is left as said (where that is is not known), and so is one said beside a request ("it's dark in the
bedroom, turn on the left lamp": the request says what to do, the complaint is talk).
"""

from __future__ import annotations

import re

from knic.language.vocabulary import normalize

_OPENING = r"(?:(?:oh|well|gosh|hmm|ugh|robot)\s+)*"
_DEGREE = (
    r"(?:(?:so|too|far|way|very|really|rather|quite|pretty|a bit|a little|awfully|terribly|getting)\s+)*"
)
_DARK = re.compile(
    rf"^{_OPENING}(?:it's|its|it is)\s+{_DEGREE}dark\s+(?:in|inside)\s+"
    r"(?P<place>(?!(?:here|there)\b)(?:(?:the|my|our|your)\s+)?[a-z']+(?:\s+[a-z']+){0,2}?)"
    r"(?:\s+(?:please|now|tonight|today))?$"
)
#: a stop or comma inside the text: more was said than the complaint
_INNER_BREAK = re.compile(r"[,;:.!?]\s*\S")


def dark_read(text: str) -> str:
    """``text`` read as the request a complaint of a dark room makes ("it's dark in the lounge": "turn on the
    lights in the lounge"), else ``text`` unchanged."""
    if _INNER_BREAK.search(text):
        return text
    match = _DARK.match(normalize(text))
    return f"turn on the lights in {match.group('place')}" if match else text
