"""Requests said the long way round, read as the plain English the reader knows, for :func:`knic.language.
understanding.understand` (people36's voices first, each rule as general as the English it reads):

* Irish English says where a place lies from the speaker before saying the place ("the light below in the
  boot room", "bring it beyond to Tadhg", "the keys within in the hall", "the sheets above in the loft"):
  the adverb is the way there, not a place, and "from beyond in the snug" is from the snug;
* a word held for a thing while the speaker finds its name ("where's the yoke, the head torch?", "the
  thingy, the remote"): the name said after it;
* "let it be at seventy", "let the lamp be on forty", "make the light to be at forty" (as a carer from
  Zimbabwe or an Indian speaker may say it): set it to that level;
* what another person wants or is trying to do, said after a request with a verb the robot does not know
  ("..., Sekuru Tadhg wants to sleep", "..., she's trying to read"): the reason, asked of nobody;
* a negative question as a request (Irish and older speakers: "you didn't see my watch anywhere?", "you
  wouldn't have seen the keys?"): "have you seen ...";
* "did anyone see my stick?", "has anybody seen the keys?", "has nobody seen my glasses?": "have you seen";
  "I'm after leaving the tablet in the bedroom" (Irish English, just now): "I left ..."; "I don't know
  where I left my glasses": "where is my glasses"; "you wouldn't have my slippers there?", "would you have
  the paper handy?", "would yous have a wee bit of brown bread going" (Irish English: can you give me):
  "bring me";
* "give us a hand and bring ...": the bringing;
* asking again ("amn't I after asking you for the beads", "I've asked you for the post twice now"): "bring
  me ...";
* "like a good man", "like a good lad", "like a good girl" (coaxing, as "there's a good lad" is): dropped;
* what is in a thing, said with it ("the blue mug with the tea in it"): no thing of its own;
* ordering as in a café ("can I get the lamp on", "can I get the lights off in the bathroom", "could I get the
  yard light on for Ciaran", "could I get the blind half open", "could I get the holdall put on the bed",
  "can I get you to go to ..."): the device switched, the thing put, and "could you";
* "bring the turf basket over beside the stove", "move the chair over next to the bed": where to, as "over
  to" is; "away up to the loft landing and ..." (Scottish and Ulster English "away" for go): "go to";
* "throw the ball over to Sadhbh", "chuck the keys over to me": to her, to me;
* "... and the landing light off" after a request that is no switching ("put the hairdryer back on the
  vanity table and the loft bedroom light off"): "and turn the landing light off";
* what a place is gone to or a thing taken there for, said last with a word the robot does not know ("take
  me over to the kitchen for the tea", "bring the frisbee out to the garden for the kids"): why, not what;
* a place said first, then asked about with "it" or "there" ("the locker beside the double bed, is my hand
  cream on it?", "the locker in our bedroom, are the keys in there?"): asked of that place;
* "before you go", "before you leave", said last: when, not where to ("feed the dog there before you go" is
  no motion without a place);
* "go out and wait by the trough", "run up and turn on the light": the second verb says what to do and
  where; the first is only the way there;
* "the bedroom of Tadhg", "the bed of Sekuru Tadhg" (of with a person, as many learners of English say it,
  with a title before the name the world does not know): "Tadhg's bedroom"; "wee Sadhbh", "little Sadhbh",
  "old Tadhg": the person.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from knic.language.vocabulary import Vocabulary

#: Irish English adverbs of where a place lies from the speaker, said before the preposition of the place
_LIE_OF_LAND = re.compile(
    r"(?:\s+(?:beyond|below|above|within))+(?=\s+(?:in|on|at|to|into|onto|inside)\b)", re.I
)
#: "from in the snug" (after the adverb is dropped): from the snug
_FROM_IN = re.compile(r"\bfrom\s+(?:in|inside)\s+(?=(?:the|my|our|your|his|her)\b)", re.I)
_PLACEHOLDER = re.compile(
    r"\b(?:the|that|this|me|my)\s+(?:yoke|thingy|thing|whatsit|what's-it|thingamajig|thingamabob|doodah|"
    r"doohickey|gizmo)\s*[,:;-]+\s*(?=(?:the|my|your|his|her|our|their|that|this)\s)",
    re.I,
)
_LET_BE = re.compile(
    r"\b(?:let|make)\s+(it|them|(?:the|my|that|this)\s+[\w\s]+?)\s+(?:to\s+)?be\s+(?:at|on)\s+(?=\w)", re.I
)
_WANTS_TO = re.compile(
    r"[,.;!]\s*(?:[\w']+\s+){0,2}?(?:wants|needs|would like|is wanting|is trying|'s trying|is going|'s going)"
    r"\s+to\s+(?P<word>[a-z]+)\b[^,.;!?]*",
    re.I,
)
_NOT_SEEN = re.compile(
    r"(^|[.?!,]\s*)(?:(?:you|ye)\s+(?:didn't|did not|never|wouldn't have|would not have|haven't|have not|"
    r"wouldn't|would not)|(?:did|has|have)\s+(?:anyone|anybody|someone|somebody)|would\s+(?:you|ye)\s+have|"
    r"(?:(?:did|has|have)\s+)?(?:nobody|no one|no-one))\s+(?:see|seen|saw)\b",
    re.I,
)
_AFTER_LEAVING = re.compile(r"\b(?:i'm|i am)\s+(?:only\s+|just\s+)?after\s+leaving\b", re.I)
_LEFT_WHERE = re.compile(
    r"\bi\s+(?:don't|do not|can't|cannot|can not)\s+(?:know|remember|think)\s+where\s+i\s+"
    r"(?:left|put|had)\s+",
    re.I,
)
_WOULD_HAVE = re.compile(
    r"(^|[.?!,]\s*)(?:(?:would|could)\s+(?:you|yous|ye)|(?:you|yous|ye)\s+(?:wouldn't|would not|couldn't))\s+"
    r"have\s+(?!seen\b|been\b|got\b|to\b|a\s+look\b|a\s+minute\b|time\b)([^,.;!?]+?)"
    r"(?:\s+(?:going|handy|to hand|there|on you))?(?=\s*(?:$|[,.;!?]))",
    re.I,
)
#: what a thing is made, said after it ("could you have the cup brought ...", "have the light on")
_MADE = frozenset(
    {"brought", "put", "taken", "shut", "open", "on", "off", "done", "sent", "set", "left", "up", "down"}
)
_PLACE_WORDS = frozenset({"to", "in", "into", "on", "onto", "from", "at"})
_A_HAND = re.compile(r"\bgive\s+(?:us|me)\s+a\s+hand(?:\s+here)?\s+and\s+", re.I)
_ASKED_AGAIN = re.compile(
    r"\b(?:amn't i|aren't i|am i not|i'm|i am|i've|i have|i was|i)\s+(?:after\s+|been\s+|already\s+)*"
    r"ask(?:ing|ed)\s+you\s+for\b(?P<rest>[^,.;!?]*?)(?:\s+(?:twice|three times|again|already|before|"
    r"all day|all morning|ages ago)(?:\s+now)?)*(?=\s*(?:$|[,.;!?]))",
    re.I,
)
_WITH_IN_IT = re.compile(
    r"\s+with\s+(?:the|a|some|my|his|her|their|its|your)\s+[\w\s]+?\s+(?:in|on)\s+(?:it|them)\b", re.I
)
_GOOD_ONE = re.compile(
    r",?\s+like\s+a\s+good\s+(?:man|lad|girl|woman|fella|fellow|boy|lass|chap|one)\b", re.I
)
_GET_YOU_TO = re.compile(r"\b(?:can|could|may)\s+i\s+(?:get|have)\s+you\s+to\b", re.I)
_DETERMINED = r"(?:the|my|our|your|his|her|their|that|this)\s+[^,.;!?]+?"
_GET_SWITCHED = re.compile(
    rf"\b(?:can|could|may)\s+i\s+(?:get|have)\s+({_DETERMINED})\s+"
    r"(on|off|open|closed|shut|half open)\b"
    r"(?=\s*(?:$|[,.;!?]|and\b|please\b|thanks\b|thank you\b|then\b|in\b|on\b|for\b|a\b|to\b|at\b))",
    re.I,
)
#: a device's state said after it in an order, as the request to make it so
_MADE_SO = {
    "on": "turn {} on",
    "off": "turn {} off",
    "open": "open {}",
    "closed": "close {}",
    "shut": "close {}",
}
_MADE_SO["half open"] = "open {} halfway"
_PARTICIPLES = {"put": "put", "placed": "put", "left": "leave", "moved": "move"}
_GET_PUT = re.compile(
    rf"\b(?:can|could|may)\s+i\s+(?:get|have)\s+({_DETERMINED})\s+({'|'.join(_PARTICIPLES)})\s+(?=(?:back\s+)?"
    r"(?:on|in|onto|into|on top of|inside)\b)",
    re.I,
)
_GO_AND = re.compile(
    r"\b(?:go|come|run|nip|pop|head)\s+(?:out|over|up|down|in|along|round|across)\s+and\s+(?=wait\b|"
    r"stay\b|turn\b|switch\b|get\b|grab\b|fetch\b|bring\b|take\b|put\b|open\b|close\b)",
    re.I,
)

_OVER_BESIDE = re.compile(r"\bover\s+(?:beside|next\s+to|alongside)\b", re.I)
_AWAY_TO = re.compile(
    r"(^|[.!?,;]\s*|\band\s+)away\s+(?:(?:up|down|over|out|in|back|round)\s+)?(?=to\b)", re.I
)
_FOR_WHAT = re.compile(
    r"(?P<kept>\b(?:to|on|onto|in|into|at)\s+(?:the|my|our|your|his|her)\s+[\w' -]+?)\s+for\s+"
    r"(?:the|a|an|my|our|some|your|his|her|their)\s+(?P<word>[a-z]+)(?=\s*(?:$|[,.;!?]))",
    re.I,
)
_PLACE_FIRST = re.compile(
    r"^(\s*)((?:the|my|our|your|his|her)\s+[^,.;!?]+?)\s*[,:;-]+\s*(is|are)\s+([^,.;!?]+?)\s+"
    r"(on|in|inside|under|at)\s+(?:it|there|them)\s*(?=[?.!]|$)",
    re.I,
)
_BEFORE_YOU_GO = re.compile(
    r",?\s+before\s+(?:you|ye)\s+(?:go|leave|head\s+(?:off|out)|go\s+out)\s*(?=$|[.!?])", re.I
)
_THROWN_OVER = re.compile(
    r"\b(throw|toss|chuck|lob|bung|fling|hoy|pass|hand)\b([^,.;!?]*?)\s+over\s+to\b", re.I
)
_SWITCHES = re.compile(r"\b(?:turn|switch|flick|make|dim|open|close|shut|draw)\b", re.I)


def roundabout_said(text: str, vocabulary: Vocabulary, unknown: Callable[[str], bool]) -> str:
    """``text`` with the ways of speaking of the module docstring said plainly; ``unknown`` tells a word that
    neither the world nor the command language knows (a reason's verb, a title before a name)."""
    text = _FROM_IN.sub("from ", _LIE_OF_LAND.sub("", text))
    text = _PLACEHOLDER.sub("", text)
    text = _LET_BE.sub(r"set \1 to ", text)
    text = _why_dropped(_WANTS_TO, text, unknown)  # "..., Tadhg wants to sleep": why, not what to do
    text = _LEFT_WHERE.sub("where is ", _NOT_SEEN.sub(r"\1have you seen", text))
    text = _AFTER_LEAVING.sub("I left", text)
    text = _A_HAND.sub("", _WOULD_HAVE.sub(_had, text))
    text = _ASKED_AGAIN.sub(lambda m: "bring me" + m.group("rest"), text)
    text = _GOOD_ONE.sub("", _WITH_IN_IT.sub("", text))
    text = _GET_YOU_TO.sub("could you", text)
    text = _GET_PUT.sub(lambda m: f"{_PARTICIPLES[m.group(2).lower()]} {m.group(1)} ", text)
    text = _GET_SWITCHED.sub(lambda m: _MADE_SO[m.group(2).lower()].format(m.group(1)), text)
    text = _BEFORE_YOU_GO.sub("", _GO_AND.sub("", text))
    text = _AWAY_TO.sub(r"\1go ", _OVER_BESIDE.sub("over to", text))
    text = _why_dropped(_FOR_WHAT, text, unknown)  # "... to the kitchen for the tea": why
    text = _PLACE_FIRST.sub(r"\1\3 \4 \5 \2", text)
    text = _THROWN_OVER.sub(r"\1\2 to", text)
    return _switched_after(_of_someone(text, vocabulary, unknown), vocabulary)


def _why_dropped(pattern: re.Pattern[str], text: str, unknown: Callable[[str], bool]) -> str:
    """``text`` without each match of ``pattern`` whose group ``word`` the robot does not know, but for its
    group ``kept`` if it has one."""
    for match in list(pattern.finditer(text))[::-1]:
        if unknown(match.group("word").lower()):
            kept = match.groupdict().get("kept") or ""
            text = text[: match.start()] + kept + text[match.end() :]
    return text


def _switched_after(text: str, vocabulary: Vocabulary) -> str:
    """ "put the hairdryer back on the vanity table and the loft bedroom light off": "... and turn the loft
    bedroom light off", when the request before it switches nothing (see the module docstring)."""
    nouns = {t.phrase.split()[-1] for t in vocabulary.terms if vocabulary.is_subtype(t.type, "device")}
    if not nouns:
        return text
    device = "|".join(re.escape(n) for n in sorted(nouns, key=len, reverse=True))
    said = re.compile(rf"(,?\s+and\s+)(the\s+(?:[a-z]+\s+){{0,3}}?(?:{device}))\s+(on|off)\b", re.I)
    match = said.search(text)
    if match is None or _SWITCHES.search(text[: match.start()]):
        return text
    return (
        f"{text[: match.start()]}{match.group(1)}turn {match.group(2)} {match.group(3)}{text[match.end() :]}"
    )


def _had(match: re.Match[str]) -> str:
    """ "would you have my slippers (there)?": "bring me my slippers"; not "could you have the blinds
    closed" or "would you have the cup brought to the kitchen" (a thing to be made so: the reader reads
    those)."""
    words = match.group(2).lower().split()
    made = words[-1] in _MADE or words[-1].endswith("ed") or any(w in _PLACE_WORDS for w in words)
    return match.group(0) if made else f"{match.group(1)}bring me {match.group(2)}"


def _of_someone(text: str, vocabulary: Vocabulary, unknown: Callable[[str], bool]) -> str:
    """ "the bedroom of (Sekuru) Tadhg": "Tadhg's bedroom" (see the module docstring)."""
    people = [t.phrase for t in vocabulary.terms if vocabulary.is_subtype(t.type, "person")]
    if not people:
        return text
    names = "|".join(re.escape(p) for p in sorted(people, key=len, reverse=True))
    said = re.compile(  # "the curtains of tomasz room" is his room's: the name ends what it owns
        rf"\bthe\s+([a-z]+)\s+of\s+(?:([\w']+)\s+)?({names})(?=\s*$|\s*[,.;!?]|\s+(?:and|then|to|in|on|at|"
        r"from|with|please|for|so|now|too|also|as|thanks)\b)",
        re.I,
    )
    text = re.sub(rf"\b(?:wee|little|young|old|auld)\s+({names})\b", r"\1", text, flags=re.I)

    def owned(match: re.Match[str]) -> str:
        title = match.group(2)
        if title is not None and not unknown(title.lower()):
            return match.group(0)
        return f"{match.group(3)}'s {match.group(1)}"

    return said.sub(owned, text)
