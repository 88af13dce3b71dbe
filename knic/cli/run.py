"""``knic run``: the whole closed loop in the simulated apartment until the goals hold.

Goals come from ``--goal`` (repeatable: a PDDL atom such as ``"(object_at glasses bedroom)"``, or a command in
English such as ``"bring me my glasses"``, understood by :mod:`knic.language`) and ``--speech FILE.wav``
(repeatable: recognised with pocketsphinx against the command grammar, then understood). The execution
trace is printed as it happens (plans, dispatches, outcomes, replans, goals), together with what perception
asserts or retracts about the entities named in the goals. Exit status 0 when every goal holds in the
knowledge base and in the simulator's ground truth; 1 with a one-line reason on stderr otherwise (also when
a goal was not confirmed); 4 when a command was not understood; 2 for other user errors.

Roles (``knic/roles.yaml``) decide what happens before the goals reach the knowledge base:

* a role with ``confirm_actions`` (service_semi_autonomous): the robot repeats each command back
  (:class:`knic.language.dialogue.Dialogue`) and waits for yes or no before any goal is added. The answer
  comes from ``--confirm yes|no`` (scripted: the same answer to every question), from ``--confirm-speech
  FILE.wav`` (one recorded answer per question, recognised with pocketsphinx against a yes/no grammar), or
  typed on stdin when it is a terminal; with none of these the run is refused before anything is built. A
  command not confirmed with a clear yes adds no goal at all and the run ends with exit status 1.
* a role with ``operator_only`` (teleoperated): the robot acts only on operator commands; the goals given on
  the command line are the operator's (provenance source ``operator``) and run as usual, with the perception
  pipeline grounding the knowledge base at the role's rates.
* other roles: the robot repeats each command back and goes ahead.

With nothing to do, a companion revisits as its role says (:mod:`knic.system.revisits`); ``--no-revisits``.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, TextIO

from core.errors import KnicError, LanguageError
from knic.cli import runtask
from knic.cli.outputs import component_lines, summary
from knic.cli.ros import add_run_ros_argument, ros_attached
from knic.cli.runtask import judge_task, start_timed_goals, task_episode, task_summary, timed_goals
from knic.cli.say import add_acoustic_argument
from knic.cli.serve import add_run_serve_arguments, run_journal, serving
from knic.language.acoustic import acoustic_model_for

if TYPE_CHECKING:
    from knic.kgm2.roles import Role
    from knic.language.dialogue import Dialogue
    from knic.system import KnicSystem
    from knowledge_base import Change, Fact

#: predicates whose perception changes are printed with the trace
WATCHED = ("object_at", "object_on", "person_at", "found", "has", "light_on", "light_off", "device_level")


class RunFailed(KnicError):
    """The run ended without every goal holding."""

    exit_code = 1


class NotConfirmed(RunFailed):
    """A command was not confirmed with a clear yes (semi-autonomous role): no goal was added."""


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
    parser.add_argument(
        "--goal-at",
        action="append",
        default=[],
        metavar="S:TEXT",
        help="a goal given while the robot runs, at S simulated seconds, through the goal intake "
        "(repeatable)",
    )
    parser.add_argument("--speaker", help='who "me" is (default annie; else the world\'s first known person)')
    parser.add_argument(
        "--role", default="companion", help="robot role from knic/roles.yaml (default companion)"
    )
    parser.add_argument(
        "--confirm",
        choices=("yes", "no"),
        help="scripted answer to every confirmation question (roles with confirm_actions)",
    )
    parser.add_argument(
        "--confirm-speech",
        action="append",
        default=[],
        metavar="FILE.wav",
        help="a spoken yes or no, one per confirmation question, in order (repeatable)",
    )
    add_acoustic_argument(parser)
    add_run_serve_arguments(parser)
    add_run_ros_argument(parser)
    parser.add_argument("--seed", type=int, default=0, help="seed of the simulation (default 0)")
    parser.add_argument(
        "--trace",
        type=Path,
        metavar="FILE.jsonl",
        help="write the trace as JSON lines; written to a temporary file next to FILE and renamed to FILE "
        "once the goals are accepted, so a refused run leaves an existing FILE untouched",
    )
    parser.add_argument(
        "--journal",
        type=Path,
        metavar="FILE.sqlite",
        help="record the knowledge base's history; written to a temporary file next to FILE and renamed to "
        "FILE once the goals are accepted (a refused run leaves FILE untouched); an existing FILE that is "
        "not a KnIC journal is refused, never replaced",
    )
    parser.add_argument(
        "--max-sim-time", type=float, default=600.0, metavar="S", help="simulated seconds (default 600)"
    )
    parser.add_argument("--gui", action="store_true", help="open the pybullet GUI window")
    parser.add_argument("--no-revisits", action="store_true", help="an idle robot waits, no revisits")
    parser.add_argument("--json", action="store_true", help="print only a JSON summary at the end")


def run(args: argparse.Namespace) -> int:
    import logging

    from knic.kgm2.roles import load_role
    from knic.system import KnicSystem, RunConfig

    if getattr(args, "ros", False):
        from knic.ros.libraries import ensure_ros_libraries

        ensure_ros_libraries()  # before anything is done: the command may start again with ROS 2's libraries

    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)  # overruns are counted, printed at the end
    episode = task_episode(args)  # a task scenario (granny_annie): the episode drawn for the seed
    later = timed_goals(args.goal_at)
    if not args.goal and not args.speech and episode is None and not later:
        raise KnicError("knic run: give at least one --goal or --speech (or a task --scenario)")
    if args.max_sim_time <= 0:
        raise KnicError(f"knic run: --max-sim-time must be positive, got {args.max_sim_time}")
    for option, wavs in (("--speech", args.speech), ("--confirm-speech", args.confirm_speech)):
        for wav in wavs:
            if not Path(wav).is_file():
                raise KnicError(f"knic run: {option} {wav}: no such file")
    role = load_role(args.role)
    journal = run_journal(args)  # with --serve: checks the options, picks a journal
    staged = StagedOutputs(args.journal, args.trace)  # refuses unusable outputs; touches no existing file
    if args.journal is not None:
        journal = staged.journal
    # refuses before anything is built when it cannot ask (a task scenario's dialogue needs no answer source)
    listen = answer_source(args, role) if args.goal or args.speech else None
    accepted = False
    trace_file = staged.trace.open("w", encoding="utf-8") if staged.trace else None
    try:
        config = RunConfig(
            world=args.world,
            scenario=episode.scenario if episode is not None else args.scenario,
            seed=args.seed,
            role=args.role,
            max_sim_time=args.max_sim_time,
            journal=journal,
            trace_stream=trace_file,
            gui=args.gui,
            revisits=not args.no_revisits,
        )
        args.speaker = args.speaker or runtask.default_speaker(config.world)
        with KnicSystem(config) as system, serving(args, system, journal), ros_attached(args, system):
            flow = None
            if episode is not None:
                from knic.system.granny_annie import start_granny_annie

                flow = start_granny_annie(system, episode, role=args.role)
                referee = runtask.TaskReferee(system, episode, flow, journal)
            dialogue = None
            if listen is not None:
                dialogue = run_dialogue(system, listen, sys.stderr if args.json else sys.stdout)
            source = "operator" if role.operator_only else "user"
            try:
                texts = add_goals(
                    system,
                    args.goal,
                    args.speech,
                    args.speaker,
                    quiet=args.json,
                    dialogue=dialogue,
                    source=source,
                    acoustic_model=args.acoustic_model,
                )
            except NotConfirmed:
                accepted = True  # the goals were valid and the dialogue ran: its record is kept
                raise
            accepted = True
            goals = system.kb.goals()
            if not args.json:
                print(f"knic run: world {args.world}, seed {args.seed}, role {args.role}")
                if episode is not None:
                    print(f'task: {episode.person} on the {episode.seat} will ask "{episode.request.text}"')
                print("goals: " + " ".join(str(g) for g in goals))
                system.trace.print_to(sys.stdout)
                watch_perception(system, goals)
            start_timed_goals(system, later, args.speaker, source, args.json, world_vocabulary(system))
            result = system.run()
            score = None
            if flow is not None:
                judge_task(result, flow, episode.request.text)
                score = referee.verdict(result.sim_time, finished=result.sim_time < args.max_sim_time - 1e-6)
            if args.json:
                out = summary(result, texts, system.scheduler.report(result.sim_time))
                if flow is not None:
                    out["task"] = task_summary(flow)
                    out["score"] = score
                print(json.dumps(out, sort_keys=True))
            else:
                state = "succeeded" if result.success else "failed"
                print(
                    f"run {state} at t={result.sim_time:.1f} s (wall {result.wall_s:.1f} s, "
                    f"{result.plans} plans, {result.replans} replans): {result.reason}"
                )
                if score is not None:
                    print(runtask.score_line(score))
                report = system.scheduler.report(result.sim_time)
                print("\n".join(component_lines(report, system.config.real_time_factor)))
            if not result.success:
                raise RunFailed(f"run failed: {result.reason}")
    finally:
        if trace_file is not None:
            trace_file.close()
        staged.finish(keep=accepted)
    return 0


class StagedOutputs:
    """The run's output files, written under temporary names and moved into place only when kept.

    Checked before anything is built: a ``--journal`` that exists and is not a KnIC journal, or that is a
    folder, and a ``--trace`` that is a folder, are refused; so is an output whose folder does not exist.
    Nothing existing is opened for writing: the run writes ``.FILE.<pid>.partial`` next to each output and
    :meth:`finish` renames it to FILE (``keep``: the goals were accepted, or valid and answered no in the
    confirmation dialogue) or deletes it (a refused run).

    Raises:
        KnicError: an output cannot be used (one line naming it).
    """

    def __init__(self, journal: Path | None, trace: Path | None) -> None:
        self.final: list[tuple[Path, Path]] = []
        self.journal = self._stage(journal, "--journal") if journal is not None else None
        self.trace = self._stage(trace, "--trace") if trace is not None else None
        if journal is not None and journal.exists():
            from knowledge_base.journal import SqliteJournal

            try:
                is_journal = "domain_text" in SqliteJournal.read_meta(journal)
            except KnicError:
                is_journal = False
            if not is_journal:
                raise KnicError(
                    f"knic run: --journal {journal}: exists and is not a KnIC journal; not replaced"
                )

    def _stage(self, path: Path, option: str) -> Path:
        if path.is_dir():
            raise KnicError(f"knic run: {option} {path}: is a folder")
        if not path.parent.is_dir():
            raise KnicError(f"knic run: {option} {path}: folder {path.parent} does not exist")
        temp = path.with_name(f".{path.name}.{os.getpid()}.partial")
        self.final.append((temp, path))
        return temp

    def finish(self, *, keep: bool) -> None:
        """Move the outputs into place (``keep``) or delete them; SQLite side files go with the journal."""
        for temp, path in self.final:
            if keep and temp.exists():
                if Path(f"{temp}-wal").exists():  # fold the write-ahead log into the file before moving it
                    import sqlite3

                    sqlite3.connect(temp).close()
                for suffix in ("-wal", "-shm"):
                    Path(f"{path}{suffix}").unlink(missing_ok=True)
                temp.replace(path)
            for suffix in ("", "-wal", "-shm"):
                Path(f"{temp}{suffix}").unlink(missing_ok=True)


def add_goals(
    system: KnicSystem,
    goals: list[str],
    speech: list[str],
    speaker: str,
    *,
    quiet: bool = False,
    dialogue: Dialogue | None = None,
    source: str = "user",
    acoustic_model: str | None = None,
) -> list[dict[str, Any]]:
    """Add every ``--goal`` and ``--speech`` goal to the system's knowledge base; all or nothing.

    Every command is understood first. Without ``dialogue`` the robot repeats each natural-language command
    and the goals are added. With ``dialogue`` (roles with ``confirm_actions``) the robot repeats each
    command, PDDL goals included, and asks for yes or no; the goals are added only when every command is
    confirmed.

    Args:
        source: provenance source of the goals (``operator`` under an operator-only role).
        acoustic_model: the recogniser's acoustic model for ``speech`` (see :mod:`knic.language.acoustic`).

    Returns:
        One record per natural-language command (text, goals).

    Raises:
        LanguageError: a command was not understood (its reason); nothing is added.
        KnowledgeBaseError: a PDDL goal is malformed or names unknown symbols; nothing is added.
        NotConfirmed: a command was answered no, or not clearly; nothing is added.
    """
    from knic.language.understanding import Understanding
    from knic.system import parse_goal

    commands: list[tuple[str, Understanding | None, list[Fact]]] = []
    records: list[dict[str, Any]] = []
    vocabulary: list[Any] = []

    def vocab() -> Any:
        if not vocabulary:
            vocabulary.append(world_vocabulary(system))
        return vocabulary[0]

    for text in goals:
        if text.strip().startswith("("):
            fact = parse_goal(text)
            commands.append((text, None, [fact]))
        else:
            understood = understand_text(vocab(), text, speaker)
            facts = with_sources(system, understood)
            records.append({"text": text, "goals": [str(f) for f in facts]})
            commands.append((text, understood, facts))
    for wav in speech:
        text = recognise(vocab(), wav, acoustic_model)
        understood = understand_text(vocab(), text, speaker)
        facts = with_sources(system, understood)
        records.append({"speech": str(wav), "text": text, "goals": [str(f) for f in facts]})
        commands.append((text, understood, facts))
    if not quiet:
        for record in records:
            print(f'understood "{record["text"]}" as ' + " ".join(record["goals"]))
    if dialogue is not None:
        for text, understood, facts in commands:
            if not confirm_command(dialogue, understood, facts):
                raise NotConfirmed(f'knic run: "{text}" was not confirmed with a yes; no goal was added')
    with system.kb.batch():
        for _, _, facts in commands:
            for fact in facts:
                system.add_goal(fact, source=source)
    if dialogue is None:
        for record in records:
            system.context.say(f"You asked me to {record['text']}.")
    return records


def with_sources(system: KnicSystem, understood: Any) -> list[Fact]:
    """The command's goals plus the goals keeping its sources (:func:`knic.intake.source_goals`)."""
    from knic.intake import source_goals

    goals = list(understood.goals)
    return goals + [g for g in source_goals(understood, system.kb) if g not in goals]


def confirm_command(dialogue: Dialogue, understood: Any, facts: list[Fact]) -> bool:
    """Repeat one command back and wait for yes or no; a PDDL goal is repeated as its atoms.

    Returns:
        True only for a clear yes (see :meth:`knic.language.dialogue.Dialogue.confirm`).
    """
    if understood is not None:
        return bool(dialogue.confirm(understood))
    return dialogue.ask(
        "You asked me to make " + " and ".join(str(f) for f in facts) + " true. Is that right?"
    )


def answer_source(args: argparse.Namespace, role: Role) -> Callable[[], str | None] | None:
    """Where the answers to confirmation questions come from, for a role that asks; None for other roles.

    ``--confirm`` first, then ``--confirm-speech`` files, then stdin when it is a terminal.

    Raises:
        KnicError: the role asks but there is no way to get an answer (no --confirm and no terminal).
    """
    if not role.confirm_actions:
        return None
    if args.confirm is not None:
        answer: str = args.confirm
        return lambda: answer
    if args.confirm_speech:
        return SpokenAnswers(args.confirm_speech, acoustic_model=args.acoustic_model)
    if sys.stdin is not None and sys.stdin.isatty():
        return typed_answer
    raise KnicError(
        f"knic run: role {role.name} asks for yes or no before adding a goal and stdin is not a terminal;"
        " pass --confirm yes|no (or --confirm-speech FILE.wav)"
    )


def typed_answer() -> str | None:
    """One answer typed on stdin (None at end of input)."""
    try:
        return input("yes or no? ")
    except EOFError:
        return None


class SpokenAnswers:
    """Recorded answers, recognised one per question with pocketsphinx against a yes/no grammar.

    The grammar admits the answer words of :mod:`knic.language.dialogue` (optionally "please") or a run of
    at least three filler words, so longer speech that is not an answer comes out as fillers and counts as
    no answer rather than being forced onto yes or no. Built lazily on the first question (model load about
    0.3 s). After the last file, there is no answer (None).

    Args:
        wavs: WAV files, in the order of the questions.
        acoustic_model: the acoustic model (see :mod:`knic.language.acoustic`; None: the answers' default).

    Raises:
        LanguageError: pocketsphinx refused the grammar (on the first question).
        AudioError: a file is not usable audio (on its question).
    """

    def __init__(self, wavs: list[str], *, acoustic_model: str | None = None) -> None:
        self.wavs = list(wavs)
        self.acoustic_model = acoustic_model_for("answers", acoustic_model)
        self._recognizer: Any = None

    def __call__(self) -> str | None:
        from knic.language.audio import load_audio
        from knic.language.speech import AnswerRecognizer

        if not self.wavs:
            return None
        audio = load_audio(self.wavs.pop(0))
        if self._recognizer is None:
            self._recognizer = AnswerRecognizer(acoustic_model=self.acoustic_model)
        return str(self._recognizer.recognize(audio))


class _Silent:
    """A voice that says nothing (espeak-ng's fallback when the sentence is printed anyway)."""

    def say(self, sentence: str) -> None:
        """Nothing."""


class RobotVoice:
    """What the robot says in a run: said in the simulation (the robot's speech) and printed ``robot: ...``.

    Args:
        system: the run (its ERL context speaks in the simulator).
        stream: where the sentence is printed.
        aloud: also speak through this voice (espeak-ng for a person at the terminal), or None.
    """

    def __init__(self, system: KnicSystem, stream: TextIO, aloud: Any = None) -> None:
        self.system = system
        self.stream = stream
        self.aloud = aloud

    def say(self, sentence: str) -> None:
        """Say one sentence (blocks while espeak-ng speaks, when used)."""
        self.system.context.say(sentence)
        print(f"robot: {sentence}", file=self.stream, flush=True)
        if self.aloud is not None:
            self.aloud.say(sentence)


def run_dialogue(system: KnicSystem, listen: Callable[[], str | None], stream: TextIO) -> Dialogue:
    """The confirmation dialogue of a run: the robot's voice, the answer source, the world's spoken names."""
    import shutil

    from knic.language.dialogue import Dialogue, EspeakVoice

    aloud = None
    espeak = shutil.which("espeak-ng")
    if listen is typed_answer and espeak:  # someone is at the terminal: speak aloud too (printed anyway)
        aloud = EspeakVoice(espeak, fallback=_Silent())
    return Dialogue(listen, voice=RobotVoice(system, stream, aloud), vocabulary=world_vocabulary(system))


def world_vocabulary(system: KnicSystem) -> Any:
    """The spoken names of the run's knowledge base, with its world's lexicon (:mod:`knic.system.names`)."""
    from knic.system.names import run_vocabulary

    return run_vocabulary(system)


def understand_text(vocabulary: Any, text: str, speaker: str) -> Any:
    """The :class:`~knic.language.understanding.Understanding` of an English command (accepted), against the
    run's knowledge base vocabulary; its ``goals`` are the PDDL goals.

    Raises:
        LanguageError: the command was not understood or names what the world does not have.
    """
    from knic.language.understanding import understand

    result = understand(text, vocabulary, speaker=speaker)
    if not result.accepted:
        raise LanguageError(f'"{text}" not understood: {result.reason}')
    return result


def recognise(vocabulary: Any, wav: str, acoustic_model: str | None = None) -> str:
    """The words of a spoken command (pocketsphinx with the grammar of the run's vocabulary).

    Raises:
        LanguageError: nothing in the grammar was recognised.
        AudioError: the file is not usable audio.
    """
    from knic.language.lmspeech import command_recognizer

    transcript = command_recognizer(vocabulary, acoustic_model=acoustic_model).recognize(wav)
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
