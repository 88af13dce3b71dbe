"""Yes/no answers: the phrases that make one and how a typed or recognised answer is read.

The phrases are data (``answers.yaml`` beside this module: general English, the development list). Shared by
:mod:`knic.language.dialogue` (asking) and :mod:`knic.language.speech` (hearing), which is why it stands apart
from both: neither needs the other to know what "yes" is.

Reading an answer: left to right, the longest phrase of any list at each position ("that's not right" before
"right", "absolutely not" before "absolutely"); openers, closers and other words are skipped. Yes when only
yes phrases were found, no when only no phrases, no answer (None) when neither, both, or an unsure phrase
("i'm not sure") was found.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from core.errors import LanguageError
from core.inputs import read_yaml
from knic.language.vocabulary import normalize

ANSWERS_FILE = Path(__file__).with_name("answers.yaml")
_LISTS = ("yes", "no", "unsure", "openers", "closers")


@dataclass(frozen=True)
class AnswerPhrases:
    """The phrase lists of ``answers.yaml`` (normalised)."""

    yes: tuple[str, ...]
    no: tuple[str, ...]
    unsure: tuple[str, ...]
    openers: tuple[str, ...]
    closers: tuple[str, ...]

    def words(self) -> frozenset[str]:
        """Every word of every list (the words a spoken answer may consist of)."""
        lists = (self.yes, self.no, self.unsure, self.openers, self.closers)
        return frozenset(w for phrases in lists for phrase in phrases for w in phrase.split())


def load_answer_phrases(path: str | Path = ANSWERS_FILE) -> AnswerPhrases:
    """Read an answer phrase file.

    Raises:
        LanguageError: the file is unreadable, a list is missing or not a list of phrases, or a phrase is
            in both the yes and the no list.
    """
    path = Path(path)
    data = read_yaml(path, "answer phrases", LanguageError)
    if not isinstance(data, dict):
        raise LanguageError(f"{path}: expected a mapping of the lists {', '.join(_LISTS)}")
    lists: dict[str, tuple[str, ...]] = {}
    for name in _LISTS:
        items = data.get(name)
        if not isinstance(items, list) or not all(isinstance(i, str) and normalize(i) for i in items):
            raise LanguageError(f"{path}: '{name}' must be a list of phrases")
        lists[name] = tuple(dict.fromkeys(normalize(i) for i in items))
    both = sorted(set(lists["yes"]) & set(lists["no"]))
    if both:
        raise LanguageError(f"{path}: phrase(s) both yes and no: {', '.join(both)}")
    return AnswerPhrases(**lists)


@lru_cache(maxsize=1)
def answer_phrases() -> AnswerPhrases:
    """The shipped answer phrases (read once)."""
    return load_answer_phrases()


YES_WORDS = frozenset(answer_phrases().yes)
NO_WORDS = frozenset(answer_phrases().no)


def _jsgf() -> str:
    phrases = answer_phrases()

    def alt(items: tuple[str, ...]) -> str:
        return " | ".join(items)

    return (
        "#JSGF V1.0;\ngrammar answer;\n"
        f"<answer_phrase> = {alt(phrases.yes + phrases.no)};\n"
        f"public <answer> = [ {alt(phrases.openers)} ] <answer_phrase> [ <answer_phrase> ]"
        f" [ {alt(phrases.closers)} ];\n"
    )


#: JSGF grammar for a yes/no answer.
YES_NO_GRAMMAR = _jsgf()


def parse_answer(text: str, phrases: AnswerPhrases | None = None) -> bool | None:
    """True for yes, False for no, None when the answer is neither, both, or unsure."""
    table = phrases or answer_phrases()
    kinds = {p: "unsure" for p in table.unsure} | {p: "yes" for p in table.yes} | {p: "no" for p in table.no}
    longest = max(len(p.split()) for p in kinds)
    words = normalize(text).split()
    found: set[str] = set()
    index = 0
    while index < len(words):
        for size in range(min(longest, len(words) - index), 0, -1):
            kind = kinds.get(" ".join(words[index : index + size]))
            if kind is not None:
                found.add(kind)
                index += size
                break
        else:
            index += 1
    if "unsure" in found or ("yes" in found) == ("no" in found):
        return None
    return "yes" in found
