"""One spoken command from a cold start (``knic say``): both decoder passes run in child processes while the
parent imports the reader and reads the world's vocabulary, itself kept from the last start.

The n-gram pass needs the command model of the world's vocabulary, which the parent only knows after
loading the world. The model is built once (:class:`~knic.language.lmspeech.NgramRecognizer`) and kept in
the temporary folder; :func:`remember_model` writes down which dictionary and binary model belong to a
world's files (:func:`world_key`: their content, the command language's data and code, the acoustic model
and the decoder settings), so that the next start finds them (:func:`remembered_model`) before loading the
world and forks the n-gram pass of each member model at once, beside the first member's phone loop
(:func:`start_passes`, each in a child process: :func:`in_child`; another member's phone loop is only run
when that member is chosen, in the parent); the vocabulary is kept too, as JSON data
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
import signal
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import LanguageError
from knic.language.acoustic import DEFAULT_NGRAM_ACOUSTIC_MODEL
from knic.language.phoneloop import (
    NGRAM_DECODER_OPTIONS,
    Decoded,
    as_decoded,
    ngram_padded,
    ngram_pass,
)

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary
    from knic.language.whisperpass import Heard

#: the code and data the command model and the vocabulary depend on, besides the world's files
_LANGUAGE = Path(__file__).resolve().parent
_CODE = [_LANGUAGE, _LANGUAGE.parents[1] / "knowledge_base", _LANGUAGE.parents[1] / "worlds"]
#: N-best hypotheses sent back by the child (the recogniser tries at most this many)
NBEST = 10
#: largest WAV file a child reads (as ``knic say``)
MAX_AUDIO_BYTES = 32 * 1024 * 1024
#: niceness added to the phone-loop child: its score is needed last (after the n-gram passes and the
#: reader), so the n-gram children and the parent go first on a busy machine
PHONE_LOOP_NICENESS = 5


def world_key(
    files: Iterable[str | Path | None], acoustic_model: str | Path = DEFAULT_NGRAM_ACOUSTIC_MODEL
) -> str:
    """A key for the command model of a world: the content of its files (domain, problem or world file,
    lexicon), of the command language's code and data, the acoustic model and the decoder settings."""
    digest = hashlib.sha256()
    sources = sorted({str(Path(f).resolve()) for f in files if f})
    patterns = ("*.py", "*.yaml", "*.txt")  # code, command language, people's phrasings
    language = sorted(p for folder in _CODE for pattern in patterns for p in folder.glob(pattern))
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


def decoder_for(model: tuple[Path, Path], acoustic_model: str | Path) -> Any:
    """A pocketsphinx decoder searching a remembered model (dictionary, binary model) with an acoustic model.

    Raises:
        RuntimeError, ValueError, KeyError, TypeError: pocketsphinx refused the model or the settings.
    """
    from pocketsphinx import Decoder, set_loglevel

    from knic.language.acoustic import acoustic_model_options

    set_loglevel("FATAL")
    options = {**NGRAM_DECODER_OPTIONS, **acoustic_model_options(acoustic_model, decoder="ngram")}
    decoder = Decoder(lm=None, loglevel="FATAL", **{**options, "dict": str(model[0])})
    decoder.add_lm_file("ngram", str(model[1]))
    decoder.activate_search("ngram")
    return decoder


def decode_here(samples: bytes, model: tuple[Path, Path], acoustic_model: str | Path) -> Decoded:
    """The n-gram pass of one utterance with a remembered model (what the child runs).

    Raises:
        RuntimeError, ValueError, KeyError, TypeError: pocketsphinx refused the model or the settings.
    """
    return ngram_pass(decoder_for(model, acoustic_model), ngram_padded(samples), NBEST)


class Child:
    """A job running in a forked child (:func:`in_child`): calling it waits for the result."""

    def __init__(self, pid: int, read_end: int):
        self.pid, self._read_end = pid, read_end
        self._done = pid == 0

    def __call__(self) -> Any:
        """The job's result (JSON data), or None when the child failed, was cancelled or never started."""
        if self._done:
            return None
        self._done = True
        try:
            with os.fdopen(self._read_end, "r", encoding="utf-8") as pipe:
                data = pipe.read()
        finally:
            with contextlib.suppress(ChildProcessError):
                os.waitpid(self.pid, 0)
        try:
            return json.loads(data)
        except ValueError:
            return None

    def cancel(self) -> None:
        """Stop the child if its result was never asked for (a pass no longer needed takes no more CPU)."""
        if self._done:
            return
        self._done = True
        with contextlib.suppress(OSError):
            os.close(self._read_end)
        with contextlib.suppress(OSError):
            os.kill(self.pid, signal.SIGKILL)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(self.pid, 0)


def in_child(job: Callable[[], Any]) -> Child:
    """Run ``job`` in a forked child; calling the returned :class:`Child` waits for its result (JSON-able),
    or gives None when the child failed or ``os.fork`` is missing (the caller then does the work itself).

    Call it before the process starts threads. :meth:`Child.cancel` stops a child whose result is not needed.
    """
    if not hasattr(os, "fork"):
        return Child(0, -1)
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
    return Child(pid, read_end)


class Passes:
    """The decoder passes of one utterance running in children (:func:`start_passes`)."""

    def __init__(self, decoded: list[Child], scores: list[Child], heard: Child | None = None):
        self._decoded, self._scores, self._heard = decoded, scores, heard

    def decoded(self) -> list[Decoded] | None:
        """Every member's n-gram result, or None (no model remembered, an unusable file: the caller decodes
        itself and reports the file's fault)."""
        found: list[Decoded] = []
        for wait in self._decoded:
            result = as_decoded(wait())
            if result is None:
                return None
            found.append(result)
        return found

    def phone_score(self, index: int) -> float | None:
        """A member's phone-loop score (by index), or None (not run in a child, or the child failed: the
        caller computes it)."""
        result = self._scores[index]() if index < len(self._scores) else None
        return float(result) if isinstance(result, (int, float)) else None

    def heard(self) -> Heard | None:
        """Whisper's hearing (:mod:`knic.language.whisperpass`), or None (not run in a child, or it failed:
        the caller hears it itself)."""
        from knic.language.whisperpass import heard_of

        return heard_of(self._heard()) if self._heard is not None else None

    @property
    def _children(self) -> list[Child]:
        return [*self._decoded, *self._scores, *([self._heard] if self._heard is not None else [])]

    @property
    def pids(self) -> list[int]:
        """The children's process ids (n-gram passes, phone loops, then Whisper)."""
        return [child.pid for child in self._children]

    def close(self) -> None:
        """Stop the children whose results were not asked for."""
        for child in self._children:
            child.cancel()


def start_passes(
    wav: str,
    files: Iterable[str | Path | None],
    acoustic_model: str | Path = DEFAULT_NGRAM_ACOUSTIC_MODEL,
    phone_loops: int = 1,
    second_opinion: bool = True,
) -> Passes:
    """Fork the n-gram pass (with the model remembered for the world's ``files``) of the WAV file ``wav``
    for each member model of ``acoustic_model`` (:func:`~knic.language.acoustic.ensemble_members`), and the
    phone loop of the first ``phone_loops`` members (the first is chosen for most utterances; a later
    member's phone loop is computed by the caller when that member is chosen), each in a child that reads
    the file itself, and with ``second_opinion`` Whisper's hearing with the world's remembered vocabulary
    (:mod:`knic.language.whisperpass`). pocketsphinx and the audio helpers are imported here once, before
    the forks, not in each child, and the phone loop runs at a lower priority (:data:`PHONE_LOOP_NICENESS`).
    ``knic say`` on the 42 utterances of speech_people/test, 2 cores shared with other work (load 4.4-5.3),
    median wall time of 30 alternating runs: every member's phone loop up front 1.14 s; the first member's
    only 0.96 s; with the imports before the forks 0.91 s; and the lower priority 0.87 s."""
    import pocketsphinx  # noqa: F401  (imported once for all the children)

    import core.inputs  # noqa: F401
    import knic.language.audio  # noqa: F401
    from knic.language.acoustic import ensemble_members

    files = list(files)
    members = ensemble_members(acoustic_model)

    def samples() -> bytes:
        from core.errors import AudioError
        from core.inputs import check_input_file
        from knic.language.audio import command_pcm

        check_input_file(wav, MAX_AUDIO_BYTES, "audio file", AudioError)  # never read /dev/zero
        return command_pcm(wav)

    def ngram(member: str | Path) -> Callable[[], Decoded | None]:
        def job() -> Decoded | None:
            model = remembered_model(world_key(files, acoustic_model))
            return decode_here(samples(), model, member) if model else None

        return job

    def phones(member: str | Path) -> Callable[[], float]:
        def job() -> float:
            from knic.language.phoneloop import PhoneLoop

            with contextlib.suppress(OSError):
                os.nice(PHONE_LOOP_NICENESS)
            return PhoneLoop(member).score_of(samples())

        return job

    def hear() -> list[object] | None:
        import numpy as np

        from knic.language.whisperpass import WhisperPass, model_dir, world_prompt

        kept, folder = remembered_vocabulary(world_key(files, acoustic_model)), model_dir()
        if kept is None or folder is None:
            return None
        heard = WhisperPass(world_prompt(kept[0]), folder=folder).hear(np.frombuffer(samples(), dtype="<i2"))
        return [heard.text, heard.mean_log_prob]

    decoded = [in_child(ngram(member)) for member in members]
    scores = [in_child(phones(member)) for member in members[: max(0, phone_loops)]]
    return Passes(decoded, scores, in_child(hear) if second_opinion else None)
