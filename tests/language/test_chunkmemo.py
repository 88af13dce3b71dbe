"""The reader's chunker remembers each token list's chunks (knic.language.chunkmemo): the same chunks as the
plain chunker, a list of its own for each caller, and the reader reads the same."""

from __future__ import annotations

from knic.language.chunkmemo import RememberedChunker
from knic.language.chunks import Chunker
from knic.language.reader import Reader
from knic.language.understanding import reader_for
from knic.language.vocabulary import Vocabulary


def test_remembered_chunks_are_the_plain_chunkers_and_each_caller_gets_its_own_list(
    vocabulary: Vocabulary,
) -> None:
    reader = reader_for(vocabulary)
    plain, remembered = Chunker(vocabulary, reader.language), RememberedChunker(vocabulary, reader.language)
    said = "bring me the mug from the kitchen table and switch off the hallway light"
    words = said.split(" ")
    first = remembered.chunks(words)
    assert first == plain.chunks(words)
    first.clear()  # a caller changes its list: the next caller's is whole
    again = remembered.chunks(words)
    assert again == plain.chunks(words) and again is not first
    assert remembered.chunks(tuple(words)) == again  # a tuple of the same words is the same list


def test_the_reader_reads_the_same_with_its_chunks_remembered(vocabulary: Vocabulary) -> None:
    said = "could you take the apple to the kitchen table, then turn the dimmer down to thirty percent"
    fresh = Reader(vocabulary)
    assert isinstance(fresh.chunker, RememberedChunker)
    first = fresh.read(said)
    assert fresh.read(said) == first
    assert [frame.kind for frame in first.frames] == ["BRINGING", "OPERATING"]
