"""Requests said by a procedure, or in another order than plain English puts them (people33, a top-floor flat
whose radio-trained owner, barrister brother-in-law, Korean grandmother and Dutch au pair asked for things):

* radio procedure, as pilots, controllers, coastguards and security staff speak on a radio: numbers said
  digit by digit where a level goes ("set the desk lamp to six zero percent", "terrace lights to four five",
  "dim it to one zero"): the number they spell (60, 45, 10), where "six zero" was read as 0 and "four five" as
  5; "my location", "my position" are the speaker ("bring the binoculars to my location"); "confirm location
  of", "report the location of" ask where a thing or person is; "task one, ...", "step two: ..." number the
  steps of a list, as "1." and "(2)" do, where "one" was read as a level; a radio check ("radio check, how do
  you read?", "do you copy?") asks for no action and is refused so, where "check" asked "check what?"; "out"
  or "over" said last after a stop ("Switch on the hallway light. Out.") signs off, where "out" was read as
  the state off; "confirm (that) the cup is on the table" asks whether it is;
* a request said in the passive, as in court, in an office or in a notice ("my laptop is to be brought to me
  forthwith", "the office blind is to be lowered by one half", "the lamp should be switched off", "the
  letters need to be taken to the office", "I should be grateful if the briefcase were brought to the sofa
  bed"): the verb said first ("bring my laptop to me ...", "if you bring the briefcase ..."); "forthwith",
  "without delay", "at your earliest convenience" say no more than "now";
* "the same" for the thing just named ("take the jigsaw ... and convey the same to the terrace table"), as
  formal and legal English says it: "it", where "same" was looked for in the world;
* a claim of where a thing is, then a request to confirm or check it ("I put it to you that the car keys are
  on the coat rack. Kindly confirm.", "I think the keys are on the hall table, can you check?"): whether the
  thing is there, a search with that ground, where the claim was read as talk;
* a person and "his" or "her" before a thing ("Otis his dummy", "Mia her coat"), as Dutch, German,
  Afrikaans and Scandinavian speakers say the possessive: the person's thing ("Otis's dummy"), where the
  person was searched for as well;
* "I go" or "we go" with a time to come ("I go with Otis to the park later", a learner's present for the
  future): what the speaker will do, no request, as "I'm going ..." is;
* a thing, then "where?" in a sentence of its own before more is said ("Femke where? Otis need bath"): where
  the thing or person is, as the same said alone is (:func:`knic.language.household.where_last`).

Each works on the text as said, before it is split into stretches (:func:`procedure_read`).
"""

from __future__ import annotations

import re

_DIGITS = {
    "zero": "0",
    "oh": "0",
    "one": "1",
    "two": "2",
    "three": "3",
    "four": "4",
    "five": "5",
    "six": "6",
    "seven": "7",
    "eight": "8",
    "nine": "9",
    "niner": "9",
}
_DIGIT = r"(?:zero|one|two|three|four|five|six|seven|eight|nine|niner)"
_DIGIT_OR_OH = r"(?:zero|oh|one|two|three|four|five|six|seven|eight|nine|niner)"

#: two or three digits said one by one where a level goes: after "to" or "at", or before "percent"
_SPELLED_NUMBER = re.compile(
    rf"(?:(?<=\bto\s)|(?<=\bat\s))(?P<a>{_DIGIT}(?:\s+{_DIGIT_OR_OH}){{1,2}})\b(?!\s+(?:{_DIGIT_OR_OH}|hundred)\b)"
    rf"|\b(?P<b>{_DIGIT}(?:\s+{_DIGIT_OR_OH}){{1,2}})(?=\s+(?:percent|per\s+cent|%))",
    re.IGNORECASE,
)

#: the speaker's place said as a radio operator says it
_MY_LOCATION = re.compile(r"\bmy\s+(?:current\s+|present\s+)?(?:location|position|posit)\b", re.IGNORECASE)

#: asking where a thing or person is, as a report is asked for on a radio
_LOCATION_OF = re.compile(
    r"\b(?:(?:please|kindly)\s+)?(?:confirm|report|give\s+me|send\s+me|say|state|request)\s+"
    r"(?:the\s+)?(?:current\s+|present\s+)?location\s+of\b",
    re.IGNORECASE,
)

#: a step of a list numbered in words ("task one, ...", "step two: ...", "job 3 -"), opening a sentence
_STEP_LABEL = re.compile(
    r"(?:^|(?<=[.,;:!?]))\s*(?:task|step|job|stage|part|action)\s+"
    r"(?:one|two|three|four|five|six|[1-6])\s*[,:.\-]+\s*",
    re.IGNORECASE,
)

#: a radio check: how the robot hears, no action asked
_RADIO_CHECK = re.compile(
    r"\b(?:radio\s+check|comms?\s+check|how\s+do\s+you\s+read(?:\s+me)?|do\s+you\s+copy|how\s+copy)\b",
    re.IGNORECASE,
)

#: the verbs a request in the passive says, by their past participle
_PARTICIPLES = {
    "brought": "bring",
    "taken": "take",
    "put": "put",
    "placed": "place",
    "moved": "move",
    "fetched": "fetch",
    "carried": "carry",
    "delivered": "deliver",
    "returned": "return",
    "switched": "switch",
    "turned": "turn",
    "lowered": "lower",
    "raised": "raise",
    "closed": "close",
    "opened": "open",
    "shut": "shut",
    "dimmed": "dim",
    "drawn": "draw",
    "found": "find",
    "located": "locate",
    "set": "set",
}
#: the same, for the passives other modules read (knic.language.clerical)
PARTICIPLES = _PARTICIPLES

#: a request in the passive: the thing, a "to be" that asks ("is to be", "should be", "needs to be"), the
#: participle and the rest of the sentence
_THING = r"(?P<thing>(?:the|my|your|his|her|our|their|this|that|these|those)\s[a-z' -]+?)\s+"
_PARTICIPLE = rf"\s+(?P<part>{'|'.join(_PARTICIPLES)})\b"
_PASSIVE = re.compile(
    rf"(?P<start>^|(?<=[.;:!?])\s*){_THING}"
    r"(?:is\s+to\s+be|are\s+to\s+be|should\s+be|must\s+be|needs?\s+to\s+be|has\s+to\s+be|have\s+to\s+be|"
    rf"ought\s+to\s+be|wants?\s+to\s+be){_PARTICIPLE}",
    re.IGNORECASE,
)

#: a wish said in the passive after "if" ("I should be grateful if the briefcase were brought to the sofa
#: bed"): as "if you bring the briefcase ..." is read
_IF_PASSIVE = re.compile(
    rf"\bif\s+{_THING}(?:were|was|could\s+be|would\s+be|might\s+be){_PARTICIPLE}", re.IGNORECASE
)

#: when, said as in court or in an office ("forthwith", "without delay", "at your earliest convenience"): no
#: more than "now"
_FORMAL_WHEN = re.compile(
    r"\s*,?\s*\b(?:forthwith|without\s+(?:further\s+)?delay|at\s+your\s+(?:earliest\s+)?convenience|promptly)\b",
    re.IGNORECASE,
)

#: "the same" standing for the thing just named: followed by where it goes or the end of the clause
_THE_SAME = re.compile(
    r"\bthe\s+same\b(?=\s*(?:$|[,.;!?]|(?:to|into|onto|on|in|at|back|from|and|then|over|up|down)\b))",
    re.IGNORECASE,
)

#: a claim of where a thing is, then a request to confirm or check it
_CLAIM_CHECKED = re.compile(
    r"^\s*(?:(?:i\s+put\s+it\s+to\s+you|i\s+(?:think|believe|reckon|suspect)|i'm\s+(?:pretty\s+)?sure|"
    r"i\s+am\s+(?:pretty\s+)?sure)\s+(?:that\s+)?)?"
    r"(?P<claim>(?:(?:the|my|your|his|her|our)\s[a-z' ]+?|[a-z]+)\s(?:is|are)\s(?:still\s)?"
    r"(?:on|in|at|under|inside|by|beside|behind|next\s+to)\s[a-z' ]+?)\s*[.;,!]\s*"
    r"(?:(?:so\s+)?(?:kindly|please|can\s+you|could\s+you|would\s+you|will\s+you|would\s+you\s+kindly)\s+)*"
    r"(?:confirm|check|verify)(?:\s+(?:that|it|this|please|for\s+me|whether\s+that\s+is\s+so))*\s*[.?!]*\s*$",
    re.IGNORECASE,
)

#: "confirm (that) X is on Y": whether it is, as "check whether" asks
_CONFIRM = re.compile(
    r"(?:^|(?<=[.;!?,]\s))(?:(?:please|kindly)\s+)?confirm\s+(?:that\s+|whether\s+|if\s+)?"
    r"(?=(?:(?:the|my|your|his|her|our)\s[a-z' ]+?|[a-z]+)\s(?:is|are)\s)",
    re.IGNORECASE,
)

#: the operator's "over" or "out" said last after a stop ("Switch on the hallway light. Out."): no state
_SIGN_OFF = re.compile(
    r"(?:(?<=[.;!?])\s*(?:over\s+and\s+out|roger\s+out|over|out)|,\s*(?:over\s+and\s+out|over))\s*[.!]*\s*$",
    re.IGNORECASE,
)

#: a person's thing said with "his" or "her" after the person's name ("where is Otis his dummy"), where a
#: word before the name shows it is no one given a thing ("give Tom his keys", "bring to Mia her coat")
_HIS_GENITIVE = re.compile(
    r"\b(?P<before>(?i:is|are|where's|wheres|of|on|in|into|onto|from|under|by|near|with|if|whether|where))\s+"
    r"(?P<person>[A-Z][a-z]+)\s+(?:his|her)\s+(?=[a-z])"
)

#: a learner's present for what the speaker will do ("I go with Otis to the park later"): "I'm going"
_GO_LATER = re.compile(
    r"^\s*(?P<who>i|we)\s+go\b(?=[^.;!?]*\b(?:later|tomorrow|tonight|soon|next\s+week|"
    r"this\s+(?:morning|afternoon|evening|weekend)|after\s+(?:lunch|dinner|work|school|breakfast)|"
    r"in\s+an?\s+(?:hour|minute|bit|while))\b)",
    re.IGNORECASE,
)

#: a thing, then "where?" in a sentence of its own, before more is said
_WHERE_FIRST = re.compile(
    r"^\s*(?P<thing>[a-z'-]+(?:\s+[a-z'-]+){0,3}?)\s*,?\s+where\s*\?\s*(?=\S)", re.IGNORECASE
)


def _spelled(match: re.Match[str]) -> str:
    said = match.group("a") or match.group("b")
    return str(int("".join(_DIGITS[w.lower()] for w in said.split())))


def _active(said: re.Match[str]) -> str:
    """A request said in the passive, its verb first: "bring my laptop" for "my laptop ... brought"."""
    return f"{_PARTICIPLES[said.group('part').lower()]} {said.group('thing')}"


def procedure_read(text: str) -> str:
    """``text`` with the turns of phrase of this module put plainly (see the module docstring)."""
    text = _SPELLED_NUMBER.sub(_spelled, text)
    text = _LOCATION_OF.sub("where is", _MY_LOCATION.sub("me", text))
    text = _STEP_LABEL.sub(" , ", text)
    text = _RADIO_CHECK.sub("over", text)  # the operator's word alone: no action, as "wilco, out" is none
    text = _PASSIVE.sub(lambda m: f"{m.group('start')}{_active(m)}", text)
    text = _IF_PASSIVE.sub(lambda m: f"if you {_active(m)}", text)
    text = _THE_SAME.sub("it", _FORMAL_WHEN.sub("", text))
    if (claim := _CLAIM_CHECKED.match(text)) is not None:
        text = f"check whether {claim.group('claim')}"
    text = _SIGN_OFF.sub("", _CONFIRM.sub("check whether ", text))
    text = _HIS_GENITIVE.sub(lambda m: f"{m.group('before')} {m.group('person')}'s ", text)
    text = _GO_LATER.sub(lambda m: "I'm going" if m.group("who").lower() == "i" else "we're going", text)
    if (where := _WHERE_FIRST.match(text)) is not None and where.group("thing").lower().split()[-1] not in (
        "is",
        "are",
        "and",
    ):
        text = f"where is {where.group('thing')}? {text[where.end() :]}"
    return text


__all__ = ["PARTICIPLES", "procedure_read"]
