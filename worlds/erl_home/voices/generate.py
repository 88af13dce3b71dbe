"""Regenerate the voice bank of the Granny Annie task: what the simulated people say, as WAV recordings.

Offline tool (needs ``espeak-ng`` and ``sox`` on PATH; nothing at run time or in the tests does)::

    .venv/bin/python worlds/erl_home/voices/generate.py

Each line of :data:`REQUESTS` and :data:`ANSWERS` is synthesised in the speaker's voice, converted to 16 kHz
mono 16-bit WAV with half a second of trailing silence, and listed in ``bank.yaml`` (file, speaker, kind,
text). The scenario ``granny_annie`` and the benchmark's spoken episodes pick their requests from that file.
"""

from __future__ import annotations

import subprocess
import tempfile
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent

#: speaker -> (espeak-ng voice, words per minute)
VOICES = {"annie": ("en-us+f4", 140)}

#: what Annie asks for, one to three chained actions, in the words of the ERL task
REQUESTS = [
    "bring me my glasses",
    "bring me the remote",
    "get me the tablet",
    "fetch me the mug",
    "bring me the juice",
    "bring me an apple from the kitchen cabinet",
    "switch on the bedroom lights",
    "switch on the hallway light",
    "set the dimmer to fifty percent",
    "open the blinds",
    "half open the blinds",
    "find the remote",
    "locate the tablet",
    "look for the candle",
    "locate the tablet and bring it to me",
    "find my glasses and bring them to me",
    "switch on the left light and bring me the remote",
    "open the blinds and bring me my glasses",
    "switch on the hallway light and find the mug",
    "locate tracy and lead her to the kitchen",
    "lead tracy to the bedroom and bring me the water",
    "switch on the bedroom lights, find the candle and bring me the juice",
    "locate tracy, lead her to the bedroom, and bring me an apple from the kitchen cabinet",
    "open the blinds, switch on the right light and bring me the tablet",
]

#: yes/no answers to the robot's "Is that right?"
ANSWERS = {"yes": ["yes", "yes please", "that is right"], "no": ["no", "no that is wrong"]}


def synthesize(text: str, voice: str, speed: int, target: Path) -> None:
    """espeak-ng, then sox to 16 kHz mono 16-bit, silence trimmed and 0.5 s of silence appended."""
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "raw.wav"
        subprocess.run(["espeak-ng", "-v", voice, "-s", str(speed), "-w", str(raw), text], check=True)
        trim = ["silence", "1", "0.05", "0.5%", "reverse", "silence", "1", "0.05", "0.5%", "reverse"]
        subprocess.run(
            [
                "sox",
                "-R",
                str(raw),
                "-r",
                "16000",
                "-c",
                "1",
                "-b",
                "16",
                str(target),
                *trim,
                "pad",
                "0",
                "0.5",
            ],
            check=True,
        )


def main() -> None:
    entries = []
    for speaker, (voice, speed) in VOICES.items():
        folder = HERE / speaker
        folder.mkdir(exist_ok=True)
        lines = [("request", t) for t in REQUESTS] + [(kind, t) for kind, ts in ANSWERS.items() for t in ts]
        counters: dict[str, int] = {}
        for kind, text in lines:
            counters[kind] = counters.get(kind, 0) + 1
            name = f"{speaker}/{kind}_{counters[kind]:02d}.wav"
            synthesize(text, voice, speed, HERE / name)
            entries.append({"file": name, "speaker": speaker, "kind": kind, "text": text})
    header = "# The voice bank of the Granny Annie task, written by generate.py (do not edit by hand).\n"
    (HERE / "bank.yaml").write_text(header + yaml.safe_dump({"utterances": entries}, sort_keys=False))


if __name__ == "__main__":
    main()
