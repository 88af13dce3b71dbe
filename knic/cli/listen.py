"""``knic listen``: listen continuously and print every command heard, with its frames and PDDL goals.

Audio comes from the default microphone (ALSA's ``arecord``), from standard input (``--stdin``: raw
16 kHz mono signed 16-bit PCM from any recorder) or from a WAV file replayed as a live stream (``--wav``).
Voice activity detection cuts it into utterances (:mod:`knic.language.listen`); each is recognised and
understood as ``knic say`` would. An utterance that is not a command is printed as rejected and listening
goes on. ``--json`` prints one JSON object per utterance (JSON Lines) with its start and end time in the
stream. It stops at the end of the stream, after ``--count`` utterances, or on Ctrl-C.
"""

from __future__ import annotations

import argparse
import json

from core.errors import AudioError
from knic.cli.goal import add_world_arguments, load_vocabulary
from knic.cli.say import add_acoustic_argument, add_decoder_argument


def add_arguments(parser: argparse.ArgumentParser) -> None:
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--stdin", action="store_true", help="read raw 16 kHz mono s16le PCM from stdin")
    source.add_argument("--wav", metavar="FILE.wav", help="replay a recording as a live stream")
    parser.add_argument("--count", type=int, default=0, help="stop after N utterances (0: never)")
    add_world_arguments(parser)
    add_acoustic_argument(parser)
    add_decoder_argument(parser)


def run(args: argparse.Namespace) -> int:
    from knic.language.listen import open_source, segments
    from knic.language.lmspeech import command_recognizer
    from knic.language.understanding import understand_transcript

    stream, recorder = open_source(stdin=args.stdin, wav=args.wav)
    vocabulary = load_vocabulary(args)
    recognizer = command_recognizer(
        vocabulary,
        decoder=getattr(args, "decoder", "ngram"),
        acoustic_model=args.acoustic_model,
        second_opinion=getattr(args, "second_opinion", True),
    )
    heard = 0
    try:
        if not args.json:
            print("listening (Ctrl-C to stop)", flush=True)
        for segment in segments(stream):
            result = understand_transcript(
                recognizer.recognize(segment.audio), vocabulary, speaker=args.speaker
            )
            data = {"start": round(segment.start, 2), "end": round(segment.end, 2), **result.to_dict()}
            if args.json:
                print(json.dumps(data), flush=True)
            else:
                verdict = (
                    "goals " + " ".join(data["goals"]) if result.accepted else f"rejected: {result.reason}"
                )
                print(
                    f"[{data['start']:.2f}-{data['end']:.2f} s] "
                    f"heard: {data.get('transcript') or '(nothing)'}"
                )
                print(f"  {verdict}", flush=True)
            heard += 1
            if args.count and heard >= args.count:
                break
    except KeyboardInterrupt:
        pass
    finally:
        if recorder is not None:
            recorder.terminate()
            code = recorder.wait()
            if heard == 0 and code not in (0, -15):
                raise AudioError(f"the microphone recorder (arecord) failed with exit code {code}")
    return 0
