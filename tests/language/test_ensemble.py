"""The n-gram decoder's ``auto`` acoustic models: each utterance is decoded with the espeak-ng adaptation and
with the wheel's model trained on human speech, and the better fitting one is kept."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from core.errors import LanguageError
from knic.cli import main
from knic.language.acoustic import acoustic_model_for, acoustic_model_options, ensemble_members
from knic.language.lmspeech import NgramRecognizer
from knic.language.membership import FIRST_MEMBER_PREFERENCE, MODEL_THRESHOLDS, choose_member
from knic.language.understanding import understand_transcript
from knic.language.vocabulary import Vocabulary

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
ENGINES = FIXTURES / "speech_engines_dev"  # flite and festival voices (development set)
PEOPLE = FIXTURES / "speech_people" / "dev"  # espeak-ng voices (development set)


def _entry(folder: Path, file: str) -> dict[str, object]:
    entries = json.loads((folder / "gold.json").read_text(encoding="utf-8"))["utterances"]
    return next(e for e in entries if e["file"] == file)


def _frames_heard(
    recognizer: NgramRecognizer, vocabulary: Vocabulary, folder: Path, file: str
) -> list[object]:
    result = understand_transcript(recognizer.recognize(folder / file), vocabulary)
    return [f.to_dict() for f in result.frames] if result.accepted else []


@pytest.fixture(scope="module")
def auto(vocabulary: Vocabulary) -> NgramRecognizer:
    # the default acoustic models (auto), without Whisper's second opinion: these tests are pocketsphinx's
    return NgramRecognizer(vocabulary, second_opinion=False)


def test_auto_is_the_adaptation_first_then_the_wheel_model(auto: NgramRecognizer) -> None:
    assert ensemble_members("auto") == ("espeak", "base") == auto.members
    assert ensemble_members("base") == ("base",)
    assert acoustic_model_for("ngram") == "auto" and acoustic_model_for("grammar") == "espeak"
    assert acoustic_model_for("answers") == "espeak" and acoustic_model_for("ngram", "base") == "base"
    assert (
        auto.threshold_of(0) == MODEL_THRESHOLDS["espeak"]
        and auto.threshold_of(1) == MODEL_THRESHOLDS["base"]
    )


def test_the_first_model_is_kept_unless_another_fits_clearly_better() -> None:
    frames = 100
    first = ("bring me the cup", 0.5, frames, (), True, 0)
    slightly = ("bring me a cup", 0.5 * math.exp(frames * FIRST_MEMBER_PREFERENCE / 2), frames, (), True, 0)
    clearly = ("bring me the cup", 0.5 * math.exp(frames * FIRST_MEMBER_PREFERENCE * 2), frames, (), True, 0)
    assert choose_member([first, slightly]) == 0
    assert choose_member([first, clearly]) == 1
    assert choose_member([("", 0.0, frames, (), True, 0), first]) == 1  # the first found no path at all
    assert choose_member([first, ("", 0.0, frames, (), True, 0)]) == 0


def test_another_engine_s_voice_is_heard_where_the_adaptation_alone_fails(
    auto: NgramRecognizer, vocabulary: Vocabulary
) -> None:
    """festival's and flite's voices: the ensemble hears each right, the espeak-ng adaptation alone not all
    (it has heard "check the kitchen for the" for the lemon, and "at" for "pick up the lemon")."""
    files = ["engines_dev_053.wav", "engines_dev_010.wav", "engines_dev_001.wav"]
    adapted = NgramRecognizer(vocabulary, acoustic_model="espeak", second_opinion=False)
    wrong = 0
    for file in files:
        entry = _entry(ENGINES, file)
        assert _frames_heard(auto, vocabulary, ENGINES, file) == entry["frames"], file
        wrong += _frames_heard(adapted, vocabulary, ENGINES, file) != entry["frames"]
    assert wrong >= 1


def test_espeak_voices_are_still_heard(auto: NgramRecognizer, vocabulary: Vocabulary) -> None:
    entries = json.loads((PEOPLE / "gold.json").read_text(encoding="utf-8"))["utterances"]
    entry = next(e for e in entries if e["text"] == "go near the sofa")
    assert _frames_heard(auto, vocabulary, PEOPLE, entry["file"]) == entry["frames"]


def test_only_the_n_gram_decoder_takes_a_set_of_models(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(LanguageError, match="'auto' is espeak and base: only the n-gram decoder takes it"):
        acoustic_model_options("auto")
    wav = str(ENGINES / "engines_dev_001.wav")
    assert main(["say", wav, "--decoder", "grammar", "--acoustic-model", "auto"]) == 4
    err = capsys.readouterr().err
    assert "only the n-gram decoder takes it" in err and err.count("\n") == 1
