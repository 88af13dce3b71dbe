"""What the say daemon (:mod:`knic.language.sayd`) keeps loaded to hear a world's commands.

A ``knic say`` without the daemon forks pocketsphinx's passes and Whisper at once
(:func:`knic.language.oneshot.start_passes`), so that a command Whisper does not settle waits for
pocketsphinx no longer than for the longer of the two, and each child loads its model first. The daemon
keeps the models loaded: Whisper in its server, pocketsphinx's decoders in the daemon itself, forked into a
child per pass and command (a fresh copy of a decoder that has decoded nothing, as the one-shot child's), and
the children are stopped as soon as Whisper settles the command. On the first 20 commands of
``tests/fixtures/speech_people/dev`` Whisper settled 7 (2-core machine, load about 3): with pocketsphinx
waited for after Whisper, as :class:`~knic.language.lmspeech.NgramRecognizer` alone does, an unsettled
command took 0.4 s of Whisper and 0.3-0.9 s of pocketsphinx (median per command 0.94 s; beside Whisper in
worker processes 0.73 s, the same transcripts). Workers kept from one command to the next went on with the
passes of a settled command into the next one; a child per command is stopped instead.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knic.language.audio import Transcript
    from knic.language.oneshot import Child
    from knic.language.phoneloop import Decoded
    from knic.language.vocabulary import Vocabulary
    from knic.language.whisperpass import Heard


class Hearing:
    """What a daemon keeps loaded to hear a world's commands, each heard as ``knic say`` hears it without
    the daemon (:meth:`~knic.language.lmspeech.NgramRecognizer.recognize` given Whisper's hearing and
    pocketsphinx's passes): Whisper hears the command in its server
    (:class:`~knic.language.whisperpass.WhisperServer`, a program of its own: no thread pool lives in this
    process, which forks) while pocketsphinx's n-gram pass of each acoustic model runs in a child forked with
    its decoder loaded (:func:`~knic.language.oneshot.in_child`). The recogniser's judging of a command
    Whisper does not settle (:class:`~knic.language.judging.Judging`) asks the same server; the phone loop
    (pocketsphinx's confidence) runs in this process only when Whisper cannot judge. Without the world's
    remembered command model (:func:`~knic.language.oneshot.remembered_model`) the recogniser decodes in this
    process, after Whisper.

    Args:
        vocabulary: the world's spoken names.
        acoustic_model: as for :class:`~knic.language.lmspeech.NgramRecognizer`.
        key: the world key (:func:`~knic.language.oneshot.world_key`) the command model is remembered by.

    Raises:
        LanguageError: pocketsphinx or Whisper cannot load their models.
        RuntimeError, ValueError, KeyError, TypeError: pocketsphinx refused the remembered model.
    """

    def __init__(self, vocabulary: Vocabulary, acoustic_model: str, key: str):
        from knic.language.acoustic import ensemble_members
        from knic.language.lmspeech import NgramRecognizer
        from knic.language.oneshot import decoder_for, remembered_model
        from knic.language.phoneloop import PhoneLoop
        from knic.language.whisperpair import PairedServer
        from knic.language.whisperpass import world_prompt

        self.whisper = PairedServer(world_prompt(vocabulary))  # it loads the model meanwhile
        # the recogniser's own passes only run when a child failed, in this process (parallel=False)
        members, model = ensemble_members(acoustic_model), remembered_model(key)
        self.recognizer = NgramRecognizer(
            vocabulary,
            acoustic_model=acoustic_model,
            lazy=True,
            parallel=False,
            command_model=model[1] if model else None,
        )
        self.recognizer.whisper = self.whisper  # the one server, for its judging too
        self._decoders = [decoder_for(model, member) for member in members] if model else []
        self._phone_loop = PhoneLoop(members[0])  # as the one-shot child's
        for index in range(1, len(members)):
            self.recognizer.phone_loop_of(index)
        self.whisper.hear(bytes(32000))  # one second of silence: its model loaded, its first pass done

    def transcript(self, samples: bytes) -> Transcript:
        """What the recogniser hears in raw 16 kHz 16-bit PCM (every pass started at once)."""
        from knic.language.oneshot import NBEST, in_child
        from knic.language.phoneloop import as_decoded, ngram_padded, ngram_pass

        whispered = self.whisper.submit(samples)
        raw = ngram_padded(samples)

        def ngram(decoder: Any) -> Child:
            return in_child(lambda: ngram_pass(decoder, raw, NBEST))

        passes = [ngram(decoder) for decoder in self._decoders]

        def heard() -> Heard | None:
            return self.whisper.result() if whispered else None

        def decoded() -> list[Decoded] | None:
            found = []
            for child in passes:
                result = as_decoded(child())
                if result is None:
                    return None
                found.append(result)
            return found or None

        def phone_score(index: int) -> float:  # only when Whisper cannot judge the command
            loop = self._phone_loop if index == 0 else self.recognizer.phone_loop_of(index)
            return float(loop.score_of(samples))

        try:
            return self.recognizer.recognize(samples, phone_score=phone_score, decoded=decoded, heard=heard)
        finally:
            for child in passes:
                child.cancel()  # the passes Whisper made unnecessary stop now

    def close(self) -> None:
        """Stop Whisper's server."""
        self.whisper.close()
        self.recognizer.close()
