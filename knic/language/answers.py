"""Yes/no answers: the words that make one and how a typed or recognised answer is read.

Shared by :mod:`knic.language.dialogue` (asking) and :mod:`knic.language.speech` (hearing), which is why it
stands apart from both: neither needs the other to know what "yes" is.
"""

from __future__ import annotations

from knic.language.vocabulary import normalize

YES_WORDS = frozenset(
    {"yes", "yeah", "yep", "correct", "right", "sure", "okay", "ok", "affirmative", "do it"}
)
NO_WORDS = frozenset({"no", "nope", "wrong", "cancel", "stop", "negative", "don't"})
#: JSGF grammar for a yes/no answer.
YES_NO_GRAMMAR = (
    "#JSGF V1.0;\ngrammar answer;\npublic <answer> = [ ( yes | no ) ] ( "
    + " | ".join(sorted(w for w in YES_WORDS | NO_WORDS if " " not in w and "'" not in w))
    + " ) [ please ];\n"
)


def parse_answer(text: str) -> bool | None:
    """True for yes, False for no, None when the answer is neither (or both)."""
    words = normalize(text).split()
    phrases = set(words) | {" ".join(words[i : i + 2]) for i in range(len(words) - 1)}
    yes, no = bool(phrases & YES_WORDS), bool(phrases & NO_WORDS)
    return None if yes == no else yes
