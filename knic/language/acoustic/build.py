"""Rebuild the shipped acoustic adaptation from synthetic speech (offline: not needed to run or test).

Run from the repository root; needs ``espeak-ng`` and ``sox`` (synthesis) and Debian's ``sphinxtrain``,
``sphinxbase-utils`` and ``pocketsphinx`` packages (``sphinx_fe``, ``bw``, ``mllr_solve``, ``map_adapt``,
``mk_s2sendump``, ``pocketsphinx_mdef_convert``)::

    apt-get install espeak-ng sox sphinxtrain sphinxbase-utils pocketsphinx
    .venv/bin/python -m knic.language.acoustic.build

What it does:

1. Samples ``--sentences`` commands from the command templates (:mod:`knic.language.sampling`, the source
   of the n-gram model, with another seed), leaving out every sentence of the spoken test and development
   sets and of the text sets (:data:`HELD_OUT_SETS`, :data:`TEXT_SETS`) and of any ``--exclude`` gold file,
   and speaks each in a voice drawn from :data:`.voices.VOICES` -- every espeak-ng English accent with
   every variant of :data:`VARIANTS`, less the voices of the test and development sets
   (:data:`HELD_OUT_VOICES`) -- at a
   speed and pitch drawn from :data:`SPEEDS` and :data:`PITCHES` (``--jobs`` at a time). With ``--engines
   espeak,flite,festival`` (``flite`` and ``festival`` need Debian's ``flite``, ``festival``,
   ``festvox-kallpc16k`` and ``festvox-us-slt-hts``) ``--other-sentences`` more sentences, sampled after
   those (so the espeak-ng part is that of an espeak-ng build), are spoken in the other engines' development
   voices (:data:`OTHER_VOICES`; an item ``engine:voice`` names one voice) at a duration stretch drawn from
   :data:`OTHER_STRETCH`; their reserved voices (:data:`RESERVED_OTHER_VOICES`) are never used (this helps
   the voices heard, not other engines' voices: see ``tests/fixtures/speech_engines_dev/generate.py``). With
   ``--corpus DIR`` it uses recordings instead (a ``gold.json`` in the test set's layout: ``file`` and
   ``text`` of each utterance), e.g. of the people a robot serves.
2. Extracts features with the model's own ``feat.params`` (``sphinx_fe``), counts state occupancies with
   Baum-Welch (``bw``, ``--jobs`` processes on shares of the corpus) against the wheel's US English model,
   and estimates a MAP update of the Gaussian means, variances and mixture weights (``map_adapt``; the wheel
   ships only the quantised ``sendump``, so the mixture weights are first expanded from it, see
   :func:`sendump_to_mixw`); ``--iterations`` rounds, each counting under the previous round's model (the
   first round aligns fewer utterances: the wheel's model fails on many espeak-ng variants).
3. Writes the adapted ``means``, ``variances`` and ``sendump`` into ``--out`` (default the n-gram decoder's
   ``espeak/ngram``; the grammar decoder's ``espeak`` itself was built by the 480-sentence version of 27 Nov)
   with a ``manifest.json`` of what was used. The mdef, transition matrices and dictionary stay the wheel's.
"""

from __future__ import annotations

import argparse
import json
import random
import shutil
import struct
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from knic.language.acoustic import MODEL_DIR, NGRAM_SUBFOLDER, wheel_model_dir
from knic.language.acoustic.voices import (
    BASES,
    HELD_OUT_VOICES,
    OTHER_STRETCH,
    PITCHES,
    RESERVED_OTHER_VOICES,
    SPEEDS,
    VOICES,
    other_voices,
    random_speakers,
    synthesize,
)

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "tests" / "fixtures"
#: The spoken test and development sets: their sentences are kept out of the adaptation corpus.
HELD_OUT_SETS = [
    FIXTURES / name / "gold.json"
    for name in (
        "speech",
        "speech_people/test",
        "speech_dev",
        "speech_people/dev",
        "speech_voices_dev",
        "speech_ood_dev",
        "speech_engines_dev",
        "speech_people2/test",
    )
]
#: The text test and development sets (people's phrasings), kept out likewise.
TEXT_SETS = [
    FIXTURES / "language" / "test.yaml",
    FIXTURES / "language" / "dev.yaml",
    *sorted((FIXTURES / "language").glob("people*/*.yaml")),
]


def sample_sentences(count: int, exclude: set[str], seed: int = 7) -> list[str]:
    """``count`` distinct commands sampled from the command templates (:mod:`knic.language.sampling`, with a
    seed other than the n-gram model's), none of them in ``exclude`` and none with a word the pronunciation
    dictionary lacks."""
    from knic.language.commands import command_language
    from knic.language.sampling import sample_sentences as sample_templates
    from knic.language.world import load_world

    _, vocabulary = load_world()
    known = {
        line.split(maxsplit=1)[0].split("(")[0]
        for line in (wheel_model_dir() / "cmudict-en-us.dict").read_text(errors="replace").splitlines()
        if line.strip()
    }
    unknown = frozenset(w for w in vocabulary.words() | command_language().words() if w not in known)
    sentences: list[str] = []
    seen = set(exclude)
    for sample in sample_templates(vocabulary, count * 3, seed=seed, exclude_words=unknown, frames=False):
        if sample.text in seen or not set(sample.text.split()) <= known:
            continue
        seen.add(sample.text)
        sentences.append(sample.text)
        if len(sentences) == count:
            break
    return sentences


def held_out_sentences() -> set[str]:
    """The normalised sentences of every test and development set (speech and text): kept out."""
    import yaml

    from knic.language.vocabulary import normalize

    texts: set[str] = set()
    for gold in HELD_OUT_SETS:
        if gold.exists():
            texts |= {u["text"] for u in json.loads(gold.read_text(encoding="utf-8"))["utterances"]}
    for cases in TEXT_SETS:
        if cases.exists():
            texts |= {str(c["text"]) for c in yaml.safe_load(cases.read_text(encoding="utf-8"))["cases"]}
    return {normalize(t) for t in texts}


def _read_string(data: bytes, offset: int) -> tuple[str | None, int]:
    (size,) = struct.unpack_from("<i", data, offset)
    offset += 4
    if size == 0:
        return None, offset
    return data[offset : offset + size - 1].decode("ascii", "replace"), offset + size


def sendump_to_mixw(sendump: Path, target: Path) -> tuple[int, int, int]:
    """Expand pocketsphinx's quantised mixture weights (``sendump``) into a sphinxtrain ``mixture_weights``
    file. Each byte is a negated log weight (base 1.0001) shifted right by ``mixw_shift`` bits.

    Returns:
        (senones, streams, densities).
    """
    data = sendump.read_bytes()
    _, offset = _read_string(data, 0)
    header: dict[str, int] = {}
    while True:
        text, offset = _read_string(data, offset)
        if text is None:
            break
        key, _, value = text.partition(" ")
        if value.strip().lstrip("-").isdigit():
            header[key] = int(value)
    shift = header.get("mixw_shift", 10)
    streams = header.get("feature_count", 1)
    if header.get("cluster_count", 0):
        raise RuntimeError(f"{sendump}: clustered sendump files are not supported")
    densities, senones = struct.unpack_from("<ii", data, offset)
    offset += 8
    raw = np.frombuffer(data, dtype=np.uint8, count=streams * densities * senones, offset=offset)
    logs = raw.reshape(streams, densities, senones).astype(np.float64) * (1 << shift)
    weights = np.power(1.0001, -logs).transpose(2, 0, 1)  # senone, stream, density
    weights /= weights.sum(axis=2, keepdims=True)
    _write_s3(target, weights.astype(np.float32))
    return senones, streams, densities


def _write_s3(target: Path, array: np.ndarray) -> None:
    """A sphinxtrain binary array file: text header (padded to a 4-byte boundary), byte-order magic,
    dimensions, element count, float32 data."""
    with target.open("wb") as out:
        head = b"s3\nversion 1.0\n"  # no chksum0 line: readers expect a checksum whenever it is present
        pad = -(len(head) + len(b"endhdr\n")) % 4  # the data must start 4-byte aligned
        out.write(head + b" " * pad + b"endhdr\n")
        out.write(struct.pack("<I", 0x11223344))
        out.write(struct.pack("<" + "I" * array.ndim, *array.shape))
        out.write(struct.pack("<I", array.size))
        out.write(np.ascontiguousarray(array, dtype="<f4").tobytes())


def run(cmd: list[str], log: Path) -> None:
    with log.open("a") as handle:
        handle.write("$ " + " ".join(cmd) + "\n")
        handle.flush()
        subprocess.run(cmd, check=True, stdout=handle, stderr=subprocess.STDOUT)


#: The model files a round reads and writes, and the sphinxtrain flag of each (``-meanfn``, ``-mapmeanfn``).
MODEL_FILES = {
    "means": "meanfn",
    "variances": "varfn",
    "mixture_weights": "mixwfn",
    "transition_matrices": "tmatfn",
}
SPHINXTRAIN = Path("/usr/lib/sphinxtrain")


def model_flags(files: dict[str, Path], prefix: str = "") -> list[str]:
    """``["-meanfn", ".../means", "-varfn", ...]`` (with ``prefix="map"``: ``-mapmeanfn`` ...)."""
    return [item for name, flag in MODEL_FILES.items() for item in (f"-{prefix}{flag}", str(files[name]))]


def adapt_once(
    work: Path,
    model: dict[str, Path],
    target: Path,
    dictionary: Path,
    tau: float,
    log: Path,
    parts: int = 1,
) -> tuple[dict[str, Path], int]:
    """One round: Baum-Welch counts of the corpus under ``model`` (in ``parts`` parallel processes, each on
    its share of the utterances), then a MAP update written to ``target``.

    Returns:
        (the updated model's files, the number of utterances Baum-Welch could align).
    """
    accs = [work / f"acc{part}" for part in range(1, parts + 1)]
    for acc in accs:
        shutil.rmtree(acc, ignore_errors=True)
        acc.mkdir()
    common = ["-moddeffn", str(work / "mdef.txt"), "-ts2cbfn", ".ptm.", *model_flags(model)]
    features = ["-feat", "1s_c_d_dd", "-svspec", "0-12/13-25/26-38", "-cmn", "batch", "-agc", "none"]
    lexicon = [
        "-dictfn",
        str(dictionary / "cmudict-en-us.dict"),
        "-fdictfn",
        str(dictionary / "en-us" / "noisedict"),
    ]
    corpus = [
        "-ctlfn",
        str(work / "fileids"),
        "-lsnfn",
        str(work / "transcription"),
        "-cepdir",
        str(work / "mfc"),
    ]
    bw = [str(SPHINXTRAIN / "bw"), *common, *features, *lexicon, *corpus]
    logs = [work / f"bw{part}.log" for part in range(1, parts + 1)]
    for part_log in logs:
        part_log.write_text("")
    with ThreadPoolExecutor(max_workers=parts) as pool:
        done = [
            pool.submit(run, [*bw, "-npart", str(parts), "-part", str(part), "-accumdir", str(acc)], part_log)
            for part, (acc, part_log) in enumerate(zip(accs, logs, strict=True), start=1)
        ]
        for future in done:
            future.result()
    skipped = 0
    with log.open("a") as handle:
        for part_log in logs:
            text = part_log.read_text()
            skipped += text.count(" ignored")
            handle.write(text)
    target.mkdir(parents=True, exist_ok=True)
    updated = {name: target / name for name in MODEL_FILES}
    tau_flags = ["-fixedtau", "yes", "-tau", str(tau)] if tau > 0 else []
    run(
        [
            str(SPHINXTRAIN / "map_adapt"),
            *common,
            "-accumdir",
            ",".join(map(str, accs)),  # a list option: comma-separated
            *model_flags(updated, "map"),
            *tau_flags,
        ],
        log,
    )
    total = len((work / "fileids").read_text().split())
    return updated, total - skipped


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sentences", type=int, default=3000)
    parser.add_argument("--workdir", default="", help="keep the corpus and accumulators here")
    parser.add_argument("--exclude", action="append", default=[], help="another gold.json to keep out")
    parser.add_argument("--tau", type=float, default=0.0, help="MAP prior weight (0: map_adapt's default)")
    parser.add_argument("--corpus", default="", help="adapt to these recordings (folder with gold.json)")
    parser.add_argument("--iterations", type=int, default=2, help="Baum-Welch + MAP rounds (3 overfits)")
    parser.add_argument("--out", default=str(MODEL_DIR / NGRAM_SUBFOLDER))
    parser.add_argument("--jobs", type=int, default=2, help="parallel synthesis and Baum-Welch processes")
    parser.add_argument(
        "--engines",
        default="espeak",
        help="comma-separated engines to speak in: espeak, flite, festival, or one voice engine:NAME",
    )
    parser.add_argument(
        "--other-sentences", type=int, default=1000, help="sentences in other engines' voices (see --engines)"
    )
    parser.add_argument(
        "--random-speakers",
        type=float,
        default=0.0,
        help="share of the espeak-ng sentences spoken by made-up speakers (voices.random_speaker)",
    )
    parser.add_argument("--speakers", type=int, default=200, help="made-up speakers to draw from")
    args = parser.parse_args(argv)
    engines = [item.strip() for item in args.engines.split(",") if item.strip()]
    others = other_voices(engines)
    espeak_count = args.sentences if "espeak" in engines else 0
    other_count = args.other_sentences if others else 0
    work = Path(args.workdir or tempfile.mkdtemp(prefix="knic-adapt-"))
    (work / "wav").mkdir(parents=True, exist_ok=True)
    log = work / "build.log"
    log.unlink(missing_ok=True)
    ids: list[str] = []
    spoken: dict[str, int] = {}  # utterances per voice
    if args.corpus:
        corpus = Path(args.corpus)
        entries = json.loads((corpus / "gold.json").read_text(encoding="utf-8"))["utterances"]
        sentences = [e["text"] for e in entries]
        for entry in entries:
            name = Path(entry["file"]).stem
            to_16k = ["-r", "16000", "-c", "1", "-b", "16"]
            subprocess.run(
                ["sox", str(corpus / entry["file"]), *to_16k, str(work / "wav" / f"{name}.wav")], check=True
            )
            ids.append(name)
        voices: list[str] = [f"recordings in {corpus}"]
    else:
        exclude = held_out_sentences()
        for gold in map(Path, args.exclude):
            exclude |= {u["text"] for u in json.loads(gold.read_text(encoding="utf-8"))["utterances"]}
        sentences = sample_sentences(espeak_count + other_count, exclude)  # the same first ones for any count
        rng = random.Random(11)
        other_rng = random.Random(12)  # a stream of its own: espeak-ng's draws stay those of an espeak build
        speaker_rng = random.Random(14)  # likewise: the stock voices drawn stay those of a build without
        made_up = random_speakers(args.speakers, work / "espeak") if args.random_speakers > 0 else []
        espeak_path = work / "espeak" if made_up else None
        jobs: list[tuple[str, str, float, Path, int, Path | None]] = []
        for index, text in enumerate(sentences):
            name = f"adapt_{index:04d}"
            target = work / "wav" / f"{name}.wav"
            if index < espeak_count:
                voice = rng.choice(VOICES)
                speed: float = rng.randint(*SPEEDS)
                pitch = rng.randint(*PITCHES)
                where: Path | None = None
                if made_up and speaker_rng.random() < args.random_speakers:
                    voice = f"{speaker_rng.choice(BASES)}+{speaker_rng.choice(made_up)}"
                    where = espeak_path
            else:
                voice = other_rng.choice(others)
                speed = round(other_rng.uniform(*OTHER_STRETCH), 2)
                pitch = 50  # unused: the other engines keep their voices' pitch
                where = None
            spoken[voice] = spoken.get(voice, 0) + 1
            if not target.exists():
                jobs.append((text, voice, speed, target, pitch, where))
            ids.append(name)
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            list(pool.map(lambda job: synthesize(*job), jobs))
        voices = sorted(spoken) if others or made_up else VOICES
    (work / "fileids").write_text("".join(f"{i}\n" for i in ids))
    (work / "transcription").write_text(
        "".join(f"<s> {t} </s> ({i})\n" for i, t in zip(ids, sentences, strict=True))
    )
    model = wheel_model_dir()
    hmm = model / "en-us"
    (work / "mfc").mkdir(exist_ok=True)
    run(
        [
            "sphinx_fe",
            "-argfile",
            str(hmm / "feat.params"),
            "-samprate",
            "16000",
            "-c",
            str(work / "fileids"),
            "-di",
            str(work / "wav"),
            "-do",
            str(work / "mfc"),
            "-ei",
            "wav",
            "-eo",
            "mfc",
            "-mswav",
            "yes",
        ],
        log,
    )
    run(["pocketsphinx_mdef_convert", "-text", str(hmm / "mdef"), str(work / "mdef.txt")], log)
    current = {
        "means": hmm / "means",
        "variances": hmm / "variances",
        "mixture_weights": work / "mixture_weights",
        "transition_matrices": hmm / "transition_matrices",
    }
    sendump_to_mixw(hmm / "sendump", current["mixture_weights"])
    aligned: list[int] = []
    for iteration in range(1, args.iterations + 1):
        current, count = adapt_once(work, current, work / f"map{iteration}", model, args.tau, log, args.jobs)
        aligned.append(count)
    run(
        [
            str(SPHINXTRAIN / "mk_s2sendump"),
            "-pocketsphinx",
            "yes",
            "-moddeffn",
            str(work / "mdef.txt"),
            "-mixwfn",
            str(current["mixture_weights"]),
            "-sendumpfn",
            str(work / "sendump"),
        ],
        log,
    )
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name, source in (("means", current["means"]), ("variances", current["variances"])):
        shutil.copyfile(source, out / name)
    shutil.copyfile(work / "sendump", out / "sendump")
    manifest = {
        "method": "MAP (sphinxtrain map_adapt) from the pocketsphinx wheel's en-us model",
        "sentences": len(sentences),
        "voices": voices,
        "tau": args.tau or "map_adapt default",
        "excluded_sentences": [str(p.relative_to(ROOT)) for p in (*HELD_OUT_SETS, *TEXT_SETS)] + args.exclude,
        "held_out_voices": sorted(HELD_OUT_VOICES),
        "speeds_wpm": list(SPEEDS),
        "pitches": list(PITCHES),
        "iterations": args.iterations,
        "aligned_utterances_per_iteration": aligned,
    }
    if made_up:
        manifest["random_speakers"] = {"share": args.random_speakers, "speakers": len(made_up), "seed": 13}
    if others:
        manifest["engines"] = engines
        manifest["espeak_sentences"] = espeak_count
        manifest["other_sentences"] = other_count
        manifest["other_stretch"] = list(OTHER_STRETCH)
        manifest["utterances_per_other_voice"] = {v: n for v, n in sorted(spoken.items()) if ":" in v}
        manifest["reserved_voices"] = sorted(RESERVED_OTHER_VOICES)
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"adapted model written to {out} (work files in {work})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
