"""The shipped acoustic adaptation: it loads, recognises what the wheel's model misses; bad names fail."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest

from core.errors import LanguageError
from knic.cli import main
from knic.language.acoustic import MODEL_DIR, acoustic_model_options, wheel_model_dir
from knic.language.speech import Recognizer
from knic.language.understanding import default_grammar
from knic.language.vocabulary import Vocabulary

from .conftest import SPEECH_FIXTURES

# Development utterances (voices none of the adaptation's) the unadapted model gets wrong: it heard
# "people was does", nothing, and "you're we're though was".
DEV = SPEECH_FIXTURES.parent / "speech_dev"
HARD = [
    ("dev_002.wav", "look for my glasses"),
    ("dev_056.wav", "half open the blinds"),
    ("dev_029.wav", "give me the glass"),
]


def test_named_models_resolve_to_files_or_to_the_wheel_model() -> None:
    options = acoustic_model_options("espeak")
    assert options == {
        "mean": str(MODEL_DIR / "means"),
        "var": str(MODEL_DIR / "variances"),
        "sendump": str(MODEL_DIR / "sendump"),
    }
    assert all(Path(str(p)).stat().st_size > 100_000 for p in options.values())
    assert acoustic_model_options("base") == {}
    ngram = acoustic_model_options("espeak", decoder="ngram")  # the n-gram decoder's own adaptation
    assert ngram == {
        option: str(MODEL_DIR / "ngram" / Path(str(path)).name) for option, path in options.items()
    }
    assert acoustic_model_options("base", decoder="ngram") == {}


def test_an_unknown_model_or_an_incomplete_folder_is_refused(tmp_path: Path) -> None:
    with pytest.raises(
        LanguageError, match=r"unknown acoustic model 'klingon': expected one of auto, base, espeak"
    ):
        acoustic_model_options("klingon")
    (tmp_path / "means").write_bytes(b"x")
    with pytest.raises(LanguageError, match="missing variances, sendump"):
        acoustic_model_options(tmp_path)


def test_the_adapted_model_recognises_what_the_wheel_model_does_not(
    vocabulary: Vocabulary, grammar_recognizer: Recognizer
) -> None:
    adapted = grammar_recognizer
    base = Recognizer(default_grammar(), vocabulary, acoustic_model="base")
    assert base.acoustic_model == {} and adapted.acoustic_model == acoustic_model_options("espeak")
    for name, words in HARD:
        assert adapted.recognize(DEV / name).text == words
    assert base.recognize(DEV / HARD[0][0]).text != HARD[0][1]


def test_say_with_an_unknown_acoustic_model_exits_with_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["say", str(SPEECH_FIXTURES / "cmd_011.wav"), "--acoustic-model", "klingon"]) == 4
    err = capsys.readouterr().err
    assert "unknown acoustic model 'klingon'" in err and err.count("\n") == 1


def test_say_with_the_base_model(capsys: pytest.CaptureFixture[str]) -> None:
    wav = str(SPEECH_FIXTURES / "cmd_011.wav")
    assert main(["say", wav, "--acoustic-model", "base", "--decoder", "grammar", "--json"]) == 0
    assert '"goals": ["(has annie glasses)"]' in capsys.readouterr().out
    assert main(["say", wav, "--acoustic-model", "base", "--json", "--no-second-opinion"]) in (0, 4)  # n-gram


def test_sendump_expands_to_normalised_mixture_weights(tmp_path: Path) -> None:
    from knic.language.acoustic.build import sendump_to_mixw

    target = tmp_path / "mixture_weights"
    senones, streams, densities = sendump_to_mixw(wheel_model_dir() / "en-us" / "sendump", target)
    assert (senones, streams, densities) == (5126, 3, 128)
    data = target.read_bytes()
    start = data.index(b"endhdr\n") + len(b"endhdr\n")
    assert start % 4 == 0  # sphinxtrain reads the data 4-byte aligned
    magic, d1, d2, d3, count = struct.unpack_from("<5I", data, start)
    assert (magic, d1, d2, d3, count) == (
        0x11223344,
        senones,
        streams,
        densities,
        senones * streams * densities,
    )
    weights = np.frombuffer(data, dtype="<f4", offset=start + 20).reshape(d1, d2, d3)
    assert np.allclose(weights.sum(axis=2), 1.0, atol=1e-4) and weights.min() >= 0.0


def test_made_up_speakers_are_drawn_within_their_ranges_and_repeat_with_the_seed(tmp_path: Path) -> None:
    import random

    from knic.language.acoustic import voices

    first = voices.random_speaker(random.Random(3), "knic_speaker_007")
    assert first == voices.random_speaker(random.Random(3), "knic_speaker_007")
    lines = first.splitlines()
    assert lines[:2] == ["language variant", "name knic_speaker_007"]
    gender = lines[2].split()[1]
    low, high = voices.SPEAKER_TRACT[gender]
    formants = [list(map(int, line.split()[1:])) for line in lines if line.startswith("formant ")]
    assert [f[0] for f in formants] == list(range(9))
    spread = voices.SPEAKER_FORMANT_SPREAD
    assert all(low - spread <= f[1] <= high + spread for f in formants)
    assert all(voices.SPEAKER_HEIGHT[0] <= f[2] <= voices.SPEAKER_HEIGHT[1] for f in formants)
    base, top = map(int, lines[3].split()[1:])
    assert voices.SPEAKER_PITCH[gender][0] <= base < top
    # many draws give both genders and other vocal tracts
    drawn = [voices.random_speaker(random.Random(seed), "x") for seed in range(40)]
    assert {d.splitlines()[2] for d in drawn} == {"gender male", "gender female"}
    assert len(set(drawn)) == 40
