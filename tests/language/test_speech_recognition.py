"""Recognition of a few committed WAV files (few, for speed; the full set is a benchmark)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from knic.language.audio import Transcript
from knic.language.speech import Recognizer
from knic.language.understanding import default_grammar, understand_transcript
from knic.language.vocabulary import Vocabulary

from .conftest import SPEECH_FIXTURES


@pytest.fixture(scope="module")
def recognizer(grammar_recognizer: Recognizer) -> Recognizer:
    return grammar_recognizer


@pytest.mark.parametrize(
    ("name", "words", "goals"),
    [
        ("cmd_011.wav", "bring me my glasses", ["(has annie glasses)"]),
        ("cmd_036.wav", "switch on the left light", ["(light_on bedroom_left_light)"]),
        ("cmd_050.wav", "locate the tablet and bring it to me", ["(reported tablet)", "(has annie tablet)"]),
    ],
)
def test_commands_are_recognised_word_for_word(
    recognizer: Recognizer, vocabulary: Vocabulary, name: str, words: str, goals: list[str]
) -> None:
    transcript = recognizer.recognize(SPEECH_FIXTURES / name)
    assert transcript.text == words and transcript.in_grammar
    result = understand_transcript(transcript, vocabulary)
    assert result.accepted and [str(g) for g in result.goals] == goals


def test_speech_outside_the_grammar_is_rejected(recognizer: Recognizer, vocabulary: Vocabulary) -> None:
    transcript = recognizer.recognize(SPEECH_FIXTURES / "oog_063.wav")  # "what is the weather like today"
    result = understand_transcript(transcript, vocabulary)
    assert not result.accepted and result.goals == ()
    assert "matched no command" in result.reason or "understand" in result.reason


def test_a_command_heard_but_refused_says_what_the_world_lacks(vocabulary: Vocabulary) -> None:
    heard = Transcript("bring me the unicorn", False, math.nan, 2.0, 10.0)  # no such thing in the apartment
    result = understand_transcript(heard, vocabulary)
    assert not result.accepted and result.goals == () and result.frames == ()
    assert "matched no command" in result.reason and "'bring me the unicorn'" in result.reason
    assert "unicorn" in result.reason.split(";", 1)[1]  # the reader's own reason follows what was heard
    other = understand_transcript(Transcript("bring me the mug", False, math.nan, 2.0, 10.0), vocabulary)
    assert not other.accepted and ";" not in other.reason  # the reader takes it: the speech refused it


def test_decoding_does_not_depend_on_what_came_before(recognizer: Recognizer) -> None:
    first = recognizer.recognize(SPEECH_FIXTURES / "cmd_011.wav")
    recognizer.recognize(SPEECH_FIXTURES / "oog_063.wav")
    again = recognizer.recognize(SPEECH_FIXTURES / "cmd_011.wav")
    assert (first.text, first.score) == (again.text, again.score)


def test_the_recogniser_knows_every_word_of_the_grammar(recognizer: Recognizer) -> None:
    assert "public <utterance>" in recognizer.jsgf and "<filler>" in recognizer.jsgf
    assert "glasses" in recognizer.graph.words()
    assert all(" " not in w for w in recognizer.unknown_words)


def test_decoder_options_override_the_defaults_for_one_recogniser(
    recognizer: Recognizer, vocabulary: Vocabulary
) -> None:
    from knic.language.speech import DECODER_OPTIONS

    tuned = Recognizer(default_grammar(), vocabulary, decoder_options={"beam": 1e-40})
    assert tuned.decoder_options["beam"] == 1e-40 and tuned.decoder_options["lw"] == DECODER_OPTIONS["lw"]
    assert "beam" not in DECODER_OPTIONS and "beam" not in recognizer.decoder_options
    transcript = tuned.recognize(SPEECH_FIXTURES / "cmd_011.wav")
    assert transcript.text == "bring me my glasses"


def test_an_option_the_decoder_does_not_know_is_refused(vocabulary: Vocabulary) -> None:
    from core.errors import LanguageError

    with pytest.raises(LanguageError, match="no_such_option"):
        Recognizer(default_grammar(), vocabulary, decoder_options={"no_such_option": 1})


def test_bench_options_are_typed_from_their_text() -> None:
    from core.errors import KnicError
    from knic.bench.speech import parse_options

    assert parse_options(["beam=1e-60", "topn=2", "bestpath=false", "cmn=batch"]) == {
        "beam": 1e-60,
        "topn": 2,
        "bestpath": False,
        "cmn": "batch",
    }
    with pytest.raises(KnicError, match="KEY=VALUE"):
        parse_options(["beam"])


@pytest.mark.parametrize(
    ("phones", "variant"),
    [
        ("W AO T ER", "W AO T AH"),  # final ER
        ("D AO R", "D AO"),  # R after a vowel at the end
        ("K AA R D B AO R D", "K AA D B AO D"),  # R before a consonant
        ("AA R M CH EH R", "AA M CH EH AH"),  # EH + R becomes a centring diphthong
        ("B EH D R UW M", "B EH D R UW M"),  # R before a vowel stays
        ("F AO R AH", "F AO R AH"),  # linking R stays
    ],
)
def test_non_rhotic_variants_drop_r_only_where_a_british_speaker_does(phones: str, variant: str) -> None:
    from knic.language.speech import non_rhotic

    assert non_rhotic(phones) == variant


def test_the_recogniser_adds_non_rhotic_alternatives_for_command_words(recognizer: Recognizer) -> None:
    added = recognizer.added_pronunciations
    assert added["water(2)"] == "W AO T AH"
    assert {"search(2)", "turn(2)", "percent(2)"} <= set(added)
    assert all(recognizer._decoder.lookup_word(name) == phones for name, phones in added.items())


def test_the_speech_bench_prints_its_figures(capsys: pytest.CaptureFixture[str]) -> None:
    import json

    from knic.cli import main

    args = ["bench", "speech", "--json", "--limit", "3", "--answers", "", "--decoder", "grammar"]
    assert main([*args, "--fixtures", "tests/fixtures/speech", "--dev", "tests/fixtures/speech_dev"]) == 0
    figures = json.loads(capsys.readouterr().out)["grammar"]
    assert figures["utterances"] == 3 and figures["acoustic_model"] == "espeak"
    assert figures["frame_argument_accuracy"] == 1.0 and figures["wer"] == 0.0  # the first three, all right
    assert set(figures["dev"]) == {
        "wer",
        "frame_accuracy",
        "frame_argument_accuracy",
        "oog_rejection",
        "ms_per_utterance",
    }
    assert 0.0 <= figures["dev"]["frame_argument_accuracy"] <= 1.0 and figures["ms_per_utterance"] > 0


def test_the_speech_bench_judges_a_level_as_the_text_bench_does(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    import json
    import shutil

    from knic.cli import main

    shutil.copy("tests/fixtures/speech_dev/dev_055.wav", tmp_path / "open.wav")  # "open the bedroom blinds"
    frame = {"frame": "OPERATING", "device": "bedroom_blinds", "state": "100"}  # the blinds open, as a level
    entry = {"file": "open.wav", "text": "open the bedroom blinds", "in_grammar": True, "frames": [frame]}
    gold = tmp_path / "gold.json"
    args = ["bench", "speech", "--json", "--answers", "", "--dev", "", "--decoder", "grammar"]
    gold.write_text(json.dumps([entry]), encoding="utf-8")  # a list, not the set's object: one clear error
    assert main([*args, "--fixtures", str(tmp_path)]) != 0
    assert "gold.json: cannot read the speech test set" in capsys.readouterr().err
    gold.write_text(json.dumps({"utterances": [entry]}), encoding="utf-8")
    assert main([*args, "--fixtures", str(tmp_path)]) == 0
    figures = json.loads(capsys.readouterr().out)["grammar"]
    assert figures["wer"] == 0.0 and figures["frame_argument_accuracy"] == 1.0


def test_the_speech_bench_hears_a_set_in_its_own_world(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    import json

    from knic.cli import main

    args = ["bench", "speech", "--json", "--answers", "", "--dev", "", "--decoder", "ngram", "--limit", "4"]
    assert main([*args, "--fixtures", "tests/fixtures/speech_world_dev"]) == 0  # said in the bungalow
    figures = json.loads(capsys.readouterr().out)["ngram"]
    # car keys, a newspaper, a teddy bear and a reading lamp: none of them in the apartment, whose words would
    # refuse all four; in the bungalow's own words the four were heard right on the machines measured
    assert figures["in_grammar"] == 4 and figures["frame_argument_accuracy"] >= 0.5
    assert main([*args, "--fixtures", "tests/fixtures/speech_world_dev2"]) == 0  # said in the student house
    figures = json.loads(capsys.readouterr().out)["ngram"]  # soy sauce, parcel, rugby ball, kitchen light
    assert figures["in_grammar"] == 4 and figures["frame_argument_accuracy"] >= 0.5
    gold = json.loads(Path("tests/fixtures/speech_world_dev/gold.json").read_text(encoding="utf-8"))
    gold["world"] = "no_such_world"
    (tmp_path / "gold.json").write_text(json.dumps(gold), encoding="utf-8")
    assert main([*args, "--fixtures", str(tmp_path)]) != 0
    assert "world 'no_such_world'" in capsys.readouterr().err
