"""Steps said one after another with less than a whole sentence each, as people give a robot a route or a
list of jobs ("go to the bedroom, then the kitchen", "navigate to the living room, then, um, to the dining
room, and grab the candle").

Called from :func:`knic.language.learners.learners_read` on the chunks of a command.
"""

from __future__ import annotations

from knic.language.chunks import Chunk
from knic.language.vocabulary import Vocabulary


def steps_read(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """The chunks with the steps of this module said whole."""
    return goings_repeated(chunks, vocabulary)


def goings_repeated(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "go to the bedroom, then the kitchen", "go to the hallway then to the study": a room or a piece of
    furniture said after "then" with no verb of its own, once the robot was sent to a place, is a second
    going, there (the verb said again), not the first place corrected ("no, the kitchen" still corrects)."""
    out: list[Chunk] = []
    going: Chunk | None = None
    placed = False  # the going has a place already
    for i, chunk in enumerate(chunks):
        out.append(chunk)
        if chunk.kind == "verb":
            going, placed = (chunk if chunk.frames[:1] == ("MOTION",) else None), False
        elif going is not None and _place(chunk, vocabulary):
            placed = True
        elif going is not None and placed and chunk.kind == "join" and "then" in chunk.text.split():
            at = i + 1
            at += at < len(chunks) and chunks[at].kind == "prep" and chunks[at].role == "goal"
            at += at < len(chunks) and chunks[at].kind == "det"
            if at < len(chunks) and _place(chunks[at], vocabulary):
                out.append(going)
                placed = False
    return out


def _place(chunk: Chunk, vocabulary: Vocabulary) -> bool:
    """Whether a chunk names only rooms and pieces of furniture."""
    return (
        chunk.kind == "entity"
        and bool(chunk.terms)
        and all(any(vocabulary.is_subtype(t.type, k) for k in ("room", "furniture")) for t in chunk.terms)
    )
