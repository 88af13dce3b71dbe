"""The phone-loop pass of the n-gram recogniser, light enough to start before the rest of the language code.

The confidence of :class:`knic.language.lmspeech.NgramRecognizer` sets the command model's best path against
pocketsphinx's unconstrained phone loop (:class:`PhoneLoop`). ``knic say`` runs this pass in a child process
from its first milliseconds (:func:`knic.language.oneshot.start_passes`), while the parent imports the
reader and loads the world; this module therefore imports little besides the acoustic model's options.
"""

from __future__ import annotations

import itertools
import operator
import sys
import tempfile
from array import array
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from core.errors import LanguageError
from knic.language.acoustic import DEFAULT_ACOUSTIC_MODEL, acoustic_model_options, wheel_model_dir

#: Silence after the speech for the n-gram pass and its phone loop (s): the grammar decoder needs 0.5 s to
#: finish its last word; the n-gram search does not, and in 0.5 s it more often heard a word that was not
#: said ("... bring me an apple from the kitchen cabinet take"). Dev sets (people's dev and
#: speech_voices_dev: 199 commands; speech_voices_dev and speech_ood_dev: 116 other utterances), commands
#: read right / other speech rejected, with the trailing-word retry of ``NgramRecognizer``: 0.5 s 173 / 101,
#: 0.3 s 172 / 107 (without the retry: 170 / 103 and 169 / 108).
NGRAM_TRAIL_SILENCE = 0.3

#: Decoder options, set on the development set (``knic bench speech --decoder ngram --fixtures
#: tests/fixtures/speech_people/dev --option KEY=VALUE``, decoding once and reading the figures per option):
#: the lattice best path on (the n-gram search benefits from it, and the N-best list comes from the lattice);
#: fwdflat off (the second flat-lexicon pass took a third of the time and changed no dev result); word
#: insertion penalty 0.2 instead of 0.65 (frame+args 0.69 -> 0.71). Tried without gain: lw 4 (0.67), lw 9
#: (0.69), wider beams (0.69), maxhmmpf 3000 with topn 2 (0.69, 15% less CPU), ds 2 (0.67, 20% less CPU);
#: all at wip 0.65. With the 3000-sentence adaptation: the 2 best Gaussians per mixture instead of 4 (topn:
#: the n-gram pass ~20% less CPU; dev frame+args 0.878 -> 0.871, people's dev set 0.887 -> 0.896).
#: Dither (a half bit of noise, fixed seed, restarted for every utterance so that a result does not depend on
#: what was decoded before): digital silence, as in synthesised recordings, is not what a
#: microphone gives: without it the 3000-sentence adaptation added words at the end of the Granny Annie voice
#: bank's requests ("switch on the hallway plant"); with it the bank's requests read right 15 -> 20 of 24,
#: people's dev set 0.896 -> 0.904, speech_voices_dev 0.821 -> 0.810, other speech rejected 1.0 both.
NGRAM_DECODER_OPTIONS: dict[str, object] = {
    "bestpath": True,
    "fwdflat": False,
    "wip": 0.2,
    "topn": 2,
    "dither": True,
}
#: The phone-loop pass runs in a decoder of its own over every third frame with the best Gaussian of each
#: mixture (ds 3, topn 1): it was the larger part of the CPU (~250 of ~410 ms per utterance at full rate).
#: It only needs the best path's score; on the dev sets it separates commands from other speech as well as
#: the full-rate pass at its own threshold (frame+args / other speech rejected at the best thresholds, with
#: the 3000-sentence adaptation: full rate 0.875 / 0.955, ds 2 0.875 / 0.955, ds 2 topn 2 0.871 / 0.955, ds 3
#: topn 2 0.875 / 0.955 but steeper; ds 2 topn 1 0.878 / 0.933; narrower beams (1e-20) lost 0.05-0.1 of
#: frame+args at the same rejection). With the ``auto`` ensemble over all five spoken dev sets (407 commands,
#: 134 other utterances), each at its best two thresholds: ds 2 topn 2 0.865 / 0.955, ds 3 topn 1 0.865 /
#: 0.963; the Granny Annie voice bank 20 of 24 both. ms per utterance, one bench alone, before and now:
#: speech_people/dev 276 and 265, speech_people2/dev 288 and 261.
PHONE_DECODER_OPTIONS: dict[str, object] = {"ds": 3, "topn": 1}


class PhoneLoop:
    """pocketsphinx's unconstrained phone loop: the best path score of any phone sequence for an utterance,
    the reference of :func:`confidence`.

    Args:
        acoustic_model: as for :class:`NgramRecognizer`.
        options: pocketsphinx options over :data:`PHONE_DECODER_OPTIONS`.

    Raises:
        LanguageError: pocketsphinx refuses the options or the phone model.
    """

    def __init__(
        self, acoustic_model: str | Path = DEFAULT_ACOUSTIC_MODEL, options: Mapping[str, object] | None = None
    ):
        from pocketsphinx import Decoder, set_loglevel

        set_loglevel("FATAL")
        settings = {
            **NGRAM_DECODER_OPTIONS,  # dither and the rest as in the n-gram pass it is set against
            **acoustic_model_options(acoustic_model, decoder="ngram"),
            **PHONE_DECODER_OPTIONS,
            **(options or {}),
        }
        with tempfile.TemporaryDirectory(prefix="knic-phones-") as tmp:
            dictionary = Path(tmp) / "phones.dict"  # the decoder wants a dictionary; the phone loop uses none
            dictionary.write_text("a AH\n", encoding="utf-8")
            try:
                self._decoder = Decoder(lm=None, loglevel="FATAL", **{**settings, "dict": str(dictionary)})
                self._decoder.add_allphone_file("phones", str(wheel_model_dir() / "en-us-phone.lm.bin"))
                self._decoder.activate_search("phones")
            except (KeyError, ValueError, TypeError, RuntimeError) as exc:
                raise LanguageError(f"pocketsphinx refused the phone-loop options {settings}: {exc}") from exc
        self._initial_cmn = self._decoder.get_cmn()

    def score_of(self, samples: bytes) -> float:
        """:meth:`score` of unpadded 16 kHz mono 16-bit PCM, padded as the n-gram pass pads it."""
        return self.score(ngram_padded(samples))

    def score(self, raw: bytes) -> float:
        """The best phone path's score (a probability, as pocketsphinx hands it over; 0.0: no path) of padded
        raw audio."""
        decoder = self._decoder
        decoder.reinit_feat()
        decoder.set_cmn(self._initial_cmn)
        decoder.start_utt()
        decoder.process_raw(raw, full_utt=True)
        decoder.end_utt()
        hyp = decoder.hyp()
        return float(hyp.best_score) if hyp is not None else 0.0


#: an n-gram pass's result: best hypothesis, its path score, frames decoded, the N-best hypotheses, whether
#: the best path reached the sentence end (False: the audio ended inside its last word, often a word heard in
#: the silence after the command: "bring me my glasses please but"), and how many of the best hypothesis's
#: last words start after the speech has ended (:func:`words_after_speech`)
Decoded = tuple[str, float, int, tuple[str, ...], bool, int]

#: Where speech ends: the last 10 ms frame whose energy is within this many dB of the utterance's loudest.
#: A word of the best path that starts after that, less :data:`SPEECH_END_MARGIN` frames, was heard in the
#: silence after the command (a synthesised recording's digital silence stepping up to the padding's noise,
#: a breath, a click). Set on the spoken dev sets (407 commands, 134 other utterances) by simulation over
#: stored passes: 124 transcripts lost such a last word ("... to the bathroom but", "... to jack thank",
#: "... in the kitchen cupboard"), three commands read right that were not, none the other way; 20 or 30 dB
#: the same, 40 dB one command fewer; margin 0 frames two fewer. Measured with ``knic bench speech`` on the
#: same sets: frame+args 357 -> 360 of 407, other speech rejected 128 of 134 both, WER speech_people/dev
#: 0.067 -> 0.051, speech_voices_dev 0.079 -> 0.065, speech_engines_dev 0.080 -> 0.079, speech_people2/dev
#: 0.153 -> 0.147; the Granny Annie voice bank 20 of 24 both.
SPEECH_END_DROP_DB = 30.0
#: frames (10 ms) before the end of speech after which a word's start counts as after the speech
SPEECH_END_MARGIN = 10


def ngram_padded(samples: bytes) -> bytes:
    """Unpadded 16 kHz mono 16-bit PCM padded for an n-gram pass and its phone loop (with
    :data:`NGRAM_TRAIL_SILENCE` after it)."""
    from knic.language.audio import pad_pcm

    return pad_pcm(samples, NGRAM_TRAIL_SILENCE)


def as_decoded(data: Any) -> Decoded | None:
    """An n-gram pass's result sent as JSON data (by a worker or a child process), or None when it is not
    one."""
    try:
        text, score, frames, nbest, finished, after = data
        return str(text), float(score), int(frames), tuple(str(h) for h in nbest), bool(finished), int(after)
    except (TypeError, ValueError):
        return None


def ngram_pass(decoder: Any, raw: bytes, nbest: int, initial_cmn: Any = None) -> Decoded:
    """One n-gram pass of padded raw audio with a decoder whose search is set: the best hypothesis, its path
    score (0.0: no path), the frames decoded, the first ``nbest`` N-best hypotheses (none without a
    lattice) and whether the best path ended with the sentence end. The dither's noise starts afresh, and
    the cepstral mean from ``initial_cmn`` when given, so that the same audio decodes the same way whatever
    was decoded before."""
    decoder.reinit_feat()
    if initial_cmn is not None:
        decoder.set_cmn(initial_cmn)
    decoder.start_utt()
    decoder.process_raw(raw, full_utt=True)
    decoder.end_utt()
    hyp = decoder.hyp()
    frames = max(1, decoder.n_frames())
    if hyp is None:
        return "", 0.0, frames, (), False, 0
    found: list[str] = []
    if nbest > 0:
        try:
            for entry in itertools.islice(decoder.nbest(), nbest):
                if entry is not None and entry.hypstr:  # pocketsphinx can yield an empty entry
                    found.append(" ".join(entry.hypstr.split()))
        except (RuntimeError, ValueError, AttributeError):  # no lattice for this utterance
            found = []
    segments = [(segment.word, segment.start_frame) for segment in decoder.seg()]
    finished = bool(segments) and segments[-1][0] == "</s>"
    after = words_after_speech(segments, speech_end(raw))
    return " ".join(hyp.hypstr.split()), float(hyp.best_score), frames, tuple(found), finished, after


def speech_end(raw: bytes) -> int:
    """The last 10 ms frame of 16 kHz 16-bit PCM whose energy is within :data:`SPEECH_END_DROP_DB` of the
    loudest frame's (0 for silence or less than a frame)."""
    values = array("h", raw[: len(raw) // 2 * 2])
    if sys.byteorder == "big":
        values.byteswap()
    size = 160
    energies = [
        sum(map(operator.mul, frame, frame)) / size
        for frame in (values[at : at + size] for at in range(0, len(values) - size + 1, size))
    ]
    if not energies or max(energies) <= 0:
        return 0
    floor = max(energies) / 10 ** (SPEECH_END_DROP_DB / 10)
    return max(index for index, energy in enumerate(energies) if energy >= floor)


def words_after_speech(segments: list[tuple[str, int]], end: int) -> int:
    """How many of the last words of a best path's segmentation (word, start frame) start after frame
    ``end`` less :data:`SPEECH_END_MARGIN` (never all of them)."""
    # pocketsphinx's segmentation has besides words <s>, </s>, <sil> and fillers in brackets ([NOISE])
    words = [start for word, start in segments if not word.startswith(("<", "["))]
    count = 0
    while count < len(words) - 1 and words[-1 - count] >= end - SPEECH_END_MARGIN:
        count += 1
    return count
