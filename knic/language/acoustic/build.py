"""Rebuild the shipped acoustic adaptation from synthetic speech (offline: not needed to run or test).

Run from the repository root; needs ``espeak-ng`` and ``sox`` (synthesis) and Debian's ``sphinxtrain``,
``sphinxbase-utils`` and ``pocketsphinx`` packages (``sphinx_fe``, ``bw``, ``mllr_solve``, ``map_adapt``,
``mk_s2sendump``, ``pocketsphinx_mdef_convert``)::

    apt-get install espeak-ng sox sphinxtrain sphinxbase-utils pocketsphinx
    .venv/bin/python -m knic.language.acoustic.build

What it does:

1. Samples ``--sentences`` commands from the command grammar (random walks over the recogniser's word graph,
   fixed seed), leaving out every sentence of the test set (``tests/fixtures/speech``), the development set
   (``tests/fixtures/speech_dev``) and any ``--exclude`` gold file, and speaks each with one of
   :data:`VOICES` -- espeak-ng voices none of which is a voice of either set -- at a speed between 130 and
   175 words per minute. With ``--corpus DIR`` it uses recordings instead (a ``gold.json`` in the test set's
   layout: ``file`` and ``text`` of each utterance), e.g. of the people a robot serves.
2. Extracts features with the model's own ``feat.params`` (``sphinx_fe``), counts state occupancies with
   Baum-Welch (``bw``) against the wheel's US English model, and estimates a MAP update of the Gaussian means,
   variances and mixture weights (``map_adapt``; the wheel ships only the quantised ``sendump``, so the
   mixture weights are first expanded from it, see :func:`sendump_to_mixw`).
3. Writes the adapted ``means``, ``variances`` and ``sendump`` into :data:`~knic.language.acoustic.MODEL_DIR`
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
from pathlib import Path

import numpy as np

from knic.language.acoustic import MODEL_DIR, wheel_model_dir

ROOT = Path(__file__).resolve().parents[3]
TEST_SET = ROOT / "tests" / "fixtures" / "speech" / "gold.json"
DEV_SET = ROOT / "tests" / "fixtures" / "speech_dev" / "gold.json"

#: espeak-ng voices for adaptation: none is a voice (base and variant together) of the test or dev set.
VOICES = [
    "en-gb-x-gbcwmd",
    "en-us+m2",
    "en-us+m6",
    "en-us+f1",
    "en-us+f5",
    "en-gb+f2",
    "en-gb+m1",
    "en-gb+m7",
    "en-gb-x-rp+f5",
    "en-gb-scotland+m3",
    "en-us+Annie",
    "en-gb+grandma",
    "en-us+grandpa",
    "en-029+f3",
    "en-gb-x-gbclan+m6",
    "en-us-nyc+f2",
]
#: sox effects trimming silence (below 0.5 % of full scale) from the start, then (reversed) from the end.
TRIM_BOTH_ENDS = ["silence", "1", "0.02", "0.5%", "reverse", "silence", "1", "0.02", "0.5%", "reverse"]


def sample_sentences(count: int, exclude: set[str], seed: int = 7) -> list[str]:
    """``count`` distinct commands from random walks over the command word graph (no filler loop)."""
    from knic.language.fsg import compile_word_graph
    from knic.language.understanding import default_grammar, understand
    from knic.language.world import load_world

    _, vocabulary = load_world()
    graph = compile_word_graph(default_grammar(), vocabulary)
    moves: dict[int, list[tuple[int, str]]] = {}
    for src, dst, _, word in graph.transitions:
        moves.setdefault(src, []).append((dst, word))
    rng = random.Random(seed)
    sentences: list[str] = []
    seen = set(exclude)
    while len(sentences) < count:
        state, words = graph.start, list[str]()
        while state != graph.final and state in moves and len(words) < 16:
            state, word = rng.choice(moves[state])
            words.append(word)
        text = " ".join(words)
        if state != graph.final or text in seen or not understand(text, vocabulary).accepted:
            continue
        seen.add(text)
        sentences.append(text)
    return sentences


def synthesize(text: str, voice: str, speed: int, target: Path) -> None:
    """espeak-ng to a temporary WAV, then sox to 16 kHz mono 16-bit with silence trimmed at both ends (no
    random dither, so the same espeak-ng version gives the same file)."""
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "raw.wav"
        subprocess.run(["espeak-ng", "-v", voice, "-s", str(speed), "-w", str(raw), text], check=True)
        output = ["-r", "16000", "-c", "1", "-b", "16", str(target)]
        subprocess.run(["sox", "-R", str(raw), *output, *TRIM_BOTH_ENDS], check=True)


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
    work: Path, model: dict[str, Path], target: Path, dictionary: Path, tau: float, log: Path
) -> tuple[dict[str, Path], int]:
    """One round: Baum-Welch counts of the corpus under ``model``, then a MAP update written to ``target``.

    Returns:
        (the updated model's files, the number of utterances Baum-Welch could align).
    """
    acc = work / "acc"
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
    before = log.read_text().count(" ignored") if log.exists() else 0
    run([str(SPHINXTRAIN / "bw"), *common, *features, *lexicon, *corpus, "-accumdir", str(acc)], log)
    skipped = log.read_text().count(" ignored") - before
    target.mkdir(parents=True, exist_ok=True)
    updated = {name: target / name for name in MODEL_FILES}
    tau_flags = ["-fixedtau", "yes", "-tau", str(tau)] if tau > 0 else []
    run(
        [
            str(SPHINXTRAIN / "map_adapt"),
            *common,
            "-accumdir",
            str(acc),
            *model_flags(updated, "map"),
            *tau_flags,
        ],
        log,
    )
    total = len((work / "fileids").read_text().split())
    return updated, total - skipped


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sentences", type=int, default=480)
    parser.add_argument("--workdir", default="", help="keep the corpus and accumulators here")
    parser.add_argument("--exclude", action="append", default=[], help="another gold.json to keep out")
    parser.add_argument("--tau", type=float, default=0.0, help="MAP prior weight (0: map_adapt's default)")
    parser.add_argument("--corpus", default="", help="adapt to these recordings (folder with gold.json)")
    parser.add_argument("--iterations", type=int, default=2, help="Baum-Welch + MAP rounds (3 overfits)")
    parser.add_argument("--out", default=str(MODEL_DIR))
    args = parser.parse_args(argv)
    work = Path(args.workdir or tempfile.mkdtemp(prefix="knic-adapt-"))
    (work / "wav").mkdir(parents=True, exist_ok=True)
    log = work / "build.log"
    log.unlink(missing_ok=True)
    ids: list[str] = []
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
        exclude: set[str] = set()
        for gold in [TEST_SET, DEV_SET, *map(Path, args.exclude)]:
            if gold.exists():
                exclude |= {u["text"] for u in json.loads(gold.read_text(encoding="utf-8"))["utterances"]}
        sentences = sample_sentences(args.sentences, exclude)
        rng = random.Random(11)
        for index, text in enumerate(sentences):
            name = f"adapt_{index:04d}"
            target = work / "wav" / f"{name}.wav"
            if not target.exists():
                synthesize(text, VOICES[index % len(VOICES)], rng.randint(130, 175), target)
            ids.append(name)
        voices = VOICES
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
        current, count = adapt_once(work, current, work / f"map{iteration}", model, args.tau, log)
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
        "excluded_gold_files": [str(p.relative_to(ROOT)) for p in (TEST_SET, DEV_SET)] + args.exclude,
        "iterations": args.iterations,
        "aligned_utterances_per_iteration": aligned,
    }
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"adapted model written to {out} (work files in {work})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
