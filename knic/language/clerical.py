"""Requests said in the English of an office's letters, and typed by people who text (people39, a Mumbai flat
whose retired railway clerk, commerce student and Hinglish-speaking family asked for things):

* "the undersigned" for the one who writes or speaks ("kindly furnish the undersigned with his reading
  glasses"): "I" opening a sentence, "me" elsewhere; "furnish me with X" is "bring me X";
* a request in the passive said with "may", "can", "might" or "shall" ("the glasses may be brought", "the
  lamp may be put on", "the newspaper lying on the diwan may be brought to me"): the verb said first, as
  :mod:`knic.language.procedure` reads "is to be brought";
* "I wish to be escorted to the puja room", "we would like to be taken to the hall", "the undersigned may
  kindly be escorted to the hall": "escort me to ...";
* a thing "is required by me" ("the bath towel on the stool is required by the undersigned"): bring it to me;
* "the whereabouts of X may kindly be intimated", "kindly intimate the whereabouts of X": where X is;
* "with immediate effect", "on priority basis", "on an urgent basis", "at the earliest", and "as per my
  instructions (of this morning)," opening a sentence say no more than "now";
* "thereafter" between steps is "then"; "&" typed between words is "and" ("hall light dim to 40 & floor
  lamp on");
* an honorific said after a name before the possessive ("take Savitri ji's medicine box to her", "Gopal
  sahib's stick"), as Hindi and Urdu speakers say it: the name's ("Savitri's"), where "ji's" was no one.

Each works on the text as said, before :func:`knic.language.procedure.procedure_read`
(:func:`clerical_read`).
"""

from __future__ import annotations

import re

from knic.language.procedure import PARTICIPLES

#: a thing's name as the passive says it: an article or possessive, then its words
_THING = r"(?P<thing>(?:the|my|your|his|her|our|their|this|that|these|those)\s[a-z' -]+?)\s+"

#: "the undersigned" opening a sentence (the subject), and elsewhere (the object)
_UNDERSIGNED_FIRST = re.compile(r"(?:^|(?<=[.;:!?,]))(?P<gap>\s*)the\s+undersigned\b", re.IGNORECASE)
_UNDERSIGNED = re.compile(r"\bthe\s+undersigned\b", re.IGNORECASE)

#: "furnish me with X": bring me X
_FURNISH = re.compile(r"\b(?:furnish|provide|supply)\s+(?P<who>me|us|him|her)\s+with\b", re.IGNORECASE)

#: participles that say where a thing is with a modal, no request ("the keys can be found in the drawer")
_FOUND = frozenset({"found", "located"})
#: a request in the passive said with a modal ("the glasses may be brought")
_MAY_PASSIVE = re.compile(
    rf"(?P<start>^|(?<=[.;:!?,])\s*){_THING}(?:may|can|might|shall)\s+(?:kindly\s+|please\s+)?be\s+"
    rf"(?P<part>{'|'.join(p for p in PARTICIPLES if p not in _FOUND)})\b",
    re.IGNORECASE,
)

#: "I wish to be escorted to ...": the verb said first, the speaker its object
_BE_LED = {
    "escorted": "escort",
    "taken": "take",
    "accompanied": "accompany",
    "led": "lead",
    "guided": "guide",
}
_WISH_LED = re.compile(
    r"\b(?:i|we)\s+(?:(?:wish|wishes|would\s+like|want|wants|need|needs|should\s+like)\s+to|may)\s+"
    r"(?:kindly\s+)?be\s+"
    rf"(?P<part>{'|'.join(_BE_LED)})\b",
    re.IGNORECASE,
)

#: "X is required by me": bring X to me
_REQUIRED = re.compile(
    rf"(?P<start>^|(?<=[.;:!?,])\s*){_THING}(?:is|are)\s+(?:urgently\s+|now\s+)?(?:required|needed|wanted)\s+"
    r"by\s+(?P<who>me|us)\b",
    re.IGNORECASE,
)

#: "the whereabouts of X may kindly be intimated (to me)", "kindly intimate me the whereabouts of X"
_WHEREABOUTS_TOLD = re.compile(
    r"\b(?:the\s+)?whereabouts\s+of\s+(?P<thing>[a-z' -]+?)\s+(?:may|might|can|should|shall|is\s+to|are\s+to)"
    r"\s+(?:kindly\s+|please\s+)?be\s+(?:intimated|communicated|reported|conveyed|informed|made\s+known|told)"
    r"(?:\s+to\s+(?:me|us))?\b",
    re.IGNORECASE,
)
_INTIMATE = re.compile(
    r"\b(?:intimate|communicate|convey)\s+(?:to\s+)?(?:me\s+|us\s+)?(?:the\s+)?whereabouts\s+of\b",
    re.IGNORECASE,
)

#: when, said as in an office's letters: no more than "now"
_OFFICE_WHEN = re.compile(
    r"\s*,?\s*\b(?:with\s+immediate\s+effect|on\s+(?:a\s+|an\s+)?(?:top\s+)?(?:priority|urgent)(?:\s+basis)?|"
    r"at\s+the\s+earliest(?:\s+possible)?)\b",
    re.IGNORECASE,
)

#: "as per my instructions of this morning, ..." opening a sentence: no request of its own
_AS_PER = re.compile(r"(?:^|(?<=[.;!?]))\s*as\s+per\s+[^,.;!?]{1,60},\s*", re.IGNORECASE)

#: "thereafter" between steps; "&" typed between words
_THEREAFTER = re.compile(r"\b(?:and\s+)?thereafter\b", re.IGNORECASE)
_AMPERSAND = re.compile(r"\s+&\s+")


#: an honorific between a name and its possessive
_HONOURED_OWNER = re.compile(r"\b(?P<name>[a-z]+)\s+(?:ji|sahib|saheb|sahab)'s\b", re.IGNORECASE)


def clerical_read(text: str) -> str:
    """``text`` with the turns of phrase of this module put plainly (see the module docstring)."""
    text = _HONOURED_OWNER.sub(lambda m: f"{m.group('name')}'s", _AMPERSAND.sub(" and ", text))
    if "undersigned" in text.lower():
        text = _UNDERSIGNED_FIRST.sub(lambda m: f"{m.group('gap')}I", text)
        text = _UNDERSIGNED.sub("me", text)
    text = _FURNISH.sub(lambda m: f"bring {m.group('who')}", text)
    text = _MAY_PASSIVE.sub(
        lambda m: f"{m.group('start')}{PARTICIPLES[m.group('part').lower()]} {m.group('thing')}", text
    )
    text = _WISH_LED.sub(lambda m: f"{_BE_LED[m.group('part').lower()]} me", text)
    text = _REQUIRED.sub(lambda m: f"{m.group('start')}bring {m.group('thing')} to {m.group('who')}", text)
    if "whereabouts" in text.lower():
        text = _WHEREABOUTS_TOLD.sub(lambda m: f"where is {m.group('thing')}", text)
        text = _INTIMATE.sub("where is", text)
    text = _AS_PER.sub("", _OFFICE_WHEN.sub("", text)).strip()
    return _THEREAFTER.sub("then", text)


__all__ = ["clerical_read"]
