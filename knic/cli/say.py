"""``knic say FILE.wav``: recognise a spoken command and print its transcript, frames and PDDL goals.

WAV files of any rate and channel count are converted in-process; other formats are refused (exit 2). Speech
that matches no command is rejected with its reason (exit 4), never forced onto the nearest command.

The n-gram decoder (:class:`knic.language.lmspeech.NgramRecognizer`) listens by default: it hears people's
phrasings better than the template grammar (``knic bench speech``) and starts in a fraction of the time
(its model is cached on disk; the grammar's word graph is compiled anew, about 2.5 s). ``--decoder grammar``
uses the template grammar (:class:`knic.language.speech.Recognizer`). Whisper hears the command first, in a
child forked at once, and settles it when it is sure (:mod:`knic.language.whisperpass`); the child asks the
daemon an earlier start left with the model loaded (:mod:`knic.language.whisperd`), else loads it itself
(the first start in a world takes about 3 s, later ones about 0.85 s; ``--no-second-opinion`` about 0.6 s).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from knic.cli.goal import add_world_arguments, load_vocabulary, print_understanding

#: largest WAV file read: 32 MB, over three minutes of 48 kHz stereo 16-bit audio
MAX_AUDIO_BYTES = 32 * 1024 * 1024

if TYPE_CHECKING:
    from knic.language.lmspeech import NgramRecognizer
    from knic.language.oneshot import Passes
    from knic.language.vocabulary import Vocabulary


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("wav", help="the spoken command as a WAV file")
    add_world_arguments(parser)
    add_acoustic_argument(parser)
    add_decoder_argument(parser)


def add_decoder_argument(parser: argparse.ArgumentParser) -> None:
    """``--decoder ngram|grammar`` (shared by the commands that listen for commands)."""
    parser.add_argument(
        "--decoder",
        choices=("ngram", "grammar"),
        default="ngram",
        help="ngram (the command language model with a confidence, default) or grammar (the templates only)",
    )
    add_second_opinion_argument(parser)


def add_second_opinion_argument(parser: argparse.ArgumentParser) -> None:
    """``--no-second-opinion``: the n-gram decoder without Whisper (:mod:`knic.language.whisperpass`)."""
    parser.add_argument(
        "--no-second-opinion",
        dest="second_opinion",
        action="store_false",
        help="pocketsphinx alone: do not also hear each command with Whisper (faster, less accurate)",
    )


def add_acoustic_argument(parser: argparse.ArgumentParser) -> None:
    """``--acoustic-model NAME|DIR`` (shared by the commands that listen)."""
    parser.add_argument(
        "--acoustic-model",
        default=None,
        metavar="NAME|DIR",
        help="auto (the n-gram decoder's default: both models below, the better fitting kept for each "
        "utterance), espeak (adapted to synthetic voices; the grammar decoder's default), base (the "
        "unadapted US English model), or a folder built by python -m knic.language.acoustic.build",
    )


def _world_files(args: argparse.Namespace) -> list[str]:
    """The files the world's vocabulary is read from: those the options name, their lexicons, the defaults."""
    from knic.language.world import DEFAULT_DOMAIN, DEFAULT_PROBLEM, LEXICON_NAME

    named = [args.domain or DEFAULT_DOMAIN, getattr(args, "world", None), args.problem, args.lexicon]
    if getattr(args, "world", None) is None and args.problem is None and args.domain is None:
        named.append(DEFAULT_PROBLEM)
    files = [str(f) for f in named if f]
    return files + [str(Path(f).parent / LEXICON_NAME) for f in files]


def run(args: argparse.Namespace) -> int:
    decoder = getattr(args, "decoder", "ngram")
    from knic.language.acoustic import acoustic_model_for

    args.acoustic_model = acoustic_model_for(decoder, args.acoustic_model)
    if decoder == "ngram":
        from knic.language import oneshot

        # the passes start in children at once, each reading the file itself, while this process checks
        # the file and loads the world (the n-gram passes when this world's model is remembered)
        passes = oneshot.start_passes(
            args.wav, _world_files(args), args.acoustic_model, second_opinion=args.second_opinion
        )
        try:
            return _run(args, decoder, passes)
        finally:
            passes.close()
    return _run(args, decoder, None)


def _run(args: argparse.Namespace, decoder: str, passes: Passes | None) -> int:
    from core.errors import AudioError
    from core.inputs import check_input_file
    from knic.language.audio import load_pcm

    check_input_file(args.wav, MAX_AUDIO_BYTES, "audio file", AudioError)  # never read /dev/zero
    audio = load_pcm(args.wav)  # refuse a bad file before loading the world
    kept = None
    if decoder == "ngram":
        from knic.language import oneshot
        from knic.language.acoustic import acoustic_model_options, ensemble_members

        for member in ensemble_members(args.acoustic_model):
            acoustic_model_options(member, decoder="ngram")  # a bad model: one line
        key = oneshot.world_key(_world_files(args), args.acoustic_model)
        kept = oneshot.remembered_vocabulary(key)
    if kept is not None:
        vocabulary, args.speaker = kept[0], args.speaker or kept[1]
    else:
        given = args.speaker
        vocabulary = load_vocabulary(args)
        if decoder == "ngram" and given is None:
            oneshot.remember_vocabulary(key, vocabulary, args.speaker)
    from knic.language.lmspeech import NgramRecognizer, command_recognizer
    from knic.language.understanding import understand_transcript

    if passes is not None:
        ngram = NgramRecognizer(
            vocabulary, acoustic_model=args.acoustic_model, lazy=True, second_opinion=args.second_opinion
        )
        transcript = ngram.recognize(  # Whisper's answer first: pocketsphinx's is waited for only if needed
            audio,
            phone_score=lambda index: _or(
                passes.phone_score(index), lambda: ngram.phone_loop_of(index).score_of(audio)
            ),
            decoded=passes.decoded,
            heard=passes.heard,
        )
    else:
        model, second = args.acoustic_model, args.second_opinion
        recognizer = command_recognizer(
            vocabulary, decoder=decoder, acoustic_model=model, second_opinion=second
        )
        transcript = recognizer.recognize(audio)
    result = understand_transcript(transcript, vocabulary, speaker=args.speaker)
    print_understanding(result.to_dict(), args.json)
    if passes is not None:
        _keep_for_the_next(args, ngram, vocabulary, key)
    return 0


def _keep_for_the_next(
    args: argparse.Namespace, ngram: NgramRecognizer, vocabulary: Vocabulary, key: str
) -> None:
    """After the answer: the first start in a world keeps its command model (built now if Whisper settled
    the command without it), and a daemon keeps Whisper's model loaded for the next command."""
    from knic.language import oneshot, whisperd
    from knic.language.whisperpass import model_dir, world_prompt

    if oneshot.remembered_model(key) is None:
        ngram.build()
        oneshot.remember_model(key, *(ngram.model_files or ("", None)))
    if args.second_opinion:
        whisperd.ensure(world_prompt(vocabulary), model_dir(), key)


def _or(value: float | None, otherwise: Callable[[], float]) -> float:
    return value if value is not None else otherwise()
