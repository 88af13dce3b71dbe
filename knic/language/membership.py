"""How sure the n-gram recogniser is of a transcript, and which of an ensemble's acoustic models it believes:
each member model's confidence threshold, :func:`confidence` (the command model's best path against the free
phone loop's) and :func:`choose_member` (the member whose pass fits the audio best).
"""

from __future__ import annotations

import math

from knic.language.phoneloop import Decoded

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
#: With the phone loop at a third of the frame rate (28 Nov 2026;
#: :data:`~knic.language.phoneloop.PHONE_DECODER_OPTIONS`), set with :data:`BASE_CONFIDENCE_THRESHOLD` over
#: all five spoken dev sets (407 commands, 134 other utterances) and the Granny Annie voice bank (24
#: requests): 0.0 and 0.001: 0.865 / 0.963, bank 20 of 24 (0.0001 and 0.001: a bank request at 0.00007
#: refused, 19; -0.0005 and 0.0009: about 0.875 / 0.910; 0.0004 and 0.001: about 0.826 / 0.985). The phone
#: loop being coarser now, commands fit the command model about as well as it or better, hence a threshold
#: near zero. Tried and not kept: padding each recording at its own background level instead of the fixed
#: faint noise (a synthesised recording's digital silence steps up to the padding, sometimes heard as a last
#: word): dev frame+args +2 commands and WER down on every set, but the voice bank fell to 16-17 of 24 (first
#: words lost: "locate the tablet" heard as "the tablet").
CONFIDENCE_THRESHOLD = 0.0
#: Confidence threshold of the wheel's unadapted model (``base``) when it is a member of an ensemble (its
#: confidences of commands sit higher than the adaptation's). Set on the development sets with the ``auto``
#: ensemble (speech_people/dev, speech_voices_dev, speech_ood_dev and speech_engines_dev: 320 commands, 128
#: other utterances), frame+args / other speech rejected: -0.0003: 0.845 / 0.914; -0.0004: 0.845 / 0.914;
#: -0.0005: 0.849 / 0.898; -0.0006: 0.852 / 0.875. Since 28 Nov 2026 0.001, set with
#: :data:`CONFIDENCE_THRESHOLD` (see there): at 0.0009 other speech rejected falls by about 0.02, at 0.0011
#: frame+args by about 0.01.
BASE_CONFIDENCE_THRESHOLD = 0.001
#: Each acoustic model's own threshold (a folder or other name: :data:`CONFIDENCE_THRESHOLD`).
MODEL_THRESHOLDS: dict[str, float] = {"espeak": CONFIDENCE_THRESHOLD, "base": BASE_CONFIDENCE_THRESHOLD}
#: Log-likelihood ratio per frame by which a later member of an ensemble must fit the audio better than the
#: first to be chosen (:func:`choose_member`). The same dev sets, frame+args / other speech rejected with the
#: ``auto`` ensemble: 0: 0.826 / 0.930; 0.0002: 0.842 / 0.914; 0.0006-0.001: 0.845 / 0.906-0.914 (espeak-ng
#: voices as with the adaptation alone: speech_people/dev 0.861, speech_voices_dev 0.845; other engines'
#: voices 0.831, against 0.068 with the adaptation alone and 0.856 with the wheel's model alone); 0.0015:
#: 0.792. The adaptation alone: 0.623 / 0.938.
FIRST_MEMBER_PREFERENCE = 0.0008


def choose_member(results: list[Decoded]) -> int:
    """The index of the member model whose n-gram pass fits the audio best: the first, unless another's best
    path beats it by more than :data:`FIRST_MEMBER_PREFERENCE` in log-likelihood per frame (a pass without a
    path never wins)."""
    best, best_log = 0, _log_score(results[0])
    for index, result in enumerate(results[1:], start=1):
        log = _log_score(result)
        if log > best_log + (FIRST_MEMBER_PREFERENCE if best == 0 else 0.0):
            best, best_log = index, log
    return best


def _log_score(result: Decoded) -> float:
    """A pass's best path log score per frame (``-inf``: no path)."""
    score, frames = result[1], result[2]
    return math.log(score) / max(1, frames) if score > 0.0 else float("-inf")


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
