"""Audio for the recognisers: WAV files to the decoders' 16 kHz mono 16-bit PCM, silence padding, and what a
recogniser heard (:class:`Transcript`).

WAV files only (RIFF/WAVE, integer PCM of 8, 16, 24 or 32 bits or IEEE float of 32 or 64 bits, any rate, any
channel count). Audio is mixed down to mono and resampled in-process to the acoustic model's 16 kHz
(windowed-sinc low-pass, then linear interpolation). Anything else raises :class:`~core.errors.AudioError`
before a decoder is touched.

A file already in the model's format (16 kHz, mono, 16-bit PCM: what the project's recordings and a
microphone capture at the model rate give) is read without numpy (:func:`load_pcm`): importing numpy is a
fifth of a one-shot ``knic say``'s budget. Everything else goes through numpy (:func:`read_wav`,
:func:`to_model_audio`).
"""

from __future__ import annotations

import random
import struct
import sys
from array import array
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from core.errors import AudioError

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

#: The acoustic model's sample rate (Hz).
MODEL_RATE = 16000
#: Silence added before and after the audio (s): the grammar search needs trailing silence to finish the
#: last word.
LEAD_SILENCE = 0.2
TRAIL_SILENCE = 0.5
#: The padding's faint noise: integers drawn uniformly from -PAD_NOISE..PAD_NOISE (about 3 LSB RMS).
PAD_NOISE = 5


@dataclass(frozen=True)
class Transcript:
    """What the recogniser heard.

    Attributes:
        text: the best hypothesis (lowercase words); "" when nothing matched the grammar at all.
        in_grammar: False when the hypothesis went through the filler loop or nothing was decoded.
        score: the decoder's path score for the hypothesis (log domain, larger is better; 0 when empty).
        duration: audio length before padding (s).
        decode_ms: wall-clock decoding time (ms).
    """

    text: str
    in_grammar: bool
    score: float
    duration: float
    decode_ms: float


def _wav_parts(path: Path) -> tuple[int, int, int, int, bytes]:
    """``(format tag, channels, rate, bits, sample bytes)`` of a WAV file, header checked.

    Raises:
        AudioError: the file is missing, not RIFF/WAVE, or lacks its 'fmt ' or 'data' chunk.
    """
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise AudioError(f"{path}: cannot read audio file: {exc.strerror or exc}") from exc
    if len(data) < 12 or data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        raise AudioError(f"{path}: not a WAV file (RIFF/WAVE header missing); only WAV audio is accepted")
    fmt: tuple[int, int, int, int] | None = None
    pcm: bytes | None = None
    offset = 12
    while offset + 8 <= len(data):
        chunk_id, size = data[offset : offset + 4], struct.unpack("<I", data[offset + 4 : offset + 8])[0]
        body = data[offset + 8 : offset + 8 + size]
        if chunk_id == b"fmt " and len(body) >= 16:
            tag, channels, rate, _, _, bits = struct.unpack("<HHIIHH", body[:16])
            if tag == 0xFFFE and len(body) >= 26:  # WAVE_FORMAT_EXTENSIBLE: the sub-format's first two bytes
                tag = struct.unpack("<H", body[24:26])[0]
            fmt = (tag, channels, rate, bits)
        elif chunk_id == b"data":
            pcm = body
        offset += 8 + size + (size & 1)
    if fmt is None or pcm is None:
        raise AudioError(f"{path}: WAV file without a 'fmt ' or 'data' chunk")
    tag, channels, rate, bits = fmt
    if channels < 1 or rate < 1000:
        raise AudioError(f"{path}: implausible WAV header ({channels} channels, {rate} Hz)")
    return tag, channels, rate, bits, pcm


def read_wav(path: str | Path) -> tuple[npt.NDArray[np.float64], int]:
    """Read a WAV file as float samples in [-1, 1], shape (frames, channels), and its sample rate (Hz).

    Raises:
        AudioError: the file is missing, not RIFF/WAVE, uses an unsupported encoding, or holds no samples.
    """
    path = Path(path)
    tag, channels, rate, bits, pcm = _wav_parts(path)
    samples = _decode_samples(path, pcm, tag, bits)
    usable = len(samples) - len(samples) % channels
    if usable == 0:
        raise AudioError(f"{path}: WAV file holds no audio samples")
    return samples[:usable].reshape(-1, channels), rate


def _decode_samples(path: Path, pcm: bytes, tag: int, bits: int) -> npt.NDArray[np.float64]:
    import numpy as np

    if tag == 1 and bits == 8:
        return (np.frombuffer(pcm, dtype=np.uint8).astype(np.float64) - 128.0) / 128.0
    if tag == 1 and bits == 16:
        return np.frombuffer(pcm[: len(pcm) // 2 * 2], dtype="<i2").astype(np.float64) / 32768.0
    if tag == 1 and bits == 24:
        raw = np.frombuffer(pcm[: len(pcm) // 3 * 3], dtype=np.uint8).reshape(-1, 3).astype(np.int32)
        values = raw[:, 0] | (raw[:, 1] << 8) | (raw[:, 2] << 16)
        values = np.where(values >= 1 << 23, values - (1 << 24), values)
        return values.astype(np.float64) / float(1 << 23)
    if tag == 1 and bits == 32:
        return np.frombuffer(pcm[: len(pcm) // 4 * 4], dtype="<i4").astype(np.float64) / float(1 << 31)
    if tag == 3 and bits in (32, 64):
        dtype = "<f4" if bits == 32 else "<f8"
        size = bits // 8
        return np.clip(
            np.frombuffer(pcm[: len(pcm) // size * size], dtype=dtype).astype(np.float64), -1.0, 1.0
        )
    raise AudioError(f"{path}: unsupported WAV encoding (format tag {tag}, {bits} bits); use PCM or float")


def to_model_audio(samples: npt.NDArray[np.float64], rate: int) -> npt.NDArray[np.int16]:
    """Mix down to mono, resample to :data:`MODEL_RATE` and convert to 16-bit PCM.

    Args:
        samples: float samples in [-1, 1], shape (frames,) or (frames, channels).
        rate: their sample rate (Hz).
    """
    import numpy as np

    mono = samples.mean(axis=1) if samples.ndim == 2 else samples
    if rate != MODEL_RATE:
        mono = resample(mono, rate, MODEL_RATE)
    return np.asarray(np.clip(np.round(mono * 32767.0), -32768, 32767), dtype=np.int16)


def resample(signal: npt.NDArray[np.float64], rate: int, target: int) -> npt.NDArray[np.float64]:
    """Resample a mono signal: windowed-sinc low-pass below the lower Nyquist rate, then linear interpolation.

    Args:
        signal: mono samples.
        rate: their rate (Hz).
        target: the wanted rate (Hz).
    """
    import numpy as np

    if rate == target or len(signal) == 0:
        return signal
    if target < rate:
        cutoff = 0.45 * target / rate  # cycles per input sample, a little under the new Nyquist rate
        taps = np.arange(-32, 33)
        kernel = 2 * cutoff * np.sinc(2 * cutoff * taps) * np.hamming(len(taps))
        signal = np.convolve(signal, kernel / kernel.sum(), mode="same")
    count = max(1, round(len(signal) * target / rate))
    positions = np.arange(count) * (rate / target)
    return np.interp(positions, np.arange(len(signal)), signal)


def load_audio(path: str | Path) -> npt.NDArray[np.int16]:
    """A WAV file as 16 kHz mono 16-bit samples ready for the decoder (no padding).

    Raises:
        AudioError: as :func:`read_wav`.
    """
    import numpy as np

    return np.frombuffer(load_pcm(path), dtype="<i2").astype(np.int16)


#: the longest recording ``knic say`` takes as one spoken command; a 36 s recording took 18 s to hear
MAX_COMMAND_S = 30.0


def command_pcm(path: str | Path) -> bytes:
    """A WAV file of one spoken command as :func:`load_pcm` returns it.

    Raises:
        AudioError: as :func:`read_wav`; the recording is longer than :data:`MAX_COMMAND_S`.
    """
    pcm = load_pcm(path)
    seconds = len(pcm) / 2 / MODEL_RATE
    if seconds > MAX_COMMAND_S:
        raise AudioError(
            f"{path}: {seconds:.1f} s of audio, and one spoken command is at most {MAX_COMMAND_S:.0f} s"
            " (knic listen --wav cuts a longer recording into utterances)"
        )
    return pcm


def load_pcm(path: str | Path) -> bytes:
    """A WAV file as the decoders' raw audio: 16 kHz mono 16-bit little-endian PCM bytes (no padding).

    Files already in that format are passed through without numpy.

    Raises:
        AudioError: as :func:`read_wav`.
    """
    path = Path(path)
    tag, channels, rate, bits, pcm = _wav_parts(path)
    if (tag, channels, rate, bits) == (1, 1, MODEL_RATE, 16):
        usable = pcm[: len(pcm) // 2 * 2]
        if not usable:
            raise AudioError(f"{path}: WAV file holds no audio samples")
        return usable
    samples, rate = read_wav(path)
    return to_model_audio(samples, rate).astype("<i2").tobytes()


def pcm_bytes(audio: str | Path | bytes | npt.NDArray[np.int16]) -> bytes:
    """The decoders' raw audio of a WAV path, raw bytes (as :func:`load_pcm` returns) or 16-bit samples."""
    if isinstance(audio, (str, Path)):
        return load_pcm(audio)
    if isinstance(audio, (bytes, bytearray, memoryview)):
        return bytes(audio)
    return bytes(audio.astype("<i2").tobytes())


@lru_cache(maxsize=1)
def _padding() -> tuple[bytes, bytes]:
    """The lead and trail padding: faint deterministic noise as 16-bit little-endian samples."""
    rng = random.Random(0)
    levels = [byte % (2 * PAD_NOISE + 1) - PAD_NOISE for byte in range(256)]

    def noise(seconds: float) -> bytes:
        values = array("h", map(levels.__getitem__, rng.randbytes(int(seconds * MODEL_RATE))))
        if sys.byteorder == "big":
            values.byteswap()
        return values.tobytes()

    return noise(LEAD_SILENCE), noise(TRAIL_SILENCE)


def pad_pcm(pcm: bytes, trail: float = TRAIL_SILENCE) -> bytes:
    """Add :data:`LEAD_SILENCE` and ``trail`` seconds (at most :data:`TRAIL_SILENCE`) of near-silence to raw
    audio.

    The padding is faint deterministic noise (:data:`PAD_NOISE`), not digital zeros: all-zero frames have no
    defined log energy and upset the decoder's cepstral normalisation.
    """
    lead, after = _padding()
    return lead + pcm + after[: 2 * int(min(trail, TRAIL_SILENCE) * MODEL_RATE)]


def pad(audio: npt.NDArray[np.int16]) -> npt.NDArray[np.int16]:
    """:func:`pad_pcm` for an array of samples."""
    import numpy as np

    return np.frombuffer(pad_pcm(pcm_bytes(audio)), dtype="<i2").astype(np.int16)


def duration_of(pcm: bytes) -> float:
    """Seconds of raw model-rate audio."""
    return len(pcm) / 2 / MODEL_RATE
