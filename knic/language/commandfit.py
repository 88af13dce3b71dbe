"""How well a transcript fits the command model: the n-gram model pocketsphinx decodes with, sampled from the
command templates and people's phrasings of the world (:func:`knic.language.lmfiles.build_model`).

Whisper judges the candidate transcripts of an utterance it did not settle by how well each fits the audio
(:class:`~knic.language.judging.Judging`). Whisper knows English, not the home: of "go to the entrance aisle"
and "go to the entrance hall" it may find the first fits a little better, of "take rosa to the kitchen minor"
and "... kitchen diner" likewise. The command model knows which of them a command says. The judge adds the
two, the command model's part weighed by :data:`~knic.language.judging.COMMAND_WEIGHT`, as a recogniser adds
its language model's score to its acoustic one.

Whisper settles an utterance it is sure of (:func:`~knic.language.whisperpass.settled`) only when the command
model has every word of its transcript (:meth:`CommandFit.knows`); one with a word no command says ("bramp the
juice", "put it on the brick shelf") is judged with pocketsphinx's transcripts instead.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Any

#: log10 probability of a word the command model does not have (the models' rarest words have about -6)
UNKNOWN_LOG10 = -7.0
#: below this the model's answer is its "no such word" (log zero), not a probability
_NO_WORD_LOG10 = -30.0


class CommandFit:
    """The command model's mean log10 probability per word of a text (its end of sentence counted as a word);
    a word the model lacks counts :data:`UNKNOWN_LOG10`, and the words before it are no history for the next.

    Args:
        model: pocketsphinx's ``NGramModel`` of the commands.
        logmath: the ``LogMath`` it was read with.
    """

    def __init__(self, model: Any, logmath: Any):
        self._model, self._logmath = model, logmath

    @classmethod
    def read(cls, binary: Path) -> CommandFit | None:
        """The fit of a command model kept in pocketsphinx's binary form (about 2 ms), or None when it cannot
        be read."""
        from pocketsphinx import Config, LogMath, NGramModel

        with contextlib.suppress(RuntimeError, ValueError, OSError, TypeError):
            logmath = LogMath()
            return cls(NGramModel(Config(loglevel="FATAL"), logmath, str(binary)), logmath)
        return None

    def _log10(self, word: str, history: list[str]) -> float | None:
        """log10 P(word | the last two words of ``history``), None when the model lacks the word."""
        found = self._logmath.log_to_log10(self._model.prob([word, *reversed(history[-2:])]))
        return None if found < _NO_WORD_LOG10 else float(found)

    def knows(self, text: str) -> bool:
        """Whether the model has every word of a text."""
        return all(self._log10(word, []) is not None for word in text.split())

    def __call__(self, text: str) -> float:
        words = [*text.split(), "</s>"]
        history, total = ["<s>"], 0.0
        for word in words:
            found = self._log10(word, history)
            if found is None:
                total += UNKNOWN_LOG10
                history = []
            else:
                total += found
                history.append(word)
        return total / len(words)
