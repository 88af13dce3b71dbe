"""How many of a kind a plural means: every one, or a question.

* "all of them", "both of them", "each of them", "every one of them" said right after plural names ("the
  lights, all of them, off"), or "all"/"both" alone before a state ("the lamps both off"), is said again
  before the things, where the reader counts it ("all the lights off"), not dropped: so the things are all
  meant because the speaker said so, not only because a plural was said.
* A plural said alone of devices in several rooms ("open the blinds" in a home with a blind in five rooms)
  asks which, offering all of them: blind writers of four dev sets (people19, people24-26) each expected a
  question there, not every blind and an awning opened. A plural of devices in one room ("turn on the lamps"
  for the two bedside lamps) is still every one, and a plural the world groups ("the lights": all_lights) is
  the group.
"""

from __future__ import annotations

from collections.abc import Sequence

from knic.language.chains import AmbiguityError
from knic.language.clauses import Arg
from knic.language.vocabulary import Vocabulary

#: a quantifier said after the things it counts ("the lights, all of them"; "the lamps both off")
_AFTER_THINGS = (
    ("all", "of", "them"),
    ("both", "of", "them"),
    ("each", "of", "them"),
    ("every", "one", "of", "them"),
)
#: words that open a noun phrase before a plural ("the", "my", "those")
_OPENINGS = frozenset({"the", "my", "your", "his", "her", "our", "their", "these", "those"})


def _plural_name(word: str, heads: set[str]) -> bool:
    """Whether a word is a plural of the names whose last words are ``heads`` ("lights", "lamps")."""
    if not word.endswith("s"):
        return False
    return word in heads or word[:-1] in heads


def _said_before(words: list[str], end: int, quantifier: str) -> None:
    """Put ``quantifier`` before the noun phrase whose last word is ``words[end - 1]`` ("the lights": "all
    the lights")."""
    start = end - 1
    while start and words[start - 1] in _OPENINGS:
        start -= 1
    words.insert(start, quantifier)


def all_of_them(words: list[str], before: list[str], heads: set[str]) -> list[str]:
    """``words`` with "all of them" (or "both", "all" alone before a state) said right after plural names
    put before those names instead; ``before`` is the sentence before, changed in place where the names end
    it ("the lights, all of them, off")."""
    for i in range(len(words)):
        last = words[i - 1] if i else (before[-1] if before else "")
        if not _plural_name(last, heads):
            continue
        said = next((len(q) for q in _AFTER_THINGS if tuple(words[i : i + len(q)]) == q), 0)
        floating = words[i] in ("all", "both") and (i + 1 == len(words) or words[i + 1] in ("on", "off"))
        if said or floating:
            quantifier = "both" if words[i] == "both" else "all"
            out = [*words[:i], *words[i + (said or 1) :]]
            if i:
                _said_before(out, i, quantifier)
            else:
                _said_before(before, len(before), quantifier)
            return out
    return words


def every_one(arg: Arg, symbols: Sequence[str], vocabulary: Vocabulary) -> list[str]:
    """The devices a plural names, all of them ("turn on the lamps"), unless said alone ("all" not said) of
    devices in more than one room ("open the blinds" in a home with blinds in five rooms).

    Raises:
        AmbiguityError: which of them is meant, offering all of them.
    """
    devices = [s for s in symbols if vocabulary.is_of(s, "device")]
    rooms = {r for s in devices for r in vocabulary.locations.get(s, ())}
    if not arg.plural or len(devices) != len(symbols) or len(rooms) < 2:
        return list(symbols)
    options = [f"the {vocabulary.phrase_of(s)}" for s in symbols]
    raise AmbiguityError(
        f"which {arg.chunk.text} do you mean: {', '.join(options[:-1])}, {options[-1]} or all of them?"
    )
