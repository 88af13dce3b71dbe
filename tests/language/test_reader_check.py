"""The recogniser's check of whether the reader reads a transcript (``reader_check``) answers as the reader
does, and reads each text once: a spoken command's candidates repeat (n-best lists, Whisper's beam)."""

from __future__ import annotations

from typing import Any

import pytest

from knic.language import understanding
from knic.language.understanding import reader_check, reader_for
from knic.language.vocabulary import Vocabulary


class _Counting:
    """A reader that counts its readings."""

    def __init__(self, reader: Any):
        self.reader, self.read_texts = reader, []  # type: ignore[var-annotated]

    def read(self, text: str) -> Any:
        self.read_texts.append(text)
        return self.reader.read(text)


@pytest.mark.parametrize(
    ("text", "read"),
    [
        ("bring me the mug", True),
        ("bring me the cup", True),  # a question back (which cup?) is understood
        ("how are you today", False),
        ("bring me the banana", False),
    ],
)
def test_each_text_is_read_once_and_answered_as_the_reader_does(
    vocabulary: Vocabulary, text: str, read: bool
) -> None:
    counting = _Counting(reader_for(vocabulary))
    reads = reader_check(counting)  # type: ignore[arg-type]
    assert [reads(text), reads(text), reads(text)] == [read] * 3
    assert counting.read_texts == [text]


def test_what_is_remembered_is_bounded(vocabulary: Vocabulary, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(understanding, "READS_KEPT", 2)
    counting = _Counting(reader_for(vocabulary))
    reads = reader_check(counting)  # type: ignore[arg-type]
    for text in ["bring me the mug", "go to the kitchen", "find tracy", "bring me the mug"]:
        assert reads(text)
    assert counting.read_texts == ["bring me the mug", "go to the kitchen", "find tracy", "bring me the mug"]
