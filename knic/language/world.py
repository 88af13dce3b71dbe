"""Loading a world for language understanding: knowledge base, lexicon and vocabulary.

The command line uses the ERL apartment as the robot knows it before a run
(``worlds/erl_home/domain.pddl`` with ``worlds/erl_home/erl_home_problem.pddl``); the lexicon of spoken names
is ``lexicon.yaml`` beside the problem file, else beside the domain file, else none (symbols are spoken as
their names).
"""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path
from typing import Any

from core.errors import LanguageError
from knic.language.vocabulary import LOCATION_PREDICATES, Lexicon, Vocabulary, normalize

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
    return kb, Vocabulary.from_knowledge_base(kb, camel_cased(problem, lexicon_data))


def camel_cased(problem: str | Path | None, lexicon: Lexicon | None) -> Lexicon | None:
    """``lexicon`` with spoken names for the symbols the problem file writes in CamelCase, which PDDL reads
    in lower case: "LivingRoom" is "living room" (and "livingroom" as typed), "BlueBottle" "blue bottle"; a
    symbol the lexicon names keeps its names. Nothing is added for a problem without such symbols."""
    if problem is None:
        return lexicon
    try:
        text = re.sub(r";[^\n]*", " ", Path(problem).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError):
        return lexicon  # the PDDL reader says what is wrong with the file
    spoken: dict[str, tuple[str, ...]] = {}
    for token in set(re.findall(r"[A-Za-z][A-Za-z0-9_-]*", text)):
        apart = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", " ", token)
        if apart != token:
            spoken[token.lower()] = (normalize(apart), normalize(token))
    if not spoken:
        return lexicon
    lexicon = lexicon or Lexicon()
    return replace(lexicon, names={**spoken, **lexicon.names})


def read_vocabulary(
    domain: str | Path = DEFAULT_DOMAIN,
    problem: str | Path | None = DEFAULT_PROBLEM,
    lexicon: str | Path | None = None,
) -> Vocabulary:
    """The vocabulary of a world read straight from its PDDL files, without building a knowledge base.

    Reads the domain's types, constants and predicate signatures and the problem's objects and the
    ``furniture_in`` / ``object_on`` / ``object_at`` facts of its initial state: all the vocabulary needs.
    This is what keeps ``knic goal`` quick to start (no planning library is imported); it does not validate
    the files as :func:`load_world` does, so a malformed file may surface later, when goals are added.

    Raises:
        LanguageError: a file is unreadable or is not PDDL; the lexicon file is invalid.
    """
    domain_tree = _read_sexp(Path(domain))
    types: dict[str, str | None] = {"object": None}
    instances: dict[str, str] = {}
    predicates: dict[str, tuple[tuple[str, str], ...]] = {}
    for section in domain_tree:
        if not isinstance(section, list) or not section:
            continue
        head = section[0]
        if head == ":types":
            for name, parent in _typed(section[1:]):
                types[name] = parent
        elif head == ":constants":
            instances.update(_typed(section[1:]))
        elif head == ":predicates":
            for atom in section[1:]:
                if isinstance(atom, list) and atom and isinstance(atom[0], str):
                    predicates[atom[0]] = tuple(_typed(atom[1:]))
    locations: dict[str, list[str]] = {}
    if problem is not None:
        for section in _read_sexp(Path(problem)):
            if isinstance(section, list) and section and section[0] == ":objects":
                instances.update(_typed(section[1:]))
            elif isinstance(section, list) and section and section[0] == ":init":
                for atom in section[1:]:
                    if isinstance(atom, list) and len(atom) == 3 and atom[0] in LOCATION_PREDICATES:
                        locations.setdefault(str(atom[1]), []).append(str(atom[2]))
    lexicon_path = Path(lexicon) if lexicon is not None else find_lexicon(domain, problem)
    lexicon_data = camel_cased(problem, Lexicon.load(lexicon_path) if lexicon_path is not None else None)
    vocabulary = Vocabulary.from_instances(instances, types, lexicon_data, predicates, locations)
    _check_named_types(Path(domain), vocabulary)
    return vocabulary


Sexp = str | list["Sexp"]

#: the types commands name things by: a domain must declare one of them, or a type below one
NAMED_TYPES = ("room", "furniture", "item", "person", "device")


def _check_named_types(domain: Path, vocabulary: Vocabulary) -> None:
    """Refuse a domain none of whose types a command can name (a domain of its own, with types such as
    ``place`` and ``thing``): every command would be refused, each for a thing that "is not an object".

    Raises:
        LanguageError: no type of the domain is, or is below, one of :data:`NAMED_TYPES`.
    """
    types = vocabulary.types
    if any(vocabulary.is_subtype(kind, named) for kind in types for named in NAMED_TYPES):
        return
    declared = ", ".join(sorted(t for t in types if t != "object")) or "none"
    raise LanguageError(
        f"{domain}: commands name things by the types {', '.join(NAMED_TYPES)} or types below them, "
        f"and this domain declares none of them (its types: {declared})"
    )


def _read_sexp(path: Path) -> list[Sexp]:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise LanguageError(f"{path}: cannot read PDDL file: {exc.strerror or exc}") from exc
    text = re.sub(r";[^\n]*", " ", text).lower()
    stack: list[list[Sexp]] = [[]]
    for token in re.findall(r"\(|\)|[^\s()]+", text):
        if token == "(":
            stack.append([])
        elif token == ")":
            if len(stack) < 2:
                raise LanguageError(f"{path}: unbalanced ')' in PDDL")
            done = stack.pop()
            stack[-1].append(done)
        else:
            stack[-1].append(token)
    if len(stack) != 1 or not stack[0] or not isinstance(stack[0][0], list):
        raise LanguageError(f"{path}: not a PDDL file (unbalanced parentheses or no '(define ...)')")
    return stack[0][0]


def _typed(items: list[Sexp]) -> list[tuple[str, str]]:
    """A PDDL typed list ``a b - t c - u d`` as [(a, t), (b, t), (c, u), (d, object)]."""
    out: list[tuple[str, str]] = []
    pending: list[str] = []
    index = 0
    while index < len(items):
        item = items[index]
        if item == "-" and index + 1 < len(items):
            parent = items[index + 1]
            name = parent if isinstance(parent, str) else "object"
            out += [(p.lstrip("?"), name) for p in pending]
            pending = []
            index += 2
            continue
        if isinstance(item, str):
            pending.append(item)
        index += 1
    out += [(p.lstrip("?"), "object") for p in pending]
    return out
