"""Spoken commands through an n-gram model: speech that is phrased unlike every template is still heard.

The grammar decoder (:class:`knic.language.speech.Recognizer`) only hears sentences of the templates. This
recogniser searches a back-off trigram model (:mod:`knic.language.ngram`) of sentences sampled from the same
templates with the world's names (:mod:`knic.language.sampling`), so word orders and combinations the
templates never produced stay reachable; the reader (:mod:`knic.language.reader`) then understands the words.
When the best hypothesis is no command the reader reads, the first of the :data:`NBEST` best hypotheses that
it reads is taken instead (the recogniser snaps to what the text side understands). A last word or two that
the best path had not finished when the audio ended (often a word heard in the silence after the command:
"bring me my glasses please but") is dropped when the reader reads the rest the same way; on the spoken dev
sets this took the word error rate from 0.125 to 0.065 (speech_people/dev), 0.134 to 0.087
(speech_voices_dev) and 0.153 to 0.125 (speech_people2/dev), every reading unchanged. Before all that, last
words of the best path that start after the speech has ended by its energy
(:data:`~knic.language.phoneloop.SPEECH_END_DROP_DB`) are dropped when the reader reads the rest, whether or
not the reading changes ("can you see if tracy is in the kitchen cupboard": the kitchen).

Out-of-domain speech: an n-gram search also forces any audio onto some word sequence of the model. Each
utterance is therefore decoded a second time with pocketsphinx's unconstrained phone loop (the wheel's
``en-us-phone.lm.bin``, in a decoder of its own at half the frame rate: :data:`PHONE_DECODER_OPTIONS`); the
confidence is the log-likelihood ratio of the two best paths per frame
(:func:`~knic.language.membership.confidence`). Command speech fits the command model about as well as the
free phone loop (confidence near zero); other speech fits it much worse. Below the model's threshold
(:data:`~knic.language.membership.CONFIDENCE_THRESHOLD`) the transcript is marked out of domain; what the
reader does not understand is rejected by the reader whatever the confidence, which already turns away most
other speech. The threshold was set on the development sets only (``knic bench speech --decoder ngram``).

A second opinion: Whisper (:mod:`knic.language.whisperpass`) hears each utterance first, in a server process
of its own. When Whisper is sure of its transcript, the reader reads it and the command model has its every
word, that transcript is taken and pocketsphinx does not decode (:func:`~knic.language.whisperpass.settled`,
:meth:`~knic.language.commandfit.CommandFit.knows`); otherwise Whisper judges among the transcripts both
recognisers offer (:mod:`knic.language.judging`). Settling took dev frame+args from 0.880 to 0.926; judging
took a dev set in voices no adaptation heard from 0.65 to 0.83 and other speech rejected from 0.940 to 0.970.
Judging, not settling, what has a word no command says took the eight spoken dev sets from 506 to 511 of 549
commands (37 of 247 settled utterances judged instead: 5 right that were wrong, none wrong that were right).
Judged among Whisper's own beam alone, without waiting for pocketsphinx, they gave 510, and 16-30 ms less per
utterance on the sets of commands; that was kept while Whisper ran on two threads. On one
(:data:`~knic.language.whisperpass.SERVER_THREADS`) every utterance is faster, and judging with pocketsphinx's
candidates too was chosen again: on the nine spoken dev sets 534 of 579 commands against 533, other speech
196 of 202 both, about 5% more CPU.
``second_opinion=False`` turns both off.

Lifecycle: build once per vocabulary (sampling and estimating the model take a few seconds; the model is
cached on disk by content), then :meth:`NgramRecognizer.recognize` per utterance; not thread-safe. With
several acoustic models the n-gram passes of the later ones run in forked worker processes
(:mod:`knic.language.passworker`), beside the first one's in this process: :meth:`NgramRecognizer.close`
stops them (so does the recogniser's garbage collection or the process's exit).
"""

from __future__ import annotations

import math
import struct
import tempfile
import time
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from core.errors import LanguageError
from knic.language.acoustic import (
    DEFAULT_NGRAM_ACOUSTIC_MODEL,
    acoustic_model_for,
    acoustic_model_options,
    ensemble_members,
    wheel_model_dir,
)
from knic.language.audio import Transcript, duration_of, pcm_bytes
from knic.language.commandfit import CommandFit
from knic.language.commands import command_language
from knic.language.judging import Judging
from knic.language.lmfiles import binary_model, build_model, dictionary_lines, model_words
from knic.language.membership import CONFIDENCE_THRESHOLD, MODEL_THRESHOLDS, choose_member, confidence
from knic.language.passworker import PassWorker, start_worker
from knic.language.phoneloop import (
    NGRAM_DECODER_OPTIONS,
    PHONE_DECODER_OPTIONS,
    Decoded,
    PhoneLoop,
    as_decoded,
    ngram_padded,
    ngram_pass,
)
from knic.language.reader import Reader
from knic.language.understanding import reader_check, reader_for, reading_of
from knic.language.vocabulary import Vocabulary
from knic.language.whisperpair import PairedServer
from knic.language.whisperpass import (
    Heard,
    Opinion,
    WhisperServer,
    model_dir,
    settled,
    world_prompt,
)

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

#: Hypotheses of the N-best list tried when the best one is not a command the reader understands (dev:
#: frame+args 0.71 -> 0.76 with 10; 30 gave the same).
NBEST = 10
#: Hypotheses (the best, then the N-best) tried without their last one or two words when none is read whole
#: (dev: see :data:`~knic.language.phoneloop.NGRAM_TRAIL_SILENCE`).
TRIMMED = 3


class _Member:
    """One acoustic model of a recogniser: its n-gram decoder, phone loop and threshold."""

    def __init__(self, model: str | Path, options: dict[str, object], threshold: float | None):
        self.model = model
        self.options = options
        self.threshold = (
            threshold if threshold is not None else MODEL_THRESHOLDS.get(str(model), CONFIDENCE_THRESHOLD)
        )
        self.decoder: Any = None
        self.initial_cmn: Any = None
        self.phone_loop: PhoneLoop | None = None


class NgramRecognizer:
    """pocketsphinx decoding with the command n-gram model and a phone-loop confidence.

    Args:
        vocabulary: the world's spoken names.
        acoustic_model: as for :class:`~knic.language.speech.Recognizer`, or a name of
            :data:`~knic.language.acoustic.ENSEMBLES`: each utterance is then decoded with every member model
            and the transcript of the one that fits it best is kept
            (:func:`~knic.language.membership.choose_member`).
        threshold: confidence below which a transcript is out of domain (default: each model's own,
            :data:`~knic.language.membership.MODEL_THRESHOLDS`).
        decoder_options: pocketsphinx options over :data:`NGRAM_DECODER_OPTIONS`.
        nbest: when the best hypothesis is no command the reader reads, the first of this many N-best
            hypotheses it reads becomes the transcript (0: the best hypothesis, always).
        reads: whether the reader understands a text (default: the world's
            :class:`~knic.language.reader.Reader` reads it, or finds it ambiguous).
        phone_options: pocketsphinx options of the phone-loop pass (:class:`PhoneLoop`) over
            ``decoder_options`` and :data:`PHONE_DECODER_OPTIONS`.
        lazy: build the decoders when they are first needed (not when the decoding is done elsewhere:
            :meth:`recognize` ``decoded``).
        parallel: run the n-gram passes of the members after the first in forked worker processes, forked
            after the first decoding (the same results as in this process, which decodes them itself where
            ``os.fork`` is missing or a worker failed).
        second_opinion: hear each utterance with Whisper first (:mod:`knic.language.whisperpass`, in a
            server process of its own) and take its transcript where
            :func:`~knic.language.whisperpass.settled` says so; off, or without the model installed,
            pocketsphinx alone.
        command_model: the command model in pocketsphinx's binary form, for judging a ``lazy`` recogniser's
            candidates before its decoders are built (:mod:`knic.language.commandfit`); a built recogniser
            uses its own.

    Raises:
        LanguageError: pocketsphinx refuses the options, the model or the phone loop.
    """

    def __init__(
        self,
        vocabulary: Vocabulary,
        *,
        acoustic_model: str | Path = DEFAULT_NGRAM_ACOUSTIC_MODEL,
        threshold: float | None = None,
        decoder_options: Mapping[str, object] | None = None,
        nbest: int = NBEST,
        reads: Callable[[str], bool] | None = None,
        phone_options: Mapping[str, object] | None = None,
        lazy: bool = False,
        parallel: bool = True,
        second_opinion: bool = True,
        command_model: Path | None = None,
    ):
        self.nbest = nbest
        reader = None if reads else reader_for(vocabulary)  # the one understanding reads with
        self.reads = reads or reader_check(reader or Reader(vocabulary))
        #: what the reader reads a text as (None: unread), to drop unfinished last words that change nothing
        #: (not with a ``reads`` of one's own)
        self._reading = reading_of(reader) if reader else None
        self._vocabulary = vocabulary
        self._decoder_options = dict(decoder_options or {})
        self._members = [
            _Member(
                model,
                {
                    **NGRAM_DECODER_OPTIONS,
                    **acoustic_model_options(model, decoder="ngram"),
                    **self._decoder_options,
                },
                threshold,
            )
            for model in ensemble_members(acoustic_model)
        ]
        self._phone_options = {**self._decoder_options, **PHONE_DECODER_OPTIONS, **(phone_options or {})}
        self._built = False
        #: the command model's fit of a transcript, for judging (:mod:`knic.language.commandfit`): read from
        #: ``command_model`` when first needed, or taken from the decoders once built
        self._command_fit: CommandFit | None = None
        self._command_model = command_model
        self._parallel = parallel
        self._workers: list[PassWorker | None] | None = None
        #: the model's dictionary and binary language model, once built (what :mod:`knic.language.oneshot`
        #: remembers for the next one-shot start)
        self.model_files: tuple[str, Path | None] | None = None
        self._prompt = world_prompt(vocabulary) if second_opinion and model_dir() else None
        #: Whisper's server (:class:`~knic.language.whisperpass.WhisperServer`), started with the decoders
        self.whisper: WhisperServer | None = None
        if not lazy:
            self.build()
            if self._prompt is not None:
                self._server()  # it loads the model meanwhile

    @property
    def members(self) -> tuple[str | Path, ...]:
        """The acoustic models each utterance is decoded with, the preferred first."""
        return tuple(member.model for member in self._members)

    def build(self) -> None:
        """Build the n-gram decoders now (on first use when the recogniser was made ``lazy``); their files
        are :attr:`model_files` then."""
        if self._built:
            return
        from pocketsphinx import Decoder, set_loglevel

        set_loglevel("FATAL")
        vocabulary = self._vocabulary
        words = vocabulary.words() | command_language().words()
        first = self._members[0].options
        source = Path(str(first.get("dict") or wheel_model_dir() / "cmudict-en-us.dict"))
        lines = dictionary_lines(source, words)
        known = {line.split(maxsplit=1)[0].split("(")[0] for line in lines}
        self.unknown_words = sorted(w for w in words if w not in known)
        arpa = build_model(vocabulary, exclude=frozenset(self.unknown_words))
        lines = dictionary_lines(source, words | model_words(arpa))  # the templates' own words too
        binary: Path | None = None
        with tempfile.TemporaryDirectory(prefix="knic-lm-") as tmp:
            # only the model's words in the dictionary: with the wheel's whole dictionary (134k words)
            # pocketsphinx took about 30 s to add the model, with these well under one
            dictionary = Path(tmp) / "commands.dict"
            dictionary.write_text("".join(lines), encoding="utf-8")
            for member in self._members:
                options = member.options
                try:
                    decoder = Decoder(lm=None, loglevel="FATAL", **{**options, "dict": str(dictionary)})
                except (KeyError, ValueError, TypeError, RuntimeError) as exc:
                    raise LanguageError(f"pocketsphinx refused the decoder options {options}: {exc}") from exc
                try:
                    model, binary = binary_model(decoder, arpa)
                    if self._command_fit is None:
                        self._command_fit = CommandFit(model, decoder.logmath)
                    decoder.add_lm("ngram", model)
                    decoder.activate_search("ngram")
                except (RuntimeError, ValueError) as exc:
                    raise LanguageError(f"pocketsphinx refused the command language model: {exc}") from exc
                member.decoder, member.initial_cmn = decoder, decoder.get_cmn()
        self._built = True
        self.model_files = ("".join(lines), binary)

    def phone_loop_of(self, index: int = 0) -> PhoneLoop:
        """The phone-loop pass of a member model, built on first use (it is not needed for speech the reader
        refuses)."""
        member = self._members[index]
        if member.phone_loop is None:
            member.phone_loop = PhoneLoop(member.model, self._phone_options)
        return member.phone_loop

    @property
    def phone_loop(self) -> PhoneLoop:
        """The first member's phone-loop pass."""
        return self.phone_loop_of(0)

    def threshold_of(self, index: int = 0) -> float:
        """The confidence threshold of a member model."""
        return self._members[index].threshold

    def _decode(self, raw: bytes) -> list[Decoded]:
        """Every member's n-gram pass (the later members' in their workers meanwhile)."""
        self.build()
        workers = self._workers or [None] * (len(self._members) - 1)
        request = struct.pack("!I", max(0, self.nbest)) + raw
        sent = [worker is not None and worker.submit(request) for worker in workers]
        first = self._members[0]
        results = [ngram_pass(first.decoder, raw, self.nbest, first.initial_cmn)]
        for member, worker, asked in zip(self._members[1:], workers, sent, strict=True):
            got = as_decoded(worker.result()) if worker is not None and asked else None
            results.append(got or ngram_pass(member.decoder, raw, self.nbest, member.initial_cmn))
        if self._workers is None and self._parallel and len(self._members) > 1:
            # forked after the first utterance, not before: a new pocketsphinx decoder scores its first
            # utterance slightly differently from the later ones, so this process's copies of the decoders
            # must have decoded too, to give the same results as the workers should one of them fail
            self._workers = [start_worker(_ngram_job(member)) for member in self._members[1:]]
        return results

    def _server(self) -> WhisperServer:
        """Whisper's server, started on first use."""
        if self.whisper is None:
            self.whisper = PairedServer(self._prompt or "")
        return self.whisper

    @property
    def whisper_pid(self) -> int | None:
        """The process id of the running Whisper server (None: none)."""
        return self.whisper.pid if self.whisper is not None else None

    @property
    def worker_pids(self) -> tuple[int, ...]:
        """The process ids of the live worker processes (none before the end of the first decoding)."""
        return tuple(w.pid for w in self._workers or [] if w is not None and w.alive)

    def close(self) -> None:
        """Stop the worker processes; the recogniser still decodes, every pass in this process."""
        self._parallel = False
        for worker in self._workers or []:
            if worker is not None:
                worker.close()
        self._workers = None
        if self.whisper is not None:
            self.whisper.close()

    def __enter__(self) -> NgramRecognizer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _snap(self, text: str, hypotheses: list[str]) -> tuple[str, bool]:
        """The best hypothesis if the reader reads it, else the first N-best one it reads, else the first of
        the :data:`TRIMMED` best that it reads without its last word or two (a word heard in the silence
        after the command: "... from the kitchen cabinet take"), else the best; and whether the reader reads
        the one returned."""
        if not text:
            return text, False
        if self.reads(text):
            return text, True
        if self.nbest <= 0:
            return text, False
        hypotheses = hypotheses[: self.nbest]
        snapped = next((h for h in hypotheses if h and h != text and self.reads(h)), None)
        if snapped:
            return snapped, True
        for hypothesis in [text, *(h for h in hypotheses if h != text)][:TRIMMED]:
            words = hypothesis.split()
            for cut in (1, 2):
                shorter = " ".join(words[:-cut])
                if len(words) > cut + 1 and self.reads(shorter):
                    return shorter, True
        return text, False

    def _command(self) -> CommandFit | None:
        """The command model's fit (:mod:`knic.language.commandfit`), None while the model is neither built
        nor given."""
        if self._command_fit is None and self._command_model is not None:
            self._command_fit = CommandFit.read(self._command_model)
            self._command_model = None  # read once, or not at all
        return self._command_fit

    def _fit(self, text: str) -> float:
        """The command model's fit of a transcript; 0.0 for every text without the model (judging is then
        by Whisper's score alone)."""
        command = self._command()
        return command(text) if command is not None else 0.0

    def _command_knows(self, text: str) -> bool:
        """Whether the command model has every word of a transcript Whisper would settle (True without the
        model: Whisper settles as before)."""
        command = self._command()
        return command.knows(text) if command is not None else True

    def _unheard_tail(self, text: str) -> str:
        """``text`` without its last word or two when the best path had not finished them as the audio ended
        and the reader reads the rest the same way (a word heard in the silence after the command: "bring me
        my glasses please but"); else ``text``."""
        if self._reading is None:
            return text
        whole = self._reading(text)
        words = text.split()
        for cut in (1, 2):
            if len(words) > cut + 1 and whole is not None and self._reading(" ".join(words[:-cut])) == whole:
                return " ".join(words[:-cut])
        return text

    def recognize(
        self,
        audio: str | Path | bytes | npt.NDArray[np.int16],
        *,
        phone_score: Callable[[int], float] | None = None,
        decoded: Callable[[], list[Decoded] | None] | None = None,
        heard: Callable[[], Heard | None] | None = None,
    ) -> Transcript:
        """Decode one utterance; ``in_grammar`` is False when the confidence is below the chosen model's
        threshold. With a second opinion (:attr:`whisper`) Whisper hears it first, and its transcript is
        taken where :func:`~knic.language.whisperpass.settled` says so, without pocketsphinx's passes;
        otherwise Whisper judges pocketsphinx's transcript (:class:`~knic.language.judging.Judging`).

        When the reader reads none of the hypotheses the command is refused whatever the confidence, so the
        phone-loop pass is skipped: ``in_grammar`` is then False and the confidence (``score``) NaN. This
        turns away most other speech at half the cost (dev: the reader refused 86% of it, and 17% of the
        commands, which it would have refused as well).

        Args:
            audio: a WAV path, raw 16 kHz mono 16-bit PCM bytes, or samples.
            phone_score: the phone loop's best path score of this utterance with the member model of that
                index, when it is computed elsewhere (:func:`knic.language.oneshot.start_passes`); default:
                this recogniser's :meth:`phone_loop_of`.
            decoded: every member's n-gram pass of this utterance done elsewhere, with this recogniser's
                model (:func:`knic.language.oneshot.start_passes`); default: done here.
            heard: Whisper's hearing of this utterance done elsewhere (None: it failed, heard here).

        Raises:
            AudioError: the file is not usable audio.
        """
        samples = pcm_bytes(audio)
        if self._prompt is None:
            return self._first_opinion(samples, phone_score, decoded)
        started = time.perf_counter()
        whispered = Opinion(self._server, samples, heard)()
        own = settled(whispered, self.reads)
        if own and self._command_knows(own):  # pocketsphinx could not change the reading
            elapsed = (time.perf_counter() - started) * 1000.0
            return Transcript(own, True, math.nan, duration_of(samples), elapsed)
        judging = None
        if whispered is not None:
            judging = Judging(self._server(), samples, whispered, self.reads, self._fit)
        first = self._first_opinion(samples, phone_score, decoded, judging)
        return replace(first, decode_ms=(time.perf_counter() - started) * 1000.0)  # Whisper's time too

    def _first_opinion(
        self,
        samples: bytes,
        phone_score: Callable[[int], float] | None,
        decoded: Callable[[], list[Decoded] | None] | None,
        judging: Judging | None = None,
    ) -> Transcript:
        """pocketsphinx's transcript of the utterance (see :meth:`recognize`), judged by Whisper when
        ``judging`` is given and Whisper answers (the phone loop's confidence is then not needed)."""
        raw = ngram_padded(samples)
        started = time.perf_counter()
        results = decoded() if decoded is not None else None
        if results is None:
            results = self._decode(raw)
        index = choose_member(results)
        chosen, paths = results[index], [result[0] for result in results]
        best, score, frames, hypotheses, finished, after = chosen
        spoken = " ".join(best.split()[:-after]) if after else best
        if spoken != best and self.reads(spoken):  # last words heard after the speech ended ("... but")
            best, finished = spoken, True  # the unfinished last word was among them
        text, read = self._snap(best, list(hypotheses))
        if read and text == best and not finished:
            text = self._unheard_tail(text)
        heard = Transcript(text, read, math.nan, duration_of(samples), 0.0)
        judged = judging.finish(heard, paths) if judging else None
        if judged is not None:
            return replace(judged, decode_ms=(time.perf_counter() - started) * 1000.0)
        if not read:
            elapsed = (time.perf_counter() - started) * 1000.0
            score = math.nan if text else float("-inf")
            return Transcript(text, read, score, duration_of(samples), elapsed)
        reference = phone_score(index) if phone_score is not None else self.phone_loop_of(index).score(raw)
        elapsed = (time.perf_counter() - started) * 1000.0
        level = confidence(score, reference, frames)
        return Transcript(text, level >= self.threshold_of(index), level, duration_of(samples), elapsed)


def _ngram_job(member: _Member) -> Callable[[bytes], Decoded]:
    """A worker's job: the n-gram pass of a member (request: the N-best size, then padded raw audio)."""

    def job(request: bytes) -> Decoded:
        (nbest,) = struct.unpack_from("!I", request)
        return ngram_pass(member.decoder, request[4:], nbest, member.initial_cmn)

    return job


#: the command decoders a listening command can use: ``ngram`` (:class:`NgramRecognizer`, the default: it
#: hears people's phrasings better and starts faster, see ``knic bench speech``) and ``grammar`` (the
#: template grammar, :class:`knic.language.speech.Recognizer`)
DECODERS = ("ngram", "grammar")


class CommandRecognizer(Protocol):
    """What the listening commands need of a decoder: one utterance in, a :class:`Transcript` out."""

    def recognize(self, audio: str | Path | bytes | npt.NDArray[np.int16]) -> Transcript:
        """Decode one utterance (a WAV path, raw 16 kHz mono 16-bit PCM or samples)."""
        ...


def command_recognizer(
    vocabulary: Vocabulary,
    *,
    decoder: str = "ngram",
    acoustic_model: str | Path | None = None,
    second_opinion: bool = True,
) -> CommandRecognizer:
    """The command recogniser of ``decoder`` (one of :data:`DECODERS`) for a world's vocabulary, with
    ``acoustic_model`` (default: the decoder's own,
    :data:`~knic.language.acoustic.DEFAULT_NGRAM_ACOUSTIC_MODEL` or
    :data:`~knic.language.acoustic.DEFAULT_ACOUSTIC_MODEL`).

    Raises:
        LanguageError: an unknown decoder.
    """
    if decoder == "ngram":
        model = acoustic_model_for(decoder, acoustic_model)
        return NgramRecognizer(vocabulary, acoustic_model=model, second_opinion=second_opinion)
    if decoder == "grammar":
        from knic.language.speech import Recognizer
        from knic.language.understanding import default_grammar

        return Recognizer(
            default_grammar(), vocabulary, acoustic_model=acoustic_model_for(decoder, acoustic_model)
        )
    raise LanguageError(f"unknown decoder {decoder!r} ({', '.join(DECODERS)})")
