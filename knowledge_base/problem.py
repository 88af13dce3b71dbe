"""Loading a PDDL problem for the knowledge base: a checked pre-scan, then unified-planning's reader.

unified-planning accepts a problem whose ``:domain`` names another domain and reports some symbol errors
without saying which file they are in. So the problem text is first read as s-expressions with line numbers
and checked against the :class:`~knowledge_base.domain.DomainModel` (domain name, object types, and every
atom of ``:init`` and ``:goal``: predicate, arity, objects, argument types). Only then is it parsed with
``PDDLReader`` and turned into a :class:`ProblemContent`.

Failure behaviour: syntax errors raise :class:`~core.errors.PDDLParseError` (file, line, column, what was
expected); inconsistencies raise :class:`~core.errors.PDDLValidationError` naming the symbol, file and line.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from core.errors import PDDLValidationError
from knowledge_base.domain import DomainModel, parse_with_up, read_pddl
from knowledge_base.model import Fact

__all__ = ["ProblemContent", "content_from_up", "load_problem", "parse_problem_text", "parse_problem_up"]

_TOKEN = re.compile(r"\(|\)|[^\s()]+")
_LOGIC = {"and", "or", "not", "imply"}
_QUANTIFIERS = {"exists", "forall"}
_SKIP = {"=", "<", ">", "<=", ">=", "preference", "always", "sometime", "within", "at-most-once"}


@dataclass(frozen=True)
class ProblemContent:
    """What a problem file adds to a knowledge base.

    Attributes:
        name: Problem name.
        objects: Object -> type (domain constants excluded).
        facts: Initial facts that hold, in file order.
        functions: Initial numeric values.
        goals: Goal atoms (the goal must be a conjunction of atoms).
        source: File name, for messages.
    """

    name: str
    objects: Mapping[str, str]
    facts: tuple[Fact, ...]
    functions: Mapping[Fact, float]
    goals: tuple[Fact, ...]
    source: str


def load_problem(domain: DomainModel, path: str | Path) -> ProblemContent:
    """Read, check and parse a problem file for ``domain``.

    Raises:
        PDDLParseError: missing file or syntax error.
        PDDLValidationError: the problem does not fit the domain.
    """
    return parse_problem_text(domain, read_pddl(path, "problem"), source=str(path))


def parse_problem_text(domain: DomainModel, text: str, *, source: str = "<problem>") -> ProblemContent:
    """Check and parse problem text (see :func:`load_problem`); the same texts give the same cached result."""
    return _parse_cached(domain, text, source)


@functools.lru_cache(maxsize=32)
def _parse_cached(domain: DomainModel, text: str, source: str) -> ProblemContent:
    return content_from_up(domain, parse_problem_up(domain, text, source=source), source)


def parse_problem_up(domain: DomainModel, text: str, *, source: str = "<problem>") -> Any:
    """Check problem text against ``domain`` (messages name file and line), then parse it with
    unified-planning; the whole problem is returned, whatever its goal formula (``knic plan`` uses it).

    Raises:
        PDDLParseError: syntax error.
        PDDLValidationError: the problem does not fit the domain.
    """
    tree = _sexp(text)
    if tree is not None:
        _prescan(domain, tree, source)
    return parse_with_up(domain.text, text, domain.source, source)


def content_from_up(domain: DomainModel, problem: Any, source: str = "<up problem>") -> ProblemContent:
    """Objects, initial facts and functions, and goals of a unified-planning ``Problem`` on ``domain``.

    Raises:
        PDDLValidationError: a goal is not a conjunction of atoms.
    """
    objects = {o.name: o.type.name for o in problem.all_objects if o.name not in domain.constants}
    facts: list[Fact] = []
    functions: dict[Fact, float] = {}
    for key, value in problem.explicit_initial_values.items():
        if not key.is_fluent_exp():
            continue
        fact = Fact(key.fluent().name, tuple(a.object().name for a in key.args))
        if key.fluent().type.is_bool_type():
            if value.is_true():
                facts.append(fact)
        else:
            functions[fact] = float(value.constant_value())
    goals: list[Fact] = []
    for goal in problem.goals:
        _flatten_goal(goal, goals, source)
    return ProblemContent(problem.name, objects, tuple(facts), functions, tuple(goals), source)


def _flatten_goal(node: Any, out: list[Fact], source: str) -> None:
    if node.is_and():
        for arg in node.args:
            _flatten_goal(arg, out, source)
    elif node.is_fluent_exp() and node.fluent().type.is_bool_type():
        out.append(Fact(node.fluent().name, tuple(a.object().name for a in node.args)))
    else:
        raise PDDLValidationError(
            f"{source}: goal {node} is not a conjunction of atoms; the knowledge base keeps atomic goals"
        )


# --------------------------------------------------------------------- s-expressions with line numbers
class _List(list):
    """A parenthesised list remembering the line it starts on."""

    line = 0


class _Atom(str):
    """A token remembering its line."""

    line = 0


def _sexp(text: str) -> _List | None:
    """The first top-level list of ``text``, or None if it is not well formed (the real parser reports it)."""
    stack: list[_List] = []
    top: _List | None = None
    for lineno, raw in enumerate(text.splitlines(), start=1):
        for token in _TOKEN.findall(raw.split(";", 1)[0]):
            if token == "(":
                node = _List()
                node.line = lineno
                if stack:
                    stack[-1].append(node)
                stack.append(node)
            elif token == ")":
                if not stack:
                    return None
                done = stack.pop()
                if not stack and top is None:
                    top = done
            elif stack:
                atom = _Atom(token.lower())
                atom.line = lineno
                stack[-1].append(atom)
            else:
                return None
    return None if stack else top


def _section(tree: _List, key: str) -> _List | None:
    for item in tree:
        if isinstance(item, _List) and item and item[0] == key:
            return item
    return None


def _prescan(domain: DomainModel, tree: _List, source: str) -> None:
    if not tree or tree[0] != "define":
        return
    dom = _section(tree, ":domain")
    if dom is not None and len(dom) == 2 and dom[1] != domain.name:
        raise PDDLValidationError(
            f"{source}:{dom.line}: problem is for domain {str(dom[1])!r}, "
            f"but the domain loaded is {domain.name!r}"
        )
    objects = dict(domain.constants)
    section = _section(tree, ":objects")
    if section is not None:
        pending: list[_Atom] = []
        items = list(section[1:])
        i = 0
        while i < len(items):
            item = items[i]
            if item == "-" and i + 1 < len(items):
                type_name = items[i + 1]
                if not domain.is_type(type_name):
                    raise PDDLValidationError(
                        f"{source}:{type_name.line}: object {str(pending[0]) if pending else '?'!r} "
                        f"has unknown type {str(type_name)!r}"
                    )
                objects.update(dict.fromkeys(pending, str(type_name)))
                pending = []
                i += 2
                continue
            if isinstance(item, _Atom):
                pending.append(item)
            i += 1
        objects.update(dict.fromkeys(pending, "object"))
    init = _section(tree, ":init")
    for atom in init[1:] if init is not None else ():
        if isinstance(atom, _List) and atom:
            _check_init(domain, objects, atom, source)
    goal = _section(tree, ":goal")
    if goal is not None:
        for item in goal[1:]:
            if isinstance(item, _List):
                _check_goal(domain, objects, item, source)


def _check_init(domain: DomainModel, objects: dict[str, str], atom: _List, source: str) -> None:
    head = atom[0]
    if head == "=" and len(atom) == 3 and isinstance(atom[1], _List):
        _check_atom(domain, objects, atom[1], source, functions=True)
    elif head == "not" and len(atom) == 2 and isinstance(atom[1], _List):
        _check_atom(domain, objects, atom[1], source)
    elif _is_timed(atom):  # timed initial literal: (at 10 (p a))
        _check_init(domain, objects, atom[2], source)
    else:
        _check_atom(domain, objects, atom, source)


def _is_timed(node: _List) -> bool:
    """``(at 10 (p a))`` or ``(at end (p a))``, as opposed to an atom of a predicate named ``at``."""
    return len(node) == 3 and node[0] == "at" and isinstance(node[1], _Atom) and isinstance(node[2], _List)


def _check_goal(domain: DomainModel, objects: dict[str, str], node: _List, source: str) -> None:
    if not node or not isinstance(node[0], _Atom):
        return
    head = str(node[0])
    if _is_timed(node):
        _check_goal(domain, objects, node[2], source)
    elif head in _LOGIC:
        for child in node[1:]:
            if isinstance(child, _List):
                _check_goal(domain, objects, child, source)
    elif head in _QUANTIFIERS:
        for child in node[2:]:
            if isinstance(child, _List):
                _check_goal(domain, objects, child, source)
    elif head not in _SKIP:
        _check_atom(domain, objects, node, source)


def _check_atom(
    domain: DomainModel, objects: dict[str, str], atom: _List, source: str, *, functions: bool = False
) -> None:
    if not atom or not isinstance(atom[0], _Atom):
        return
    name = str(atom[0])
    args = [a for a in atom[1:]]
    text = "(" + " ".join(str(a) for a in atom if isinstance(a, str)) + ")"
    where = f"{source}:{atom.line}"
    table = domain.functions if functions else domain.predicates
    sig = table.get(name)
    if sig is None:
        what = "function" if functions else "predicate"
        raise PDDLValidationError(f"{where}: unknown {what} {name!r} in {text} (domain {domain.name})")
    if len(sig) != len(args):
        raise PDDLValidationError(f"{where}: {name} takes {len(sig)} arguments, {text} has {len(args)}")
    for (param, type_name), arg in zip(sig, args, strict=True):
        if not isinstance(arg, _Atom) or arg.startswith("?"):
            continue
        actual = objects.get(str(arg))
        if actual is None:
            raise PDDLValidationError(f"{where}: unknown object {str(arg)!r} in {text}")
        if not domain.is_subtype(actual, type_name):
            raise PDDLValidationError(
                f"{where}: {text}: argument ?{param} must be of type {type_name}, {str(arg)!r} is a {actual}"
            )
