"""Continuous listening: a live 16 kHz mono 16-bit PCM stream cut into utterances, each recognised.

A microphone, a pipe or a replayed recording all arrive as a byte stream of raw PCM. pocketsphinx's
voice-activity endpointer (:class:`pocketsphinx.Endpointer`, WebRTC-style VAD over 30 ms frames) finds where
speech starts and ends; each utterance goes to a :class:`~knic.language.speech.Recognizer` whole, so a live
utterance is decoded exactly as a file of the same audio would be. An utterance longer than ``max_seconds``
is cut there (a stuck-open endpointer must not hold audio forever).

Sources (:func:`open_source`): ``arecord`` from ALSA's utilities for the default microphone, standard input
for any other recorder (``sox -d -t raw -r 16000 -c 1 -b 16 -e signed -``), or a WAV file replayed as a
stream.
"""

from __future__ import annotations

import io
import shutil
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from typing import BinaryIO, cast

import numpy as np
import numpy.typing as npt

from core.errors import AudioError
from knic.language.audio import MODEL_RATE, load_audio

#: The command that records the default microphone as raw 16 kHz mono 16-bit PCM.
MICROPHONE_COMMAND = ["arecord", "-q", "-t", "raw", "-f", "S16_LE", "-r", str(MODEL_RATE), "-c", "1"]


@dataclass(frozen=True)
class Segment:
    """One utterance found in a stream.

    Attributes:
        start: where speech started, seconds from the start of the stream.
        end: where it ended (s).
        audio: its 16 kHz mono samples.
    """

    start: float
    end: float
    audio: npt.NDArray[np.int16]


def segments(
    stream: BinaryIO, *, window: float = 0.3, ratio: float = 0.9, max_seconds: float = 15.0
) -> Iterator[Segment]:
    """Cut a raw PCM stream (16 kHz, mono, signed 16-bit little-endian) into utterances as it arrives.

    Args:
        stream: the byte stream; read in 30 ms frames until it ends.
        window: the endpointer's decision window (s).
        ratio: share of the window that must be speech (or silence) to switch state.
        max_seconds: longest utterance; longer speech is cut into pieces of this length.
    """
    from pocketsphinx import Endpointer

    endpointer = Endpointer(window=window, ratio=ratio, sample_rate=MODEL_RATE)
    size = endpointer.frame_bytes
    pieces: list[bytes] = []
    start = 0.0
    read = 0
    limit = int(max_seconds * MODEL_RATE) * 2

    def cut(end: float) -> Segment:
        audio = np.frombuffer(b"".join(pieces), dtype="<i2").astype(np.int16)
        pieces.clear()
        return Segment(start, end, audio)

    while True:
        frame = stream.read(size)
        read += len(frame)
        if len(frame) < size:
            speech = endpointer.end_stream(frame + b"\0" * (size - len(frame)) if frame else b"")
            if speech is not None:
                pieces.append(speech)
            if pieces:
                yield cut(read / 2 / MODEL_RATE)
            return
        was_speaking = endpointer.in_speech
        speech = endpointer.process(frame)
        if speech is None:
            continue
        if not was_speaking or not pieces:
            start = endpointer.speech_start if not was_speaking else read / 2 / MODEL_RATE
        pieces.append(speech)
        if not endpointer.in_speech:
            yield cut(endpointer.speech_end)
        elif sum(len(p) for p in pieces) >= limit:
            yield cut(read / 2 / MODEL_RATE)


def open_source(
    *, stdin: bool = False, wav: str | None = None
) -> tuple[BinaryIO, subprocess.Popen[bytes] | None]:
    """The PCM stream to listen to: a WAV file replayed, standard input, or the default microphone.

    Returns:
        (stream, recorder process to stop afterwards, or None).

    Raises:
        AudioError: the WAV file is unusable, or there is no recorder for a microphone.
    """
    if wav is not None:
        return io.BytesIO(load_audio(wav).astype("<i2").tobytes()), None
    if stdin:
        return sys.stdin.buffer, None
    if shutil.which(MICROPHONE_COMMAND[0]) is None:
        raise AudioError(
            "no microphone recorder: install alsa-utils (arecord), or pipe 16 kHz mono 16-bit PCM into "
            "'knic listen --stdin'"
        )
    process = subprocess.Popen(MICROPHONE_COMMAND, stdout=subprocess.PIPE)
    if process.stdout is None:  # pragma: no cover - stdout=PIPE always gives a stream
        raise AudioError("the microphone recorder gave no output stream")
    return cast(BinaryIO, process.stdout), process
