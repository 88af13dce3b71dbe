"""The command grammar compiled to an epsilon-free finite-state grammar (pocketsphinx FSG text format).

pocketsphinx turns a JSGF grammar into a finite-state grammar with many null (epsilon) transitions: every
optional word, rule reference and alternative adds some, and it precomputes their closure. For the ERL grammar
that is about 30,000 null transitions against 1,300 word transitions, and decoding took seconds per utterance.
This module builds the same language from the same grammar tree (:mod:`knic.language.grammar`) and removes the
epsilons itself, so the decoder sees only word transitions and decodes in real time. :func:`to_jsgf` remains
the readable, portable form of the grammar; this is the form the recogniser loads.

Transition probabilities: the command part splits each state's probability evenly over its outgoing
transitions, as the JSGF compiler does. An optional filler loop (``fillers``) runs from the start state to the
final state in parallel with the commands; each filler word costs ``filler_weight``.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from knic.language.grammar import Alt, Bind, Frame, Grammar, Node, Opt, Ref, Repeat, Seq, Slot, Words
from knic.language.vocabulary import Vocabulary


@dataclass(frozen=True)
class WordGraph:
    """An epsilon-free word graph: states 0..num_states-1, one start and one final state.

    ``transitions`` holds (source, destination, probability, word).
    """

    num_states: int
    start: int
    final: int
    transitions: tuple[tuple[int, int, float, str], ...]

    def to_fsg(self, name: str = "command") -> str:
        """The graph in pocketsphinx's FSG text format."""
        lines = [
            f"FSG_BEGIN {name}",
            f"NUM_STATES {self.num_states}",
            f"START_STATE {self.start}",
            f"FINAL_STATE {self.final}",
        ]
        lines += [f"TRANSITION {s} {d} {p:.6g} {w}" for s, d, p, w in self.transitions]
        lines.append("FSG_END")
        return "\n".join(lines) + "\n"

    def words(self) -> set[str]:
        """Every word on a transition."""
        return {t[3] for t in self.transitions}


class _Nfa:
    def __init__(self) -> None:
        self.count = 0
        self.words: list[tuple[int, int, str]] = []
        self.eps: dict[int, list[int]] = {}

    def state(self) -> int:
        self.count += 1
        return self.count - 1

    def chain(self, src: int, text: str, dst: int | None = None) -> int:
        tokens = text.split()
        current = src
        for i, word in enumerate(tokens):
            nxt = dst if (dst is not None and i == len(tokens) - 1) else self.state()
            self.words.append((current, nxt, word))
            current = nxt
        return current

    def epsilon(self, src: int, dst: int) -> None:
        self.eps.setdefault(src, []).append(dst)


def compile_word_graph(
    grammar: Grammar,
    vocabulary: Vocabulary,
    *,
    exclude_words: Iterable[str] = (),
    fillers: Sequence[str] = (),
    filler_weight: float = 0.1,
    branch_penalty: bool = True,
) -> WordGraph:
    """Compile the grammar's top rule with the vocabulary's phrases into an epsilon-free word graph.

    Args:
        grammar: the command grammar; :class:`Repeat` becomes an unbounded loop (the text parser enforces the
            bound), :class:`Bind` consumes nothing.
        vocabulary: phrases for the slots.
        exclude_words: words the recogniser cannot pronounce; phrases containing them are left out.
        fillers: filler words for a parallel loop that absorbs speech outside the grammar.
        filler_weight: probability attached to each filler word.
        branch_penalty: split each state's probability over its transitions (else every command transition
            has probability 1 and the acoustics alone choose among them).
    """
    excluded = set(exclude_words)
    nfa = _Nfa()
    start = nfa.state()

    def build(node: Node, src: int) -> int:
        if isinstance(node, Words):
            return nfa.chain(src, node.text)
        if isinstance(node, Seq):
            current = src
            for part in node.parts:
                current = build(part, current)
            return current
        if isinstance(node, Alt):
            end = nfa.state()
            for option in node.options:
                nfa.epsilon(build(option, src), end)
            return end
        if isinstance(node, Opt):
            end = build(node.part, src)
            nfa.epsilon(src, end)
            return end
        if isinstance(node, Slot):
            end = nfa.state()
            phrases = {
                t.phrase
                for t in vocabulary.terms_of(node.categories, groups=node.groups)
                if not excluded.intersection(t.phrase.split())
            }
            for phrase in sorted(phrases):
                nfa.chain(src, phrase, end)
            return end
        if isinstance(node, Bind):
            return src
        if isinstance(node, Ref):
            return build(grammar.rule(node.name), src)
        if isinstance(node, Repeat):
            hub = nfa.state()
            nfa.epsilon(src, hub)
            nfa.epsilon(build(node.part, hub), hub)
            return hub
        if isinstance(node, Frame):
            return build(node.body, src)
        raise TypeError(f"unknown grammar node {node!r}")  # pragma: no cover - the Node union is closed

    accept = build(grammar.rule(grammar.top), start)
    fillers = [f for f in fillers if f not in excluded]
    return _remove_epsilons(nfa, start, accept, fillers, filler_weight, branch_penalty)


def _remove_epsilons(
    nfa: _Nfa, start: int, accept: int, fillers: Sequence[str], filler_weight: float, branch_penalty: bool
) -> WordGraph:
    closures: dict[int, set[int]] = {}

    def closure(state: int) -> set[int]:
        if state not in closures:
            seen, stack = {state}, [state]
            while stack:
                for nxt in nfa.eps.get(stack.pop(), ()):
                    if nxt not in seen:
                        seen.add(nxt)
                        stack.append(nxt)
            closures[state] = seen
        return closures[state]

    out: dict[int, list[tuple[int, str]]] = {}
    for src, dst, word in nfa.words:
        out.setdefault(src, []).append((dst, word))
    # Explore from the start state over word transitions; each visited state keeps the words of its closure.
    renumber = {start: 0}
    final = -1  # patched below once the number of states is known
    edges: list[tuple[int, int, str]] = []
    queue = [start]
    while queue:
        state = queue.pop()
        moves = {(dst, word) for q in closure(state) for dst, word in out.get(q, ())}
        for dst, word in sorted(moves, key=lambda m: (m[1], m[0])):
            if dst not in renumber:
                renumber[dst] = len(renumber)
                queue.append(dst)
            edges.append((renumber[state], renumber[dst], word))
            if accept in closure(dst):
                edges.append((renumber[state], final, word))
    final = len(renumber)
    num_states = final + 1
    transitions: list[tuple[int, int, float, str]] = []
    degree: dict[int, int] = {}
    for src, _, _ in edges:
        degree[src] = degree.get(src, 0) + 1
    for src, dst, word in edges:
        probability = 1.0 / degree[src] if branch_penalty else 1.0
        transitions.append((src, final if dst == -1 else dst, probability, word))
    if fillers:
        loop = num_states
        num_states += 1
        for word in sorted(set(fillers)):
            transitions += [(0, loop, filler_weight, word), (loop, loop, filler_weight, word)]
            transitions.append((0, final, filler_weight, word))
            transitions.append((loop, final, filler_weight, word))
    return WordGraph(num_states, 0, final, tuple(transitions))


def answer_graph(
    answers: Sequence[str],
    fillers: Sequence[str],
    filler_weight: float,
    *,
    openers: Sequence[str] = (),
    closers: Sequence[str] = ("please",),
) -> WordGraph:
    """The yes/no answer grammar as an epsilon-free word graph.

    An optional opener ("well"), one or two answer phrases ("no", "that's wrong"; two only after a one-word
    phrase: "no, that's wrong"), an optional closer
    ("please", "thank you"); in parallel, three or more filler words, each costing ``filler_weight``, so
    speech that is not an answer comes out as fillers instead of being forced onto yes or no. Phrases of
    several words become chains of states.
    """
    start, opened, one, two, final, f1, f2, f3 = range(8)
    transitions: list[tuple[int, int, float, str]] = []
    count = [8]

    def path(origin: int, target: int, weight: float, phrase: str) -> None:
        words = phrase.split()
        here = origin
        for index, word in enumerate(words):
            nxt = target if index == len(words) - 1 else count[0]
            if nxt != target:
                count[0] += 1
            transitions.append((here, nxt, weight if index == 0 else 1.0, word))
            here = nxt

    share = 1.0 / max(1, len(answers))
    for phrase in openers:
        path(start, opened, 0.05 / max(1, len(openers)), phrase)
    for origin in (start, opened, one):
        # a second phrase follows a one-word first ("no, that's wrong") and is less likely than none
        second = origin == one
        for phrase in answers:
            weight = share * (0.2 if second else 0.5)
            path(origin, two if second or " " in phrase else one, weight, phrase)
            path(origin, final, weight, phrase)
    for origin in (one, two):
        for phrase in closers:
            path(origin, final, 0.2 / max(1, len(closers)), phrase)
    for word in fillers:
        transitions += [(start, f1, filler_weight, word), (f1, f2, filler_weight, word)]
        transitions += [(f2, f3, filler_weight, word), (f2, final, filler_weight, word)]
        transitions += [(f3, f3, filler_weight, word), (f3, final, filler_weight, word)]
    return WordGraph(count[0], start, final, tuple(transitions))
