"""``knic say FILE.wav``: recognise a spoken command and print its transcript, frames and PDDL goals.

WAV files of any rate and channel count are converted in-process; other formats are refused (exit 2). Speech
that matches no command is rejected with its reason (exit 4), never forced onto the nearest command.

The n-gram decoder (:class:`knic.language.lmspeech.NgramRecognizer`) listens by default: it hears people's
phrasings better than the template grammar (``knic bench speech``) and starts in a fraction of the time
(its model is cached on disk; the grammar's word graph is compiled anew, about 2.5 s). ``--decoder grammar``
uses the template grammar (:class:`knic.language.speech.Recognizer`). Whisper hears the command first and
settles it when it is sure (:mod:`knic.language.whisperpass`).

A say daemon keeps a world's recogniser loaded between commands (:mod:`knic.language.sayd`): the first
``knic say`` in a world hears the command itself, in children forked at once while it loads the world
(:mod:`knic.language.oneshot`), and starts the daemon after printing the answer; the next ones check and
read the WAV file, send the audio to the daemon and print what it understood (the same text, JSON and exit
code), or hear it themselves as before when no daemon answers. ``--decoder grammar`` and
``--no-second-opinion`` never ask it. ``knic bench startup --runs 20`` on the project's 2-core machine shared
with other work (load 3-4, 29 Nov 2026): the first start in a world 3.7 s; later ones 1.15 s median through
the daemon (p90 1.5 s), against 3.1 s with the same recogniser and no daemon (each command Whisper does not
settle is judged by a Whisper server the say then loads itself); ``--no-second-opinion`` 1.0 s; ``knic goal``
0.37 s. Through the daemon a command Whisper settles took 0.4-0.8 s of the daemon's time, one it judges
0.7-1.9 s, and the say itself 0.15-0.25 s (the interpreter, its imports, the world key, printing).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

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


#: the world files :mod:`knic.language.world` reads by default (as its constants: that module is not imported
#: before the say daemon is asked, :mod:`knic.language.sayd`)
_WORLDS = Path(__file__).resolve().parents[2] / "worlds"
_DEFAULT_DOMAIN, _DEFAULT_PROBLEM = (
    _WORLDS / "erl_home" / "domain.pddl",
    _WORLDS / "erl_home" / "erl_home_problem.pddl",
)
_LEXICON_NAME = "lexicon.yaml"


def _world_files(args: argparse.Namespace) -> list[str]:
    """The files the world's vocabulary is read from: those the options name (a world's name as its file),
    their lexicons, the defaults."""
    world = getattr(args, "world", None)
    named = [args.domain or _DEFAULT_DOMAIN, world, args.problem, args.lexicon]
    if world is not None and world.isidentifier():  # a world's name (its file, whatever the folder holds)
        named += sorted(_WORLDS.glob(f"*/{world}.yaml"))
    if world is None and args.problem is None and args.domain is None:
        named.append(_DEFAULT_PROBLEM)
    files = [str(f) for f in named if f]
    return files + [str(Path(f).parent / _LEXICON_NAME) for f in files]


def run(args: argparse.Namespace) -> int:
    decoder = getattr(args, "decoder", "ngram")
    from knic.language.acoustic import acoustic_model_for

    args.acoustic_model = acoustic_model_for(decoder, args.acoustic_model)
    if decoder == "ngram" and args.second_opinion:
        understood = _asked(args)  # the say daemon, when one runs for this world
        if understood is not None:
            print_understanding(understood, args.json)
            return 0
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


def _audio(args: argparse.Namespace) -> bytes:
    """The WAV file as raw 16 kHz 16-bit PCM.

    Raises:
        AudioError: the file is missing, not a regular file, larger than :data:`MAX_AUDIO_BYTES` or no WAV
            file the decoders can take.
    """
    from core.errors import AudioError
    from core.inputs import check_input_file
    from knic.language.audio import command_pcm

    check_input_file(args.wav, MAX_AUDIO_BYTES, "audio file", AudioError)  # never read /dev/zero
    return command_pcm(args.wav)


def _asked(args: argparse.Namespace) -> dict[str, Any] | None:
    """The say daemon's understanding of the command (:mod:`knic.language.sayd`), or None: no daemon runs for
    this world, or it gave no answer (the command is then heard here). The file is checked and read first,
    as :func:`_run` does, so a bad file is the same error with or without a daemon.

    Raises:
        AudioError: as :func:`_audio`.
    """
    from knic.language import sayd
    from knic.language.oneshot import world_key

    if sayd.idle_s() <= 0:  # daemons are off
        return None
    audio = _audio(args)
    path = sayd.socket_path(world_key(_world_files(args), args.acoustic_model), args.acoustic_model)
    return sayd.ask(path, audio, args.speaker)


def _run(args: argparse.Namespace, decoder: str, passes: Passes | None) -> int:
    audio = _audio(args)  # refuse a bad file before loading the world
    kept = None
    if decoder == "ngram":
        from knic.language import oneshot
        from knic.language.acoustic import acoustic_model_options, ensemble_members

        for member in ensemble_members(args.acoustic_model):
            acoustic_model_options(member, decoder="ngram")  # a bad model: one line
        key = oneshot.world_key(_world_files(args), args.acoustic_model)
        kept = oneshot.remembered_vocabulary(key)
    if kept is not None:
        vocabulary, speaker = kept
    else:
        given, args.speaker = args.speaker, None
        vocabulary = load_vocabulary(args)  # who "me" is by default too, for the next start
        speaker = args.speaker
        if decoder == "ngram":
            oneshot.remember_vocabulary(key, vocabulary, speaker)
        args.speaker = given
    args.speaker = args.speaker or speaker
    from knic.language.lmspeech import NgramRecognizer, command_recognizer
    from knic.language.understanding import understand_transcript

    if passes is not None:
        remembered = oneshot.remembered_model(key)  # its command model judges Whisper's candidates
        ngram = NgramRecognizer(
            vocabulary,
            acoustic_model=args.acoustic_model,
            lazy=True,
            second_opinion=args.second_opinion,
            command_model=remembered[1] if remembered else None,
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
    try:
        print_understanding(result.to_dict(), args.json)
    finally:  # a refused command too: the next one is heard by the daemon
        if passes is not None:
            _keep_for_the_next(args, ngram, vocabulary, speaker, key)
    return 0


def _keep_for_the_next(
    args: argparse.Namespace, ngram: NgramRecognizer, vocabulary: Vocabulary, speaker: str, key: str
) -> None:
    """After the answer: the first start in a world keeps its command model (built now if Whisper settled
    the command without it), and a say daemon keeps everything loaded for the next command
    (:mod:`knic.language.sayd`; ``speaker``: who "me" is by default)."""
    from knic.language import oneshot, sayd

    if oneshot.remembered_model(key) is None:
        ngram.build()
        oneshot.remember_model(key, *(ngram.model_files or ("", None)))
    if args.second_opinion:
        files, model = _world_files(args), args.acoustic_model
        path, place = sayd.socket_path(key, model), sayd.place_of(files, model)
        sayd.ensure(path, place, vocabulary, speaker, model, key)


def _or(value: float | None, otherwise: Callable[[], float]) -> float:
    return value if value is not None else otherwise()
