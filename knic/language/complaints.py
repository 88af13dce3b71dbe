"""A complaint about the light, read as the request it makes.

"It's far too dark in the study" (or "on the landing"; "pitch black", "gloomy"; "I can't see a thing in the
study", "the study is too dark", a learner's "in the study is too dark") asks for the study's lights: the
whole command is read as "turn on the lights in the study" (the room's light, its group of lights, or a
question which). A complaint
about "here" or "there" is left as said (where that is is not known), and so is one said beside a request
("it's dark in the bedroom, turn on the left lamp": the request says what to do, the complaint is talk),
unless the request names no light of its own ("it's dark in the study, turn on the light", "the casita's dark,
could you turn on the light in here?"): the study's; a sigh said first ("uff da, ...") is left out.

A complaint that one cannot see, said beside a device said to be off ("i can't see a thing in here, the
reading lamp is off"), asks for that device on; one that it is too bright beside a device said to be on or
open ("it's far too bright, the blinds are open") asks for it off or closed.
"""

from __future__ import annotations

import re

from knic.language.vocabulary import normalize

_OPENING = r"(?:(?:oh|well|gosh|hmm|ugh|robot)\s+)*"
_DEGREE = (
    r"(?:(?:so|too|far|way|very|really|rather|quite|pretty|a bit|a little|awfully|terribly|getting|ever so"
    r"|pitch|a tad|dreadfully|horribly)\s+)*"
)
_PLACE = (
    r"(?P<place>(?!(?:here|there|it|this|that|everything)\b)(?:(?:the|my|our|your)\s+)?[a-z']+"
    r"(?:\s+[a-z']+){0,2}?)"
)
_DARK = re.compile(
    rf"^{_OPENING}(?:(?:it's|its|it is)\s+{_DEGREE}(?:dark|black|gloomy|dim)"
    r"|i (?:can't|cannot|can not) see(?: a thing| anything)?)"
    rf"\s+(?:in|inside|on|out on|up on|down in)\s+{_PLACE}"
    r"(?:\s+(?:please|now|tonight|today))?$"
)
#: "the living room is too dark": the room said first
_DARK_ROOM = re.compile(
    rf"^{_OPENING}{_PLACE}(?:\s+is|'s)\s+{_DEGREE}(?:dark|gloomy|pitch black)"
    r"(?:\s+(?:please|now|tonight|today))?$"
)
#: "in my room is too dark" (a learner's order: the place first)
_DARK_IN = re.compile(
    rf"^{_OPENING}(?:in|on)\s+{_PLACE}\s+(?:is|it's|it is)\s+{_DEGREE}(?:dark|black|gloomy|dim)"
    r"(?:\s+(?:please|now|tonight|today))?$"
)
#: a request for the light that says no room ("turn on light", "the lights on please")
_LIGHT_ON = re.compile(
    r"^(?:please\s+)?(?:(?:could|can|would|will)\s+(?:you|ya)\s+)?(?:please\s+)?"
    r"(?:(?:turn|switch|put)\s+on\s+(?:the\s+)?(?:light|lights|lamp)"
    r"|(?:turn|switch|put)\s+(?:the\s+)?(?:light|lights|lamp)\s+on|(?:the\s+)?(?:light|lights)\s+on)"
    r"(?:\s+(?:in\s+)?here)?(?:\s+please)?$"  # "... in here": where the complaint said it is dark
)
#: a stop or comma inside the text: more was said than the complaint
_INNER_BREAK = re.compile(r"[,;:.!?]\s*\S")
#: the sentences of a command
_SENTENCES = re.compile(r"[,;:.!?]+")
#: complaints that one cannot see / that it is too bright, and what they ask of a device said so
_CANNOT_SEE = re.compile(rf"^{_OPENING}(?:i can't see|i cannot see|i can not see|it's {_DEGREE}dark\b)")
_TOO_BRIGHT = re.compile(rf"^{_OPENING}(?:it's|its|it is)\s+{_DEGREE}(?:bright|glary|sunny)\b")
_SAID_TO_BE = re.compile(
    r"^(?P<device>(?:the|my|our)\s+[a-z' ]+?)\s+(?:is|are|'s)\s+(?:still\s+)?"
    r"(?P<state>off|on|open|closed|shut)$"
)
_ASKED = {
    "dark": {"off": "turn on", "closed": "open", "shut": "open"},
    "bright": {"on": "turn off", "open": "close"},
}


def dark_read(text: str) -> str:
    """``text`` read as the request a complaint of a dark room makes ("it's dark in the lounge": "turn on the
    lights in the lounge"), or of darkness or glare beside a device said to be in a state, else ``text``
    unchanged."""
    if _INNER_BREAK.search(text):
        return _said_beside(text)
    match = _dark_in(normalize(text))
    return f"turn on the lights in {match.group('place')}" if match else text


def _dark_in(text: str) -> re.Match[str] | None:
    """The complaint of a dark place said in ``text`` (normalised), else None."""
    return _DARK.match(text) or _DARK_ROOM.match(text) or _DARK_IN.match(text)


def _said_beside(text: str) -> str:
    """A complaint and a device said to be off (or on): the device's other state asked for; else ``text``."""
    sentences = [normalize(s) for s in _SENTENCES.split(text) if normalize(s)]
    while len(sentences) > 2 and len(sentences[0].split()) <= 2:  # "uff da, the den's dark, ...": a sigh
        sentences = sentences[1:]
    if len(sentences) != 2:
        return text
    complaint, said = sentences
    dark = _dark_in(complaint)
    if dark and _LIGHT_ON.match(said):  # "in my room is too dark, turn on light": the lights there
        return f"turn on the lights in {dark.group('place')}"
    kind = "dark" if _CANNOT_SEE.match(complaint) else "bright" if _TOO_BRIGHT.match(complaint) else None
    match = _SAID_TO_BE.match(said) if kind else None
    verb = _ASKED[kind].get(match.group("state")) if kind and match else None
    return f"{verb} {match.group('device')}" if verb and match else text
