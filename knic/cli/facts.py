"""``knic facts``: the fact base recorded in a journal, now, at a past time, or live.

Reads the SQLite journal a running system writes (``--journal FILE``); it never writes to it, so it is safe
to run while the system runs. Times are the journal's clock (simulated seconds in a closed-loop run, Unix
seconds for wall time).

Examples::

    knic facts --journal run.sqlite
    knic facts --journal run.sqlite --predicate robot_at --json
    knic facts --journal run.sqlite --at 42.5
    knic facts --journal run.sqlite --why "(object_at glasses kitchen)"
    knic facts --journal run.sqlite --watch --watch-seconds 30
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys
import time
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import KnicError

if TYPE_CHECKING:
    from knowledge_base import Change, Fact, KnowledgeBase, Provenance, State

#: Clock values above this are Unix wall time and are shown as dates; below, simulated seconds.
_WALL_TIME = 1e9


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--journal", required=True, metavar="FILE", help="the SQLite journal of a run")
    parser.add_argument("--predicate", metavar="P", help="only facts of predicate P")
    parser.add_argument("--json", action="store_true", help="print JSON (a list of fact objects)")
    parser.add_argument("--at", metavar="TIME", help="the fact base as it was at clock time TIME (seconds)")
    parser.add_argument(
        "--why", metavar="FACT", help='why a fact is believed, e.g. "(object_at glasses kitchen)"'
    )
    parser.add_argument("--watch", action="store_true", help="follow the journal live, printing every change")
    parser.add_argument(
        "--watch-seconds",
        type=float,
        metavar="N",
        help="with --watch: stop after N seconds (default: until ^C)",
    )
    parser.add_argument("--poll", type=float, default=0.2, metavar="S", help="with --watch: poll period (s)")
    parser.add_argument(
        "--recover",
        metavar="OUT",
        help="copy the committed prefix of a damaged journal (every event before the first corrupt row) to "
        "the new journal OUT (never replaced) and stop",
    )


def run(args: argparse.Namespace) -> int:
    from knowledge_base import Fact, KnowledgeBase

    if args.recover is not None:
        from knowledge_base.journal import recover

        kept, dropped = recover(args.journal, args.recover)
        print(f"{args.recover}: kept {kept} event(s)" + (f"; dropped {dropped}" if dropped else ""))
        return 0
    if args.watch and args.watch_seconds is not None:
        from knic.cli.bounded import positive_seconds

        positive_seconds(args.watch_seconds, "--watch-seconds")
    if args.watch:
        from knic.cli.bounded import positive_seconds

        positive_seconds(args.poll, "--poll")
    if args.watch:
        from knic.cli.outputs import running_journal

        args.journal = running_journal(Path(args.journal))
    kb = KnowledgeBase.from_journal(args.journal, read_only=True)
    try:
        if args.predicate is not None and args.predicate not in kb.domain.predicates:
            raise KnicError(f"--predicate: unknown predicate {args.predicate!r} in domain {kb.domain.name}")
        state = kb.snapshot() if args.at is None else kb.state_at(_parse_time(args.at))
        if args.why is not None:
            return _why(kb, state, Fact.parse(args.why), args.json)
        _print_facts(state, args.predicate, args.json)
        if args.watch:
            _watch(kb, args)
        return 0
    finally:
        kb.close()


def _parse_time(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise KnicError(f"--at: expected a time in seconds, got {text!r}") from None
    if not math.isfinite(value):
        raise KnicError(f"--at: expected a finite time in seconds, got {text!r}")
    return value


def _format_time(t: float) -> str:
    if t >= _WALL_TIME:
        return datetime.fromtimestamp(t, UTC).isoformat(timespec="milliseconds").replace("+00:00", "Z")
    return f"{t:.2f}"


def _record(fact: Fact, prov: Provenance) -> dict[str, Any]:
    return {
        "predicate": fact.predicate,
        "arguments": list(fact.args),
        "status": prov.status.value,
        "author": prov.source,
        "since": prov.since,
        "confidence": prov.confidence,
        "support": list(prov.support),
    }


def _change_record(change: Change) -> dict[str, Any]:
    return {
        "seq": change.seq,
        "time": change.time,
        "change": change.kind.value,
        "name": change.name,
        "arguments": list(change.args),
        "value": change.value,
        "author": change.provenance.source,
        "status": change.provenance.status.value,
    }


def _print_facts(state: State, predicate: str | None, as_json: bool) -> None:
    items = sorted(
        ((f, p) for f, p in state.facts.items() if predicate is None or f.predicate == predicate),
        key=lambda fp: (fp[0].predicate, fp[0].args),
    )
    if as_json:
        print(json.dumps([_record(f, p) for f, p in items]))
        return
    rows = [("PREDICATE", "ARGUMENTS", "STATUS", "AUTHOR", "SINCE")]
    rows += [
        (f.predicate, " ".join(f.args), p.status.value, p.source, _format_time(p.since)) for f, p in items
    ]
    widths = [max(len(r[i]) for r in rows) for i in range(5)]
    for row in rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths, strict=True)).rstrip())
    print(f"{len(items)} fact(s)")


def _why(kb: KnowledgeBase, state: State, fact: Fact, as_json: bool) -> int:
    if fact.predicate not in kb.domain.predicates:
        raise KnicError(f"--why {fact}: unknown predicate {fact.predicate!r} in domain {kb.domain.name}")
    arity = len(kb.domain.predicates[fact.predicate])
    if len(fact.args) != arity:
        raise KnicError(f"--why {fact}: {fact.predicate} takes {arity} argument(s), got {len(fact.args)}")
    for arg in fact.args:
        if arg not in state.instances and arg not in kb.domain.constants:
            raise KnicError(f"--why {fact}: {arg!r} is not an instance known to this journal")
    prov = state.facts.get(fact)
    history = [
        c for c in kb.changes() if c.fact == fact and c.seq <= state.seq and c.kind.value.endswith("_fact")
    ]
    from knic.kgm3.fusion import claims_from

    sources = claims_from(history, fact, prov, state.time if history else 0.0)
    if as_json:
        out: dict[str, Any] = {"fact": str(fact), "holds": prov is not None}
        if prov is not None:
            out.update(_record(fact, prov))
        out["history"] = [_change_record(c) for c in history]
        out["sources"] = [dataclasses.asdict(c) for c in sources]
        print(json.dumps(out))
    elif prov is None:
        print(
            f"{fact} is not believed"
            + (f" (last retracted at {_format_time(history[-1].time)})" if history else "")
        )
    else:
        support = f", supported by {', '.join(prov.support)}" if prov.support else ""
        print(
            f"{fact} is {prov.status.value}: written by {prov.source} at {_format_time(prov.since)} "
            f"with confidence {prov.confidence:g}{support}"
        )
        for c in history:
            print(f"  {c.describe()}")
    for claim in [] if as_json else sources:  # every source's latest claim, heaviest first (knic.kgm3.fusion)
        print(
            f"  source {claim.source}: {'asserts' if claim.holds else 'retracts'} it, {claim.status}, "
            f"confidence {claim.confidence:g}, weight now {claim.weight:g}"
            + (" (the belief)" if claim.current else "")
        )
    return 0


def _watch(kb: KnowledgeBase, args: argparse.Namespace) -> None:
    def show(change: Change) -> None:
        if args.predicate is not None and change.name != args.predicate:
            return
        if args.json:
            print(json.dumps(_change_record(change)))
        else:
            print(change.describe())
        sys.stdout.flush()

    kb.subscribe(show)
    print("-- watching; ^C to stop", file=sys.stderr)
    end = math.inf if args.watch_seconds is None else time.monotonic() + args.watch_seconds
    while time.monotonic() < end:
        kb.refresh()
        time.sleep(max(0.01, min(args.poll, end - time.monotonic())))
    kb.refresh()
