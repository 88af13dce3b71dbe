"""``knic bench speech``: speech recognition and command understanding, both decoders, dev and test sets.

The sets are ``tests/fixtures/speech_people/test`` (held out: never tuned on) and ``.../dev`` (tuned on):
the commands of the text sets (``tests/fixtures/language``) and out-of-domain speech, synthesised with
espeak-ng in voices that neither the other set nor the acoustic adaptation uses (``generate.py`` there). Each
``gold.json`` has each file's transcription, whether it is a command (``in_grammar``), and its gold frames;
its ``world``, when that is a world file (relative to the set's folder) or a world's name, is the home the set
is said in (``speech_world_dev``: the bungalow of ``worlds/test_bungalow``), else the apartment.
Both decoders run on both sets: ``grammar`` (the template grammar, :class:`knic.language.speech.Recognizer`)
and ``ngram`` (the n-gram model with a confidence, :class:`knic.language.lmspeech.NgramRecognizer`);
``--decoder`` picks one. The earlier sets (``tests/fixtures/speech``, ``speech_dev``: template phrasings,
decoder settings tuned on them) still run with ``--fixtures`` and ``--dev``.
Figures (wall-clock time; the decoder is built once before timing):

* ``wer`` -- word error rate of the transcripts of in-grammar utterances (edit distance / gold words,
  both normalised);
* ``frame_accuracy`` -- share of in-grammar utterances whose frame kinds are all right, in order;
* ``frame_argument_accuracy`` -- share whose frames are right with every argument;
* ``oog_rejection`` -- share of out-of-grammar utterances rejected (not accepted as a command);
* ``false_rejection`` -- share of in-grammar utterances rejected;
* ``ms_per_utterance`` -- mean recognition plus understanding time per utterance;
* ``by_voice`` -- frame-with-arguments accuracy of the in-grammar utterances of each voice in ``gold.json``;
* ``by_class`` -- the same per phrasing class (fillers, relative, chains, levels, several, ...) when given;
* ``dev`` -- the same main figures on the development set (``tests/fixtures/speech_people/dev``: every
  command of the text dev set, 115, and 6 other utterances, in voices and sentences the test set does not
  have), to see how far the figures carry to unseen voices;
* ``answer_accuracy`` -- share of ``tests/fixtures/speech_answers`` (spoken yes, no, and speech that is no
  answer) that the confirmation recogniser takes as the right answer, or as no answer;
  ``answer_phrase_accuracy`` the same on ``speech_answers_dev`` beside it (answers of several words: "no,
  that's wrong", "of course"); both are development sets.

``--fixtures DIR`` runs another set in the same layout, e.g. ``tests/fixtures/speech_dev``, the dev set
(other sentences and voices, to tune on without touching the test set), ``speech_voices_dev`` (the
development commands and other speech in four more voices, for measures that must carry across voices) or
``speech_ood_dev``; ``--option KEY=VALUE`` (repeatable),
``--no-branch-penalty`` and ``--acoustic-model NAME|DIR`` (``auto``, the n-gram decoder's default: both
models below, the better fitting kept per utterance; ``espeak``, the grammar decoder's default; ``base``, the
unadapted model: see :mod:`knic.language.acoustic`) change the recogniser for that run only. The n-gram
decoder hears with Whisper's second opinion (:mod:`knic.language.whisperpass`) unless
``--no-second-opinion``; ``second_opinion`` in the figures says which.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path
from typing import Any

from core.errors import KnicError
from knic.bench.language import same_states
from knic.cli.say import add_acoustic_argument, add_second_opinion_argument

FIXTURES = Path(__file__).resolve().parents[2] / "tests" / "fixtures" / "speech_people" / "test"
ANSWERS = FIXTURES.parents[1] / "speech_answers"
DEV = FIXTURES.parent / "dev"
DECODERS = ("grammar", "ngram")
#: the development set's figures printed under ``"dev"``
DEV_FIGURES = ("wer", "frame_accuracy", "frame_argument_accuracy", "oog_rejection", "ms_per_utterance")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--fixtures", default=str(FIXTURES), help="folder with gold.json and the WAV files")
    parser.add_argument("--limit", type=int, default=0, help="use only the first N utterances (0: all)")
    parser.add_argument(
        "--filler-weight", type=float, default=None, help="filler loop prior (default: built in)"
    )
    parser.add_argument("--verbose", action="store_true", help="list every utterance that went wrong")
    parser.add_argument(
        "--option",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="pocketsphinx option for this run, e.g. beam=1e-60 (repeatable)",
    )
    parser.add_argument(
        "--no-branch-penalty", action="store_true", help="do not split grammar probability over branches"
    )
    add_acoustic_argument(parser)
    parser.add_argument(
        "--answers", default=str(ANSWERS), help="folder with the yes/no answer set ('' skips)"
    )
    parser.add_argument("--dev", default=str(DEV), help="folder with the development set ('' skips)")
    parser.add_argument("--decoder", choices=DECODERS, help="only this decoder (default: both)")
    add_second_opinion_argument(parser)


def parse_options(pairs: list[str]) -> dict[str, object]:
    """``["beam=1e-60", "bestpath=false"]`` -> ``{"beam": 1e-60, "bestpath": False}`` (int, float, bool, str).

    Raises:
        KnicError: an item is not KEY=VALUE.
    """
    options: dict[str, object] = {}
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep or not key.strip():
            raise KnicError(f"--option {pair!r}: expected KEY=VALUE, e.g. beam=1e-60")
        value: object = text
        if text.lower() in ("true", "false"):
            value = text.lower() == "true"
        else:
            for kind in (int, float):
                try:
                    value = kind(text)
                    break
                except ValueError:
                    continue
        options[key.strip()] = value
    return options


def word_errors(reference: list[str], hypothesis: list[str]) -> int:
    """Word-level edit distance (substitutions, insertions, deletions)."""
    from knic.language.speech import edit_distance

    return edit_distance(reference, hypothesis)


#: recognisers built by :func:`evaluate`, with the milliseconds each took to build, by their settings
_BUILT: dict[str, tuple[Any, float]] = {}


def evaluate(
    fixtures: Path,
    limit: int = 0,
    filler_weight: float | None = None,
    *,
    decoder_options: dict[str, object] | None = None,
    branch_penalty: bool = True,
    acoustic_model: str | None = None,
    decoder: str = "grammar",
    second_opinion: bool = True,
) -> dict[str, Any]:
    """Run the test set and return the figures plus the per-utterance mistakes under ``"errors"``.

    Args:
        fixtures: folder with ``gold.json`` and the WAV files it names.
        limit: use only the first ``limit`` utterances (0: all).
        filler_weight: filler loop prior (None: the recogniser's default).
        decoder_options: pocketsphinx options for this run over the module defaults.
        branch_penalty: passed to :class:`~knic.language.speech.Recognizer`.
        acoustic_model: passed to :class:`~knic.language.speech.Recognizer`.
        decoder: ``grammar`` or ``ngram`` (see the module docstring).
        second_opinion: the n-gram decoder also hears each utterance with Whisper
            (:mod:`knic.language.whisperpass`).

    Raises:
        KnicError: the gold file is missing or malformed, or the decoder refuses an option.
    """
    from knic.language.audio import load_audio
    from knic.language.frames import CommandFrame
    from knic.language.lmspeech import NgramRecognizer
    from knic.language.speech import Recognizer
    from knic.language.understanding import default_grammar, understand_transcript
    from knic.language.vocabulary import normalize
    from knic.language.world import read_vocabulary

    try:
        gold = json.loads((fixtures / "gold.json").read_text(encoding="utf-8"))
        utterances = gold["utterances"][: limit or None]
    except (OSError, ValueError, KeyError, TypeError) as exc:  # TypeError: not an object with a list
        raise KnicError(f"{fixtures / 'gold.json'}: cannot read the speech test set: {exc}") from exc
    world = gold.get("world")
    if isinstance(world, str) and not world.endswith(".pddl"):  # a world file or name: its own vocabulary
        from knic.bench.language import world_file_vocabulary

        vocabulary = world_file_vocabulary(world, fixtures / "gold.json")
    else:  # the apartment's PDDL problem, the default
        vocabulary = read_vocabulary()
    speaker = gold.get("speaker", "annie")
    from knic.language.acoustic import acoustic_model_for

    acoustic_model = str(acoustic_model_for(decoder, acoustic_model))
    started = time.perf_counter()
    extra: dict[str, Any] = {
        "decoder_options": decoder_options,
        "branch_penalty": branch_penalty,
        "acoustic_model": acoustic_model,
    }
    if filler_weight is not None:
        extra["filler_weight"] = filler_weight
    key = json.dumps([decoder, extra, filler_weight, second_opinion, world], sort_keys=True, default=str)
    if key not in _BUILT:  # the sets of one run read in the same world share the recogniser
        recognizer: Any
        if decoder == "ngram":
            recognizer = NgramRecognizer(
                vocabulary,
                acoustic_model=acoustic_model,
                decoder_options=decoder_options,
                second_opinion=second_opinion,
            )
        else:
            recognizer = Recognizer(default_grammar(), vocabulary, **extra)
        _BUILT[key] = (recognizer, (time.perf_counter() - started) * 1000.0)
    recognizer, setup_ms = _BUILT[key]
    errors_total = words_total = kinds_ok = args_ok = rejected_in = rejected_oog = n_in = n_oog = 0
    elapsed: list[float] = []
    durations: list[float] = []
    mistakes: list[dict[str, Any]] = []
    voices: dict[str, list[int]] = {}
    classes: dict[str, list[int]] = {}
    for entry in utterances:
        audio = load_audio(fixtures / entry["file"])
        started = time.perf_counter()
        result = understand_transcript(recognizer.recognize(audio), vocabulary, speaker=speaker)
        elapsed.append((time.perf_counter() - started) * 1000.0)
        durations.append(len(audio) / 16000.0)
        heard = str(result.extra.get("transcript", ""))
        if entry["in_grammar"]:
            n_in += 1
            reference = normalize(entry["text"]).split()
            errors_total += word_errors(reference, heard.split())
            words_total += len(reference)
            expected = [CommandFrame.from_dict(f) for f in entry["frames"]]
            got = list(result.frames) if result.accepted else []
            kinds_ok += [f.kind for f in got] == [f.kind for f in expected]
            # judged as the text bench judges: "open" is the level 100, "closed" the level 0
            right = same_states([f.to_dict() for f in got]) == same_states([f.to_dict() for f in expected])
            args_ok += right
            for table, key in ((voices, "voice"), (classes, "class")):
                if key in entry:
                    tally = table.setdefault(str(entry[key]), [0, 0])
                    tally[0] += right
                    tally[1] += 1
            rejected_in += not result.accepted
            if not right:
                mistakes.append(
                    {"file": entry["file"], "text": entry["text"], "heard": heard, "reason": result.reason}
                )
        else:
            n_oog += 1
            rejected_oog += not result.accepted
            if result.accepted:
                mistakes.append(
                    {"file": entry["file"], "text": entry["text"], "heard": heard, "accepted": True}
                )
    return {
        "utterances": n_in + n_oog,
        "in_grammar": n_in,
        "out_of_grammar": n_oog,
        "wer": round(errors_total / words_total, 4) if words_total else None,
        "frame_accuracy": round(kinds_ok / n_in, 4) if n_in else None,
        "frame_argument_accuracy": round(args_ok / n_in, 4) if n_in else None,
        "oog_rejection": round(rejected_oog / n_oog, 4) if n_oog else None,
        "false_rejection": round(rejected_in / n_in, 4) if n_in else None,
        "ms_per_utterance": round(sum(elapsed) / len(elapsed), 1) if elapsed else None,
        "audio_s_per_utterance": round(sum(durations) / len(durations), 3) if durations else None,
        "decoder_setup_ms": round(setup_ms, 1),
        "decoder": decoder,
        "acoustic_model": acoustic_model,
        "second_opinion": decoder == "ngram" and getattr(recognizer, "whisper", None) is not None,
        "by_voice": {voice: round(ok / n, 4) for voice, (ok, n) in sorted(voices.items())},
        "by_class": {name: round(ok / n, 4) for name, (ok, n) in sorted(classes.items())},
        "errors": mistakes,
    }


def evaluate_answers(folder: Path, acoustic_model: str = "espeak") -> tuple[float, list[dict[str, Any]]]:
    """Share of the answer set understood right (yes, no, or no answer), and the mistakes.

    Raises:
        KnicError: the gold file is missing or malformed.
    """
    from knic.language.dialogue import parse_answer
    from knic.language.speech import AnswerRecognizer

    try:
        entries = json.loads((folder / "gold.json").read_text(encoding="utf-8"))["utterances"]
    except (OSError, ValueError, KeyError) as exc:
        raise KnicError(f"{folder / 'gold.json'}: cannot read the answer set: {exc}") from exc
    recognizer = AnswerRecognizer(acoustic_model=acoustic_model)
    mistakes: list[dict[str, Any]] = []
    for entry in entries:
        heard = recognizer.recognize(folder / entry["file"])
        verdict = parse_answer(heard) if heard else None
        got = None if verdict is None else ("yes" if verdict else "no")
        if got != entry["answer"]:
            mistakes.append({"file": entry["file"], "text": entry["text"], "heard": heard})
    return round(1 - len(mistakes) / len(entries), 4) if entries else 0.0, mistakes


def run(args: argparse.Namespace) -> int:
    def evaluate_set(folder: str, decoder: str) -> dict[str, Any]:
        return evaluate(
            Path(folder),
            args.limit,
            args.filler_weight,
            decoder_options=parse_options(args.option),
            branch_penalty=not args.no_branch_penalty,
            acoustic_model=args.acoustic_model,
            decoder=decoder,
            second_opinion=args.second_opinion,
        )

    figures: dict[str, Any] = {}
    mistakes: list[dict[str, Any]] = []
    for decoder in [args.decoder] if args.decoder else list(DECODERS):
        result = evaluate_set(args.fixtures, decoder)
        mistakes += [{**m, "decoder": decoder} for m in result.pop("errors")]
        if args.dev and Path(args.dev).resolve() != Path(args.fixtures).resolve():
            dev = evaluate_set(args.dev, decoder)
            result["dev"] = {key: dev[key] for key in DEV_FIGURES}
        figures[decoder] = result
    if args.answers:
        from knic.language.acoustic import acoustic_model_for

        answers_model = str(acoustic_model_for("answers", args.acoustic_model))
        figures["answer_accuracy"], wrong = evaluate_answers(Path(args.answers), answers_model)
        mistakes += wrong
        phrases = Path(args.answers).parent / "speech_answers_dev"
        if (phrases / "gold.json").is_file():
            figures["answer_phrase_accuracy"], wrong = evaluate_answers(phrases, answers_model)
            mistakes += wrong
    if args.verbose:
        figures["errors"] = mistakes
    if args.json:
        print(json.dumps(figures))
        return 0
    for key, value in figures.items():
        if isinstance(value, dict):
            print(f"{key}:")
            for inner, figure in value.items():
                print(f"  {inner}: {figure}")
        elif key != "errors":
            print(f"{key}: {value}")
    for mistake in figures.get("errors", []):
        said, heard = mistake["text"], mistake["heard"]
        print(f"  {mistake.get('decoder', '')} {mistake['file']}: said '{said}', heard '{heard}'")
    return 0
