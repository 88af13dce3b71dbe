"""Ways of speaking read as the plain English the reader knows, for :func:`knic.language.understanding.
understand` (people34's voices first, each rule as general as the English it reads):

* "out" before where someone or something is ("is he out in the garage?", "the counter out in the casita"):
  where, not a state, unless a light or a switch is said before it ("turn the light out in the hall");
* a question said without its "is" ("He in the den?", "Wes in the garage?"), "where X at?" ("where my
  cooler at?", said in the American South) and a learner's "where he go?";
* why, said last as a sigh ("..., too bright", "..., so hot"), asks nothing;
* what is said after the request of a thing of someone's the world has no name for ("..., my plant need
  sun") is a remark;
* what another person named does or did, said after the request ("..., Wes forgot it again", "..., Clyde
  goes in bath"), is said of them: no request (what they want or need still is: "..., tracy wants it");
* a person said first in a sentence and "his" or "her" after ("Clyde, his glasses, where?"; Dutch and
  Afrikaans speakers' "Clyde his pill organizer stands on ...") is that person's thing: "clyde's glasses"
  (said after another word, :mod:`knic.language.procedure` reads it);
* a thing that "stands", "lies" or "sits" somewhere (as German and Dutch say it) "is" there;
* "not the X, the Y" said first: the Y; "is that the porch light?" before a request: the porch light;
* "go see is Huong in the kitchen" (Irish and Southern English): "see if Huong is in the kitchen"; "make the
  chandelier go to forty": "make the chandelier to forty";
* "too" after a state said last ("put the string lights on too") is "also", not "to";
* "is the aspirin in it?" after a place said alone is "in there";
* what a thing is put somewhere for, said last ("put it on the counter to thaw"), is a reason;
* "do the light on/out" (Dutch "doe het licht aan/uit") is "turn the light on/off"; "light up the porch
  light" (as a fire is lit) is "switch on";
* "I go to the market now." (the speaker's own plans, in a sentence of its own beside a request) is talk;
* "bring me both" after two things are named is "them";
* a room said first ("my room, blinds down to ten percent") is where the device said next is;
* "in the mudroom by the boot bench": by the boot bench, when it stands in that room;
* "turn that lamp on. The one by the recliner. That one.": "turn on the lamp. the one by the recliner."; "the
  big one in the kitchen": "the one in the kitchen" (the place tells which); "the remote, for the TV": "the
  remote for the TV"; "in here" before the thing said again by its name ("close them blinds in here. The den
  blinds.") is left out: the name says which.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from knic.language.selecting import SIZES
from knic.language.vocabulary import Vocabulary

_SENTENCE = re.compile(r"(?:[^.?!]|\.(?=\d))+[.?!]*")  # a decimal's point ends none
_DET = r"(?:the|my|his|her|their|our|your|that|this)"
_OUT_AT = re.compile(rf"\bout\s+((?:in|on|at)\s+{_DET}\b)", re.IGNORECASE)
_SWITCHED = re.compile(
    r"\b(?:light|lights|lamp|lamps|candle|fire|turn|switch|put|blow|knock)\b", re.IGNORECASE
)
_STANDS = re.compile(r"\b(?:stands|lies|sits|is standing|is lying|is sitting)\s+(?=(?:on|in|at|by|near)\b)")
_NOT_FIRST = re.compile(
    rf"^\s*(?:no,?\s+)?not\s+{_DET}\s+[^,.;!?]+,\s*(?:but\s+)?(?={_DET}\b)", re.IGNORECASE
)
_TOO = re.compile(r"\b(on|off|open|closed|shut|out)\s+too\b(?=\s*(?:[,.!?;]|$))", re.IGNORECASE)
_IN_IT = re.compile(r"^((?:[^,?]*,\s*)?(?:is|are)\b[^?]*\b(?:in|on|inside))\s+it(\s*\?)", re.IGNORECASE)
_PURPOSE = re.compile(r"\s+to\s+([a-z]+)(?=\s*(?:[,.!?;]|$))", re.IGNORECASE)
_PLACED = re.compile(rf"\b(?:in|on|into|onto|inside)\s+{_DET}\s", re.IGNORECASE)
_DO = re.compile(rf"\bdo\s+({_DET}\s+(?:[a-z]+\s+){{1,3}}?)(on|off|out)\b", re.IGNORECASE)
_OWN_PLANS = re.compile(
    r"^\s*i\s+(?:go|am going|'m going)\s+(?:to\s+)?(?!need|want|have|be\b)",
    re.IGNORECASE,
)
_BOTH = re.compile(
    r"\b(bring|take|give|fetch|get|carry|hand|pass)(\s+(?:me|us|him|her))?\s+both\b"
    r"(?=\s*(?:[,.!?;]|$|(?:to|into|in|on|onto|over|here|up|down|for|please)\b))",
    re.IGNORECASE,
)
#: a person's doing said in the third person or the past ("goes", "forgot", "left"), not what they want
_DOES = (
    r"(?!(?:wants|needs|asks|likes|loves|would)\b)(?:[a-z]+(?:[^s']s|ed)|forgot|went|left|took|got|did|had|was"
    r"|came|broke|made|knows)\b"
)
#: "is that the porch light?" before a request: the thing pointed at, not asked about
_POINTED = re.compile(rf"^(\s*)is\s+(?:that|this)\s+({_DET}\s[^?]+\?)\s*$", re.IGNORECASE)
_SEE_IS = re.compile(r"\b(see|check|ask|find out)\s+(is|are)\s+(.+?)\s+(?=(?:still\s+)?(?:in|on|at)\b)", re.I)
_GO_TO_LEVEL = re.compile(
    r"\s+go\s+(?=(?:up\s+|down\s+)?to\s+(?:\d|[a-z]+\s*(?:percent|per cent|%)|[a-z]+ty\b))", re.I
)
#: why, said last ("the blinds, close for me, too bright", "..., so hot", a learner's "hot too much")
_TOO_MUCH = re.compile(
    r"[,;!]\s*(?:it's\s+|it\s+is\s+)?(?:(?:too|so|very|really)\s+(?:much\s+)?[a-z]+|[a-z]+\s+too\s+much)"
    r"\s*[.!?]*\s*$",
    re.IGNORECASE,
)
#: a remark after the request on something of the speaker's or another's ("..., my plant needs sun")
_THEIRS = re.compile(
    r"[,.;!]\s*(?:my|our|his|her|their)\s+([a-z]+)\s+(?:needs?|wants?|is|are|was|were|has|have|gets?|likes?)\b"
    r"[^,.;!?]*",
    re.IGNORECASE,
)
#: "light up the shop light" (as a fire is lit): on; "turn the light up to 80" is no such verb
_LIGHT_UP = re.compile(rf"\blight\s+up(?=\s+(?:{_DET}|all)\b)", re.IGNORECASE)
#: "the one" and where, said after a thing ("..., the one by the recliner")
_THE_ONE = re.compile(r"[,.]\s*the\s+ones?\s+(?=(?:by|near|beside|next to|in|on|at|over|under|from)\b)", re.I)
_STATE_BEFORE = re.compile(
    r"\b(turn|switch|put|flip|flick)\s+(the\s+(?:[a-z]+\s+){0,2}?[a-z]+)\s+(on|off)\s*$", re.I
)
_THAT_ONE_AGAIN = re.compile(r"(?<=[.!?])\s*(?:that|this)\s+one\s*[.!]*\s*$", re.IGNORECASE)
_WORD_ONE = re.compile(r"\bthe\s+([a-z]+)\s+(ones?)\s+(?=(?:in|on|inside|from|at|by|near|beside)\b)", re.I)
#: "close the blinds in here. The den blinds.": where the speaker is, said again by the thing's name
_HERE_THEN_NAMED = re.compile(r"\s+(?:in|out)\s+here(?=\s*[.,]\s*the\s)", re.IGNORECASE)
_FOR_THE = re.compile(r",\s*for\s+the\b", re.IGNORECASE)
_DEVICE_NOUN = r"(?:blinds?|shades?|curtains?|lights?|lamps?)"


def plainly_said(text: str, vocabulary: Vocabulary, unknown: Callable[[str], bool]) -> str:
    """``text`` with the ways of speaking of the module docstring said plainly; ``unknown`` tells a word that
    neither the world nor the command language knows (a purpose's verb)."""
    people = [t.phrase for t in vocabulary.terms if vocabulary.is_subtype(t.type, "person")]
    rooms = [t.phrase for t in vocabulary.terms if vocabulary.is_subtype(t.type, "room")]
    devices = {t.phrase.split()[-1] for t in vocabulary.terms if vocabulary.is_subtype(t.type, "device")}
    sentences = [_sentence(s, people, devices, unknown) for s in _SENTENCE.findall(text)]
    said = [s for s in sentences if s.strip()]
    if len(said) > 1:  # the speaker's own plans beside a request; "is that the porch light? turn it off"
        kept = [s for s in said if not _OWN_PLANS.match(s)]
        sentences = [_POINTED.sub(r"\1\2", s) for s in kept[:-1]] + kept[-1:] if kept else said
    text = " ".join(s.strip() for s in sentences) if sentences else text
    text = _TOO_MUCH.sub("", text)
    for remark in list(_THEIRS.finditer(text))[::-1]:  # "..., my plant need sun": of a thing the world lacks
        if unknown(remark.group(1).lower()):
            text = text[: remark.start()] + text[remark.end() :]
    if people:  # "..., Wes forgot it again": what another person does or did is said of them, not asked
        names = "|".join(re.escape(p) for p in sorted(people, key=len, reverse=True))
        text = re.sub(rf"[,.;!]\s*(?:{names})\s+{_DOES}[^,.;!?]*", "", text, flags=re.IGNORECASE)
    text = _the_one(text)
    text = _LIGHT_UP.sub("switch on", text)
    text = _BOTH.sub(lambda m: f"{m.group(1)}{m.group(2) or ''} them", text)
    if rooms:
        names = "|".join(re.escape(r) for r in sorted(rooms, key=len, reverse=True))
        topic = (
            rf"(^|[.?!]\s*)((?:my room|my bedroom|(?:the\s+)?(?:{names}))),\s*(?:the\s+)?({_DEVICE_NOUN})\b"
        )
        text = re.sub(topic, r"\1the \3 in \2", text, flags=re.IGNORECASE)
    return _by_furniture(text, vocabulary)


def _sentence(sentence: str, people: list[str], devices: set[str], unknown: Callable[[str], bool]) -> str:
    """One sentence with the rules said of sentences (see the module docstring)."""
    if not _SWITCHED.search(sentence.split(" out ")[0]):
        sentence = _OUT_AT.sub(r"\1", sentence)
    names = "|".join(re.escape(p) for p in sorted(people, key=len, reverse=True))
    who = rf"(?:he|she|they|it{'|' + names if names else ''})"
    if sentence.rstrip().endswith("?"):
        sentence = re.sub(
            rf"^(\s*)({who})\s+(?=(?:still\s+)?(?:in|on|at)\b)", r"\1is \2 ", sentence, flags=re.I
        )
    sentence = re.sub(
        r"\bwhere\s+(?!is\b|are\b)(.+?)\s+at(?=\s*[?.!]*\s*$)", r"where is \1", sentence, flags=re.I
    )
    if sentence.rstrip().endswith("?"):  # "Clyde, where he go?"; "put it where it goes" is no question
        sentence = re.sub(
            rf"(^|,)(\s*)where\s+({who})\s+(?:go|gone|went)\b", r"\1\2where is \3", sentence, flags=re.I
        )
    if names:
        sentence = re.sub(rf"^(\s*)({names}),?\s+(?:his|her)\s+", r"\1\2's ", sentence, flags=re.IGNORECASE)
    sentence = _STANDS.sub("is ", sentence)
    sentence = _SEE_IS.sub(r"\1 if \3 \2 ", sentence)  # "go see is Huong in the kitchen" (Irish, Southern)
    if _names_in(sentence.split(" go ")[0], devices):  # "make the chandelier go to forty": set it to forty
        sentence = _GO_TO_LEVEL.sub(" ", sentence)
    sentence = _NOT_FIRST.sub("", sentence)
    sentence = _TOO.sub(r"\1", sentence)
    sentence = _IN_IT.sub(r"\1 there\2", sentence)
    sentence = _DO.sub(
        lambda m: f"turn {m.group(1)}{m.group(2)}" if _names_in(m.group(1), devices) else m.group(0), sentence
    )
    purpose = list(_PURPOSE.finditer(sentence))
    if purpose and unknown(purpose[-1].group(1).lower()) and _PLACED.search(sentence[: purpose[-1].start()]):
        sentence = sentence[: purpose[-1].start()] + sentence[purpose[-1].end() :]
    return sentence


def _the_one(text: str) -> str:
    """ "turn that lamp on. The one by the recliner. That one.": "turn on the lamp. the one by the recliner."
    (a state said before "the one ..." and "that one" said again kept apart from it); "the big one in the
    kitchen": "the one in the kitchen" (a size before "one" left out: the place tells which; a colour the
    world does not name is still refused); "the remote, for the TV": "the remote for the TV"; "the blinds in
    here. The den blinds.": "the blinds. The den blinds." (the name says which)."""
    text = _FOR_THE.sub(" for the", _HERE_THEN_NAMED.sub("", text))
    text = _WORD_ONE.sub(lambda m: f"the {m.group(2)} " if m.group(1).lower() in SIZES else m.group(0), text)
    said = _THE_ONE.search(text)
    if said is None:
        return text
    before, after = text[: said.start()], text[said.start() :]
    before = _STATE_BEFORE.sub(
        r"\1 \3 \2", re.sub(r"\b(?:that|this)\s+(?=[a-z]+\s+(?:on|off)?\s*$)", "the ", before)
    )
    return before + _THAT_ONE_AGAIN.sub("", after)


def _names_in(phrase: str, last_words: set[str]) -> bool:
    """Whether a noun phrase ends with one of ``last_words`` (a device's: "the garage light")."""
    words = phrase.lower().split()
    return bool(words) and words[-1] in last_words


def _by_furniture(text: str, vocabulary: Vocabulary) -> str:
    """ "in the mudroom by the boot bench" as "by the boot bench", where the boot bench is in the mudroom."""
    if not re.search(r"\bin\s+the\s.*\b(?:by|next to|beside|near)\s+the\b", text, re.IGNORECASE):
        return text
    for term in vocabulary.terms:
        if not vocabulary.is_subtype(term.type, "furniture"):
            continue
        for room in vocabulary.locations.get(term.symbol, ()):
            said = vocabulary.phrase_of(room)
            near = r"(?:by|next to|beside|near)"
            pattern = rf"\bin\s+the\s+{re.escape(said)}\s+({near}\s+the\s+{re.escape(term.phrase)})\b"
            text = re.sub(pattern, r"\1", text, flags=re.IGNORECASE)
    return text


#: a word after "a", "an" or "some" ("bring me a pop"), or first as the topic before "you" ("pho, you make")
_A_WORD = re.compile(r"\b(?:a|an|some)\s+([a-z]+)\b", re.IGNORECASE)
_TOPIC = re.compile(r"^\s*([a-z]+),\s*you\b", re.IGNORECASE)


def lacked(text: str, kind_of: Callable[[str], str]) -> str | None:
    """The word a request's thing was said by, where the reader found no thing in it ("bring what?"): after
    "a", "an" or "some" a word it reads as a verb or not at all ("could ya bring me a pop": 'pop'), or a word
    it does not know said first as the topic before "you" ("Pho, you make for me?": 'pho'); else None."""
    topic = _TOPIC.match(text)
    if topic is not None and kind_of(topic.group(1).lower()) == "unknown":
        return topic.group(1).lower()
    said = [m.group(1).lower() for m in _A_WORD.finditer(text)]
    return next((w for w in said if kind_of(w) in ("verb", "unknown")), None)
