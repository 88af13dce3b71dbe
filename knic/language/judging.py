"""Whisper as the judge of a spoken command it did not settle: of the transcripts both recognisers offer that
the reader reads, the one Whisper finds fits the audio best.

Whisper settles an utterance when it is sure of its own transcript and the reader reads it
(:func:`~knic.language.whisperpass.settled`). Otherwise, before this module, pocketsphinx decided alone:
its adapted acoustic model hears the voices it was adapted to well, and voices unlike them poorly, while
Whisper, trained on far more speakers, often hears them nearly right ("could you get jagged you send an
apple") or has the right transcript in its beam. So Whisper is asked two more things about the utterance
(:meth:`~knic.language.whisperpass.WhisperServer.ask`, in its server, the encoder's output kept):

1. the other transcripts of the beam search it heard the utterance with
   (:data:`~knic.language.whisperpass.BEAM`; kept from its hearing, so asked at once);
2. the score of every candidate the reader reads -- pocketsphinx's transcript and each acoustic model's
   best path, Whisper's beam's transcripts -- as the mean log-probability of the candidate's
   tokens when Whisper is made to write it (:meth:`~knic.language.whisperpass.WhisperPass.scores`).

Each candidate's score is Whisper's plus, weighed by :data:`COMMAND_WEIGHT`, how well it fits the command
model (:class:`~knic.language.commandfit.CommandFit`: Whisper knows English, the command model the home's
commands). pocketsphinx's transcript is kept when the reader reads it, Whisper's score of it is above
:data:`KEEP_LOG_PROB` and no other candidate scores more than :data:`KEEP_MARGIN` higher. Else, where some
candidate scores above :data:`STRETCH_FLOOR`, Whisper also hears the utterance played a little slower or
faster (:data:`STRETCH`, :meth:`~knic.language.whisperpass.WhisperPass.stretched`: resampled, so the voice is
higher or lower too), which for voices it mishears often gives the right transcript (on the dev set of voices
no adaptation heard, commands with a right candidate went from 4 to 11 of the 23 judged wrong), and those it
reads are scored too. The best-scoring candidate is taken when Whisper's score of it is above
:data:`TAKE_LOG_PROB`; else the utterance is refused. A transcript looping on one word (:func:`looped`) is no
candidate: Whisper scores the repeats too well (on a dev set of other speech such a transcript was taken).
pocketsphinx's own confidence (its phone-loop pass, :func:`~knic.language.membership.confidence`) is not
needed then: on the dev sets below judging without it gave one command more at the same rejection, and saved
the phone loop's time; it still decides when Whisper cannot answer. A candidate is only ever a transcript one
of the recognisers heard, so Whisper's score cannot make up a command; other speech is refused because none of
the candidates fits it (their scores fall far lower than those of commands, whichever recogniser heard them).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import Any, Protocol

from knic.language.audio import Transcript
from knic.language.vocabulary import normalize
from knic.language.whisperpass import BEAM, Heard, heard_of

#: Whisper's score above which pocketsphinx's transcript is kept. With :data:`TAKE_LOG_PROB`, set on the five
#: spoken dev sets (407 commands in 20 voices, 134 other utterances) and ``speech_people3/dev`` (112
#: commands, 12 other utterances, in 7 voices no acoustic adaptation heard), frame+args and other speech
#: rejected (pocketsphinx alone after Whisper's settling: 377 and 73 commands, 126 and 12 rejected), with
#: pocketsphinx's confidence: -2.0 and -3.5: 377 and 92, 130 and 12; -2.0 and -4.0: 381 and 94, 130 and 12
#: (other speech's best candidates cluster between -4.0 and -4.7, hence -3.5); -1.5 and -3.0: 372 and 93;
#: -3.0 and -3.0: 376 and 91; without it (as now): -2.0 and -3.5: 378 and 93, 130 and 12; -1.5: 375 and 94;
#: -2.5: 380 and 93. Other rules that gave no more: keeping pocketsphinx's only within a margin of the best
#: candidate's score, Whisper's beam without the prompt as more candidates, words of Whisper's transcript
#: the command model lacks replaced by the nearest it has in sound (+1 command, -2 other speech).
KEEP_LOG_PROB = -2.0
#: Whisper's score above which the best-scoring candidate the reader reads is taken (see above).
TAKE_LOG_PROB = -3.5
#: the paces Whisper also hears an utterance at when pocketsphinx's transcript does not fit, for more
#: candidates (:meth:`~knic.language.whisperpass.WhisperPass.stretched`). On the six spoken dev sets (519
#: commands, 146 other utterances), frame+args and other speech rejected: none 465 and 145; 0.9 alone 471
#: and 145; 0.9 and 1.1: 473 and 145; 0.9 and 1.1 heard without the world's prompt (half the decoder's
#: time): 469 and 144. On those and ``speech_ood_dev2`` (40 more other utterances), asked only where some
#: candidate at the utterance's own pace scores above :data:`STRETCH_FLOOR`: the same 473 commands and 181 of
#: 186 rejected, at a third less time per other utterance (ms per utterance of the sets' other speech: 517 ->
#: 315 and 437 -> 411); asked where any candidate reads: the same figures.
STRETCH = (0.9, 1.1)
#: the score some candidate must pass before Whisper hears the utterance at other paces (the commands rescued
#: so on the dev sets had a best candidate of -5.6 or better; other speech mostly has none that reads)
STRETCH_FLOOR = -6.0
#: the weight of the command model's fit (mean log10 probability per word,
#: :class:`~knic.language.commandfit.CommandFit`) added to Whisper's score (mean natural-log probability per
#: token) to rank the candidates. Whisper hears English, the command model knows what commands say: "go to the
#: entrance aisle" fit the audio a little better than "... hall" (-0.64 against -0.84), the command model
#: much less (-2.12 against -0.77). Measured offline on the candidates of the eight spoken dev sets (549
#: commands, 194 other utterances, candidates as scored on 29 Nov), with :data:`KEEP_MARGIN`: frame+args
#: 500 with Whisper alone; weight 0.5: 504; 0.8: 506; 1.0: 505; 2.0: 503 (margin not used); with margin 0.4:
#: weight 0.5: 508, 0.8: 511, 1.0: 509. Other speech rejected 188 in each (its candidates score too low
#: either way). Measured by the recogniser on the same sets: 498 -> 506 commands, 188 other utterances
#: rejected either way. Tried and not kept: candidates blended from pocketsphinx's and Whisper's transcripts
#: (each place they differ taken from one or the other, the four the command model fits best scored too):
#: 509 commands, but 181 other utterances rejected ("do you know where i was born" became "... where
#: eyeglasses are in"); pocketsphinx's 10-best as candidates too: one command more offline.
COMMAND_WEIGHT = 0.8
#: pocketsphinx's transcript, though it fits above :data:`KEEP_LOG_PROB`, is not kept when another
#: candidate's score (Whisper's with the command model's, above) is higher by more than this; it still may
#: win with the rest. Measured as above, weight 0.8: margin 0.2: 509, 0.3: 511, 0.4: 511, 0.5: 511, none: 506.
KEEP_MARGIN = 0.4
#: a word said this many times in a row makes a transcript no candidate (:func:`looped`)
LOOP = 4


class Asked(Protocol):
    """What judging needs of Whisper's server (:class:`~knic.language.whisperpass.WhisperServer`)."""

    def ask(self, samples: bytes, question: dict[str, Any]) -> bool:
        """Send a question about an utterance; False when it could not be sent."""
        ...

    def answer(self) -> Any:
        """The answer to the last question (None: none)."""
        ...


class Judging:
    """One utterance's judging, started before pocketsphinx decodes it (Whisper's beam is asked for then) and
    finished with pocketsphinx's transcript.

    Args:
        server: Whisper's server.
        samples: the utterance (raw 16 kHz 16-bit PCM).
        heard: Whisper's best transcript of it, when there is one.
        reads: whether the reader reads a text (or asks about it).
        fit: the command model's fit of a text (:class:`~knic.language.commandfit.CommandFit`), added to
            Whisper's score weighed by :data:`COMMAND_WEIGHT`; None: Whisper's score alone.
    """

    def __init__(
        self,
        server: Asked,
        samples: bytes,
        heard: Heard | None,
        reads: Callable[[str], bool],
        fit: Callable[[str], float] | None = None,
    ):
        self._server, self._samples, self._heard, self._reads, self._fit = server, samples, heard, reads, fit
        self._asked = server.ask(samples, {"beam": BEAM})
        self._beam: Any = None  # its answer, once read
        self._fits: dict[str, float] = {}  # Whisper's score of each candidate
        self._command: dict[str, float] = {}  # the command model's, once asked for

    def _judged(self, text: str) -> float:
        """A candidate's score: Whisper's, plus the command model's fit weighed by :data:`COMMAND_WEIGHT`."""
        if self._fit is None:
            return self._fits[text]
        if text not in self._command:
            self._command[text] = self._fit(text)
        return self._fits[text] + COMMAND_WEIGHT * self._command[text]

    def _beam_answer(self) -> Any:
        """Whisper's beam (asked for when judging began), read once."""
        if self._asked:
            self._beam, self._asked = self._server.answer(), False
        return self._beam

    def finish(self, first: Transcript, paths: Sequence[str]) -> Transcript | None:
        """The judged transcript, given pocketsphinx's (``first``: ``in_grammar`` when the reader reads it)
        and each acoustic model's best path (``paths``); None when Whisper cannot answer (pocketsphinx's
        confidence decides then)."""
        beam = self._beam_answer()
        if not isinstance(beam, list):
            return None
        fits = self._fits
        if not self._scored([first.text, *paths], [self._heard, *(heard_of(b) for b in beam)], fits):
            return None
        if first.in_grammar and fits.get(first.text, -math.inf) > KEEP_LOG_PROB:
            rival = max(fits, key=self._judged)
            if self._judged(first.text) >= self._judged(rival) - KEEP_MARGIN:
                return replace(first, score=fits[first.text])
        if not fits or max(fits.values()) <= STRETCH_FLOOR:  # nothing said resembles a command
            return replace(first, in_grammar=False, score=math.nan)
        # pocketsphinx's does not fit: what Whisper hears at other paces is asked for only now (it is kept
        # when it fits, whatever else is heard, so nothing is lost by not asking before)
        asked = self._server.ask(self._samples, {"stretch": list(STRETCH)})
        stretched = self._server.answer() if asked else None
        more = [heard_of(item) for item in stretched] if isinstance(stretched, list) else []
        if not self._scored([], more, fits):
            return None
        best = max(fits, key=self._judged)
        if fits[best] > TAKE_LOG_PROB:
            return replace(first, text=best, in_grammar=True, score=fits[best])
        return replace(first, in_grammar=False, score=math.nan)

    def _scored(self, heard: list[str], whispered: list[Heard | None], fits: dict[str, float]) -> bool:
        """Score the texts not scored yet that the reader reads (``heard`` as written, Whisper's normalised)
        into ``fits``; False when Whisper cannot answer."""
        texts = [*heard, *(normalize(found.text) for found in whispered if found is not None)]
        candidates: list[str] = []
        for text in texts:
            if looped(text):  # a decoder's loop, not speech; its repeated words score too well
                continue
            if text and text not in candidates and text not in fits and self._reads(text):
                candidates.append(text)
        if not candidates:
            return True
        scores = self._server.answer() if self._server.ask(self._samples, {"score": candidates}) else None
        if not isinstance(scores, list) or len(scores) != len(candidates):
            return False
        fits.update(zip(candidates, (float(s) for s in scores), strict=True))
        return True


def looped(text: str) -> bool:
    """Whether a transcript says one word :data:`LOOP` times or more in a row ("is my fetch are it a a a a a
    a"): pocketsphinx's decoder looping on a short word through noise or speech it cannot match. Whisper
    scores such a text high (each repeat is easy to predict after the one before): it is no candidate."""
    words = text.split()
    return any(len(set(words[i : i + LOOP])) == 1 for i in range(len(words) - LOOP + 1))
