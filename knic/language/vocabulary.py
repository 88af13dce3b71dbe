"""The spoken vocabulary of a world: which phrases name which knowledge-base symbols.

A :class:`Vocabulary` is built once from a knowledge base (its instances by type, the domain's type hierarchy
and its ``level`` constants) plus a lexicon of spoken names (``worlds/<world>/lexicon.yaml``). The grammar
(:mod:`knic.language.grammar`) takes its noun phrases from here, for the text parser and for the JSGF
grammar alike, so both accept exactly the things the world has. The vocabulary is an immutable snapshot:
instances added to the knowledge base later need a new one. Phrases are normalised text: lowercase words
separated by single spaces (see :func:`normalize`)."""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Protocol

from core.errors import LanguageError
from core.inputs import read_yaml
from knic.language.decimals import decimals_read, digits_apart, plain_typed
from knic.language.kinds import aliased, is_subtype
from knic.language.shortnames import contains, english_nearer, own_phrases, short_names

#: Number words for 0..100, enough for percent levels.
UNIT_WORDS = [
    "zero",
    "one",
    "two",
    "three",
    "four",
    "five",
    "six",
    "seven",
    "eight",
    "nine",
    "ten",
    "eleven",
    "twelve",
    "thirteen",
    "fourteen",
    "fifteen",
    "sixteen",
    "seventeen",
    "eighteen",
    "nineteen",
]
TENS_WORDS = ["_", "_", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"]
#: Facts ``(predicate thing place)`` that say where a thing is (read into :attr:`Vocabulary.locations`).
LOCATION_PREDICATES = ("furniture_in", "object_on", "object_at")
_LEVEL_CONSTANT = re.compile(r"^l(\d{1,3})$")


def number_words(value: int) -> str:
    """Spell an integer in 0..100 as spoken English ("twenty five", "one hundred").

    Raises:
        ValueError: the value is outside 0..100.
    """
    if not 0 <= value <= 100:
        raise ValueError(f"number {value} is outside 0..100")
    if value == 100:
        return "one hundred"
    if value < 20:
        return UNIT_WORDS[value]
    tens, unit = divmod(value, 10)
    return TENS_WORDS[tens] if unit == 0 else f"{TENS_WORDS[tens]} {UNIT_WORDS[unit]}"


def normalize(text: str) -> str:
    """Normalise a typed or recognised command to the grammar's token form.

    Lowercases, reads typographic marks as plain ones (:func:`plain_typed`), ``%`` as "percent" and decimals
    as whole numbers (:func:`decimals_read`), spells numbers 0..100 as words, turns hyphens and underscores
    into spaces, drops other punctuation (commas and full stops separate nothing the grammar needs), and
    collapses whitespace: ``normalize("Half-open the blinds, please!") == "half open the blinds please"``.
    """
    text = digits_apart(decimals_read(plain_typed(text))).lower().replace("%", " percent ").replace("-", " ")
    text = text.replace("_", " ")
    text = re.sub(
        r"\d+", lambda m: number_words(int(m.group())) if int(m.group()) <= 100 else m.group(), text
    )
    text = re.sub(r"[^a-z0-9' ]+", " ", text)
    return " ".join(text.split())


class KnowledgeSource(Protocol):
    """What the vocabulary reads from a knowledge base (a subset of ``knowledge_base.KnowledgeBase``)."""

    @property
    def domain(self) -> Any:
        """The domain model: ``types`` ({type: parent}) and ``constants`` are read."""

    def instances(self, type: str | None = None) -> list[str]:
        """Instance names, of a type and its subtypes when given."""

    def type_of(self, name: str) -> str | None:
        """The declared type of an instance, or None."""


@dataclass(frozen=True)
class Term:
    """One spoken phrase and what it names.

    Attributes:
        phrase: normalised spoken words, e.g. ``"reading glasses"``.
        symbol: the knowledge-base symbol (``"glasses"``), or a group's name (``"all_lights"``).
        type: the symbol's PDDL type (for a group: its members' common type).
        members: the symbols a group stands for; ``(symbol,)`` for a plain term.
        given: the phrase is given by a synonym or a shorter name, not the world's own name or its lexicon's
            (a thing's own name beats it: "the table" is the dining table, not the nightstand that is also a
            "bedside table").
    """

    phrase: str
    symbol: str
    type: str
    members: tuple[str, ...]
    given: bool = False

    @property
    def is_group(self) -> bool:
        """True when the phrase names several symbols at once."""
        return self.members != (self.symbol,)


@dataclass(frozen=True)
class GroupSpec:
    """A lexicon group: a name, its phrases, and either a member type or explicit members."""

    name: str
    phrases: tuple[str, ...]
    type: str | None = None
    members: tuple[str, ...] = ()


@dataclass(frozen=True)
class Lexicon:
    """Spoken names from a lexicon file: ``names`` {symbol: phrases} and ``groups``."""

    names: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    groups: tuple[GroupSpec, ...] = ()

    @classmethod
    def load(cls, path: str | Path) -> Lexicon:
        """Read a lexicon YAML file (format in ``worlds/erl_home/lexicon.yaml``).

        Raises:
            LanguageError: the file is missing or malformed; the message names the file and the entry.
        """
        path = Path(path)
        data = read_yaml(path, "lexicon", LanguageError) or {}
        if not isinstance(data, dict):
            raise LanguageError(f"{path}: a lexicon is a mapping with 'names' and 'groups'")
        names: dict[str, tuple[str, ...]] = {}
        for symbol, phrases in (data.get("names") or {}).items():
            if not isinstance(phrases, list) or not all(isinstance(p, str) for p in phrases):
                raise LanguageError(f"{path}: names.{symbol} must be a list of phrases")
            names[str(symbol)] = tuple(normalize(p) for p in phrases)
        groups = []
        for name, spec in (data.get("groups") or {}).items():
            if not isinstance(spec, dict) or not spec.get("names") or ("type" in spec) == ("members" in spec):
                raise LanguageError(
                    f"{path}: groups.{name} needs 'names' and exactly one of 'type', 'members'"
                )
            groups.append(
                GroupSpec(
                    name=str(name),
                    phrases=tuple(normalize(p) for p in spec["names"]),
                    type=spec.get("type"),
                    members=tuple(spec.get("members") or ()),
                )
            )
        return cls(names=names, groups=tuple(groups))

    def with_entrances(self, rooms: Iterable[str], back: Iterable[str] = ()) -> Lexicon:
        """This lexicon with each of ``rooms`` also called "the front door" (the rooms a door to the outside
        opens into, as a world file says: "go to the front door", "the table by the front door") and each of
        ``back`` "the back door" (the rooms of the other doors to the outside), where the one front door is
        still "the door" ("go and answer the door"); a room keeps its own names, or its name spoken."""
        names = dict(self.names)
        rooms, back = list(rooms), [room for room in back if room not in rooms]
        plain = ("door",) if back and len(rooms) == 1 else ()
        for room in rooms:
            names[room] = (*(names.get(room) or (normalize(room),)), *FRONT_DOOR, *plain)
        for room in back:
            names[room] = (*(names.get(room) or (normalize(room),)), BACK_DOOR)
        return Lexicon(names=names, groups=self.groups)


#: what the room a door to the outside opens into is also called: "guide her to the exit" (with_entrances)
FRONT_DOOR = ("front door", "exit")
#: what the room of another door to the outside is also called (:meth:`Lexicon.with_entrances`)
BACK_DOOR = "back door"
SYNONYMS_FILE = Path(__file__).with_name("synonyms.yaml")


@lru_cache(maxsize=1)
def _synonyms_file() -> dict[str, object]:
    """:data:`SYNONYMS_FILE` as data (read once)."""
    data = read_yaml(SYNONYMS_FILE, "synonyms", LanguageError) or {}
    return data if isinstance(data, dict) else {}


@lru_cache(maxsize=1)
def english_synonyms() -> tuple[tuple[str, ...], ...]:
    """The sets of :data:`SYNONYMS_FILE` (read once).

    Raises:
        LanguageError: the file is unreadable or not a list of sets of two or more phrases.
    """
    raw = _synonyms_file().get("synonyms")
    if not isinstance(raw, list) or not all(
        isinstance(group, list) and len(group) >= 2 and all(isinstance(p, str) and p.split() for p in group)
        for group in raw
    ):
        raise LanguageError(f"{SYNONYMS_FILE}: 'synonyms' is a list of sets of two or more phrases")
    return tuple(tuple(" ".join(p.lower().split()) for p in group) for group in raw)


@lru_cache(maxsize=1)
def english_broader() -> frozenset[str]:
    """The broader words of :data:`SYNONYMS_FILE` (``broader``: "computer"), read once."""
    raw = _synonyms_file().get("broader", [])
    if not isinstance(raw, list) or not all(isinstance(p, str) and p.split() for p in raw):
        raise LanguageError(f"{SYNONYMS_FILE}: 'broader' is a list of phrases")
    return frozenset(" ".join(p.lower().split()) for p in raw)


def _synonym_variants(terms: Sequence[Term], synonyms: Sequence[Sequence[str]]) -> list[Term]:
    """The names synonyms give: each whole-word synonym in a name (the longest at each place) replaced by the
    others of its set, where that makes no name the world already has. A broader word
    (:func:`english_broader`) ending a longer name is left: "tablet computer" gives no "tablet laptop", which
    would make "the laptop" name the tablet. A longer name's last word is not replaced by one that ends a name
    of another thing of the world: where the office has "blinds" and the bedroom "curtains", the world tells
    them apart by that word, so the office blinds are no "office curtains" and "the curtains" are the
    bedroom's. A word of a nearer subset (:func:`english_nearer`) is not given to a thing said with a word of
    another where the world names something else with a word of its own subset: where a flat has a toilet
    and a wet room, the toilet is no "bathroom"."""
    taken = {t.phrase for t in terms}
    nearer = english_nearer()
    owners = [
        {t.symbol for t in terms if any(contains(t.phrase.split(), p.split()) for p in g)} for g in nearer
    ]
    heads: dict[str, set[str]] = {}  # the last word of a longer name -> the things named so
    for t in terms:
        if len(t.phrase.split()) > 1:
            heads.setdefault(t.phrase.split()[-1], set()).add(t.symbol)
    sets = [[s.split() for s in sorted(group, key=lambda p: -len(p.split()))] for group in synonyms]
    broader = english_broader()
    out: list[Term] = []
    for term in terms:
        if term.type == "level":
            continue
        words = term.phrase.split()
        for i in range(len(words)):
            for members in sets:
                said = next((m for m in members if words[i : i + len(m)] == m), None)
                if said is None or (i > 0 and i + len(said) == len(words) and " ".join(said) in broader):
                    continue
                last = i > 0 and i + len(said) == len(words)
                for other in members:
                    phrase = " ".join([*words[:i], *other, *words[i + len(said) :]])
                    told_apart = last and bool(heads.get(other[-1], set()) - {term.symbol})
                    told_apart = told_apart or any(
                        " ".join(other) in group and " ".join(said) not in group and owners[k] - {term.symbol}
                        for k, group in enumerate(nearer)
                    )
                    if other != said and phrase not in taken and not told_apart:
                        taken.add(phrase)
                        out.append(Term(phrase, term.symbol, term.type, term.members, given=True))
    return out


def level_percent(symbol: str) -> int | None:
    """The percentage of a ``level`` constant named ``lNN`` (``"l50"`` -> 50), else None."""
    match = _LEVEL_CONSTANT.match(symbol)
    return int(match.group(1)) if match and int(match.group(1)) <= 100 else None


class Vocabulary:
    """Spoken phrases for a world's instances, with the type hierarchy to match them against slots.

    Build with :meth:`from_knowledge_base` (normal use) or :meth:`from_instances` (tests, tools).
    ``level`` constants named ``lNN`` become the spoken numbers "NN" so that "fifty percent" names ``l50``.
    """

    def __init__(
        self,
        terms: Iterable[Term],
        types: Mapping[str, str | None],
        instances: Mapping[str, str],
        predicates: Mapping[str, tuple[tuple[str, str], ...]] | None = None,
        locations: Mapping[str, Sequence[str]] | None = None,
    ):
        self._terms = tuple(terms)
        #: symbol -> the places (rooms, furniture) the world says it is in or on (furniture_in, object_on,
        #: object_at facts); used to tell "the table in the kitchen" from the other tables.
        self.locations: dict[str, tuple[str, ...]] = {k: tuple(v) for k, v in (locations or {}).items()}
        self._types = aliased(types)  # a domain's "location" is a room (knic.language.kinds)
        self._subtypes: dict[tuple[str, str], bool] = {}
        self._instances = dict(instances)
        #: predicate -> ((parameter, type), ...) from the domain; goals are checked against it.
        self.predicates: dict[str, tuple[tuple[str, str], ...]] = dict(predicates or {})
        robots = sorted(s for s, t in self._instances.items() if self.is_subtype(t, "robot"))
        #: the robot that carries out commands (the first robot instance), or None.
        self.robot: str | None = robots[0] if robots else None
        by_first: dict[str, list[Term]] = {}
        for term in self._terms:
            by_first.setdefault(term.phrase.split()[0], []).append(term)
        self._by_first = by_first

    @classmethod
    def from_instances(
        cls,
        instances: Mapping[str, str],
        types: Mapping[str, str | None],
        lexicon: Lexicon | None = None,
        predicates: Mapping[str, tuple[tuple[str, str], ...]] | None = None,
        locations: Mapping[str, Sequence[str]] | None = None,
        synonyms: Sequence[Sequence[str]] | None = None,
    ) -> Vocabulary:
        """Build from ``{instance or constant: type}``, ``{type: parent type}`` and the domain's predicates.

        Symbols get their lexicon phrases, or their own name spoken (underscores as spaces). Lexicon
        entries for symbols not in ``instances`` are ignored. Groups whose members are all missing are left
        out; members that are missing are dropped from the group. Each name also gets the variants that
        common English synonyms give (``synonyms``, default :func:`english_synonyms`: "the couch" for a
        world's ``sofa``, "the kitchen cupboard" for its ``kitchen_cabinet``), unless a variant is already a
        name of the world, and the shorter names of :func:`knic.language.shortnames.short_names` ("the second
        bedroom", "the kitchen" for a ``kitchen_diner``, "the paper" for a ``newspaper``).
        """
        lexicon = lexicon or Lexicon()
        terms: list[Term] = []
        for symbol, type_name in sorted(instances.items()):
            if type_name == "level":
                percent = level_percent(symbol)
                phrases: tuple[str, ...] = (number_words(percent),) if percent is not None else ()
            else:
                phrases = own_phrases(
                    symbol,
                    lexicon.names.get(symbol) or (normalize(symbol),),
                    instances,
                    is_subtype(types, type_name, "room"),
                )
            terms.extend(Term(p, symbol, type_name, (symbol,)) for p in phrases)
        terms += _synonym_variants(terms, english_synonyms() if synonyms is None else synonyms)
        terms += [
            Term(phrase, t.symbol, t.type, t.members, given=True)
            for phrase, t in short_names(
                terms,
                lambda k: is_subtype(types, k, "room"),
                exclude=lambda k: k == "level" or is_subtype(types, k, "person"),
            )
        ]
        for group in lexicon.groups:
            if group.type is not None:
                members = tuple(s for s, t in sorted(instances.items()) if is_subtype(types, t, group.type))
                group_type = group.type
            else:
                members = tuple(m for m in group.members if m in instances)
                kinds = {instances[m] for m in members}
                group_type = kinds.pop() if len(kinds) == 1 else "device"
            if members:
                terms.extend(Term(p, group.name, group_type, members) for p in group.phrases)
        return cls(terms, types, instances, predicates, locations)

    @classmethod
    def from_knowledge_base(
        cls,
        kb: KnowledgeSource,
        lexicon: Lexicon | str | Path | None = None,
        rooms: Mapping[str, str] | None = None,
    ) -> Vocabulary:
        """Build from a knowledge base's instances and its domain's ``level`` constants.

        Args:
            kb: the knowledge base (read once; later changes are not seen).
            lexicon: a :class:`Lexicon`, a lexicon file, or None for spoken symbol names only.
            rooms: the room of things the domain has no fact for (a device's room, from the world file:
                "the light in the sitting room" for its reading lamp).
        """
        if lexicon is not None and not isinstance(lexicon, Lexicon):
            lexicon = Lexicon.load(lexicon)
        domain = kb.domain
        types: dict[str, str | None] = dict(getattr(domain, "types", {}) or {})
        instances: dict[str, str] = {}
        for name in kb.instances():
            type_name = kb.type_of(name)
            if type_name:
                instances[name] = type_name
        instances.update(_constants(getattr(domain, "constants", {})))
        predicates = dict(getattr(domain, "predicates", {}) or {})
        locations: dict[str, list[str]] = {}
        facts = getattr(kb, "facts", None)
        if callable(facts):
            for predicate in LOCATION_PREDICATES:
                if predicate in predicates:
                    for fact in facts(predicate):
                        locations.setdefault(str(fact.args[0]), []).append(str(fact.args[1]))
        for thing, room in (rooms or {}).items():
            if thing in instances and room not in locations.get(thing, []):
                locations.setdefault(thing, []).append(room)
        return cls.from_instances(instances, types, lexicon, predicates, locations)

    def to_data(self) -> dict[str, Any]:
        """The vocabulary as plain JSON data (:meth:`from_data` reads it back)."""
        return {
            "terms": [
                [t.phrase, t.symbol, t.type, list(t.members), *([True] if t.given else [])]
                for t in self._terms
            ],
            "types": self._types,
            "instances": self._instances,
            "predicates": {k: [list(p) for p in v] for k, v in self.predicates.items()},
            "locations": {k: list(v) for k, v in self.locations.items()},
        }

    @classmethod
    def from_data(cls, data: Mapping[str, Any]) -> Vocabulary:
        """A vocabulary from :meth:`to_data`'s form.

        Raises:
            LanguageError: the data is not in that form.
        """
        try:
            terms = [
                Term(str(p), str(s), str(t), tuple(str(m) for m in ms), given=bool(given and given[0]))
                for p, s, t, ms, *given in data["terms"]
            ]
            predicates = {
                str(k): tuple((str(a), str(b)) for a, b in v) for k, v in dict(data["predicates"]).items()
            }
            return cls(
                terms,
                {str(k): (str(v) if v is not None else None) for k, v in dict(data["types"]).items()},
                {str(k): str(v) for k, v in dict(data["instances"]).items()},
                predicates,
                {str(k): tuple(str(x) for x in v) for k, v in dict(data["locations"]).items()},
            )
        except (KeyError, TypeError, ValueError) as exc:
            raise LanguageError(f"not a vocabulary's data: {exc}") from None

    @property
    def instances(self) -> dict[str, str]:
        """Every instance and constant of the world: {symbol: type}."""
        return dict(self._instances)

    @property
    def types(self) -> dict[str, str | None]:
        """The domain's type hierarchy: {type: parent type}."""
        return dict(self._types)

    def level(self, percent: int) -> str | None:
        """The ``level`` constant for a percentage (50 -> ``"l50"``), or None when the domain has none."""
        for symbol, type_name in self._instances.items():
            if type_name == "level" and level_percent(symbol) == percent:
                return symbol
        return None

    @property
    def terms(self) -> tuple[Term, ...]:
        """Every phrase of the vocabulary."""
        return self._terms

    def is_subtype(self, type_name: str, ancestor: str) -> bool:
        """Whether ``type_name`` is ``ancestor`` or derives from it (remembered: asked 1,200 times a read)."""
        found = self._subtypes.get((type_name, ancestor))
        if found is None:
            found = self._subtypes[type_name, ancestor] = is_subtype(self._types, type_name, ancestor)
        return found

    def terms_of(self, categories: Sequence[str], *, groups: bool = False) -> list[Term]:
        """The terms whose type falls under one of ``categories``; group terms only when ``groups``."""
        wanted = [t for t in self._terms if groups or not t.is_group]
        return [t for t in wanted if any(self.is_subtype(t.type, c) for c in categories)]

    def match(
        self, tokens: Sequence[str], start: int, categories: Sequence[str], *, groups: bool = False
    ) -> list[tuple[int, Term]]:
        """Terms of ``categories`` spoken at ``tokens[start:]``, as (end index, term), longest first."""
        if start >= len(tokens):
            return []
        found = []
        for term in self._by_first.get(tokens[start], ()):
            if (groups or not term.is_group) and any(self.is_subtype(term.type, c) for c in categories):
                words = term.phrase.split()
                if tuple(tokens[start : start + len(words)]) == tuple(words):
                    found.append((start + len(words), term))
        found.sort(key=lambda pair: -pair[0])
        return found

    def type_of(self, symbol: str) -> str | None:
        """The type of an instance, constant or group name known to the vocabulary."""
        if symbol in self._instances:
            return self._instances[symbol]
        return next((term.type for term in self._terms if term.symbol == symbol), None)

    def is_of(self, symbol: str, kind: str) -> bool:
        """Whether a symbol's type is ``kind`` or derives from it (False for a symbol the world lacks)."""
        return self.is_subtype(self.type_of(symbol) or "", kind)

    def members(self, symbol: str) -> tuple[str, ...]:
        """The symbols a name stands for: the group's members, or ``(symbol,)``."""
        for term in self._terms:
            if term.symbol == symbol:
                return term.members
        return (symbol,)

    def group_of(self, symbols: Iterable[str]) -> str | None:
        """The group whose members are exactly ``symbols`` ({left, right bedroom light}: bedroom_lights)."""
        wanted = set(symbols)
        for term in self._terms:
            if term.is_group and set(term.members) == wanted:
                return term.symbol
        return None

    def phrase_of(self, symbol: str) -> str:
        """The first spoken phrase for a symbol (for replies), or the symbol spoken."""
        for term in self._terms:
            if term.symbol == symbol:
                return term.phrase
        return normalize(symbol)

    def words(self) -> set[str]:
        """Every word used by a phrase."""
        return {w for t in self._terms for w in t.phrase.split()}


def _constants(constants: Any) -> dict[str, str]:
    """Domain constants as {name: type}, from a mapping or from (name, type) pairs."""
    if isinstance(constants, Mapping):
        return {str(k): str(v) for k, v in constants.items()}
    result = {}
    for item in constants or ():
        if isinstance(item, tuple) and len(item) == 2:
            result[str(item[0])] = str(item[1])
        elif hasattr(item, "name") and hasattr(item, "type"):
            result[str(item.name)] = str(item.type)
    return result
