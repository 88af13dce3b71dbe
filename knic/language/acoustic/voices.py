"""The voices that speak the acoustic adaptation's corpus (offline, like :mod:`.build`): espeak-ng accents and
variants, other engines' development voices, and the synthesis of one sentence to a 16 kHz mono WAV.

The voices of the spoken test and development sets are never used here (:data:`HELD_OUT_VOICES`,
:data:`RESERVED_OTHER_VOICES`), so those sets stay unheard by any adaptation.
"""

from __future__ import annotations

import random
import shutil
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


#: Name prefix of the random speakers' espeak-ng variants (:func:`random_speakers`). Made-up speakers were
#: meant to make the adaptation hear unheard espeak-ng variants better. Tried on 28 Nov 2026 (``build
#: --random-speakers 0.5``, 200 speakers, otherwise the shipped build), as the ``auto`` ensemble's first
#: member, frame+args on the spoken dev sets: speech_people/dev 0.922 -> 0.887, speech_voices_dev 0.869 ->
#: 0.857, speech_people2/dev 0.800 -> 0.756, other engines' voices unchanged; as a third member 0.875 ->
#: 0.877 overall at a third more CPU. The shipped adaptation does not use them.
RANDOM_SPEAKER_PREFIX = "knic_speaker_"
#: Ranges of the random speakers' parameters, about those the adaptation's own variants (:data:`VARIANTS`)
#: span: voice pitch base and range (Hz-like espeak-ng units) by gender, a vocal-tract scale of every formant
#: frequency (percent) with a small spread per formant, formant heights and widths (percent).
SPEAKER_PITCH = {"male": (70, 125), "female": (125, 200)}
SPEAKER_PITCH_RANGE = (30, 120)
SPEAKER_TRACT = {"male": (86, 104), "female": (100, 118)}
SPEAKER_FORMANT_SPREAD = 5
SPEAKER_HEIGHT = (65, 135)
SPEAKER_WIDTH = (70, 150)
#: Made-up speakers one espeak-ng data folder holds (espeak-ng lists 349 voices, the English accents among
#: them).
MAX_SPEAKERS = 300


def random_speaker(rng: random.Random, name: str) -> str:
    """An espeak-ng voice variant file of a made-up speaker: gender, pitch, a vocal-tract length (all formant
    frequencies scaled together, each by a little more or less), formant heights and widths, and now and then
    roughness, flutter, breath or echo."""
    gender = rng.choice(("male", "female"))
    base = rng.randint(*SPEAKER_PITCH[gender])
    tract = rng.randint(*SPEAKER_TRACT[gender])
    lines = [
        "language variant",
        f"name {name}",
        f"gender {gender}",
        f"pitch {base} {base + rng.randint(*SPEAKER_PITCH_RANGE)}",
    ]
    for formant in range(9):
        frequency = tract + rng.randint(-SPEAKER_FORMANT_SPREAD, SPEAKER_FORMANT_SPREAD)
        lines.append(
            f"formant {formant} {frequency} {rng.randint(*SPEAKER_HEIGHT)} {rng.randint(*SPEAKER_WIDTH)}"
        )
    if rng.random() < 0.3:
        lines.append(f"roughness {rng.randint(1, 4)}")
    if rng.random() < 0.3:
        lines.append(f"flutter {rng.randint(2, 25)}")
    if rng.random() < 0.2:
        lines.append("breath " + " ".join(str(rng.randint(0, 4)) for _ in range(8)))
    if rng.random() < 0.3:
        lines.append(f"echo {rng.randint(100, 150)} {rng.randint(5, 15)}")
    return "\n".join(lines) + "\n"


def espeak_data_dir() -> Path:
    """The installed espeak-ng's data folder (``espeak-ng-data``).

    Raises:
        FileNotFoundError: espeak-ng's data folder is not where Debian installs it.
    """
    for parent in (Path("/usr/lib/x86_64-linux-gnu"), Path("/usr/lib/aarch64-linux-gnu"), Path("/usr/share")):
        if (parent / "espeak-ng-data" / "voices").is_dir():
            return parent / "espeak-ng-data"
    raise FileNotFoundError("espeak-ng-data not found: apt-get install espeak-ng")


def random_speakers(count: int, folder: Path, seed: int = 13) -> list[str]:
    """A copy of espeak-ng's data under ``folder`` (for ``espeak-ng --path``) with ``count`` made-up
    speakers (:func:`random_speaker`) among its variants; their variant names."""
    data = folder / "espeak-ng-data"
    if not data.is_dir():
        shutil.copytree(espeak_data_dir(), data)
        # espeak-ng lists at most 349 voices (languages and variants) and silently ignores the rest, the
        # made-up ones among them: keep only its English accents and the made-up variants
        for language in (data / "lang").rglob("*"):
            if language.is_file() and not language.name.lower().startswith("en"):
                language.unlink()
        for variant in (data / "voices" / "!v").iterdir():
            variant.unlink()
    if count > MAX_SPEAKERS:
        raise ValueError(f"{count} made-up speakers: espeak-ng lists at most {MAX_SPEAKERS}")
    rng = random.Random(seed)
    names = [f"{RANDOM_SPEAKER_PREFIX}{index:03d}" for index in range(count)]
    for name in names:
        (data / "voices" / "!v" / name).write_text(random_speaker(rng, name), encoding="utf-8")
    return names


def synthesize(
    text: str, voice: str, speed: float, target: Path, pitch: int = 50, espeak_path: Path | None = None
) -> None:
    """espeak-ng (or, for a voice ``engine:NAME``, :func:`other_engine_wav`) to a temporary WAV, then sox to
    16 kHz mono 16-bit with silence trimmed at both ends (no random dither, so the same engine version gives
    the same file). ``speed``: espeak-ng's words per minute, or the other engine's duration stretch.
    ``pitch``: espeak-ng's ``-p`` (50: the voice's own; other engines keep their own). ``espeak_path``: the
    folder holding the ``espeak-ng-data`` to use (:func:`random_speakers`; default: the installed one)."""
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "raw.wav"
        if ":" in voice:
            other_engine_wav(text, voice, speed, raw)
        else:
            where = [f"--path={espeak_path}"] if espeak_path else []
            espeak = [
                "espeak-ng",
                *where,
                "-v",
                voice,
                "-s",
                str(speed),
                "-p",
                str(pitch),
                "-w",
                str(raw),
                text,
            ]
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
