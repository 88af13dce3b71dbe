"""``knic run``: the whole closed loop in the simulated apartment until the goals hold.

Goals come from ``--goal`` (repeatable: a PDDL atom such as ``"(object_at glasses bedroom)"``, or a command in
English such as ``"bring me my glasses"``, understood by :mod:`knic.language`) and ``--speech FILE.wav``
(repeatable: recognised with pocketsphinx against the command grammar, then understood). The execution
trace is printed as it happens (plans, dispatches, outcomes, replans, goals), together with what perception
asserts or retracts about the entities named in the goals. Exit status 0 when every goal holds in the
knowledge base and in the simulator's ground truth; 1 with a one-line reason on stderr otherwise; 4 when a
command was not understood; 2 for other user errors.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from knic.errors import KnicError, LanguageError

if TYPE_CHECKING:
    from knic.system import KnicSystem
    from knowledge_base import Change, Fact

LEXICON = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "lexicon.yaml"
#: predicates whose perception changes are printed with the trace
WATCHED = ("object_at", "object_on", "person_at", "found", "has", "light_on", "light_off", "device_level")


class RunFailed(KnicError):
    """The run ended without every goal holding."""

    exit_code = 1


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--world", default="erl_home", help="world name (erl_home, erl_home_paper) or world file"
    )
    parser.add_argument("--scenario", help="scenario name (worlds/erl_home/scenarios) or scenario file")
    parser.add_argument(
        "--goal",
        action="append",
        default=[],
        metavar="TEXT",
        help='a PDDL goal "(object_at glasses bedroom)" or a command "bring me my glasses" (repeatable)',
    )
    parser.add_argument(
        "--speech", action="append", default=[], metavar="FILE.wav", help="a spoken command (repeatable)"
    )
    parser.add_argument("--speaker", default="annie", help='the person "me" refers to (default annie)')
    parser.add_argument(
        "--role", default="companion", help="robot role from knic/roles.yaml (default companion)"
    )
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulation (default 0)")
    parser.add_argument("--trace", type=Path, metavar="FILE.jsonl", help="write the trace as JSON lines")
    parser.add_argument(
        "--journal", type=Path, metavar="FILE.sqlite", help="record the knowledge base's history (replaced)"
    )
    parser.add_argument(
        "--max-sim-time", type=float, default=600.0, metavar="S", help="simulated seconds (default 600)"
    )
    parser.add_argument("--gui", action="store_true", help="open the pybullet GUI window")
    parser.add_argument("--json", action="store_true", help="print only a JSON summary at the end")


def run(args: argparse.Namespace) -> int:
    import logging

    from knic.system import KnicSystem, RunConfig

    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)  # overruns are counted, not printed
    if not args.goal and not args.speech:
        raise KnicError("knic run: give at least one --goal or --speech")
    if args.max_sim_time <= 0:
        raise KnicError(f"knic run: --max-sim-time must be positive, got {args.max_sim_time}")
    for wav in args.speech:
        if not Path(wav).is_file():
            raise KnicError(f"knic run: --speech {wav}: no such file")
    trace_file = args.trace.open("w", encoding="utf-8") if args.trace else None
    try:
        config = RunConfig(
            world=args.world,
            scenario=args.scenario,
            seed=args.seed,
            role=args.role,
            max_sim_time=args.max_sim_time,
            journal=args.journal,
            trace_stream=trace_file,
            gui=args.gui,
        )
        with KnicSystem(config) as system:
            texts = add_goals(system, args.goal, args.speech, args.speaker, quiet=args.json)
            goals = system.kb.goals()
            if not args.json:
                print(f"knic run: world {args.world}, seed {args.seed}, role {args.role}")
                print("goals: " + " ".join(str(g) for g in goals))
                system.trace.print_to(sys.stdout)
                watch_perception(system, goals)
            result = system.run()
            if args.json:
                print(json.dumps(summary(result, texts), sort_keys=True))
            else:
                state = "succeeded" if result.success else "failed"
                print(
                    f"run {state} at t={result.sim_time:.1f} s (wall {result.wall_s:.1f} s, "
                    f"{result.plans} plans, {result.replans} replans): {result.reason}"
                )
            if not result.success:
                raise RunFailed(f"run failed: {result.reason}")
    finally:
        if trace_file is not None:
            trace_file.close()
    return 0


def add_goals(
    system: KnicSystem, goals: list[str], speech: list[str], speaker: str, *, quiet: bool = False
) -> list[dict[str, Any]]:
    """Add every ``--goal`` and ``--speech`` goal to the system's knowledge base; all or nothing.

    Returns one record per natural-language command (text, goals). The robot repeats what it understood.

    Raises:
        LanguageError: a command was not understood (its reason); nothing is added.
        KnowledgeBaseError: a PDDL goal is malformed or names unknown symbols.
    """
    from knic.system import parse_goal

    pending: list[Fact] = []
    records: list[dict[str, Any]] = []
    vocabulary: list[Any] = []

    def vocab() -> Any:
        if not vocabulary:
            vocabulary.append(world_vocabulary(system))
        return vocabulary[0]

    for text in goals:
        if text.strip().startswith("("):
            pending.append(parse_goal(text))
        else:
            facts = understand_text(vocab(), text, speaker)
            records.append({"text": text, "goals": [str(f) for f in facts]})
            pending += facts
    for wav in speech:
        text = recognise(vocab(), wav)
        facts = understand_text(vocab(), text, speaker)
        records.append({"speech": str(wav), "text": text, "goals": [str(f) for f in facts]})
        pending += facts
    with system.kb.batch():
        for fact in pending:
            system.add_goal(fact)
    for record in records:
        system.context.say(f"You asked me to {record['text']}.")
        if not quiet:
            print(f'understood "{record["text"]}" as ' + " ".join(record["goals"]))
    return records


def world_vocabulary(system: KnicSystem) -> Any:
    """The spoken names of the run's knowledge base (with the ERL lexicon: "reading glasses" -> glasses)."""
    from knic.language.vocabulary import Vocabulary

    return Vocabulary.from_knowledge_base(system.kb, LEXICON if LEXICON.is_file() else None)


def understand_text(vocabulary: Any, text: str, speaker: str) -> list[Fact]:
    """PDDL goals of an English command, against the run's knowledge base vocabulary.

    Raises:
        LanguageError: the command was not understood or names what the world does not have.
    """
    from knic.language.understanding import understand

    result = understand(text, vocabulary, speaker=speaker)
    if not result.accepted:
        raise LanguageError(f'"{text}" not understood: {result.reason}')
    return list(result.goals)


def recognise(vocabulary: Any, wav: str) -> str:
    """The words of a spoken command (pocketsphinx with the grammar of the run's vocabulary).

    Raises:
        LanguageError: nothing in the grammar was recognised.
        AudioError: the file is not usable audio.
    """
    from knic.language.speech import Recognizer
    from knic.language.understanding import default_grammar

    transcript = Recognizer(default_grammar(), vocabulary).recognize(wav)
    if not transcript.text or not transcript.in_grammar:
        heard = f' (heard "{transcript.text}")' if transcript.text else ""
        raise LanguageError(f"{wav}: no command recognised{heard}")
    return transcript.text


def watch_perception(system: KnicSystem, goals: list[Fact]) -> None:
    """Print what perception asserts or retracts about the entities the goals name, as trace-like lines."""
    names = {a for g in goals for a in g.args}

    def show(change: Change) -> None:
        kind = change.kind.value
        if kind not in ("add_fact", "remove_fact") or change.name not in WATCHED:
            return
        source = change.provenance.source
        if source == "dispatcher" or not names.intersection(change.args):
            return
        sign = "+" if kind == "add_fact" else "-"
        atom = "(" + " ".join((change.name, *change.args)) + ")"
        status = change.provenance.status.value
        print(f"{change.time:9.2f}  perceived    {sign} {atom} [{source}, {status}]", flush=True)

    system.kb.subscribe(show)


def summary(result: Any, commands: list[dict[str, Any]]) -> dict[str, Any]:
    """The ``--json`` summary of a run."""
    return {
        "success": result.success,
        "reason": result.reason,
        "sim_time": round(result.sim_time, 3),
        "wall_s": round(result.wall_s, 3),
        "goals": result.goals,
        "unconfirmed": result.unconfirmed,
        "plans": result.plans,
        "replans": result.replans,
        "counters": result.counters,
        "commands": commands,
    }
