"""What the say daemon (:mod:`knic.language.sayd`) keeps loaded to hear a world's commands.

A ``knic say`` without the daemon forks pocketsphinx's passes and Whisper at once
(:func:`knic.language.oneshot.start_passes`), so that a command Whisper does not settle waits for
pocketsphinx no longer than for the longer of the two. The daemon does the same with processes started once:
Whisper's server, pocketsphinx's passes in worker processes. On the first 20 commands of
``tests/fixtures/speech_people/dev`` Whisper settled 7 (2-core machine, load about 3): with pocketsphinx
waited for after Whisper, as :class:`~knic.language.lmspeech.NgramRecognizer` alone does, an unsettled
command took 0.4 s of Whisper and 0.3-0.9 s of pocketsphinx.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knic.language.audio import Transcript
    from knic.language.phoneloop import Decoded
    from knic.language.vocabulary import Vocabulary
    from knic.language.whisperpass import Heard


class Hearing:
    """What a daemon keeps loaded to hear a world's commands, each heard as ``knic say`` hears it without
    the daemon (:meth:`~knic.language.lmspeech.NgramRecognizer.recognize` given Whisper's hearing and
    pocketsphinx's passes): pocketsphinx's n-gram pass of each acoustic model and the first model's phone
    loop run in worker processes (:mod:`knic.language.passworker`) while Whisper hears the command in its
    server (:class:`~knic.language.whisperpass.WhisperServer`, a program of its own: no thread pool lives
    in this process, which forks), so that a command Whisper does not settle waits for pocketsphinx no
    longer than for the longer of the two. Without the world's remembered command model
    (:func:`~knic.language.oneshot.remembered_model`) the recogniser decodes in this process afterwards.

    Args:
        vocabulary: the world's spoken names.
        acoustic_model: as for :class:`~knic.language.lmspeech.NgramRecognizer`.
        key: the world key (:func:`~knic.language.oneshot.world_key`) the command model is remembered by.

    Raises:
        LanguageError: pocketsphinx or Whisper cannot load their models.
    """

    def __init__(self, vocabulary: Vocabulary, acoustic_model: str, key: str):
        from knic.language.acoustic import ensemble_members
        from knic.language.lmspeech import NgramRecognizer
        from knic.language.oneshot import remembered_model
        from knic.language.passworker import start_worker
        from knic.language.whisperpass import WhisperServer, world_prompt

        # the recogniser's own passes only run when a worker failed, in this process (parallel=False)
        self.recognizer = NgramRecognizer(
            vocabulary, acoustic_model=acoustic_model, lazy=True, parallel=False
        )
        members, model = ensemble_members(acoustic_model), remembered_model(key)
        self._passes = [start_worker(_ngram_job(model, member)) for member in members] if model else []
        self._phones = start_worker(_phone_job(members[0]))
        self.whisper = WhisperServer(
            world_prompt(vocabulary)
        )  # started after the forks: none holds its pipes
        silence = bytes(32000)  # one second: the workers make their decoders now, while Whisper loads
        for worker in [*self._passes, self._phones]:
            if worker is not None and worker.submit(silence):
                worker.result()
        for index in range(1, len(members)):
            self.recognizer.phone_loop_of(index)
        self.whisper.hear(silence)  # its model loaded, and its first pass done

    def transcript(self, samples: bytes) -> Transcript:
        """What the recogniser hears in raw 16 kHz 16-bit PCM (every pass started at once)."""
        from knic.language.phoneloop import as_decoded, ngram_padded

        whispered = self.whisper.submit(samples)
        raw = ngram_padded(samples)
        sent = [worker is not None and worker.submit(raw) for worker in self._passes]
        phones = self._phones is not None and self._phones.submit(samples)

        def heard() -> Heard | None:
            return self.whisper.result() if whispered else None

        def decoded() -> list[Decoded] | None:
            found = []
            for worker, asked in zip(self._passes, sent, strict=True):
                result = as_decoded(worker.result()) if worker is not None and asked else None
                if result is None:
                    return None
                found.append(result)
            return found or None

        def phone_score(index: int) -> float:
            score = self._phones.result() if index == 0 and phones and self._phones is not None else None
            if isinstance(score, (int, float)):
                return float(score)
            return self.recognizer.phone_loop_of(index).score_of(samples)

        return self.recognizer.recognize(samples, phone_score=phone_score, decoded=decoded, heard=heard)

    def close(self) -> None:
        """Stop the worker processes and Whisper's server."""
        for worker in [*self._passes, self._phones]:
            if worker is not None:
                worker.close()
        self.whisper.close()
        self.recognizer.close()


def _ngram_job(model: tuple[Path, Path], member: str | Path) -> Callable[[bytes], Decoded]:
    """A worker's job: the n-gram pass of padded raw audio with a member model (its decoder made at the first
    request, in the worker; reset to its first state before each utterance, as the recogniser's own)."""
    kept: list[Any] = []

    def job(raw: bytes) -> Decoded:
        from knic.language.oneshot import NBEST, decoder_for
        from knic.language.phoneloop import ngram_pass

        if not kept:
            decoder = decoder_for(model, member)
            kept.extend([decoder, decoder.get_cmn()])
        return ngram_pass(kept[0], raw, NBEST, kept[1])

    return job


def _phone_job(member: str | Path) -> Callable[[bytes], float]:
    """A worker's job: the phone loop's score of unpadded audio with a member model, at a lower priority
    (:data:`~knic.language.oneshot.PHONE_LOOP_NICENESS`: its score is needed last)."""
    kept: list[Any] = []

    def job(samples: bytes) -> float:
        from knic.language.oneshot import PHONE_LOOP_NICENESS
        from knic.language.phoneloop import PhoneLoop

        if not kept:
            with contextlib.suppress(OSError):
                os.nice(PHONE_LOOP_NICENESS)
            kept.append(PhoneLoop(member))
        return float(kept[0].score_of(samples))

    return job
