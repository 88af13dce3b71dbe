"""Spoken commands through an n-gram model: speech that is phrased unlike every template is still heard.

The grammar decoder (:class:`knic.language.speech.Recognizer`) only hears sentences of the templates. This
recogniser searches a back-off trigram model (:mod:`knic.language.ngram`) of sentences sampled from the same
templates with the world's names (:mod:`knic.language.sampling`), so word orders and combinations the
templates never produced stay reachable; the reader (:mod:`knic.language.reader`) then understands the words.
When the best hypothesis is no command the reader reads, the first of the :data:`NBEST` best hypotheses that
it reads is taken instead (the recogniser snaps to what the text side understands).

Out-of-domain speech: an n-gram search also forces any audio onto some word sequence of the model. Each
utterance is therefore decoded a second time with pocketsphinx's unconstrained phone loop (the wheel's
``en-us-phone.lm.bin``, in a decoder of its own at half the frame rate: :data:`PHONE_DECODER_OPTIONS`); the
confidence is the log-likelihood ratio of the two best paths per frame
(:func:`confidence`). Command speech fits the command model about as well as the free phone loop
(confidence near zero); other speech fits it much worse. Below :data:`CONFIDENCE_THRESHOLD` the transcript
is marked out of domain; what the reader does not understand is rejected by the reader whatever the
confidence, which already turns away most other speech. The threshold was set on the development sets only
(``knic bench speech --decoder ngram``).

Lifecycle: build once per vocabulary (sampling and estimating the model take a few seconds; the model is
cached on disk by content), then :meth:`NgramRecognizer.recognize` per utterance; not thread-safe.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import math
import shutil
import tempfile
import time
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from core.errors import LanguageError
from knic.language.acoustic import DEFAULT_ACOUSTIC_MODEL, acoustic_model_options, wheel_model_dir
from knic.language.audio import Transcript, duration_of, pad_pcm, pcm_bytes
from knic.language.commands import command_language
from knic.language.phoneloop import (
    NGRAM_DECODER_OPTIONS,
    NGRAM_TRAIL_SILENCE,
    PHONE_DECODER_OPTIONS,
    PhoneLoop,
)
from knic.language.reader import AmbiguityError, Reader
from knic.language.vocabulary import Vocabulary

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

#: Sentences sampled for the model. Measured on the development sets with the templates of 28 Nov 2026 (263
#: commands in 10 voices, 134 other utterances; see :data:`CONFIDENCE_THRESHOLD`): frame+args 0.817 with 4000,
#: 0.852 with 12000, 0.829 with 30000 (more templates need more samples; past that, no gain).
SENTENCES = 12000
#: Confidence (:func:`confidence`: log-likelihood ratio of the n-gram and phone-loop best paths, per frame)
#: below which speech is taken as out of domain. Set on the development sets only, in 13 voices:
#: ``tests/fixtures/speech_people/dev`` (115 commands, 6 other), ``speech_ood_dev`` (24 other),
#: ``speech_voices_dev`` (84 commands, 92 other, four voices no other set has) and ``speech_dev`` without
#: the voices that the test set also uses (64 commands, 12 other); 263 commands and 134 other utterances.
#: With the acoustic adaptation of 28 Nov 2026 (3000 sentences in 214 voices, none of these sets') and the
#: decoder settings below, frame+args / other speech rejected by threshold: -0.0002: 0.757 / 0.978; -0.0004:
#: 0.825 / 0.970; -0.0006: 0.859 / 0.970; -0.0008: 0.871 / 0.955; -0.001: 0.871 / 0.940. -0.0008 keeps every
#: command read right (the earlier 480-sentence adaptation, phone loop in the n-gram decoder: 0.825 / 0.955
#: at -0.0016). The median confidence of commands moves with the voice, so the threshold sits as low as the
#: other speech allows. Tried on the same sets: rejecting also by the
#: model's own log-probability per word of the transcript (garbage transcripts of other speech are unlikely
#: word strings) gained at most one point of rejection for a point of frame+args. The previous measure (the
#: difference of the two scores as probabilities, per frame) depended on the voice much more. With dither
#: (below) a speech_voices_dev command fell to -0.00097: -0.001 keeps it, other speech rejected
#: speech_ood_dev 1.0, speech_voices_dev 0.913 (at -0.0012: 0.917 and 0.902). With the stdlib padding noise
#: of :mod:`knic.language.audio` (28 Nov 2026; the same dev sets, frame+args / other speech rejected):
#: -0.0006: 0.825 / 0.963; -0.0008: 0.829 / 0.955; -0.001: 0.840 / 0.925; -0.0011: 0.840 / 0.925; -0.0012:
#: 0.844 / 0.910. -0.0011 keeps a speech_voices_dev command that fell to -0.00110 at the same rejection.
CONFIDENCE_THRESHOLD = -0.0011
#: Hypotheses of the N-best list tried when the best one is not a command the reader understands (dev:
#: frame+args 0.71 -> 0.76 with 10; 30 gave the same).
NBEST = 10
#: Hypotheses (the best, then the N-best) tried without their last one or two words when none is read whole
#: (dev: see :data:`~knic.language.phoneloop.NGRAM_TRAIL_SILENCE`).
TRIMMED = 3


def build_model(
    vocabulary: Vocabulary,
    sentences: int = SENTENCES,
    *,
    seed: int = 0,
    exclude: frozenset[str] = frozenset(),
) -> str:
    """The ARPA text of the command model for a vocabulary (cached in the temporary folder by content)."""
    language = command_language()
    key = hashlib.sha256()
    key.update(Path(language.source).read_bytes() if language.source else b"")
    for term in vocabulary.terms:
        key.update(f"{term.phrase}|{term.type}|{term.is_group};".encode())
    from knic.language.sampling import FIRST_PHRASE_SHARE, sample_sentences  # only to build a model

    key.update(f"{sentences}|{seed}|{sorted(exclude)}|{FIRST_PHRASE_SHARE}".encode())
    cache = Path(tempfile.gettempdir()) / f"knic-ngram-{key.hexdigest()[:20]}.arpa"
    if cache.is_file():
        return cache.read_text(encoding="utf-8")
    samples = sample_sentences(vocabulary, sentences, seed=seed, exclude_words=exclude, frames=False)
    texts = [s.text for s in samples]
    from knic.language.ngram import arpa_from_sentences

    arpa = arpa_from_sentences(texts)
    with contextlib.suppress(OSError):  # no cache: built again next time
        cache.write_text(arpa, encoding="utf-8")
    return arpa


class NgramRecognizer:
    """pocketsphinx decoding with the command n-gram model and a phone-loop confidence.

    Args:
        vocabulary: the world's spoken names.
        acoustic_model: as for :class:`~knic.language.speech.Recognizer`.
        threshold: confidence below which a transcript is out of domain.
        decoder_options: pocketsphinx options over :data:`NGRAM_DECODER_OPTIONS`.
        nbest: when the best hypothesis is no command the reader reads, the first of this many N-best
            hypotheses it reads becomes the transcript (0: the best hypothesis, always).
        reads: whether the reader understands a text (default: the world's
            :class:`~knic.language.reader.Reader` reads it, or finds it ambiguous).
        phone_options: pocketsphinx options of the phone-loop pass (:class:`PhoneLoop`) over
            ``decoder_options`` and :data:`PHONE_DECODER_OPTIONS`.
        lazy: build the decoder when it is first needed (not when the decoding is done elsewhere:
            :meth:`recognize` ``decoded``).

    Raises:
        LanguageError: pocketsphinx refuses the options, the model or the phone loop.
    """

    def __init__(
        self,
        vocabulary: Vocabulary,
        *,
        acoustic_model: str | Path = DEFAULT_ACOUSTIC_MODEL,
        threshold: float = CONFIDENCE_THRESHOLD,
        decoder_options: Mapping[str, object] | None = None,
        nbest: int = NBEST,
        reads: Callable[[str], bool] | None = None,
        phone_options: Mapping[str, object] | None = None,
        lazy: bool = False,
    ):
        self.threshold = threshold
        self.nbest = nbest
        self.reads = reads or _reader_check(vocabulary)
        self._vocabulary = vocabulary
        self._options = {
            **NGRAM_DECODER_OPTIONS,
            **acoustic_model_options(acoustic_model, decoder="ngram"),
            **(decoder_options or {}),
        }
        self._acoustic_model = acoustic_model
        self._phone_options = {**(decoder_options or {}), **PHONE_DECODER_OPTIONS, **(phone_options or {})}
        self._phone_loop: PhoneLoop | None = None
        self._decoder: Any = None
        #: the model's dictionary and binary language model, once built (what :mod:`knic.language.oneshot`
        #: remembers for the next one-shot start)
        self.model_files: tuple[str, Path | None] | None = None
        if not lazy:
            self._build()

    def _build(self) -> Any:
        """The n-gram decoder (built on first use when the recogniser was made ``lazy``)."""
        if self._decoder is not None:
            return self._decoder
        from pocketsphinx import Decoder, set_loglevel

        set_loglevel("FATAL")
        options, vocabulary = self._options, self._vocabulary
        words = vocabulary.words() | command_language().words()
        source = Path(str(options.get("dict") or wheel_model_dir() / "cmudict-en-us.dict"))
        lines = _dictionary_lines(source, words)
        known = {line.split(maxsplit=1)[0].split("(")[0] for line in lines}
        self.unknown_words = sorted(w for w in words if w not in known)
        arpa = build_model(vocabulary, exclude=frozenset(self.unknown_words))
        lines = _dictionary_lines(source, words | _model_words(arpa))  # the templates' own words too
        with tempfile.TemporaryDirectory(prefix="knic-lm-") as tmp:
            # only the model's words in the dictionary: with the wheel's whole dictionary (134k words)
            # pocketsphinx took about 30 s to add the model, with these well under one
            dictionary = Path(tmp) / "commands.dict"
            dictionary.write_text("".join(lines), encoding="utf-8")
            try:
                decoder = Decoder(lm=None, loglevel="FATAL", **{**options, "dict": str(dictionary)})
            except (KeyError, ValueError, TypeError, RuntimeError) as exc:
                raise LanguageError(f"pocketsphinx refused the decoder options {options}: {exc}") from exc
            try:
                model, binary = _binary_model(decoder, arpa)
                decoder.add_lm("ngram", model)
                decoder.activate_search("ngram")
            except (RuntimeError, ValueError) as exc:
                raise LanguageError(f"pocketsphinx refused the command language model: {exc}") from exc
        self._decoder = decoder
        self._initial_cmn = decoder.get_cmn()
        self.model_files = ("".join(lines), binary)
        return decoder

    @property
    def phone_loop(self) -> PhoneLoop:
        """The phone-loop pass, built on first use (it is not needed for speech the reader refuses)."""
        if self._phone_loop is None:
            self._phone_loop = PhoneLoop(self._acoustic_model, self._phone_options)
        return self._phone_loop

    def _decode(self, raw: bytes) -> tuple[str, float, int]:
        decoder = self._build()
        decoder.reinit_feat()  # the dither's noise starts afresh: the same audio decodes the same way
        decoder.set_cmn(self._initial_cmn)
        decoder.start_utt()
        decoder.process_raw(raw, full_utt=True)
        decoder.end_utt()
        hyp = decoder.hyp()
        if hyp is None:
            return "", float("-inf"), max(1, decoder.n_frames())
        return " ".join(hyp.hypstr.split()), float(hyp.best_score), max(1, decoder.n_frames())

    def _nbest(self) -> list[str]:
        """The N-best hypotheses of the utterance just decoded (none without a lattice)."""
        try:
            found = itertools.islice(self._build().nbest(), self.nbest)
            return [" ".join(h.hypstr.split()) for h in found if h is not None and h.hypstr]
        except (RuntimeError, ValueError, AttributeError):  # no lattice for this utterance
            return []

    def _snap(self, text: str, nbest: Callable[[], list[str]] | None = None) -> tuple[str, bool]:
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
        hypotheses = (nbest or self._nbest)()[: self.nbest]
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

    def recognize(
        self,
        audio: str | Path | bytes | npt.NDArray[np.int16],
        *,
        phone_score: Callable[[], float] | None = None,
        decoded: Callable[[], Decoded] | None = None,
    ) -> Transcript:
        """Decode one utterance; ``in_grammar`` is False when the confidence is below the threshold.

        When the reader reads none of the hypotheses the command is refused whatever the confidence, so the
        phone-loop pass is skipped: ``in_grammar`` is then False and the confidence (``score``) NaN. This
        turns away most other speech at half the cost (dev: the reader refused 86% of it, and 17% of the
        commands, which it would have refused as well).

        Args:
            audio: a WAV path, raw 16 kHz mono 16-bit PCM bytes, or samples.
            phone_score: the phone loop's best path score of this utterance when it is computed elsewhere
                (:func:`knic.language.oneshot.start_passes`); default: this recogniser's :attr:`phone_loop`.
            decoded: the n-gram pass of this utterance done elsewhere, with this recogniser's model
                (:func:`knic.language.oneshot.start_passes`); default: done here.

        Raises:
            AudioError: the file is not usable audio.
        """
        samples = pcm_bytes(audio)
        raw = pad_pcm(samples, NGRAM_TRAIL_SILENCE)
        started = time.perf_counter()
        if decoded is not None:
            text, score, frames, hypotheses = decoded()
            text, read = self._snap(text, lambda: list(hypotheses))
        else:
            text, score, frames = self._decode(raw)
            text, read = self._snap(text)
        if not read:
            elapsed = (time.perf_counter() - started) * 1000.0
            return Transcript(text, False, math.nan if text else float("-inf"), duration_of(samples), elapsed)
        reference = phone_score() if phone_score is not None else self.phone_loop.score(raw)
        elapsed = (time.perf_counter() - started) * 1000.0
        level = confidence(score, reference, frames)
        return Transcript(text, level >= self.threshold, level, duration_of(samples), elapsed)


#: an n-gram pass's result: best hypothesis, its path score, frames decoded, the N-best hypotheses
Decoded = tuple[str, float, int, tuple[str, ...]]


def confidence(score: float, phone_score: float, frames: int) -> float:
    """Log-likelihood ratio per frame of the command model's best path against the free phone loop's.

    pocketsphinx hands path scores over as probabilities (its log scores exponentiated), so the ratio of two
    is the difference of the log scores; per frame, so that long and short utterances compare. Zero: the
    command model explains the audio as well as any phone sequence; negative: worse. ``-inf`` when either
    path is missing.
    """
    if score <= 0.0 or phone_score <= 0.0:
        return float("-inf")
    return math.log(score / phone_score) / max(1, frames)


def _reader_check(vocabulary: Vocabulary) -> Callable[[str], bool]:
    reader = Reader(vocabulary)

    def reads(text: str) -> bool:
        try:
            reader.read(text)
        except AmbiguityError:
            return True  # understood up to a question back
        except LanguageError:
            return False
        return True

    return reads


def _dictionary_lines(source: Path, words: set[str]) -> list[str]:
    """The lines of a pronunciation dictionary for ``words`` (every pronunciation of each); kept in the
    temporary folder, keyed by the dictionary file and the words (reading the 134k-word dictionary took a
    third of the recogniser's start-up).

    Raises:
        LanguageError: the dictionary cannot be read.
    """
    try:
        stat = source.stat()
    except OSError as exc:
        raise LanguageError(f"{source}: cannot read the pronunciation dictionary: {exc}") from exc
    key = hashlib.sha256(f"{source.resolve()}|{stat.st_size}|{stat.st_mtime_ns}|".encode())
    key.update(" ".join(sorted(words)).encode())
    cache = Path(tempfile.gettempdir()) / f"knic-dict-{key.hexdigest()[:20]}.dict"
    with contextlib.suppress(OSError, UnicodeDecodeError):
        return cache.read_text(encoding="utf-8").splitlines(keepends=True)
    try:
        text = source.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        raise LanguageError(f"{source}: cannot read the pronunciation dictionary: {exc}") from exc
    lines = [
        line + "\n"
        for line in text.splitlines()
        if line.strip() and line.split(maxsplit=1)[0].split("(")[0] in words
    ]
    with contextlib.suppress(OSError):  # no cache: read again next time
        cache.write_text("".join(lines), encoding="utf-8")
    return lines


def _binary_model(decoder: Any, arpa: str) -> tuple[Any, Path | None]:
    """The ARPA model as pocketsphinx's ``NGramModel``, read from a binary copy kept in the temporary folder
    by content (reading the binary form takes about 1 ms, parsing the ARPA text about 60), and that copy's
    path (None when it could not be kept).

    Raises:
        RuntimeError, ValueError: pocketsphinx cannot read the model.
    """
    from pocketsphinx import NGramModel

    key = hashlib.sha256(arpa.encode()).hexdigest()[:20]
    cache = Path(tempfile.gettempdir()) / f"knic-ngram-{key}.lm.bin"
    if cache.is_file():
        with contextlib.suppress(RuntimeError, ValueError, OSError):  # unreadable: made again below
            return NGramModel(decoder.config, decoder.logmath, str(cache)), cache
    with tempfile.TemporaryDirectory(prefix="knic-lm-") as tmp:
        path = Path(tmp) / "commands.arpa"
        path.write_text(arpa, encoding="utf-8")
        model = NGramModel(decoder.config, decoder.logmath, str(path))
        with contextlib.suppress(OSError, RuntimeError, ValueError):  # no cache: parsed again next time
            partial = Path(tmp) / "commands.lm.bin"
            model.write(str(partial), NGramModel.str_to_type("bin"))
            shutil.move(str(partial), cache)
    return model, (cache if cache.is_file() else None)


def _model_words(arpa: str) -> set[str]:
    """The words of an ARPA model's 1-grams."""
    found: set[str] = set()
    inside = False
    for line in arpa.split("\\2-grams:", 1)[0].splitlines():
        if line.startswith("\\1-grams:"):
            inside = True
        elif line.startswith("\\"):
            if inside:
                break
        elif inside and line.strip():
            found.add(line.split()[1])
    return found


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
    vocabulary: Vocabulary, *, decoder: str = "ngram", acoustic_model: str | Path = DEFAULT_ACOUSTIC_MODEL
) -> CommandRecognizer:
    """The command recogniser of ``decoder`` (one of :data:`DECODERS`) for a world's vocabulary.

    Raises:
        LanguageError: an unknown decoder.
    """
    if decoder == "ngram":
        return NgramRecognizer(vocabulary, acoustic_model=acoustic_model)
    if decoder == "grammar":
        from knic.language.speech import Recognizer
        from knic.language.understanding import default_grammar

        return Recognizer(default_grammar(), vocabulary, acoustic_model=acoustic_model)
    raise LanguageError(f"unknown decoder {decoder!r} ({', '.join(DECODERS)})")
