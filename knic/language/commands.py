"""The command language as data: ``commands.yaml`` read into phrase tables and template grammar nodes.

One file says how people phrase commands (politeness and fillers, joiners, verb classes, prepositions, states,
levels, and templates of whole phrasings). Three consumers read it through :func:`command_language`:

* :mod:`knic.language.reader` reads typed or recognised text with the phrase tables;
* :mod:`knic.language.grammar` turns the templates into the grammar the speech decoder searches;
* :mod:`knic.language.sampling` samples sentences (with their frames) from the templates, for the n-gram
  model of the recogniser and for tests.

The file holds general English only; what the world has (objects, rooms, people, devices) comes from the
vocabulary (:mod:`knic.language.vocabulary`).
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import re
import tempfile
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from core.errors import LanguageError
from core.inputs import MAX_YAML_BYTES, read_text_limited, safe_yaml
from knic.language.grammar import Alt, Bind, Frame, Grammar, Node, Opt, Ref, Repeat, Seq, Slot, Words

DEFAULT_PATH = Path(__file__).resolve().parent / "commands.yaml"
#: Frame kinds a template may produce.
TEMPLATE_KINDS = ("SEARCHING", "BRINGING", "TAKING", "PLACING", "ACCOMPANYING", "MOTION", "OPERATING")
#: Template slot types -> (PDDL categories, group phrases admitted).
SLOT_TYPES: dict[str, tuple[tuple[str, ...], bool]] = {
    "item": (("item",), False),
    "person": (("person",), False),
    "room": (("room",), False),
    "furniture": (("furniture",), False),
    "place": (("room", "furniture"), False),
    "light": (("light",), False),
    "lights": (("light",), True),
    "dimmer": (("dimmer",), False),
    "blinds": (("blinds",), False),
    "device": (("device",), True),
    "level": (("level",), False),
}
_TOKEN = re.compile(r"\{[^}]+\}|=[a-z_]+:[A-Za-z0-9_-]+|[\[\]()|]|[^\s\[\]()|{}=]+")


@dataclass(frozen=True)
class VerbClass:
    """A verb class: its phrases, the frame kinds it can start (in order), the state it implies, the
    beneficiary it implies ("i need ..." is for the speaker), and whether its phrases are verbs only when
    they open the command ("is the remote in the living room?")."""

    name: str
    phrases: tuple[str, ...]
    frames: tuple[str, ...]
    state: str | None = None
    beneficiary: str | None = None
    opening: bool = False
    #: the phrases read in text and in what the recogniser heard but left out of the templates, so of what
    #: the speech model hears (rare words that would only add confusions there: "snatch", "scout for")
    text_only: tuple[str, ...] = ()

    @property
    def spoken(self) -> tuple[str, ...]:
        """The phrases the templates, and so the speech model, use."""
        return tuple(p for p in self.phrases if p not in self.text_only)


@dataclass(frozen=True)
class CommandLanguage:
    """The phrase tables and templates of ``commands.yaml`` (see the file for each table's meaning)."""

    fillers: tuple[str, ...]
    joiners: tuple[str, ...]
    determiners: tuple[str, ...]
    pronouns: dict[str, str]
    verbs: tuple[VerbClass, ...]
    prepositions: dict[str, tuple[str, ...]]
    states: dict[str, tuple[str, ...]]
    levels: dict[int, tuple[str, ...]]
    percent: tuple[str, ...]
    partitive: tuple[str, ...]
    templates: tuple[tuple[str, str], ...]  # (kind, body); kind "alone KIND": a whole command only
    openers: tuple[str, ...]
    closers: tuple[str, ...]
    source: str = ""
    lists: dict[str, tuple[str, ...]] = field(default_factory=dict)
    vague_levels: tuple[str, ...] = ()
    unsaid_goal: tuple[str, ...] = ()
    quantifiers: dict[str, tuple[str, ...]] = field(default_factory=dict)
    everything: tuple[str, ...] = ()
    there: tuple[str, ...] = ()
    here: tuple[str, ...] = ()
    containment: tuple[str, ...] = ()
    anywhere: tuple[str, ...] = ()
    except_words: tuple[str, ...] = ()
    discard_verbs: tuple[str, ...] = ()
    discard_places: tuple[str, ...] = ()
    past_forms: dict[str, str] = field(default_factory=dict)
    bare_request: str | None = None
    type_nouns: dict[str, tuple[str, ...]] = field(default_factory=dict)
    repairs: tuple[str, ...] = ()
    negations: tuple[str, ...] = ()
    not_requests: tuple[str, ...] = ()
    not_requests_unless: tuple[str, ...] = ()
    spellings: dict[str, str] = field(default_factory=dict)
    digit_words: dict[str, str] = field(default_factory=dict)
    typed_words: dict[str, str] = field(default_factory=dict)
    homophones: dict[str, str] = field(default_factory=dict)
    spoken_marks: dict[str, str] = field(default_factory=dict)
    spanish_words: dict[str, str] = field(default_factory=dict)
    spanish_articles: dict[str, str] = field(default_factory=dict)
    spanish_after_articles: dict[str, str] = field(default_factory=dict)
    verb_numbers: dict[str, str] = field(default_factory=dict)

    def verb_frames(self) -> dict[str, tuple[tuple[str, ...], str | None]]:
        """Verb phrase -> (frame kinds in order, implied state); a phrase in several classes gets all."""
        table: dict[str, tuple[tuple[str, ...], str | None]] = {}
        for verb in self.verbs:
            if verb.opening:
                continue
            for phrase in verb.phrases:
                kinds, state = table.get(phrase, ((), None))
                merged = kinds + tuple(k for k in verb.frames if k not in kinds)
                table[phrase] = (merged, state or verb.state)
        return table

    def verb_beneficiaries(self) -> dict[str, str]:
        """Verb phrase -> the beneficiary it implies, for the phrases of classes that imply one."""
        return {p: v.beneficiary for v in self.verbs if v.beneficiary for p in v.phrases}

    def opening_verbs(self) -> dict[str, VerbClass]:
        """Phrase -> its class, for the classes whose phrases are verbs only when they open the command."""
        return {p: v for v in self.verbs if v.opening for p in v.phrases}

    def words(self) -> set[str]:
        """Every word of every phrase table (not the world's names)."""
        found: set[str] = set()
        for phrases in self.lists.values():
            for phrase in phrases:
                found.update(phrase.split())
        return found

    def template_nodes(self) -> list[Frame]:
        """Each template as a grammar :class:`~knic.language.grammar.Frame`.

        Raises:
            LanguageError: a template is malformed; the message names the template.
        """
        return [
            Frame(
                kind.removeprefix("alone "),
                _parse_template(text, self.lists, f"{self.source}: template {kind}: {text!r}"),
                kind.startswith("alone "),
            )
            for kind, text in self.templates
        ]


def _phrases(data: dict[str, Any], key: str, source: str) -> tuple[str, ...]:
    value = data.get(key) or []
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise LanguageError(f"{source}: '{key}' must be a list of phrases")
    return tuple(" ".join(v.lower().split()) for v in value)


def load_language(path: str | Path = DEFAULT_PATH) -> CommandLanguage:
    """Read a command-language file.

    Raises:
        LanguageError: the file is unreadable or malformed; the message names the file and the entry.
    """
    path = Path(path)
    source = str(path)
    data = _parsed(path)
    if not isinstance(data, dict):
        raise LanguageError(f"{source}: the command language is a mapping of tables")
    verbs = []
    for name, spec in (data.get("verbs") or {}).items():
        if not isinstance(spec, dict) or not spec.get("phrases") or not spec.get("frames"):
            raise LanguageError(f"{source}: verbs.{name} needs 'phrases' and 'frames'")
        unknown = [k for k in spec["frames"] if k not in TEMPLATE_KINDS]
        if unknown:
            raise LanguageError(f"{source}: verbs.{name}: unknown frame kind(s) {', '.join(unknown)}")
        beneficiary = spec.get("beneficiary")
        if beneficiary not in (None, "me", "subject"):
            raise LanguageError(
                f"{source}: verbs.{name}: beneficiary may only be 'me' or 'subject', not {beneficiary!r}"
            )
        text_only = _phrases(spec, "text_phrases", source)
        verbs.append(
            VerbClass(
                str(name),
                _phrases(spec, "phrases", source) + text_only,
                tuple(spec["frames"]),
                spec.get("state"),
                beneficiary,
                bool(spec.get("opening", False)),
                text_only,
            )
        )
    tables: dict[str, dict[str, tuple[str, ...]]] = {}
    for key in ("prepositions", "states", "levels", "quantifiers", "type_nouns"):
        raw = data.get(key) or {}
        if not isinstance(raw, dict):
            raise LanguageError(f"{source}: '{key}' must map names to phrase lists")
        tables[key] = {str(k): _phrases(raw, k, source) for k in raw}
    try:
        levels = {int(k): v for k, v in tables["levels"].items()}
    except ValueError as exc:
        raise LanguageError(f"{source}: levels are keyed by a percentage: {exc}") from exc
    templates = []
    for text in data.get("templates") or []:
        kind, sep, body = str(text).partition(": ")
        if not sep or kind.removeprefix("alone ") not in TEMPLATE_KINDS:
            raise LanguageError(
                f"{source}: template {text!r} must start with a frame kind (or 'alone' and a kind) and ': '"
            )
        templates.append((kind, body))
    pronouns = {str(k): str(v) for k, v in (data.get("pronouns") or {}).items()}
    unknown_quantifiers = sorted(set(tables["quantifiers"]) - {"all", "both"})
    if unknown_quantifiers:
        raise LanguageError(
            f"{source}: quantifiers are 'all' and 'both', not {', '.join(unknown_quantifiers)}"
        )
    bare = data.get("bare_request")
    if bare is not None and bare not in {v.name for v in verbs}:
        raise LanguageError(f"{source}: bare_request {bare!r} is not a verb class")
    language = CommandLanguage(
        fillers=_phrases(data, "fillers", source),
        joiners=_phrases(data, "joiners", source),
        determiners=_phrases(data, "determiners", source),
        pronouns=pronouns,
        verbs=tuple(verbs),
        prepositions=tables["prepositions"],
        states=tables["states"],
        levels=levels,
        percent=_phrases(data, "percent", source),
        partitive=_phrases(data, "partitive", source),
        templates=tuple(templates),
        openers=_phrases(data, "openers", source),
        closers=_phrases(data, "closers", source),
        source=source,
        vague_levels=_phrases(data, "vague_levels", source),
        unsaid_goal=_phrases(data, "unsaid_goal", source),
        quantifiers=tables["quantifiers"],
        everything=_phrases(data, "everything", source),
        there=_phrases(data, "there", source),
        here=_phrases(data, "here", source),
        containment=_phrases(data, "containment", source),
        anywhere=_phrases(data, "anywhere", source),
        except_words=_phrases(data, "except_words", source),
        discard_verbs=_phrases(data, "discard_verbs", source),
        discard_places=_phrases(data, "discard_places", source),
        bare_request=bare,
        type_nouns=tables["type_nouns"],
        repairs=_phrases(data, "repairs", source),
        negations=_phrases(data, "negations", source),
        not_requests=_phrases(data, "not_requests", source),
        not_requests_unless=_phrases(data, "not_requests_unless", source),
        spellings=_spellings(data, source),
        digit_words=_spellings(data, source, "digit_words"),
        typed_words=_spellings(data, source, "typed_words"),
        homophones=_spellings(data, source, "homophones"),
        past_forms=_spellings(data, source, "past_forms"),
        spoken_marks=_marks(data, source),
        spanish_words=_spellings(data, source, "spanish_words"),
        spanish_articles=_spellings(data, source, "spanish_articles"),
        spanish_after_articles=_spellings(data, source, "spanish_after_articles"),
        verb_numbers=_spellings(data, source, "verb_numbers"),
    )
    lists: dict[str, tuple[str, ...]] = {v.name: v.spoken for v in verbs}
    spoken = _phrases(data, "spoken_determiners", source) or language.determiners
    lists.update(det=spoken, fillers=language.fillers, joiners=language.joiners)
    lists.update(percent=language.percent, openers=language.openers, closers=language.closers)
    lists.update(vague_levels=language.vague_levels, unsaid_goal=language.unsaid_goal)
    lists.update(everything=language.everything, there=language.there, anywhere=language.anywhere)
    lists.update(repairs=language.repairs)
    lists.update({f"quantifier_{k}": v for k, v in language.quantifiers.items()})
    object.__setattr__(language, "lists", lists)
    language.template_nodes()  # fail early on a malformed template
    return language


def _spellings(data: dict[str, Any], source: str, key: str = "spellings") -> dict[str, str]:
    """The ``spellings`` (or ``digit_words``, ``typed_words``) table: one word -> the words it stands for.

    Raises:
        LanguageError: not a mapping of single words to phrases.
    """
    raw = data.get(key) or {}
    if not isinstance(raw, dict) or not all(
        isinstance(k, str) and isinstance(v, str) and len(k.split()) == 1 and v.split()
        for k, v in raw.items()
    ):
        raise LanguageError(f"{source}: '{key}' maps single words to the words they stand for")
    return {k: " ".join(v.split()) for k, v in raw.items()}


def _marks(data: dict[str, Any], source: str) -> dict[str, str]:
    """The ``spoken_marks`` table: the words said for a punctuation mark -> the mark ("" for none).

    Raises:
        LanguageError: not a mapping of words to marks.
    """
    raw = data.get("spoken_marks") or {}
    if not isinstance(raw, dict) or not all(
        isinstance(k, str) and k.split() and isinstance(v, str) and not v.strip(".,?!;")
        for k, v in raw.items()
    ):
        raise LanguageError(f"{source}: 'spoken_marks' maps words to the punctuation mark they name")
    return {" ".join(k.lower().split()): v for k, v in raw.items()}


def _parsed(path: Path) -> Any:
    """The file's YAML as data, through a JSON copy in the temporary folder keyed by the file's content
    (parsing the YAML takes most of ``knic goal``'s own start-up; the copy is checked like the file).

    Raises:
        LanguageError: the file is unreadable, too large, not UTF-8 or not valid YAML.
    """
    text = read_text_limited(path, MAX_YAML_BYTES, "command language", LanguageError)
    digest = hashlib.sha256(text.encode("utf-8")).hexdigest()[:20]
    cache = Path(tempfile.gettempdir()) / f"knic-commands-{digest}.json"
    with contextlib.suppress(OSError, ValueError):
        return json.loads(cache.read_text(encoding="utf-8"))
    data = safe_yaml(text, str(path), LanguageError)
    with contextlib.suppress(OSError, TypeError, ValueError):  # no copy: parsed again next time
        cache.write_text(json.dumps(data), encoding="utf-8")
    return data


@lru_cache(maxsize=4)
def command_language(path: str = str(DEFAULT_PATH)) -> CommandLanguage:
    """The command language of a file, read once."""
    return load_language(path)


def _parse_template(text: str, lists: dict[str, tuple[str, ...]], where: str) -> Node:
    tokens = _TOKEN.findall(text)
    position = 0

    def sequence(closers: str) -> Node:
        nonlocal position
        options: list[list[Node]] = [[]]
        while position < len(tokens) and tokens[position] not in closers:
            token = tokens[position]
            position += 1
            if token == "|":
                options.append([])
            elif token in "[(":
                inner = sequence("])")
                if position >= len(tokens) or tokens[position] != ("]" if token == "[" else ")"):
                    raise LanguageError(f"{where}: unbalanced '{token}'")
                position += 1
                options[-1].append(Opt(inner) if token == "[" else inner)
            else:
                options[-1].append(_atom(token, lists, where))
        alternatives = [Seq(tuple(parts)) for parts in options]
        return alternatives[0] if len(alternatives) == 1 else Alt(tuple(alternatives))

    node = sequence("")
    if position != len(tokens):
        raise LanguageError(f"{where}: unexpected '{tokens[position]}'")
    return node


def _atom(token: str, lists: dict[str, tuple[str, ...]], where: str) -> Node:
    if token.startswith("="):
        role, _, value = token[1:].partition(":")
        return Bind(role, value)
    if token.startswith("{"):
        name = token[1:-1]
        if ":" in name:
            kind, _, role = name.partition(":")
            if kind not in SLOT_TYPES:
                raise LanguageError(
                    f"{where}: unknown slot type {kind!r}; expected one of {', '.join(SLOT_TYPES)}"
                )
            categories, groups = SLOT_TYPES[kind]
            return Slot(role, categories, groups)
        if name not in lists:
            raise LanguageError(
                f"{where}: unknown list {{{name}}}; expected one of {', '.join(sorted(lists))}"
            )
        phrases = tuple(p for p in lists[name] if p)
        node = Alt(tuple(Words(p) for p in phrases))
        return Opt(node) if name == "det" else node
    return Words(token.lower())


def command_grammar(max_actions: int = 3, language: CommandLanguage | None = None) -> Grammar:
    """The command grammar of the templates: an optional opener, up to ``max_actions`` actions (each one
    template) with optional joiners between them, and an optional closer.

    The speech decoder searches this grammar (:mod:`knic.language.fsg`); text is read by the more forgiving
    :mod:`knic.language.reader`, which understands every sentence the grammar admits.
    """
    language = language or command_language()
    frames = language.template_nodes()
    rules: dict[str, Node] = {}
    names = []
    for index, frame in enumerate(frames):
        name = f"{frame.kind.lower()}_{index}"
        rules[name] = frame
        names.append(name)
    rules["action"] = Alt(tuple(Ref(n) for n in names))
    rules["opener"] = Alt(tuple(Words(p) for p in language.openers if p))
    rules["joiner"] = Alt(tuple(Words(p) for p in language.joiners if p))
    rules["closer"] = Alt(tuple(Words(p) for p in language.closers if p))
    rules["command"] = Seq(
        (
            Opt(Ref("opener")),
            Ref("action"),
            Repeat(Seq((Opt(Ref("joiner")), Ref("action"))), max_actions - 1),
            Opt(Ref("closer")),
        )
    )
    return Grammar(rules, "command")
