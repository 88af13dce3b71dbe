"""Where from and where to said in two stretches before a verb said last ("porridge oats from larder, on
kitchen island put", a learner's order: Korean, Japanese, Turkish and German speakers put the verb last): one
stretch, so that :mod:`knic.language.selecting` reads it as "put the porridge oats from the larder on the
kitchen island", where the larder was looked for on the island (:func:`onto_joined`)."""

from __future__ import annotations

#: the verbs that end such a request, said last
_PUT_LAST = frozenset({"put", "place", "bring", "take", "leave", "keep", "set", "move"})
#: what says where to at the start of the second stretch
_ONTO = frozenset({"on", "onto", "in", "into", "inside"})


def onto_joined(segments: list[list[str]]) -> list[list[str]]:
    """``segments`` with a stretch that says where from last ("... from larder") and the next, which says
    where to first and ends with the verb ("on kitchen island put"), made one; the others as said."""
    out: list[list[str]] = []
    for segment in segments:
        put_last = segment[-1:] and segment[-1] in _PUT_LAST and segment[0] in _ONTO
        if out and put_last and "from" in out[-1][-4:-1] and out[-1][0] != "from":
            out[-1] = [*out[-1], *segment]
        else:
            out.append(list(segment))
    return out


__all__ = ["onto_joined"]
