"""The reader's chunker, remembering each token list's chunks.

The reader's rules chunk the same words again and again while they try readings (on the spoken dev set's
candidate transcripts: 9,266 chunkings of 617 different token lists in 388 reads), and a chunking depends on
the tokens and the world only (:class:`~knic.language.chunks.Chunker` is not changed after it is built). Each
answer is kept, and a copy of the list is handed out (callers may change the list; they never change a
:class:`~knic.language.chunks.Chunk`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from knic.language.chunks import Chunk as Chunk  # the name the reader imports from here
from knic.language.chunks import Chunker

#: token lists whose chunks are kept (then all are forgotten and it starts again)
KEPT = 8192


class RememberedChunker(Chunker):
    """:class:`~knic.language.chunks.Chunker` whose :meth:`chunks` remembers each token list's answer."""

    def __init__(self, *args: Any, **kwargs: Any):
        super().__init__(*args, **kwargs)
        self._chunked: dict[tuple[str, ...], list[Chunk]] = {}

    def chunks(self, tokens: Sequence[str]) -> list[Chunk]:
        key = tuple(tokens)
        found = self._chunked.get(key)
        if found is None:
            if len(self._chunked) >= KEPT:
                self._chunked.clear()
            found = self._chunked[key] = super().chunks(key)
        return list(found)
