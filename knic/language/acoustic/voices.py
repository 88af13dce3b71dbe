"""The voices that speak the acoustic adaptation's corpus (offline, like :mod:`.build`): espeak-ng accents and
variants, other engines' development voices, and the synthesis of one sentence to a 16 kHz mono WAV.

The voices of the spoken test and development sets are never used here (:data:`HELD_OUT_VOICES`,
:data:`RESERVED_OTHER_VOICES`), so those sets stay unheard by any adaptation.
"""

from __future__ import annotations

import subprocess
import tempfile
from pathlib import Path

#: espeak-ng voices (base language and variant) of the test and development sets: never used for adaptation.
HELD_OUT_VOICES = frozenset(
    {
        # test sets (tests/fixtures/speech, speech_people/test)
        "en-us+m5",
        "en-gb-x-rp+f4",
        "en-us+m1",
        # development sets (speech_people/dev, speech_ood_dev, speech_dev, speech_voices_dev)
        "en-us+m4",
        "en-gb+f3",
        "en-us+f4",
        "en-029",
        "en-gb+f1",
        "en-gb+f4",
        "en-gb+m2",
        "en-gb-scotland",
        "en-gb-x-gbclan",
        "en-us-nyc",
        "en-029+m7",
        "en-gb-scotland+m3",
        "en-gb-x-gbclan+f1",
        "en-us-nyc+f2",
    }
)
#: Voices of other engines than espeak-ng that adaptation may use: the development voices of
#: ``tests/fixtures/speech_engines_dev`` (the kal and slt speakers), as ``engine:voice``.
OTHER_VOICES = ("flite:kal16", "festival:kal_diphone", "flite:slt", "festival:cmu_us_slt_arctic_hts")
#: Other engines' voices reserved for a later test set (other speakers, and kal at 8 kHz): never used here.
RESERVED_OTHER_VOICES = frozenset({"flite:awb", "flite:rms", "festival:ked_diphone", "flite:kal"})
#: Duration stretch (1.0: the voice's own rate) of the other engines' voices, drawn for each sentence.
OTHER_STRETCH = (0.85, 1.25)
#: espeak-ng's English accents.
BASES = [
    "en-us",
    "en-gb",
    "en-gb-x-rp",
    "en-gb-scotland",
    "en-gb-x-gbclan",
    "en-gb-x-gbcwmd",
    "en-029",
    "en-us-nyc",
]
#: espeak-ng voice variants (pitch, formants, breath). The variants of the test set's voices (m1, m5, f4) and
#: of the people development set's (m4, f3) are left out with every accent, so both sets' voices stay unheard.
VARIANTS = [
    "",
    "m2",
    "m3",
    "m6",
    "m7",
    "m8",
    "f1",
    "f2",
    "f5",
    "Annie",
    "grandma",
    "grandpa",
    "aunty",
    "belinda",
    "benjamin",
    "edward",
    "linda",
    "steph",
    "john",
    "max",
    "quincy",
    "travis",
    "victor",
    "zac",
    "michael",
    "paul",
    "robert",
    "david",
]
#: espeak-ng voices for adaptation: every accent with every variant, less the held-out voices.
VOICES = [
    f"{base}+{variant}" if variant else base
    for variant in VARIANTS
    for base in BASES
    if (f"{base}+{variant}" if variant else base) not in HELD_OUT_VOICES
]
#: Speaking rates (words per minute) and pitch settings (espeak-ng ``-p``, 50 the voice's own) drawn
#: uniformly for each sentence.
SPEEDS = (120, 185)
PITCHES = (25, 75)
#: sox effects trimming silence (below 0.5 % of full scale) from the start, then (reversed) from the end.
TRIM_BOTH_ENDS = ["silence", "1", "0.02", "0.5%", "reverse", "silence", "1", "0.02", "0.5%", "reverse"]


def other_engine_wav(text: str, voice: str, stretch: float, raw: Path) -> None:
    """``text`` in another engine's ``voice`` (``flite:NAME`` or ``festival:NAME``) into the WAV ``raw``, in
    the engine's own sample rate. ``stretch``: duration factor (1.0: the voice's own rate; larger is slower).

    Raises:
        ValueError: the engine is neither flite nor festival.
    """
    engine, _, name = voice.partition(":")
    if engine == "flite":
        flags = ["--setf", f"duration_stretch={stretch:.3f}"]
        subprocess.run(["flite", "-voice", name, *flags, "-t", text, "-o", str(raw)], check=True)
    elif engine == "festival":
        if name.endswith("_hts"):  # the HTS engine ignores Duration_Stretch: its own speech rate instead
            rate = f'(set! hts_engine_params (append hts_engine_params (list (list "-r" {1 / stretch:.3f}))))'
        else:
            rate = f"(Parameter.set 'Duration_Stretch {stretch:.3f})"
        with tempfile.NamedTemporaryFile("w", suffix=".txt") as source:
            source.write(text + "\n")
            source.flush()
            text2wave = ["text2wave", "-eval", f"(voice_{name})", "-eval", rate, source.name, "-o", str(raw)]
            subprocess.run(text2wave, check=True, stdout=subprocess.DEVNULL)
    else:
        raise ValueError(f"unknown engine in voice {voice!r}: expected flite:NAME or festival:NAME")


def synthesize(text: str, voice: str, speed: float, target: Path, pitch: int = 50) -> None:
    """espeak-ng (or, for a voice ``engine:NAME``, :func:`other_engine_wav`) to a temporary WAV, then sox to
    16 kHz mono 16-bit with silence trimmed at both ends (no random dither, so the same engine version gives
    the same file). ``speed``: espeak-ng's words per minute, or the other engine's duration stretch.
    ``pitch``: espeak-ng's ``-p`` (50: the voice's own; other engines keep their own)."""
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "raw.wav"
        if ":" in voice:
            other_engine_wav(text, voice, speed, raw)
        else:
            espeak = ["espeak-ng", "-v", voice, "-s", str(speed), "-p", str(pitch), "-w", str(raw), text]
            subprocess.run(espeak, check=True)
        output = ["-r", "16000", "-c", "1", "-b", "16", str(target)]
        subprocess.run(["sox", "-R", str(raw), *output, *TRIM_BOTH_ENDS], check=True)


def other_voices(engines: list[str]) -> list[str]:
    """The other engines' voices that ``engines`` (``espeak``, ``flite``, ``festival`` or ``engine:NAME``)
    name, from :data:`OTHER_VOICES`.

    Raises:
        ValueError: an item names no development voice (a reserved voice, or an unknown engine or voice).
    """
    chosen: list[str] = []
    for item in engines:
        if item == "espeak":
            continue
        found = [v for v in OTHER_VOICES if v == item or v.partition(":")[0] == item]
        if not found:
            why = "reserved for a test set" if item in RESERVED_OTHER_VOICES else "not a development voice"
            raise ValueError(f"--engines {item!r}: {why} (choose from espeak, {', '.join(OTHER_VOICES)})")
        chosen += [v for v in found if v not in chosen]
    return chosen
