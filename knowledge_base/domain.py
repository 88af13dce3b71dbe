"""The PDDL domain as the knowledge base sees it: types, predicates, constants, functions, actions, metadata.

A :class:`DomainModel` is built once from a domain file (or from the domain text stored in a journal) through
unified-planning's ``PDDLReader`` and the optional ``<domain stem>.meta.yaml`` sidecar, which says in data
what PDDL cannot: which predicates are single-valued (``single_valued: {robot_at: [0]}``) and which actions
are sensing actions (``sensing: {search_object: [found, object_at]}``). It is immutable after construction and
precomputes the per-predicate type tables that make validating a write a few dictionary look-ups.

Failure behaviour: a file that does not parse raises :class:`~core.errors.PDDLParseError` naming file, line,
column and what the parser expected; a domain or sidecar that parses but is inconsistent raises
:class:`~core.errors.PDDLValidationError`.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from core.errors import JournalError, PDDLParseError, PDDLValidationError
from core.inputs import read_text_limited, safe_yaml

__all__ = ["MAX_PDDL_BYTES", "DomainModel", "meta_path_for", "parse_with_up", "read_pddl"]

#: Root of every PDDL type hierarchy.
OBJECT = "object"
#: Largest PDDL file read (bytes): far above any hand-written or generated household problem.
MAX_PDDL_BYTES = 8 * 1024 * 1024


def meta_path_for(domain_path: Path) -> Path:
    """The sidecar of a domain: ``worlds/erl_home/domain.pddl`` -> ``worlds/erl_home/domain.meta.yaml``."""
    return domain_path.with_name(f"{domain_path.stem}.meta.yaml")


def read_pddl(path: str | Path, what: str, max_bytes: int | None = None) -> str:
    """The text of a PDDL (or sidecar) file, read with limits: at most ``max_bytes`` (default
    :data:`MAX_PDDL_BYTES`), UTF-8, a regular file.

    Raises:
        PDDLParseError: missing, not a regular file, too large, or not UTF-8 text (one line naming the file).
    """
    limit = MAX_PDDL_BYTES if max_bytes is None else max_bytes
    return read_text_limited(path, limit, f"{what} file", PDDLParseError)


def parse_with_up(
    domain_text: str, problem_text: str | None, domain_file: str, problem_file: str | None
) -> Any:
    """Parse PDDL text with unified-planning, turning its exceptions into the project's error tree.

    Args:
        domain_text: Domain PDDL.
        problem_text: Problem PDDL, or None for the domain alone.
        domain_file: Name used in messages for the domain.
        problem_file: Name used in messages for the problem.

    Returns:
        The ``unified_planning.model.Problem``. With a problem, the domain must already be known to parse
        (load it alone first), so that every error can be attributed to the right file.

    Raises:
        PDDLParseError: a syntax error (file, line, column, what was expected).
        PDDLValidationError: unified-planning refused the content (undefined type, unknown symbol, ...).
    """
    import pyparsing
    from unified_planning.io import PDDLReader

    if problem_text is None:
        try:
            return PDDLReader().parse_problem_string(domain_text)
        except pyparsing.ParseBaseException as exc:
            raise _parse_error(domain_file, exc) from None
        except Exception as exc:  # unified-planning raises SyntaxError, UPException, AssertionError...
            raise PDDLValidationError(f"{domain_file}: {_first_line(exc)}") from None
    # With a problem, the caller has already loaded the domain alone, so any error is the problem's.
    try:
        return PDDLReader().parse_problem_string(domain_text, problem_text)
    except pyparsing.ParseBaseException as exc:
        raise _parse_error(problem_file or "<problem>", exc) from None
    except Exception as exc:
        raise PDDLValidationError(f"{problem_file}: {_first_line(exc)}") from None


def _parse_error(file: str, exc: Any) -> PDDLParseError:
    return PDDLParseError(f"{file}:{exc.lineno}:{exc.col}: {exc.msg}, found {_found(exc)}")


def _found(exc: Any) -> str:
    text = exc.pstr[exc.loc : exc.loc + 20].split("\n")[0].strip()
    return repr(text) if text else "end of file"


def _first_line(exc: BaseException) -> str:
    text = str(exc).replace("\n", " ").strip() or type(exc).__name__
    return text


@dataclass(frozen=True, eq=False)
class DomainModel:
    """A parsed PDDL domain plus its metadata; immutable, shared by a knowledge base and its readers.

    Attributes:
        name: The domain's name.
        types: Type -> parent type (``"object"`` for top-level types).
        predicates: Predicate -> ((parameter, type), ...).
        constants: Constant name -> type; constants are instances of every knowledge base on this domain.
        functions: Numeric function -> ((parameter, type), ...).
        actions: Action names (instantaneous and durative), in file order.
        single_valued: Predicate -> argument positions that determine the rest.
        sensing: Sensing action -> predicates of its effects that perception must confirm.
        text: The domain PDDL text (stored in journals so a reader needs only the journal file).
        meta_text: The sidecar YAML text ("" when there is none).
        source: Where the domain came from (file path or "<journal>"), for messages.
        up_domain: unified-planning ``Problem`` holding the domain (its objects are the constants); parsed on
            first use when the model was rebuilt from a journal's summary.
    """

    name: str
    types: Mapping[str, str]
    predicates: Mapping[str, tuple[tuple[str, str], ...]]
    constants: Mapping[str, str]
    functions: Mapping[str, tuple[tuple[str, str], ...]]
    actions: tuple[str, ...]
    single_valued: Mapping[str, tuple[int, ...]]
    sensing: Mapping[str, tuple[str, ...]]
    text: str
    meta_text: str
    source: str
    _up: Any = field(repr=False, compare=False, default=None)
    _subtypes: Mapping[str, frozenset[str]] = field(repr=False, compare=False, default_factory=dict)

    @property
    def up_domain(self) -> Any:
        """The unified-planning ``Problem`` of the domain alone (constants as its objects)."""
        if self._up is None:
            object.__setattr__(self, "_up", parse_with_up(self.text, None, self.source, None))
        return self._up

    # ----------------------------------------------------------------- construction
    @classmethod
    def from_file(cls, domain_path: str | Path) -> DomainModel:
        """Load a domain file and its ``<stem>.meta.yaml`` sidecar when present.

        Raises:
            PDDLParseError: the file is missing or does not parse.
            PDDLValidationError: the domain or sidecar is inconsistent.
        """
        path = Path(domain_path)
        text = read_pddl(path, "domain")
        meta = meta_path_for(path)
        meta_text = read_pddl(meta, "sidecar") if meta.is_file() else ""
        return cls.from_text(text, meta_text, source=str(path), meta_source=str(meta))

    @classmethod
    def from_text(
        cls, text: str, meta_text: str = "", *, source: str = "<domain>", meta_source: str = "<meta>"
    ) -> DomainModel:
        """Build a domain model from PDDL text and sidecar YAML text (see :meth:`from_file`).

        Models are immutable, so the same texts give the same (cached) model: loading one domain many times
        (tests, tools) parses it once.
        """
        return _domain_from_text(text, meta_text, source, meta_source)

    @classmethod
    def _build(cls, text: str, meta_text: str, source: str, meta_source: str) -> DomainModel:
        problem = parse_with_up(text, None, source, None)
        types: dict[str, str] = {}
        for t in problem.user_types:
            if t.name != OBJECT:  # an untyped domain declares ``object`` itself (with no parent)
                types[t.name] = t.father.name if t.father is not None else OBJECT
        predicates: dict[str, tuple[tuple[str, str], ...]] = {}
        functions: dict[str, tuple[tuple[str, str], ...]] = {}
        for fluent in problem.fluents:
            sig = tuple(
                (p.name, p.type.name if p.type.is_user_type() else str(p.type)) for p in fluent.signature
            )
            if fluent.type.is_bool_type():
                predicates[fluent.name] = sig
            else:
                functions[fluent.name] = sig
        constants = {o.name: o.type.name for o in problem.all_objects}
        actions = tuple(a.name for a in problem.actions)
        single_valued, sensing = _parse_meta(meta_text, meta_source, predicates, actions)
        subtypes = _subtype_closure(types)
        return cls(
            name=problem.name,
            types=types,
            predicates=predicates,
            constants=constants,
            functions=functions,
            actions=actions,
            single_valued=single_valued,
            sensing=sensing,
            text=text,
            meta_text=meta_text,
            source=source,
            _up=problem,
            _subtypes=subtypes,
        )

    def to_summary(self) -> dict[str, Any]:
        """The parsed symbols as JSON-able data (journals store it: readers need not run the PDDL parser)."""
        return {
            "name": self.name,
            "types": dict(self.types),
            "predicates": {k: [list(p) for p in v] for k, v in self.predicates.items()},
            "constants": dict(self.constants),
            "functions": {k: [list(p) for p in v] for k, v in self.functions.items()},
            "actions": list(self.actions),
        }

    @classmethod
    def from_journal_meta(cls, path: str | Path, meta: Mapping[str, str]) -> DomainModel:
        """The domain a journal stored in its meta table (``domain_text``, ``meta_text``, ``domain_summary``).

        Raises:
            JournalError: not a KnIC journal (no domain stored) or a corrupt summary.
            PDDLParseError, PDDLValidationError: the stored domain no longer loads.
        """
        import json

        if "domain_text" not in meta:
            raise JournalError(f"{path}: not a KnIC journal (no domain stored)")
        source = f"{path}:domain"
        if not meta.get("domain_summary"):
            return cls.from_text(
                meta["domain_text"], meta.get("meta_text", ""), source=source, meta_source=f"{path}:meta"
            )
        try:
            summary = json.loads(meta["domain_summary"])
        except ValueError:
            raise JournalError(f"{path}: corrupt domain summary") from None
        return cls.from_summary(summary, meta["domain_text"], meta.get("meta_text", ""), source=source)

    @classmethod
    def from_summary(
        cls, summary: Mapping[str, Any], text: str, meta_text: str = "", *, source: str = "<journal>"
    ) -> DomainModel:
        """Rebuild a model from :meth:`to_summary` data and the texts, without parsing the PDDL again.

        Raises:
            PDDLValidationError: the summary is malformed or the sidecar does not fit it.
        """
        try:
            predicates = {k: tuple((p, t) for p, t in v) for k, v in summary["predicates"].items()}
            functions = {k: tuple((p, t) for p, t in v) for k, v in summary["functions"].items()}
            types = dict(summary["types"])
            actions = tuple(summary["actions"])
            single_valued, sensing = _parse_meta(meta_text, f"{source}:meta", predicates, actions)
            return cls(
                name=str(summary["name"]),
                types=types,
                predicates=predicates,
                constants=dict(summary["constants"]),
                functions=functions,
                actions=actions,
                single_valued=single_valued,
                sensing=sensing,
                text=text,
                meta_text=meta_text,
                source=source,
                _subtypes=_subtype_closure(types),
            )
        except (KeyError, TypeError, ValueError) as exc:
            raise PDDLValidationError(f"{source}: malformed domain summary ({exc})") from None

    # ----------------------------------------------------------------- queries
    def is_type(self, name: str) -> bool:
        """Whether ``name`` is a declared type (or ``object``)."""
        return name == OBJECT or name in self.types

    def is_subtype(self, type_name: str, ancestor: str) -> bool:
        """Whether ``type_name`` equals ``ancestor`` or descends from it."""
        return type_name in self._subtypes.get(ancestor, ())

    def subtypes(self, type_name: str) -> frozenset[str]:
        """``type_name`` and all its descendants (empty for an unknown type)."""
        return self._subtypes.get(type_name, frozenset())

    def signature(self, name: str) -> tuple[tuple[str, str], ...] | None:
        """Parameters of a predicate or function, or None if neither exists."""
        sig = self.predicates.get(name)
        return sig if sig is not None else self.functions.get(name)


@functools.lru_cache(maxsize=16)
def _domain_from_text(text: str, meta_text: str, source: str, meta_source: str) -> DomainModel:
    return DomainModel._build(text, meta_text, source, meta_source)


def _subtype_closure(types: Mapping[str, str]) -> dict[str, frozenset[str]]:
    """Each type -> itself and its descendants (iterative: deep or cyclic type tables cannot recurse)."""
    children: dict[str, set[str]] = {}
    for t, parent in types.items():
        if t != parent:
            children.setdefault(parent, set()).add(t)

    def collect(t: str) -> frozenset[str]:
        out = {t}
        stack = [t]
        while stack:
            for child in children.get(stack.pop(), ()):
                if child not in out:
                    out.add(child)
                    stack.append(child)
        return frozenset(out)

    closure = {t: collect(t) for t in types}
    closure[OBJECT] = collect(OBJECT)
    return closure


def _parse_meta(
    meta_text: str,
    meta_source: str,
    predicates: Mapping[str, tuple[tuple[str, str], ...]],
    actions: tuple[str, ...],
) -> tuple[dict[str, tuple[int, ...]], dict[str, tuple[str, ...]]]:
    if not meta_text.strip():
        return {}, {}
    data = safe_yaml(meta_text, meta_source, PDDLParseError) or {}
    if not isinstance(data, dict):
        raise PDDLValidationError(f"{meta_source}: expected a mapping with 'single_valued' and 'sensing'")
    single: dict[str, tuple[int, ...]] = {}
    for pred, positions in (data.get("single_valued") or {}).items():
        if pred not in predicates:
            raise PDDLValidationError(f"{meta_source}: single_valued names unknown predicate {pred!r}")
        arity = len(predicates[pred])
        if not isinstance(positions, list) or not all(
            isinstance(p, int) and 0 <= p < arity for p in positions
        ):
            raise PDDLValidationError(
                f"{meta_source}: single_valued {pred}: expected a list of argument positions 0..{arity - 1}"
            )
        if len(positions) >= arity:
            raise PDDLValidationError(
                f"{meta_source}: single_valued {pred}: the key must leave an argument free"
            )
        single[pred] = tuple(positions)
    sensing: dict[str, tuple[str, ...]] = {}
    for action, preds in (data.get("sensing") or {}).items():
        if action not in actions:
            raise PDDLValidationError(f"{meta_source}: sensing names unknown action {action!r}")
        unknown = [p for p in preds or () if p not in predicates]
        if unknown:
            raise PDDLValidationError(f"{meta_source}: sensing {action}: unknown predicate {unknown[0]!r}")
        sensing[action] = tuple(preds or ())
    return single, sensing
