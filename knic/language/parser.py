"""A small deterministic parser over :mod:`knic.language.grammar` for normalised command text.

The parser walks the grammar tree by backtracking over the token list and returns the first complete parse in
rule order (the grammar lists its alternatives from most to least specific). No evaluation of user text, no
statistics: the same text always gives the same frames. When no parse covers the whole text, it reports
the furthest token it could not fit and what the grammar expected there, which becomes the user's reply.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field

from knic.language.grammar import Alt, Bind, Frame, Grammar, Opt, Ref, Repeat, Seq, Slot, Words
from knic.language.vocabulary import Term, Vocabulary, level_percent

#: How slot categories read in a reply.
_CATEGORY_NAMES = {
    "item": "an object",
    "person": "a person",
    "room": "a room",
    "furniture": "a piece of furniture",
    "light": "a light",
    "dimmer": "a dimmer",
    "blinds": "the blinds",
    "level": "a level in percent",
    "command": "a command such as 'bring me ...', 'find ...', 'go to ...', 'lead ... to ...', 'switch on'",
}

Value = Term | str


@dataclass(frozen=True)
class RawFrame:
    """One parsed action: its frame kind and its (role, value) bindings in utterance order.

    A value is a :class:`~knic.language.vocabulary.Term` for a vocabulary phrase, else the bound string
    ("me", a pronoun, a device state).
    """

    kind: str
    args: tuple[tuple[str, Value], ...]


@dataclass(frozen=True)
class ParseFailure:
    """Where and why parsing stopped: the furthest token index reached and what was expected there."""

    position: int
    expected: tuple[str, ...]
    tokens: tuple[str, ...]

    def reason(self, vocabulary: Vocabulary, grammar_words: set[str]) -> str:
        """A one-line reply saying what was not understood."""
        if not self.tokens:
            return "nothing to understand: the command is empty"
        expected = _describe(self.expected, vocabulary)
        before = " ".join(self.tokens[: self.position])
        if self.position >= len(self.tokens):
            return f"the command stops too early after '{before}': expected {expected}"
        word = self.tokens[self.position]
        known = word in grammar_words or word in vocabulary.words()
        where = f"after '{before}'" if before else "at the start"
        if not known:
            return f"I do not know the word '{word}' ({where}); expected {expected}"
        return (
            f"I did not understand '{' '.join(self.tokens[self.position :])}' ({where}); expected {expected}"
        )


@dataclass
class _Progress:
    position: int = -1
    expected: list[str] = field(default_factory=list)

    def note(self, position: int, what: str) -> None:
        if position > self.position:
            self.position, self.expected = position, [what]
        elif position == self.position and what not in self.expected:
            self.expected.append(what)


# A parse item: a (role, value) binding inside a frame, or a RawFrame once the frame is complete.
_Item = tuple[str, Value] | RawFrame


class Parser:
    """Parses normalised token lists against a grammar and a vocabulary.

    Construct once per (grammar, vocabulary); :meth:`parse` is pure and may be called from any thread.
    """

    def __init__(self, grammar: Grammar, vocabulary: Vocabulary):
        self.grammar = grammar
        self.vocabulary = vocabulary

    def parse(self, tokens: Sequence[str]) -> list[RawFrame] | ParseFailure:
        """The frames of the first complete parse, or where parsing failed.

        Args:
            tokens: normalised words (see :func:`knic.language.vocabulary.normalize`).
        """
        toks = tuple(tokens)
        progress = _Progress()
        if toks:
            for end, items in self._match(self.grammar.rule(self.grammar.top), toks, 0, progress):
                if end == len(toks):
                    return [item for item in items if isinstance(item, RawFrame)]
                progress.note(end, "the end of the command or 'and'")
        return ParseFailure(max(progress.position, 0), tuple(progress.expected), toks)

    def _match(
        self, node: object, toks: tuple[str, ...], pos: int, progress: _Progress
    ) -> Iterator[tuple[int, tuple[_Item, ...]]]:
        if isinstance(node, Words):
            text = node.text.split()
            if toks[pos : pos + len(text)] == tuple(text):
                yield pos + len(text), ()
            else:
                progress.note(pos, f"'{node.text}'")
        elif isinstance(node, Seq):
            yield from self._seq(node.parts, 0, toks, pos, progress)
        elif isinstance(node, Alt):
            for option in node.options:
                yield from self._match(option, toks, pos, progress)
        elif isinstance(node, Opt):
            yield from self._match(node.part, toks, pos, progress)
            yield pos, ()
        elif isinstance(node, Slot):
            matches = self.vocabulary.match(toks, pos, node.categories, groups=node.groups)
            if not matches:
                for category in node.categories:
                    progress.note(pos, f"<{category}>")
            for end, term in matches:
                yield end, ((node.role, term),)
        elif isinstance(node, Repeat):
            yield from self._repeat(node, node.most, toks, pos, progress)
        elif isinstance(node, Bind):
            yield pos, ((node.role, node.value),)
        elif isinstance(node, Ref):
            produced = False
            for result in self._match(self.grammar.rule(node.name), toks, pos, progress):
                produced = True
                yield result
            if not produced and node.name == "action":
                progress.note(pos, "<command>")
        elif isinstance(node, Frame):
            for end, items in self._match(node.body, toks, pos, progress):
                args = tuple(item for item in items if not isinstance(item, RawFrame))
                yield end, (RawFrame(node.kind, args),)
        else:  # pragma: no cover - the Node union is closed
            raise TypeError(f"unknown grammar node {node!r}")

    def _repeat(
        self, node: Repeat, left: int, toks: tuple[str, ...], pos: int, progress: _Progress
    ) -> Iterator[tuple[int, tuple[_Item, ...]]]:
        if left > 0:
            for mid, head in self._match(node.part, toks, pos, progress):
                if mid > pos:
                    for end, tail in self._repeat(node, left - 1, toks, mid, progress):
                        yield end, head + tail
        yield pos, ()

    def _seq(
        self, parts: tuple[object, ...], index: int, toks: tuple[str, ...], pos: int, progress: _Progress
    ) -> Iterator[tuple[int, tuple[_Item, ...]]]:
        if index == len(parts):
            yield pos, ()
            return
        for mid, head in self._match(parts[index], toks, pos, progress):
            for end, tail in self._seq(parts, index + 1, toks, mid, progress):
                yield end, head + tail


def _describe(expected: Sequence[str], vocabulary: Vocabulary) -> str:
    if "<command>" in expected:
        return _CATEGORY_NAMES["command"]
    categories = [_CATEGORY_NAMES.get(e[1:-1], e[1:-1]) for e in expected if e.startswith("<")]
    if "<level>" in expected:
        levels = sorted(vocabulary.terms_of(("level",)), key=lambda t: level_percent(t.symbol) or 0)
        named = _CATEGORY_NAMES["level"] + " (" + ", ".join(t.phrase for t in levels) + ")"
        categories = [named if c == _CATEGORY_NAMES["level"] else c for c in categories]
    literals = [e for e in expected if not e.startswith("<")]
    if categories:
        return " or ".join(dict.fromkeys(categories))
    shown = literals[:6] + (["..."] if len(literals) > 6 else [])
    return " or ".join(shown) if shown else "a known command"
