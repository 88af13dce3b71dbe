"""Language understanding: typed and spoken commands to validated PDDL goals.

Pipeline (one module per step; the grammar is defined once and shared by text and speech):

* :mod:`~knic.language.vocabulary` -- spoken names of a world's instances (knowledge base + lexicon).
* :mod:`~knic.language.commands` -- how people phrase commands, as data (``commands.yaml``): fillers, verbs,
  prepositions, levels and templates; the one source of the reader, the speech grammar and the samples.
* :mod:`~knic.language.chunks` / :mod:`~knic.language.reader` -- reading text: chunks, then clauses
  (:mod:`~knic.language.clauses`), roles (:mod:`~knic.language.roles`) and chains and pronouns
  (:mod:`~knic.language.chains`).
* :mod:`~knic.language.grammar` -- grammar nodes and the JSGF form of the templates.
* :mod:`~knic.language.sampling` -- sentences with their frames sampled from the templates.
* :mod:`~knic.language.ngram` -- an ARPA n-gram model of sampled sentences for the speech recogniser.
* :mod:`~knic.language.frames` -- command frames (BRINGING, SEARCHING, ...).
* :mod:`~knic.language.goals` -- frames to PDDL goals checked against the domain; adding them to a KB.
* :mod:`~knic.language.understanding` -- :func:`understand`: text to :class:`Understanding`.
* :mod:`~knic.language.fsg` / :mod:`~knic.language.speech` -- WAV audio to a transcript with pocketsphinx.
* :mod:`~knic.language.dialogue` -- repeating back, yes/no confirmation, espeak-ng or printed replies.
* :mod:`~knic.language.world` -- loading a world's knowledge base and vocabulary for the command line.

Typical use::

    kb, vocabulary = knic.language.world.load_world()
    result = knic.language.understand("bring me my glasses", vocabulary, speaker="annie")
    if result.accepted:
        knic.language.add_goals(kb, result.goals, source="speech")
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knic.language.commands import command_grammar
    from knic.language.frames import CommandFrame
    from knic.language.goals import add_goals
    from knic.language.grammar import to_jsgf
    from knic.language.understanding import Understanding, understand
    from knic.language.vocabulary import Lexicon, Vocabulary

#: public name -> the module it lives in; imported on first use, so that a submodule (the audio reader, the
#: acoustic model's options) is imported without the whole reader (``knic say`` starts its first pass sooner)
_EXPORTS = {
    "CommandFrame": "knic.language.frames",
    "Lexicon": "knic.language.vocabulary",
    "Understanding": "knic.language.understanding",
    "Vocabulary": "knic.language.vocabulary",
    "add_goals": "knic.language.goals",
    "command_grammar": "knic.language.commands",
    "to_jsgf": "knic.language.grammar",
    "understand": "knic.language.understanding",
}

__all__ = [
    "CommandFrame",
    "Lexicon",
    "Understanding",
    "Vocabulary",
    "add_goals",
    "command_grammar",
    "to_jsgf",
    "understand",
]


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(importlib.import_module(_EXPORTS[name]), name)
    raise AttributeError(f"module 'knic.language' has no attribute {name!r}")
