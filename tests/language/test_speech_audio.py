"""Audio input: WAV encodings, rates and channel counts converted in-process; anything else refused."""

from __future__ import annotations

import struct
import wave
from pathlib import Path

import numpy as np
import pytest

from core.errors import AudioError
from knic.language.audio import MODEL_RATE, load_audio, pad, read_wav, resample

from .conftest import SPEECH_FIXTURES


def write_wav(path: Path, samples: np.ndarray, rate: int, *, tag: int = 1, bits: int = 16) -> Path:
    """Write a RIFF/WAVE file by hand (any tag and width), samples shaped (frames, channels) in [-1, 1]."""
    _, channels = samples.shape
    if tag == 3:
        data = samples.astype("<f4" if bits == 32 else "<f8").tobytes()
    elif bits == 8:
        data = np.round(samples * 127 + 128).astype(np.uint8).tobytes()
    elif bits == 24:
        ints = np.round(samples * (2**23 - 1)).astype("<i4").reshape(-1)
        data = b"".join(int(v).to_bytes(3, "little", signed=True) for v in ints)
    else:
        data = np.round(samples * (2 ** (bits - 1) - 1)).astype(f"<i{bits // 8}").tobytes()
    block = channels * bits // 8
    fmt = struct.pack("<HHIIHH", tag, channels, rate, rate * block, block, bits)
    body = (
        b"WAVE" + b"fmt " + struct.pack("<I", len(fmt)) + fmt + b"data" + struct.pack("<I", len(data)) + data
    )
    path.write_bytes(b"RIFF" + struct.pack("<I", len(body)) + body)
    return path


def tone(rate: int, seconds: float = 0.5, hz: float = 440.0, channels: int = 1) -> np.ndarray:
    t = np.arange(int(rate * seconds)) / rate
    mono = 0.5 * np.sin(2 * np.pi * hz * t)
    return np.stack([mono] * channels, axis=1)


@pytest.mark.parametrize(("tag", "bits"), [(1, 8), (1, 16), (1, 24), (1, 32), (3, 32), (3, 64)])
def test_every_pcm_and_float_width_reads_back(tmp_path: Path, tag: int, bits: int) -> None:
    original = tone(16000)
    samples, rate = read_wav(write_wav(tmp_path / "a.wav", original, 16000, tag=tag, bits=bits))
    assert rate == 16000 and samples.shape == original.shape
    assert np.max(np.abs(samples - original)) < (0.02 if bits == 8 else 1e-3)


def test_stereo_44k_is_mixed_down_and_resampled(tmp_path: Path) -> None:
    stereo = tone(44100, seconds=1.0, channels=2)
    stereo[:, 1] = 0.0  # mono mix halves the amplitude
    audio = load_audio(write_wav(tmp_path / "s.wav", stereo, 44100))
    assert audio.dtype == np.int16 and abs(len(audio) - MODEL_RATE) <= 1
    spectrum = np.abs(np.fft.rfft(audio.astype(float)))
    assert abs(np.argmax(spectrum) * MODEL_RATE / len(audio) - 440.0) < 2.0  # the tone keeps its pitch
    assert 0.2 * 32767 < np.max(np.abs(audio)) < 0.3 * 32767


def test_8k_is_upsampled(tmp_path: Path) -> None:
    audio = load_audio(write_wav(tmp_path / "n.wav", tone(8000, seconds=0.5), 8000))
    assert abs(len(audio) - MODEL_RATE // 2) <= 1


def test_resampling_removes_content_above_the_new_nyquist_rate() -> None:
    high = tone(48000, seconds=1.0, hz=12000.0)[:, 0]
    assert np.max(np.abs(resample(high, 48000, 16000))[100:-100]) < 0.05


def test_committed_fixture_reads_as_16k_mono() -> None:
    with wave.open(str(SPEECH_FIXTURES / "cmd_011.wav")) as handle:
        assert (handle.getframerate(), handle.getnchannels(), handle.getsampwidth()) == (16000, 1, 2)
    audio = load_audio(SPEECH_FIXTURES / "cmd_011.wav")
    assert len(pad(audio)) == len(audio) + int(0.7 * MODEL_RATE)


def test_non_wav_is_refused(tmp_path: Path) -> None:
    mp3 = tmp_path / "command.mp3"
    mp3.write_bytes(b"ID3\x03\x00\x00\x00" + bytes(200))
    with pytest.raises(AudioError, match="not a WAV file"):
        load_audio(mp3)


def test_missing_empty_and_unsupported_wavs_are_refused(tmp_path: Path) -> None:
    with pytest.raises(AudioError, match="cannot read"):
        load_audio(tmp_path / "nothing.wav")
    with pytest.raises(AudioError, match="no audio samples"):
        load_audio(write_wav(tmp_path / "empty.wav", np.zeros((0, 1)), 16000))
    with pytest.raises(AudioError, match="unsupported WAV encoding"):
        load_audio(write_wav(tmp_path / "alaw.wav", tone(8000), 8000, tag=6, bits=8))
    truncated = tmp_path / "truncated.wav"
    truncated.write_bytes(b"RIFF\x10\x00\x00\x00WAVEfmt ")
    with pytest.raises(AudioError, match="without a 'fmt ' or 'data' chunk"):
        load_audio(truncated)


def test_a_recording_too_long_for_one_command_is_refused_saying_so(tmp_path: Path) -> None:
    from knic.language.audio import MAX_COMMAND_S, command_pcm

    fits = command_pcm(write_wav(tmp_path / "fits.wav", tone(16000, seconds=MAX_COMMAND_S - 1), 16000))
    assert len(fits) == 2 * int(16000 * (MAX_COMMAND_S - 1))
    with pytest.raises(AudioError, match=r"40\.0 s of audio, and one spoken command is at most 30 s"):
        command_pcm(write_wav(tmp_path / "long.wav", tone(16000, seconds=40), 16000))


def test_knic_say_refuses_a_recording_too_long_for_one_command(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from knic.cli import main

    long = write_wav(tmp_path / "long.wav", tone(16000, seconds=40), 16000)
    assert main(["say", str(long)]) == 2
    assert "40.0 s of audio, and one spoken command is at most 30 s" in capsys.readouterr().err
