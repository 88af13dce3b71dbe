"""A request said again at once, shorter, for weight (people39: "beta, suno, bring my gita, bring it"; "open
them, open them fully" is said again with more, and stays):

* a sentence that is only the verb of the sentence before and "it" or "them" (with "please", "here", "now",
  "na" after it), straight after that sentence, asks nothing more: dropped, where "bring my gita, bring it"
  was read as a taking and then a bringing.

Used by :func:`knic.language.household.ones_named`, on the sentences of a command (:func:`asked_twice`).
"""

from __future__ import annotations

#: the words that point back at what the sentence before named
_POINTING = frozenset({"it", "them"})
#: what may be said after the pointing word without saying more
_BARE = frozenset({"please", "here", "now", "na", "quickly", "fast", "pls", "plz"})


def asked_twice(segments: list[list[str]]) -> list[list[str]]:
    """``segments`` without a sentence that only says the verb of the one before again with "it" (see the
    module docstring)."""
    out: list[list[str]] = []
    for segment in segments:
        before = out[-1] if out else []
        if (
            len(segment) >= 2
            and len(before) > 2
            and segment[0] == before[0]
            and segment[1] in _POINTING
            and _POINTING.isdisjoint(before)
            and all(word in _BARE for word in segment[2:])
        ):
            continue
        out.append(segment)
    return out


__all__ = ["asked_twice"]
