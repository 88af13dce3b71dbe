"""Whisper's front end in numpy: the log-mel spectrogram its encoder reads (:mod:`knic.language.whisperpass`).

A Hann window of 400 samples, hop 160, 80 Slaney-scale mel bands, log10 clamped 8 below the maximum, scaled
by 4, as Whisper computes them.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

#: Whisper's front end
SAMPLE_RATE, N_FFT, HOP, N_MELS = 16000, 400, 160, 80


@lru_cache(maxsize=2)
def mel_filters(n_mels: int = N_MELS) -> npt.NDArray[np.float32]:
    """Triangular filters on the Slaney mel scale (linear below 1 kHz, logarithmic above), each normalised
    to unit area, as a ``(n_mels, N_FFT // 2 + 1)`` matrix."""
    import numpy as np

    def to_hz(mel: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        linear = 200.0 / 3 * mel
        knee = 15.0  # 1 kHz in mels
        return np.where(mel < knee, linear, 1000.0 * np.exp(math.log(6.4) / 27.0 * (mel - knee)))

    top = 3 * math.log(SAMPLE_RATE / 2 / 1000.0) / math.log(6.4) * 9 + 15.0  # Nyquist in mels
    edges = to_hz(np.linspace(0.0, top, n_mels + 2))
    bins = np.linspace(0.0, SAMPLE_RATE / 2, N_FFT // 2 + 1)
    rising = (bins[None, :] - edges[:-2, None]) / (edges[1:-1] - edges[:-2])[:, None]
    falling = (edges[2:, None] - bins[None, :]) / (edges[2:] - edges[1:-1])[:, None]
    weights = np.maximum(0.0, np.minimum(rising, falling))
    weights *= (2.0 / (edges[2:] - edges[:-2]))[:, None]
    return weights.astype(np.float32)


def log_mel(samples: npt.NDArray[np.float32]) -> npt.NDArray[np.float32]:
    """Whisper's log-mel spectrogram of 16 kHz samples in [-1, 1]: ``(N_MELS, len(samples) // HOP)``.

    The frames of the silence an utterance is padded with (:mod:`knic.language.whisperpass`) are not
    transformed: all zeros, their bands take the floor value, as a transform would give them (the same
    features, in about half the time for a command of 2.5 s in a window of 8 s)."""
    import numpy as np

    padded = np.pad(samples.astype(np.float32), N_FFT // 2, mode="reflect")
    frames = 1 + (len(padded) - N_FFT) // HOP
    sounding = np.flatnonzero(padded)
    # frames from the first whose window starts after the last sample that is not zero are silent
    needed = min(frames, int(sounding[-1]) // HOP + 1) if len(sounding) else 0
    index = np.arange(N_FFT)[None, :] + HOP * np.arange(needed)[:, None]
    window = (0.5 - 0.5 * np.cos(2 * np.pi * np.arange(N_FFT) / N_FFT)).astype(np.float32)
    power = np.zeros((frames, N_FFT // 2 + 1))
    power[:needed] = np.abs(np.fft.rfft(padded[index] * window, axis=1)) ** 2
    mel = mel_filters() @ power[:-1].T.astype(np.float32)
    logs = np.log10(np.maximum(mel, 1e-10))
    logs = np.maximum(logs, logs.max() - 8.0)
    return ((logs + 4.0) / 4.0).astype(np.float32)
