"""One spoken command from a cold start (``knic say``): both decoder passes run in child processes while the
parent imports the reader and reads the world's vocabulary, itself kept from the last start.

The n-gram pass needs the command model of the world's vocabulary, which the parent only knows after
loading the world. The model is built once (:class:`~knic.language.lmspeech.NgramRecognizer`) and kept in
the temporary folder; :func:`remember_model` writes down which dictionary and binary model belong to a
world's files (:func:`world_key`: their content, the command language's data and code, the acoustic model
and the decoder settings), so that the next start finds them (:func:`remembered_model`) before loading the
world and forks the n-gram pass at once, beside the phone loop (:func:`start_passes`, each in a child
process: :func:`in_child`); the vocabulary is kept too, as JSON data
(:func:`remember_vocabulary`), so the parent need not parse the world's PDDL again. A world whose files
changed has another key: its first start loads and decodes in the parent, as without this module, and
remembers both for the next.

Like the phone loop, this imports only pocketsphinx, the acoustic model's options and the audio helpers.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import LanguageError
from knic.language.acoustic import DEFAULT_NGRAM_ACOUSTIC_MODEL
from knic.language.phoneloop import NGRAM_DECODER_OPTIONS, NGRAM_TRAIL_SILENCE

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary

#: the code and data the command model and the vocabulary depend on, besides the world's files
_LANGUAGE = Path(__file__).resolve().parent
_CODE = [_LANGUAGE, _LANGUAGE.parents[1] / "knowledge_base", _LANGUAGE.parents[1] / "worlds"]
#: N-best hypotheses sent back by the child (the recogniser tries at most this many)
NBEST = 10
#: largest WAV file a child reads (as ``knic say``)
MAX_AUDIO_BYTES = 32 * 1024 * 1024

Decoded = tuple[str, float, int, tuple[str, ...]]


def world_key(
    files: Iterable[str | Path | None], acoustic_model: str | Path = DEFAULT_NGRAM_ACOUSTIC_MODEL
) -> str:
    """A key for the command model of a world: the content of its files (domain, problem or world file,
    lexicon), of the command language's code and data, the acoustic model and the decoder settings."""
    digest = hashlib.sha256()
    sources = sorted({str(Path(f).resolve()) for f in files if f})
    language = sorted(p for folder in _CODE for pattern in ("*.py", "*.yaml") for p in folder.glob(pattern))
    for path in [*sources, *map(str, language)]:
        digest.update(path.encode())
        with contextlib.suppress(OSError):
            digest.update(Path(path).read_bytes())
    digest.update(f"{acoustic_model}|{sorted(NGRAM_DECODER_OPTIONS.items())}".encode())
    return digest.hexdigest()[:24]


def _index(key: str) -> Path:
    return Path(tempfile.gettempdir()) / f"knic-oneshot-{key}.json"


def remember_model(key: str, dictionary: str, binary: Path | None) -> None:
    """Keep the dictionary text and note where the binary model of a world is (nothing when there is no
    binary copy; a failure to write leaves the next start to decode in its parent)."""
    if binary is None:
        return
    digest = hashlib.sha256(dictionary.encode()).hexdigest()[:20]
    words = Path(tempfile.gettempdir()) / f"knic-oneshot-{digest}.dict"
    with contextlib.suppress(OSError):
        if not words.is_file():
            words.write_text(dictionary, encoding="utf-8")
        _index(key).write_text(json.dumps({"dict": str(words), "lm": str(binary)}), encoding="utf-8")


def remembered_model(key: str) -> tuple[Path, Path] | None:
    """The dictionary and binary model remembered for a world key, when both are still there."""
    try:
        entry = json.loads(_index(key).read_text(encoding="utf-8"))
        files = Path(entry["dict"]), Path(entry["lm"])
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return files if all(f.is_file() for f in files) else None


def _vocabulary_file(key: str) -> Path:
    return Path(tempfile.gettempdir()) / f"knic-oneshot-{key}-vocabulary.json"


def remember_vocabulary(key: str, vocabulary: Vocabulary, speaker: str) -> None:
    """Keep a world's vocabulary and who "me" is there by default (JSON data, never code)."""
    with contextlib.suppress(OSError):
        data = {"vocabulary": vocabulary.to_data(), "speaker": speaker}
        _vocabulary_file(key).write_text(json.dumps(data), encoding="utf-8")


def remembered_vocabulary(key: str) -> tuple[Vocabulary, str] | None:
    """The vocabulary and default speaker kept for a world key, or None (a damaged copy counts as none)."""
    from knic.language.vocabulary import Vocabulary

    try:
        data = json.loads(_vocabulary_file(key).read_text(encoding="utf-8"))
        return Vocabulary.from_data(data["vocabulary"]), str(data["speaker"])
    except (OSError, ValueError, KeyError, TypeError, LanguageError):
        return None


def decode_here(samples: bytes, model: tuple[Path, Path], acoustic_model: str | Path) -> Decoded:
    """The n-gram pass of one utterance with a remembered model (what the child runs).

    Raises:
        RuntimeError, ValueError, KeyError, TypeError: pocketsphinx refused the model or the settings.
    """
    from pocketsphinx import Decoder, set_loglevel

    from knic.language.acoustic import acoustic_model_options
    from knic.language.audio import pad_pcm

    set_loglevel("FATAL")
    options = {**NGRAM_DECODER_OPTIONS, **acoustic_model_options(acoustic_model, decoder="ngram")}
    decoder = Decoder(lm=None, loglevel="FATAL", **{**options, "dict": str(model[0])})
    decoder.add_lm_file("ngram", str(model[1]))
    decoder.activate_search("ngram")
    decoder.start_utt()
    decoder.process_raw(pad_pcm(samples, NGRAM_TRAIL_SILENCE), full_utt=True)
    decoder.end_utt()
    hyp = decoder.hyp()
    frames = max(1, decoder.n_frames())
    if hyp is None:
        return "", 0.0, frames, ()
    nbest: list[str] = []
    with contextlib.suppress(RuntimeError, ValueError):  # no lattice
        for entry in decoder.nbest():
            if entry is None or not entry.hypstr:  # pocketsphinx can yield an empty entry
                continue
            nbest.append(" ".join(entry.hypstr.split()))
            if len(nbest) == NBEST:
                break
    return " ".join(hyp.hypstr.split()), float(hyp.best_score), frames, tuple(nbest)


def in_child(job: Callable[[], Any]) -> Callable[[], Any]:
    """Run ``job`` in a forked child; the returned call waits for its result (JSON-able), or None when the
    child failed or ``os.fork`` is missing (the caller then does the work itself).

    Call it before the process starts threads. A result never asked for leaves the child to finish alone.
    """
    if not hasattr(os, "fork"):
        return lambda: None
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: work, write the result as JSON, leave without the parent's exit handlers
        status = 1
        try:
            os.close(read_end)
            with os.fdopen(write_end, "w", encoding="utf-8") as pipe:
                pipe.write(json.dumps(job()))
            status = 0
        except BaseException:  # any failure: the parent does the work itself
            status = 1
        finally:
            os._exit(status)
    os.close(write_end)

    def wait() -> Any:
        try:
            with os.fdopen(read_end, "r", encoding="utf-8") as pipe:
                data = pipe.read()
        finally:
            with contextlib.suppress(ChildProcessError):
                os.waitpid(pid, 0)
        try:
            return json.loads(data)
        except ValueError:
            return None

    return wait


def start_passes(
    wav: str, files: Iterable[str | Path | None], acoustic_model: str | Path = DEFAULT_NGRAM_ACOUSTIC_MODEL
) -> tuple[Callable[[], list[Decoded] | None], Callable[[int], float | None]]:
    """Fork the n-gram pass (with the model remembered for the world's ``files``) and the phone loop of the
    WAV file ``wav`` for each member model of ``acoustic_model``
    (:func:`~knic.language.acoustic.ensemble_members`), each in a child that reads the file itself. The
    first call returns every member's n-gram result, the second a member's phone-loop score (by index);
    either gives None (no model remembered, an unusable file: the caller decodes itself and reports the
    file's fault)."""
    from knic.language.acoustic import ensemble_members

    files = list(files)
    members = ensemble_members(acoustic_model)

    def samples() -> bytes:
        from core.errors import AudioError
        from core.inputs import check_input_file
        from knic.language.audio import load_pcm

        check_input_file(wav, MAX_AUDIO_BYTES, "audio file", AudioError)  # never read /dev/zero
        return load_pcm(wav)

    def ngram(member: str | Path) -> Callable[[], Decoded | None]:
        def job() -> Decoded | None:
            model = remembered_model(world_key(files, acoustic_model))
            return decode_here(samples(), model, member) if model else None

        return job

    def phones(member: str | Path) -> Callable[[], float]:
        def job() -> float:
            from knic.language.audio import pad_pcm
            from knic.language.phoneloop import PhoneLoop

            return PhoneLoop(member).score(pad_pcm(samples(), NGRAM_TRAIL_SILENCE))

        return job

    decoded = [in_child(ngram(member)) for member in members]
    scores = [in_child(phones(member)) for member in members]

    def got_decoded() -> list[Decoded] | None:
        found: list[Decoded] = []
        for wait in decoded:
            result = wait()
            if not isinstance(result, list) or len(result) != 4:
                return None
            text, path_score, frames, nbest = result
            found.append((str(text), float(path_score), int(frames), tuple(str(h) for h in nbest)))
        return found

    def got_score(index: int) -> float | None:
        result = scores[index]()
        return float(result) if isinstance(result, (int, float)) else None

    return got_decoded, got_score
