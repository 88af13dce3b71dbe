"""Things said in a list and then gathered up by "all" or "both" before where they go ("fruit bowl and
laptop, both to the sitting room", "bread, butter, clotted cream: all to the dining table", a list read out):
the list is what is meant, so "all" and "both" are dropped, as they are after "them" ("bring them both to
the kitchen", :mod:`knic.language.contracted`). Said after a verb or a pronoun ("bring all to the kitchen",
"put both in the sink") they still ask which things. Said after a comma or a colon, the stretch before is
the list (:func:`gathered_up`)."""

from __future__ import annotations

#: where the gathered things go
_GOING = frozenset({"to", "in", "into", "on", "onto"})
#: words before "all"/"both" that make it no gathering of a list said before it
_NO_LIST = frozenset(
    {"it", "them", "em", "they", "you", "me", "us", "and", "of", "the", "a", "my", "these", "those", "this"}
    | {"that", "up", "down", "out", "back", "please", "bring", "take", "put", "move", "carry", "fetch", "get"}
    | {"grab", "give", "send", "pick", "place", "leave", "drop", "them", "we", "i", "is", "are", "at"}
)


def gathered(tokens: list[str]) -> list[str]:
    """``tokens`` without an "all" or "both" that gathers up a list of things said before it."""
    out: list[str] = []
    for i, token in enumerate(tokens):
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
        if token in ("all", "both") and nxt in _GOING and len(out) >= 2 and out[-1] not in _NO_LIST:
            continue
        out.append(token)
    return out


def gathered_up(segments: list[list[str]]) -> list[list[str]]:
    """The stretches of a command that are not empty, one opening with "all" or "both" before where things go
    ("bread butter clotted cream" | "all to the dining table") joined to the list said in the stretch before
    it, when that ends with no verb or pronoun."""
    out: list[list[str]] = []
    for segment in segments:
        if not segment:
            continue
        if (
            out
            and segment[0] in ("all", "both")
            and segment[1:2]
            and segment[1] in _GOING
            and out[-1][-1] not in _NO_LIST
        ):
            out[-1] = out[-1] + segment[1:]
            continue
        out.append(segment)
    return out
