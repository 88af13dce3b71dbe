"""Whisper's server with a partner process for the stretched hearings (:mod:`knic.language.judging`).

An utterance pocketsphinx's transcript does not fit is heard again at other paces
(:data:`~knic.language.judging.STRETCH`), one batch in Whisper's server on one CPU thread while the caller
waits: the machine's other core idles then. :class:`PairedServer` hears the first pace itself and hands the
others to a second server process, so both cores work on them. The partner is started at the first stretched
hearing (which is heard the old way) and is used from the next one on; when it is gone, the paces it was
given are heard by the server itself. Whether two processes beat one batch on this machine is measured in
the changelog (the same transcripts; the stretched hearings' wall time).
"""

from __future__ import annotations

from typing import Any

from knic.language.whisperpass import WhisperServer


class PairedServer(WhisperServer):
    """:class:`~knic.language.whisperpass.WhisperServer` whose ``stretch`` questions of more than one pace
    are split with a partner server (see the module docstring); every other request is the server's alone."""

    def __init__(self, *args: Any, **kwargs: Any):
        super().__init__(*args, **kwargs)
        self._partner: WhisperServer | None = None
        #: the utterance and the paces the partner was asked for, until the answer is read
        self._split: tuple[bytes, list[Any]] | None = None

    def ask(self, samples: bytes, question: dict[str, Any]) -> bool:
        rates, partner, self._split = question.get("stretch"), self._partner, None
        if not isinstance(rates, list) or len(rates) < 2:
            return super().ask(samples, question)
        if partner is None:
            self._partner = WhisperServer(self.prompt, self.folder)  # it loads while this one answers
        elif partner.keep(samples) and partner.ask(samples, {"stretch": rates[1:]}):
            self._split = (samples, rates[1:])
            return super().ask(samples, {"stretch": rates[:1]})
        return super().ask(samples, question)

    def answer(self) -> Any:
        mine, split, self._split = super().answer(), self._split, None
        if split is None or not isinstance(mine, list):
            return mine
        theirs = self._partner.answer() if self._partner is not None else None
        if not isinstance(theirs, list):  # the partner died: its paces heard here
            samples, rates = split
            theirs = super().answer() if super().ask(samples, {"stretch": rates}) else None
        return [*mine, *theirs] if isinstance(theirs, list) else None

    def close(self) -> None:
        if self._partner is not None:
            self._partner.close()
            self._partner = None
        super().close()
