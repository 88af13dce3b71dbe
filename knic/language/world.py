"""Loading a world for language understanding: knowledge base, lexicon and vocabulary.

The command line uses the ERL apartment as the robot knows it before a run
(``worlds/erl_home/domain.pddl`` with ``worlds/erl_home/erl_home_problem.pddl``); the lexicon of spoken names
is ``lexicon.yaml`` beside the problem file, else beside the domain file, else none (symbols are spoken as
their names).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from knic.language.vocabulary import Lexicon, Vocabulary

WORLDS = Path(__file__).resolve().parents[2] / "worlds"
DEFAULT_DOMAIN = WORLDS / "erl_home" / "domain.pddl"
DEFAULT_PROBLEM = WORLDS / "erl_home" / "erl_home_problem.pddl"
LEXICON_NAME = "lexicon.yaml"


def find_lexicon(domain: str | Path, problem: str | Path | None) -> Path | None:
    """The lexicon beside the problem file, else beside the domain file, else None."""
    for base in (problem, domain):
        if base is not None:
            candidate = Path(base).parent / LEXICON_NAME
            if candidate.is_file():
                return candidate
    return None


def load_world(
    domain: str | Path = DEFAULT_DOMAIN,
    problem: str | Path | None = DEFAULT_PROBLEM,
    lexicon: str | Path | None = None,
) -> tuple[Any, Vocabulary]:
    """Load a knowledge base from PDDL files and build its vocabulary.

    Returns:
        (knowledge base, vocabulary). The knowledge base has no journal and wall-clock time.

    Raises:
        PDDLParseError, PDDLValidationError: the PDDL files are invalid.
        LanguageError: the lexicon file is invalid.
    """
    from knowledge_base import KnowledgeBase

    kb = KnowledgeBase.from_pddl(str(domain), str(problem) if problem is not None else None)
    lexicon_path = Path(lexicon) if lexicon is not None else find_lexicon(domain, problem)
    lexicon_data = Lexicon.load(lexicon_path) if lexicon_path is not None else None
    return kb, Vocabulary.from_knowledge_base(kb, lexicon_data)
