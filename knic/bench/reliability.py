"""``knic bench reliability``: how KnIC takes bad input and being killed, with counts.

Figures (``--json`` for one object):

* ``fuzz`` -- property-based fuzzing with hypothesis (a fixed seed, no example database) of four boundaries:
  ``pddl_loader`` (mutated domain-valid problem texts through the checked PDDL problem reader),
  ``world_loader`` (mutated world YAML through the limited YAML reader and the world validator),
  ``goal_parser`` (arbitrary text through ``Fact.parse`` and ``add_goal``) and ``kb_api`` (arbitrary
  names, lists, numbers and control characters through the knowledge base's writes). For each: ``cases``,
  ``accepted``, ``handled`` (refused with a one-line :class:`~core.errors.KnicError`), ``crashed`` (any
  other exception, or a multi-line message) and the first crash.
* ``durability`` -- a writer process journals batches and acknowledges each one after the write returned;
  it is killed with SIGKILL at random moments ``kills`` times; after each kill the journal is reopened and
  every acknowledged write must be there: ``acknowledged``, ``lost_acknowledged`` (target 0), and the
  journal must reopen every time (``reopen_failures``, target 0).

* ``faults`` -- fault injection in the closed loop (:mod:`knic.bench.reliability_faults`): one episode per
  fault in the simulated apartment (an action raises, hangs or returns false; the camera or the
  localisation drops out for 20 s; the planner's subprocess is killed), each with the goal still to reach:
  ``injected`` and ``recovered`` (target: every injected fault recovered), and each episode's outcome.
* ``soak`` -- the closed loop running errands for ``--soak-s`` simulated seconds (default one hour), resident
  memory sampled (:mod:`knic.bench.reliability_soak`): start, end and peak MB and the slope per simulated
  hour.

``--quick`` shrinks every size (for tests): fewer fuzz cases and kills, one fault, a 60 s soak. ``--parts``
runs some of the parts only (e.g. ``--parts soak``).
"""

from __future__ import annotations

import argparse
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
ERL = ROOT / "worlds" / "erl_home"
ROOMS = ("kitchen", "bedroom", "entrance", "living_room")


#: the parts of the benchmark, in the order they run
PARTS = ("fuzz", "durability", "faults", "soak")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--quick", action="store_true", help="small sizes (seconds, not representative)")
    parser.add_argument("--seed", type=int, default=0, help="random seed")
    parser.add_argument(
        "--soak-s",
        type=float,
        default=None,
        metavar="SECONDS",
        help="simulated seconds of the soak (default 3600, 60 with --quick; 0 skips it)",
    )
    parser.add_argument(
        "--parts",
        default=",".join(PARTS),
        metavar="LIST",
        help=f"comma-separated parts to run (default all: {','.join(PARTS)})",
    )


def run(args: argparse.Namespace) -> int:
    if args.soak_s is not None and not (args.soak_s >= 0 and args.soak_s < float("inf")):
        print(
            f"knic bench reliability: --soak-s must be a number of seconds >= 0, got {args.soak_s}",
            file=sys.stderr,
        )
        return 2
    parts = tuple(p.strip() for p in args.parts.split(",") if p.strip())
    unknown = [p for p in parts if p not in PARTS]
    if unknown or not parts:
        print(f"knic bench reliability: --parts takes {','.join(PARTS)}, got {args.parts!r}", file=sys.stderr)
        return 2
    figures = measure(quick=args.quick, seed=args.seed, soak_s=args.soak_s, parts=parts)
    if args.json:
        print(json.dumps(figures))
    else:
        for key, value in figures.items():
            print(f"{key:14s} {json.dumps(value)}")
    return 0


def measure(
    *, quick: bool = False, seed: int = 0, soak_s: float | None = None, parts: tuple[str, ...] = PARTS
) -> dict[str, Any]:
    """The measurements of ``parts`` (see the module docstring); ``soak_s`` None: 3600 (60 when ``quick``),
    0: no soak. ``meets_targets`` judges the parts run."""
    from knic.bench.reliability_faults import FAULTS, fault_runs
    from knic.bench.reliability_soak import soak

    out: dict[str, Any] = {}
    if "fuzz" in parts:
        out["fuzz"] = fuzz_all(60 if quick else 600, seed)
        out["crashes"] = sum(f["crashed"] for f in out["fuzz"].values())
    if "durability" in parts:
        out["durability"] = durability(kills=3 if quick else 20, seed=seed)
    if "faults" in parts:
        out["faults"] = fault_runs(("action_false",) if quick else FAULTS, seed=seed)
    soak_s = (60.0 if quick else 3600.0) if soak_s is None else soak_s
    if "soak" in parts and soak_s > 0:
        out["soak"] = soak(soak_s, seed=seed)
    out["meets_targets"] = (
        out.get("crashes", 0) == 0
        and out.get("durability", {}).get("lost_acknowledged", 0) == 0
        and out.get("faults", {}).get("recovered", 0) == out.get("faults", {}).get("injected", 0)
    )
    return out


# --------------------------------------------------------------------------------------------- fuzzing
class _Tally:
    def __init__(self) -> None:
        self.counts = {"cases": 0, "accepted": 0, "handled": 0, "crashed": 0}
        self.first_crash = ""

    def run(self, fn: Callable[[], Any]) -> None:
        from core.errors import KnicError

        self.counts["cases"] += 1
        try:
            fn()
        except KnicError as exc:
            if "\n" in str(exc):
                self._crash(f"multi-line message: {str(exc)[:200]!r}")
            else:
                self.counts["handled"] += 1
        except Exception as exc:
            self._crash(f"{type(exc).__name__}: {str(exc)[:200]}")
        else:
            self.counts["accepted"] += 1

    def _crash(self, what: str) -> None:
        self.counts["crashed"] += 1
        self.first_crash = self.first_crash or what

    def result(self) -> dict[str, Any]:
        return {**self.counts, "first_crash": self.first_crash}


def _drive(strategy: Any, body: Callable[[Any], None], cases: int, seed: int) -> None:
    from hypothesis import HealthCheck, given, settings
    from hypothesis import seed as hseed

    @hseed(seed)
    @settings(
        max_examples=cases,
        database=None,
        deadline=None,
        derandomize=False,
        suppress_health_check=list(HealthCheck),
    )
    @given(strategy)
    def check(value: Any) -> None:
        body(value)

    check()


def _mutations(text: str) -> Any:
    """Texts made from ``text`` by deleting, duplicating or replacing a slice, or inserting odd characters."""
    from hypothesis import strategies as st

    pieces = st.sampled_from([*"()-?;:=\r\t\n\x00\u00a0\u200b\u00e9*&!\\", "and", "(not", "?x", "(:goal"])
    odd = st.lists(pieces, max_size=6).map("".join)
    return st.tuples(
        st.integers(0, len(text)), st.integers(0, 40), st.sampled_from(["delete", "dup", "insert"]), odd
    ).map(lambda m: _mutate(text, *m))


def _mutate(text: str, at: int, size: int, how: str, extra: str) -> str:
    if how == "delete":
        return text[:at] + text[at + size :]
    if how == "dup":
        return text[:at] + text[at : at + size] * 3 + text[at:]
    return text[:at] + extra + text[at:]


def fuzz_all(cases: int, seed: int) -> dict[str, Any]:
    """The four fuzzed boundaries (see the module docstring)."""
    from hypothesis import strategies as st

    from core.inputs import safe_yaml
    from knowledge_base import Fact, KnowledgeBase
    from knowledge_base.domain import DomainModel
    from knowledge_base.problem import parse_problem_up
    from worlds.loader import world_from_dict

    domain = DomainModel.from_file(ERL / "domain.pddl")
    problem_text = (ERL / "paper_problem.pddl").read_text(encoding="utf-8")
    world_text = (ERL / "erl_home_paper.yaml").read_text(encoding="utf-8")
    results: dict[str, Any] = {}

    tally = _Tally()
    _drive(
        _mutations(problem_text),
        lambda text: tally.run(lambda: parse_problem_up(domain, text, source="fuzz.pddl")),
        cases,
        seed,
    )
    results["pddl_loader"] = tally.result()

    def world(text: str) -> None:
        from core.errors import WorldError

        world_from_dict(safe_yaml(text, "fuzz.yaml", WorldError), file="fuzz.yaml")

    tally = _Tally()
    _drive(_mutations(world_text), lambda text: tally.run(lambda: world(text)), cases, seed)
    results["world_loader"] = tally.result()

    kb = KnowledgeBase.from_pddl(ERL / "domain.pddl", ERL / "paper_problem.pddl", clock=lambda: 0.0)

    def goal(text: str) -> None:
        fact = Fact.parse(text)
        kb.add_goal(fact.predicate, *fact.args)
        kb.remove_goal(fact.predicate, *fact.args)

    names = st.one_of(
        st.sampled_from(["glasses", "kitchen", "r2d2", "annie", "bedroom"]),
        st.text(max_size=12),
        st.lists(st.text(max_size=3), max_size=2),
        st.integers(),
        st.none(),
    )
    goal_texts = st.one_of(
        st.text(max_size=60),
        st.lists(names.map(str), min_size=1, max_size=4).map(lambda xs: "(" + " ".join(xs) + ")"),
    )
    tally = _Tally()
    _drive(goal_texts, lambda text: tally.run(lambda: goal(text)), cases, seed)
    results["goal_parser"] = tally.result()

    operations = st.tuples(
        st.sampled_from(
            ["add_instance", "add_fact", "remove_fact", "add_goal", "set_function", "set_anchor"]
        ),
        names,
        st.lists(names, max_size=3),
    )

    def api(op: tuple[str, Any, list[Any]]) -> None:
        kind, first, rest = op
        before = kb.snapshot()
        try:
            if kind == "add_instance":
                kb.add_instance("item" if not rest else rest[0], first)
            elif kind == "set_function":
                kb.set_function(first, *rest, value=1.0)
            elif kind == "set_anchor":
                kb.set_anchor(first, {"pose": rest})
            else:
                getattr(kb, kind)(first, *rest)
        except Exception:
            if not kb.snapshot().same_content(before):
                raise AssertionError("a refused write changed the knowledge base") from None
            raise

    tally = _Tally()
    _drive(operations, lambda op: tally.run(lambda: api(op)), cases, seed)
    results["kb_api"] = tally.result()
    return results


# ------------------------------------------------------------------------------------------- durability
def durability(*, kills: int, seed: int) -> dict[str, Any]:
    """SIGKILL a journal writer ``kills`` times; count acknowledged writes missing after reopening."""
    from knowledge_base import KnowledgeBase

    rng = random.Random(seed)
    acknowledged = 0
    lost = 0
    reopen_failures = 0
    with tempfile.TemporaryDirectory(prefix="knic-bench-reliability-") as tmp:
        path = Path(tmp) / "durable.sqlite"
        KnowledgeBase.from_pddl(
            ERL / "domain.pddl", ERL / "paper_problem.pddl", path, clock=lambda: 0.0
        ).close()
        for _ in range(kills):
            child = subprocess.Popen(
                [sys.executable, "-m", "knic.bench.reliability", "writer", str(path)],
                stdout=subprocess.PIPE,
                text=True,
                cwd=ROOT,
                env={**os.environ, "PYTHONPATH": str(ROOT)},
            )
            assert child.stdout is not None
            if child.stdout.readline().strip() != "ready":
                child.kill()
                child.wait()
                reopen_failures += 1
                continue
            deadline = time.monotonic() + rng.uniform(0.05, 0.4)
            acks: list[int] = []
            while time.monotonic() < deadline:
                line = child.stdout.readline()
                if not line:
                    break
                acks.append(int(line.split()[1]))
            os.kill(child.pid, signal.SIGKILL)
            child.wait()
            # anything printed before the kill was acknowledged too
            acks += [int(x.split()[1]) for x in child.stdout.read().splitlines() if x.startswith("ack")]
            child.stdout.close()
            try:
                kb = KnowledgeBase.from_journal(path, read_only=True)
            except Exception:
                reopen_failures += 1
                continue
            items = set(kb.instances("item"))
            kb.close()
            acknowledged += len(acks)
            lost += sum(1 for i in acks if f"dur{i}" not in items)
    return {
        "kills": kills,
        "acknowledged": acknowledged,
        "lost_acknowledged": lost,
        "reopen_failures": reopen_failures,
    }


def _writer(path: str) -> None:
    """The child of :func:`durability`: batches of 5 objects, ``ack <last object>`` after each returned."""
    from knowledge_base import KnowledgeBase

    kb = KnowledgeBase.from_journal(path)
    start = len([n for n in kb.instances("item") if n.startswith("dur")])
    print("ready", flush=True)
    i = start
    while True:
        with kb.batch():
            for _ in range(5):
                kb.add_instance("item", f"dur{i}", source="writer")
                kb.add_fact("object_at", f"dur{i}", ROOMS[i % 4], source="writer", status="observed")
                i += 1
        print(f"ack {i - 1}", flush=True)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "writer":
        _writer(sys.argv[2])
