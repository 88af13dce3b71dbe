"""The command grammar: one definition for the text parser and for the speech recogniser's JSGF grammar.

The grammar is a small tree of nodes (:class:`Words`, :class:`Seq`, :class:`Alt`, :class:`Opt`,
:class:`Slot`, :class:`Bind`, :class:`Ref`, :class:`Frame`). Slots are filled from a
:class:`~knic.language.vocabulary.Vocabulary`, so the same tree accepts exactly the objects, rooms, people and
devices the world has. :mod:`knic.language.sampling` walks the tree to sample sentences; :func:`to_jsgf`
writes it as a JSGF grammar for pocketsphinx.

The command grammar itself is data: :func:`knic.language.commands.command_grammar` builds it from the
templates of ``commands.yaml``.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from knic.language.vocabulary import Vocabulary


@dataclass(frozen=True)
class Words:
    """Literal words, e.g. ``Words("look for")``."""

    text: str


@dataclass(frozen=True)
class Seq:
    """Parts in order."""

    parts: tuple[Node, ...]


@dataclass(frozen=True)
class Alt:
    """One of the options; the parser tries them in order."""

    options: tuple[Node, ...]


@dataclass(frozen=True)
class Opt:
    """The part or nothing."""

    part: Node


@dataclass(frozen=True)
class Slot:
    """A vocabulary phrase of one of ``categories`` (PDDL types) bound to the frame argument ``role``.

    ``groups`` admits group phrases ("the lights") as well as single symbols.
    """

    role: str
    categories: tuple[str, ...]
    groups: bool = False

    @property
    def rule_name(self) -> str:
        """The JSGF rule holding this slot's phrases."""
        return "_".join(self.categories) + ("_groups" if self.groups else "")


@dataclass(frozen=True)
class Bind:
    """Consumes nothing; sets the frame argument ``role`` to ``value`` (e.g. state "on" after "switch on")."""

    role: str
    value: str


@dataclass(frozen=True)
class Ref:
    """A named rule of the grammar (a shared JSGF rule)."""

    name: str


@dataclass(frozen=True)
class Repeat:
    """The part repeated 0 to ``most`` times. The JSGF form (``( part )*``) admits any count, which keeps
    the speech decoder's graph small; the text parser enforces ``most``, so recognised speech with too many
    repetitions is rejected when it is parsed."""

    part: Node
    most: int


@dataclass(frozen=True)
class Frame:
    """A command: its body's bindings become one command frame of kind ``kind`` (e.g. ``"BRINGING"``).
    ``alone``: the phrasing is a whole command, never chained ("is the remote in the kitchen", "the remote
    please"); the grammar still admits it anywhere, the sampler says it only alone."""

    kind: str
    body: Node
    alone: bool = False


Node = Words | Seq | Alt | Opt | Slot | Bind | Ref | Repeat | Frame


@dataclass(frozen=True)
class Grammar:
    """Named rules and the name of the top rule (the whole utterance)."""

    rules: dict[str, Node]
    top: str

    def rule(self, name: str) -> Node:
        """The named rule; KeyError names the rule when the grammar lacks it."""
        return self.rules[name]


def words(*texts: str) -> Node:
    """One of several literal phrases."""
    return Words(texts[0]) if len(texts) == 1 else Alt(tuple(Words(t) for t in texts))


def tagged(role: str, choices: dict[str, str]) -> Node:
    """One of several phrases, each binding ``role`` to its value: ``tagged("state", {"on": "on"})``."""
    return Alt(tuple(Seq((Words(phrase), Bind(role, value))) for phrase, value in choices.items()))


def seq(*parts: Node) -> Seq:
    """Parts in order."""
    return Seq(parts)


def alt(*options: Node) -> Alt:
    """One of the options, tried in order."""
    return Alt(options)


def slots(grammar: Grammar) -> list[Slot]:
    """Every distinct slot of the grammar, in first-use order."""
    found: dict[Slot, None] = {}
    for node in grammar.rules.values():
        for sub in _walk(node):
            if isinstance(sub, Slot):
                found.setdefault(Slot("", sub.categories, sub.groups), None)
    return list(found)


def grammar_words(grammar: Grammar) -> set[str]:
    """Every literal word of the grammar (not counting vocabulary phrases)."""
    return {
        w
        for node in grammar.rules.values()
        for sub in _walk(node)
        if isinstance(sub, Words)
        for w in sub.text.split()
    }


def _walk(node: Node) -> Iterator[Node]:
    yield node
    if isinstance(node, Seq):
        for part in node.parts:
            yield from _walk(part)
    elif isinstance(node, Alt):
        for option in node.options:
            yield from _walk(option)
    elif isinstance(node, Opt | Repeat):
        yield from _walk(node.part)
    elif isinstance(node, Frame):
        yield from _walk(node.body)


def to_jsgf(
    grammar: Grammar,
    vocabulary: Vocabulary,
    *,
    name: str = "knic",
    garbage: Iterable[str] = (),
    exclude_words: Iterable[str] = (),
    filler_weight: float = 0.1,
) -> str:
    """Write the grammar as JSGF V1.0 with the vocabulary's phrases in the slot rules.

    Args:
        grammar: the command grammar.
        vocabulary: the phrases for the slots; a slot with no phrase becomes ``<VOID>``.
        name: the JSGF grammar name.
        garbage: filler words; when given, the public rule also admits any sequence of them, so an utterance
            outside the command grammar can be decoded as filler instead of being forced onto a command.
        exclude_words: words the recogniser cannot pronounce; phrases containing them are left out.
        filler_weight: the filler loop's JSGF weight against 1 for the command rule.

    Returns:
        The JSGF text; its public rule is ``<utterance>``.
    """
    excluded = set(exclude_words)
    lines = ["#JSGF V1.0;", f"grammar {name};"]
    top = f"<{grammar.top}>"
    fillers = sorted({w for w in garbage if w not in excluded})
    if fillers:
        lines.append(f"public <utterance> = /1.0/ {top} | /{filler_weight:g}/ <filler>+;")
        lines.append("<filler> = " + " | ".join(fillers) + ";")
    else:
        lines.append(f"public <utterance> = {top};")
    for rule_name, node in grammar.rules.items():
        lines.append(f"<{rule_name}> = {_jsgf(node)};")
    for slot in slots(grammar):
        phrases = sorted(
            {
                t.phrase
                for t in vocabulary.terms_of(slot.categories, groups=slot.groups)
                if not excluded.intersection(t.phrase.split())
            }
        )
        lines.append(f"<{slot.rule_name}> = " + (" | ".join(phrases) if phrases else "<VOID>") + ";")
    return "\n".join(lines) + "\n"


def _jsgf(node: Node) -> str:
    if isinstance(node, Words):
        return node.text
    if isinstance(node, Seq):
        parts = [_jsgf(p) for p in node.parts if not isinstance(p, Bind)]
        return " ".join(parts) if parts else "<NULL>"
    if isinstance(node, Alt):
        return "( " + " | ".join(_jsgf(o) for o in node.options) + " )"
    if isinstance(node, Opt):
        return f"[ {_jsgf(node.part)} ]"
    if isinstance(node, Slot):
        return f"<{node.rule_name}>"
    if isinstance(node, Bind):
        return "<NULL>"
    if isinstance(node, Ref):
        return f"<{node.name}>"
    if isinstance(node, Repeat):
        return f"( {_jsgf(node.part)} )*"
    return _jsgf(node.body)
