"""Clauses of a command: chunks split into one clause per action, each with its noun phrases and roles.

A new action starts at every verb (with or without "and" / "then" before it); "and" before a noun joins
several objects in one action. A verb right after a bare motion verb says what to do ("go get the cup"). A
clause without a verb is a device command when it names a device and a state ("lights off"), otherwise the
words before the first verb are taken as address. See :mod:`knic.language.reader` for the whole reading.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from knic.language.chunks import Chunk


@dataclass
class Arg:
    """A noun phrase of a clause with the preposition before it."""

    chunk: Chunk
    prep: str | None = None  # the preposition's role table ("source", "goal", "place", ...)
    prep_text: str = ""
    joined: bool = False  # "and" before it: the same role as the previous argument
    consumed: bool = False  # used to narrow down the previous argument


@dataclass
class Clause:
    """One action as said: its verb (None for a verbless device command) and what follows."""

    verb: Chunk | None
    args: list[Arg] = field(default_factory=list)
    states: list[str] = field(default_factory=list)
    levels: list[int] = field(default_factory=list)
    missing: list[str] = field(default_factory=list)  # unknown words where a name was expected


def split_clauses(chunks: list[Chunk], names_device: Callable[[Chunk], bool]) -> list[Clause]:
    """Split chunks into clauses at verbs.

    Args:
        chunks: the command's chunks (:class:`~knic.language.chunks.Chunker`).
        names_device: whether an entity chunk may name a device (for a verbless "lights off").
    """
    chunks = [  # "her glasses": a possessive, not the pronoun
        Chunk("det", c.text)
        if c.kind == "pronoun"
        and c.role == "person"
        and i + 1 < len(chunks)
        and chunks[i + 1].kind == "entity"
        else c
        for i, c in enumerate(chunks)
    ]
    clauses: list[Clause] = []
    current: Clause | None = None
    preamble: list[Chunk] = []
    pending_prep: Chunk | None = None
    joined = False
    expecting = False  # a noun phrase is expected (after a determiner or a preposition)
    for index, chunk in enumerate(chunks):
        nxt = chunks[index + 1] if index + 1 < len(chunks) else None
        if chunk.kind == "verb":
            if current is not None and current.verb is not None and not current.args and not current.states:
                if "MOTION" in current.verb.frames and current.verb.frames == ("MOTION",):
                    current.verb = chunk  # "go get the cup": the second verb says what to do
                    continue
                if current.verb.frames == ("OPERATING",) and chunk.frames[0] == "OPERATING":
                    current.verb = chunk
                    continue
            current = Clause(chunk)
            clauses.append(current)
            pending_prep, joined = None, False
            continue
        if current is None:
            preamble.append(chunk)
            continue
        if chunk.kind == "partitive" and current.args and nxt is not None and nxt.kind in ("entity", "det"):
            container = current.args.pop()  # "a glass of water": the water is meant
            pending_prep = Chunk("prep", container.prep_text, role=container.prep) if container.prep else None
            joined = container.joined
            continue
        if chunk.kind == "join":
            joined = nxt is not None and nxt.kind in ("entity", "det", "pronoun", "me", "unknown")
            continue
        add_to_clause(current, chunk, nxt, pending_prep, joined, expecting)
        expecting = chunk.kind in ("det", "prep") or (expecting and chunk.kind == "unknown")
        if chunk.kind == "prep":
            pending_prep = chunk
        elif chunk.kind in ("entity", "pronoun", "me"):
            pending_prep, joined = None, False
    if preamble:
        verbless = _verbless(preamble, names_device)
        if verbless is not None:
            clauses.insert(0, verbless)
    return clauses


def add_to_clause(
    clause: Clause,
    chunk: Chunk,
    nxt: Chunk | None,
    prep: Chunk | None,
    joined: bool,
    expecting: bool = False,
) -> None:
    """Add one chunk to a clause: a noun phrase as an argument, a state, a level, or a missing name."""
    if chunk.kind in ("entity", "me", "pronoun"):
        clause.args.append(Arg(chunk, prep.role if prep else None, prep.text if prep else "", joined))
    elif chunk.kind == "state" or (chunk.kind == "prep" and chunk.state):
        clause.states.append(chunk.state or "")
    elif chunk.kind in ("level", "number"):
        clause.levels.append(chunk.value or 0)
    elif chunk.kind == "unknown" and expecting and (nxt is None or nxt.kind in ("join", "prep", "verb")):
        clause.missing.append(chunk.text)


def _verbless(preamble: list[Chunk], names_device: Callable[[Chunk], bool]) -> Clause | None:
    clause = Clause(None)
    for index, chunk in enumerate(preamble):
        nxt = preamble[index + 1] if index + 1 < len(preamble) else None
        add_to_clause(clause, chunk, nxt, None, False)
    devices = [a for a in clause.args if names_device(a.chunk)]
    if devices and (clause.states or clause.levels):
        return clause
    return None
