"""Loose ways of speaking around a request, put into the plain words the reader knows (people40: a chalet
let to a holiday group; a hedging British guest, a Swiss caretaker, a guest who runs requests together):

* "but" opening a question after a hedge ("I'm probably being silly, but is the camera still in the chest of
  drawers?", "sorry, but are the keys on the hall chest?"): the question, as "..., but could you ..." already
  is; "but" inside a sentence ("all the lights but the kitchen one") stays;
* a close said last that asks nothing ("... and put the bedside lamp on at thirty and that's it really",
  "..., that's all", "just go to the bunk room and leave me alone", "... and leave me in peace"): dropped, so
  that no empty step is read after the last one;
* "need" or "want" opening a sentence with no one said to need it, after a thing said alone ("plasters...
  need plasters from the bathroom shelf", a tired speaker's; "headlamp. want my headlamp"): "I need", so
  that the thing said first is not read as the one who needs; "need to ..." stays;
* a bystander's "which?" set off by dashes, answered after it ("bring the wine — which wine? — the red one,
  to the stube", a group talking at once): a comma, so that the answer describes the thing said before it,
  as "bring the wine, the red one, to the stube" does;
* "it has" for "there is", as German ("es hat"), Swiss German ("es hät") and French ("il y a") speakers
  say it, opening a sentence before "no", "no more", "still", "some" or an article ("it has no more milk in
  the fridge"): "there is", a remark that asks nothing, not "it" for a thing never named;
* "wait on me" (Swiss, German and American English for "wait for me", "wait there on me"): "wait for me";
* a thing that "needs to go" somewhere, said as the request ("the white mug on the stube table needs to go
  to the sink and the bread basket needs to go back to the kitchen table"): "take" it there. Only a thing
  said with a determiner at the start of a clause, going "to" a place; "I need to go to the kitchen" stays,
  and so does "the remote needs to go on the tv table", already put there (:mod:`knic.language.household`).

Text only, before the words are split into sentences (:func:`knic.language.tidy.cut_off_dropped`).
"""

from __future__ import annotations

import re
from collections.abc import Callable

#: "but" at the start of a sentence or after a break, before a verb that opens a yes/no question
_BUT_ASKING = re.compile(
    r"(^|[,;:.!?—–]\s*|\s-\s)but\s+(?=(?:is|are|was|were|has|have|had|do|does|did|is there|are there)\b)",
    re.IGNORECASE,
)
#: a close said last: "and that's it (really)", ", that's all then", "and leave me alone"
_CLOSE = re.compile(
    r"(?:\s*,\s*|\s+and\s+|\s+)(?:that'?s (?:it|all)(?: really| then| for now| thanks)?"
    r"|(?:just )?leave me (?:alone|be|in peace))\s*[.!]*\s*$",
    re.IGNORECASE,
)
#: "need"/"want" opening a sentence after another, not "need to"
_SUBJECTLESS_WISH = re.compile(r"([.!?;…]\s*)(need|want)\s+(?!to\b)", re.IGNORECASE)
#: "— which wine? —", "— which one? —": a question of which, set off by a pair of dashes
_WHICH_ASIDE = re.compile(
    r"\s*(?:—|–|\s-{1,2}\s|--)\s*which\b[^—–?!.]{0,30}\?\s*(?:—|–|\s-{1,2}\s|--)\s*", re.IGNORECASE
)
#: "it has no more milk", opening a sentence
_IT_HAS = re.compile(
    r"(^|[.!?;,]\s*)it has (?=(?:no|not any|still|some|a|an|any|enough|too much|too many|nothing)\b)",
    re.IGNORECASE,
)
#: "wait on me", "wait there on us": waiting for the speaker
_WAIT_ON = re.compile(r"\bwait((?:\s+(?:there|here))?)\s+on\s+(me|us)\b", re.IGNORECASE)
#: "the mug needs to go (back) to the sink" at the start of a clause
_NEEDS_TO_GO = re.compile(
    r"(^|[,;:.!?]\s*|\b(?:and|then|so|also)\s+)((?:the|my|your|our|this|that|these|those)\s+[^,;:.!?]+?)\s+"
    r"(?:needs|need|has|have|ought|should)\s+(?:to\s+)?go\s+(back\s+)?(?=to\b)",
    re.IGNORECASE,
)


def _taken_there(match: re.Match[str]) -> str:
    return f"{match.group(1)}take {match.group(2)} {match.group(3) or ''}"


#: each turn, after a word it cannot be without (looked for first: most commands have none), and what it
#: becomes
_TURNS: tuple[tuple[str, re.Pattern[str], str | Callable[[re.Match[str]], str]], ...] = (
    ("but", _BUT_ASKING, r"\1"),
    ("", _CLOSE, ""),
    ("it has", _IT_HAS, r"\1there is "),
    ("which", _WHICH_ASIDE, ", "),
    ("", _SUBJECTLESS_WISH, r"\1I \2 "),
    (" on ", _WAIT_ON, r"wait\1 for \2"),
    (" go ", _NEEDS_TO_GO, _taken_there),
)


def loosely_said(text: str) -> str:
    """``text`` with the loose turns above put plainly ("sorry, but is X in Y?" -> "sorry, is X in Y?")."""
    lowered = text.lower()
    for word, pattern, plain in _TURNS:
        if word in lowered:
            text = pattern.sub(plain, text)
    return text
