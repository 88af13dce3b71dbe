"""Questions said in another order than the usual English one, put back before a command is read (used by
:func:`knic.language.household.where_last`, on the whole text with its punctuation). General English and
learners' English only, no world's names:

* the thing said first, then asked about as "it", "she", "he" or "they" ("our Ellis, is she at the dining
  table?", "the hoist remote, is it on the bedside cabinet?"): "is our Ellis at the dining table?";
* a statement asked with a question mark, its verb left where a statement has it ("the charger of the
  wheelchair is on the charging point?", "Ottavia is in the conservatory?", learners and casual speech),
  said last: "is the charger of the wheelchair on the charging point?" (with more said after it, "hand cream
  is on the bedside table? look please", it says where the thing is for what follows, as it did);
* a thing or person, "where?", then a place alone, asked again ("Theo where? Courtyard?", in the word
  order of British Sign Language, or a tired speaker): "is Theo in the courtyard?";
* a thing and then "where?" said last, after another sentence ("Me go wet room. Towel where?"): "where is
  the towel?", as it already was said alone;
* "where she is", "where he is" said as a learner's question ("Merline, where she is now?"): "where is
  she" (the order of a question inside another, "do you know where she is", stays);
* "'s" after a person or thing and before a past participle ("our Theo's cut his knee", "the milk's gone
  off", "Nan's dropped her glasses"): "has", a remark about what happened, not a thing of theirs;
* "our" before a name written with its capital ("our Theo's cut his knee", "take it to our Ellis",
  Northern English and Scouse for one of the family): the name alone;
* a verb "be" left out (Caribbean English, African American English, learners): "this chair giving me
  trouble" ("this chair is giving ...", a remark), "I hungry", "I cold" ("I'm hungry", a reason after a
  request);
* "they", "he", "she" or "it" opening a stretch straight before where ("bring meh slippers, dey on de
  profiling bed"): "they're", "he's", "she's", "it's", where the thing or person is;
* what a thing is for said as someone's meal after a request ("bring my mug for my tea", "... for lunch"):
  left out, the meal is no thing to bring ("bring me the cup for the tea" still names the tea, a thing);
* Caribbean "nah" said straight after a request ("pass me de remote nah", "bring me a roti nah, I
  hungry"): urging, left out ("nah" set apart, "..., nah, the cup", stays "no", a correction);
* Caribbean English "it have" for "there is", and "ent it have" (isn't there) or "it have" opening a question
  ("ent it have sorrel in the fridge?", "it have milk in the fridge?"): "is there".
"""

from __future__ import annotations

import re

#: prepositions that say where a thing or person is asked to be
_WHERE = r"(?:in|on|at|inside|under|by|near|next to|still in|still on|still at)"
#: the thing said first, then asked about as a pronoun ("the remote, is it on the table?")
_TOPIC = re.compile(
    rf"(?P<topic>[^,.?!;:]+?)\s*[,-]+\s*(?P<aux>is|are)\s+(?:it|she|he|they)\s+(?P<where>{_WHERE}\s[^?.!]*\?)",
    re.IGNORECASE,
)
#: what a statement asked as a question may not open with: it is then a question already, or no thing's name
_NOT_SAID = frozenset(
    {"where", "what", "which", "who", "why", "how", "when", "is", "are", "it", "she", "he", "they", "there"}
    | {"this", "that", "i", "you", "we", "nobody", "no", "nothing", "everything", "all", "if", "and", "but"}
)
#: a statement asked with a question mark: "<the thing> is <where>?"
_STATEMENT = re.compile(
    rf"(?:^|(?<=[.!?;,]\s))(?P<thing>[a-z][\w' ]*?)\s+(?P<aux>is|are)\s+(?P<where>{_WHERE}\s[^?.!,]*\?)\s*$",
    re.IGNORECASE,
)
#: "<the thing> where? <a place>?"
_WHERE_AGAIN = re.compile(
    r"^\s*(?P<thing>[a-z][\w' ]*?)\s+where\s*\?\s*(?P<place>[a-z][\w' ]*?)\s*\?\s*$", re.IGNORECASE
)
#: a thing and "where?" said last after another sentence ("... Towel where?")
_WHERE_ENDING = re.compile(r"(?<=[.!?;]\s)([a-z][\w' ]{0,30}?)\s+where\s*\?\s*$", re.IGNORECASE)
#: the determiners a place said alone may already have
_DETERMINED = frozenset({"the", "my", "his", "her", "their", "our", "your", "a"})
#: a learner's question "where she is" said as the request, not inside another question
_WHERE_SHE = re.compile(
    r"(?<![\w'])(?<!know )(?<!knows )(?<!tell me )(?<!see )where (she|he) is\b(?!\s+(?:the|a|my))",
    re.IGNORECASE,
)
#: Caribbean "it have" (there is), "ent it have" (isn't there)
_IT_HAVE = re.compile(r"\b(?:ent|eh|isn't|is) it have\b", re.IGNORECASE)
_IT_HAVE_ASKED = re.compile(r"(?:^|(?<=[.!?;,]\s))it have\b(?=[^.!?]*\?)", re.IGNORECASE)
_THERE_IS = re.compile(r"(?<![\w'])(?<!does )(?<!would )(?<!will )it have\b(?!\s+(?:to|got|been|a look))")


#: past participles said after "'s" (has), not things someone owns (no "left", "broken": "the bedroom's left
#: light", "jack's broken glasses")
_DONE = (
    "cut|hurt|lost|gone|fallen|fell|burned|dropped|spilled|spilt|done|got|finished"
    "|taken|eaten|forgotten|forgot|bumped|banged|grazed|scraped|twisted|sprained|knocked|tripped|been"
)
#: "our" before a capitalised name ("our Theo")
_FAMILY = re.compile(r"(?<![\w'])[Oo]ur (?=[A-Z][a-z])")
_HAS_DONE = re.compile(rf"\b([a-z]+)'s ({_DONE})\b(?!\s+(?:and|or)\b)", re.IGNORECASE)


#: "this" or "that", a noun and a verb in "-ing" with "is" left out, opening a stretch ("dis chair giving me
#: trouble"; "bring me that mug sitting on the table" stays)
_THIS_DOING = re.compile(
    r"(?:^|(?<=[,.;!?]\s))(this|that|dis|dat) ([a-z]+) ([a-z]{2,}ing)\b(?! (?:is|are|was)\b)", re.IGNORECASE
)
#: words in "-ing" that are no verb's
_NOT_DOING = frozenset(
    {"thing", "ring", "king", "ceiling", "building", "evening", "morning", "string", "bring", "sling", "wing"}
    | {"something", "nothing", "anything", "everything", "swing", "spring", "pudding", "icing", "stuffing"}
)
#: how the speaker feels, said with "I" and "be" left out ("I hungry")
_FEELING = re.compile(
    r"(?:^|(?<=[,.;!?]\s))I (hungry|thirsty|tired|cold|hot|sleepy|busy|sick|ill|late|bored|starving|freezing"
    r"|cold now|hungry now|tired now|ready|done)\b",
)
#: "they", "he", "she", "it" and "be" left out opening a stretch before where ("dey on de bed")
_BEING_WHERE = re.compile(
    r"(?:^|(?<=[,.;!?]\s))(they|dey|he|she|it)"
    r"(?= (?:on|in|at|under|inside|by|near) (?:the|de|my|meh|his|her|your)\b)",
    re.IGNORECASE,
)
_BEING = {"they": "they're", "dey": "they're", "he": "he's", "she": "she's", "it": "it's"}
#: Caribbean "nah" straight after a request's last word, urging it on
_URGING_NAH = re.compile(r"(?<=[a-z]) nah(?=\s*(?:[,.!?]|$))", re.IGNORECASE)
#: a meal said as what a thing is for ("for my tea", "for lunch")
_FOR_MEAL = re.compile(
    r"\s+for (?:my |your |his |her |our |meh )?(?:tea|breakfast|lunch|dinner|supper|snack|elevenses)"
    r"(?=\s*(?:[.,!?]|$))",
    re.IGNORECASE,
)


def asked_plainly(text: str) -> str:
    """``text`` with the questions of the module docstring put in the usual English order."""
    text = _THIS_DOING.sub(lambda m: _doing(m), _FEELING.sub(lambda m: f"I'm {m.group(1)}", text))
    text = _URGING_NAH.sub("", _FOR_MEAL.sub("", text))
    text = _BEING_WHERE.sub(lambda m: _BEING[m.group(1).lower()], text)
    text = _HAS_DONE.sub(lambda m: f"{m.group(1)} has {m.group(2)}", _FAMILY.sub("", text))
    text = _IT_HAVE.sub("is there", text)
    text = _IT_HAVE_ASKED.sub("is there", text)
    text = _THERE_IS.sub("there is", text)
    text = _WHERE_SHE.sub(lambda m: f"where is {m.group(1)}", text)
    text = _WHERE_ENDING.sub(lambda m: f"where is {m.group(1)}?", text)
    again = _WHERE_AGAIN.match(text)
    if again and len(again.group("place").split()) <= 3:
        place = again.group("place")
        article = "" if place.split()[0].lower() in _DETERMINED else "the "
        return f"is {again.group('thing')} in {article}{place}?"
    text = _TOPIC.sub(_topic_asked, text)
    return _STATEMENT.sub(_statement_asked, text)


def _topic_asked(match: re.Match[str]) -> str:
    said = match.group("topic")
    topic = said.strip()
    if topic.split()[-1].lower() in _NOT_SAID:
        return match.group(0)
    lead = said[: len(said) - len(said.lstrip())]
    return f"{lead}{match.group('aux')} {topic} {match.group('where')}"


def _statement_asked(match: re.Match[str]) -> str:
    thing = match.group("thing").strip()
    if thing.split()[0].lower() in _NOT_SAID or len(thing.split()) > 6:
        return match.group(0)
    return f"{match.group('aux')} {thing} {match.group('where')}"


def _doing(match: re.Match[str]) -> str:
    if match.group(3).lower() in _NOT_DOING or match.group(2).lower() in ("is", "was", "are", "one"):
        return match.group(0)
    return f"{match.group(1)} {match.group(2)} is {match.group(3)}"
