"""Spoken goals uploaded through the page: a WAV file decoded in memory and recognised with pocketsphinx.

Nothing of an upload touches the file system: the bytes are parsed here (PCM WAV, 8/16/32-bit integer),
converted to the recogniser's 16 kHz mono samples (:func:`knic.language.speech.to_model_audio`) and decoded
against the run's command grammar, or against the yes/no grammar while the robot waits for an answer. The
transcript then goes through the goal intake like typed text.
"""

from __future__ import annotations

import io
import threading
import wave
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from core.errors import AudioError, LanguageError

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary

#: longest upload accepted, seconds of audio
MAX_SECONDS = 30.0


def decode_wav(data: bytes) -> npt.NDArray[np.int16]:
    """PCM WAV bytes as 16 kHz mono 16-bit samples.

    Raises:
        AudioError: not a PCM WAV file, no samples, or longer than :data:`MAX_SECONDS`.
    """
    from knic.language.audio import to_model_audio

    if len(data) < 12 or data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        raise AudioError("upload: not a WAV file (RIFF/WAVE header missing)")
    try:
        with wave.open(io.BytesIO(data), "rb") as wav:
            channels, width, rate = wav.getnchannels(), wav.getsampwidth(), wav.getframerate()
            frames = wav.getnframes()
            if rate < 1000 or channels < 1:
                raise AudioError(f"upload: implausible WAV header ({channels} channels, {rate} Hz)")
            if frames > MAX_SECONDS * rate:
                raise AudioError(f"upload: {frames / rate:.1f} s of audio; at most {MAX_SECONDS:g} s")
            pcm = wav.readframes(frames)
    except (wave.Error, EOFError) as exc:
        raise AudioError(f"upload: not a PCM WAV file ({exc})") from None
    if width == 1:
        samples = (np.frombuffer(pcm, dtype=np.uint8).astype(np.float64) - 128.0) / 128.0
    elif width == 2:
        samples = np.frombuffer(pcm[: len(pcm) // 2 * 2], dtype="<i2").astype(np.float64) / 32768.0
    elif width == 4:
        samples = np.frombuffer(pcm[: len(pcm) // 4 * 4], dtype="<i4").astype(np.float64) / float(1 << 31)
    else:
        raise AudioError(f"upload: {8 * width}-bit WAV samples are not supported; use 8, 16 or 32-bit PCM")
    usable = len(samples) - len(samples) % channels
    if usable == 0:
        raise AudioError("upload: the WAV file holds no audio samples")
    return to_model_audio(samples[:usable].reshape(-1, channels), rate)


class SpeechInput:
    """Recognises uploaded commands and answers for one run (recognisers built on first use, then reused).

    Safe to call from several threads: one decode at a time.

    Args:
        vocabulary: the run's spoken names (the command grammar is built from it).
    """

    def __init__(self, vocabulary: Vocabulary) -> None:
        self.vocabulary = vocabulary
        self._lock = threading.Lock()
        self._command: Any = None
        self._answer: Any = None

    def transcribe(self, data: bytes, *, answer: bool = False) -> str:
        """The words of an uploaded WAV: a command, or (``answer``) a yes/no answer.

        Raises:
            AudioError: not usable audio.
            LanguageError: no command of the grammar was recognised.
        """
        audio = decode_wav(data)
        with self._lock:
            if answer:
                if self._answer is None:
                    from knic.language.speech import AnswerRecognizer

                    self._answer = AnswerRecognizer()
                return str(self._answer.recognize(audio))
            if self._command is None:
                from knic.language.lmspeech import command_recognizer

                self._command = command_recognizer(self.vocabulary)
            transcript = self._command.recognize(audio)
        if not transcript.text or not transcript.in_grammar:
            heard = f' (heard "{transcript.text}")' if transcript.text else ""
            raise LanguageError(f"upload: no command recognised{heard}")
        return str(transcript.text)
