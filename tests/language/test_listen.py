"""Continuous listening: a stream cut into utterances by voice activity, each recognised (``knic listen``)."""

from __future__ import annotations

import io
import json
from pathlib import Path

import numpy as np
import pytest

from knic.cli import main
from knic.language.audio import MODEL_RATE, load_audio
from knic.language.listen import segments

from .conftest import SPEECH_FIXTURES


def silence(seconds: float) -> np.ndarray:
    return np.zeros(int(seconds * MODEL_RATE), dtype=np.int16)


@pytest.fixture(scope="module")
def stream() -> tuple[bytes, list[float]]:
    """Three utterances (command, small talk, command) with pauses; and where each one starts (s)."""
    parts, starts, at = [silence(0.6)], [], 0.6
    for name in ("cmd_011.wav", "oog_063.wav", "cmd_036.wav"):
        audio = load_audio(SPEECH_FIXTURES / name)
        starts.append(at)
        parts += [audio, silence(1.2)]
        at += len(audio) / MODEL_RATE + 1.2
    return np.concatenate(parts).astype("<i2").tobytes(), starts


def write_wav(path: Path, pcm: bytes) -> None:
    import wave

    with wave.open(str(path), "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(MODEL_RATE)
        out.writeframes(pcm)


def test_a_stream_is_cut_where_the_speech_is(stream: tuple[bytes, list[float]]) -> None:
    pcm, starts = stream
    found = list(segments(io.BytesIO(pcm)))
    assert len(found) == 3
    for segment, start in zip(found, starts, strict=True):
        assert abs(segment.start - start) < 0.35 and segment.end > segment.start
        assert len(segment.audio) == pytest.approx((segment.end - segment.start) * MODEL_RATE, rel=0.1)


def test_long_speech_is_cut_at_the_limit(stream: tuple[bytes, list[float]]) -> None:
    found = list(segments(io.BytesIO(stream[0]), max_seconds=0.5))
    assert len(found) > 3 and all(len(s.audio) <= 0.5 * MODEL_RATE + 480 for s in found)


def test_listen_prints_each_utterance_as_json(
    stream: tuple[bytes, list[float]], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    wav = tmp_path / "stream.wav"
    write_wav(wav, stream[0])
    assert main(["listen", "--wav", str(wav), "--json"]) == 0
    lines = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [line["accepted"] for line in lines] == [True, False, True]
    assert lines[0]["goals"] == ["(has annie glasses)"] and lines[2]["goals"] == [
        "(light_on bedroom_left_light)"
    ]
    # other speech: refused by the confidence, or heard as words that ask for nothing
    assert not lines[1]["goals"] and any(
        why in lines[1]["reason"] for why in ("matched no command", "asks for nothing to achieve")
    )
    assert lines[0]["end"] < lines[1]["start"] < lines[1]["end"] < lines[2]["start"]


def test_listen_reads_raw_pcm_from_stdin(
    stream: tuple[bytes, list[float]], monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    class Stdin:
        buffer = io.BytesIO(stream[0])

    monkeypatch.setattr("sys.stdin", Stdin())
    assert main(["listen", "--stdin", "--count", "1", "--json"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 1 and json.loads(lines[0])["text"] == "bring me my glasses"


def test_without_a_recorder_listen_says_what_to_install(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr("shutil.which", lambda name: None)
    assert main(["listen"]) == 2
    err = capsys.readouterr().err
    assert "no microphone recorder" in err and "--stdin" in err and err.count("\n") == 1
