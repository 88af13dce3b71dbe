"""``knic run``'s task parts: a task scenario's episode (``--scenario granny_annie``) and the goals given
while the robot runs (``--goal-at S:TEXT``)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import KnicError, WorldError

if TYPE_CHECKING:
    from knic.system import KnicSystem


def timed_goals(specs: list[str]) -> list[tuple[float, str]]:
    """``--goal-at S:TEXT`` options as (time, text), earliest first.

    Raises:
        KnicError: an option is not ``S:TEXT`` with S a time in seconds >= 0.
    """
    out = []
    for spec in specs:
        head, sep, text = spec.partition(":")
        try:
            at = float(head)
        except ValueError:
            at = -1.0
        if not sep or at < 0 or not text.strip():
            raise KnicError(f"knic run: --goal-at {spec!r} is not S:TEXT (e.g. 30:switch on the light)")
        out.append((at, text.strip()))
    return sorted(out)


def start_timed_goals(
    system: KnicSystem,
    later: list[tuple[float, str]],
    speaker: str,
    source: str,
    quiet: bool,
    vocabulary: Any,
) -> None:
    """Schedule the ``--goal-at`` goals (:class:`knic.system.timed.TimedGoals`) for an intake over
    ``vocabulary``; replies printed unless ``quiet``."""
    if not later:
        return
    from knic.intake import GoalIntake
    from knic.system.timed import TimedGoals

    def show(now: float, text: str, reply: Any) -> None:
        if not quiet:
            print(f"{now:9.2f}  intake        {reply.outcome.value}: {text} -> {reply.reply}", flush=True)

    intake = GoalIntake(system.kb, vocabulary, say=system.context.say)
    system.add_flow(TimedGoals(system, intake, later, speaker=speaker, source=source, on_reply=show))


def task_episode(args: argparse.Namespace) -> Any:
    """The :class:`worlds.granny_annie.Episode` of ``--scenario`` for ``--seed`` when the scenario describes a
    task (a ``task:`` section), else None.

    Raises:
        WorldError: unknown world or scenario, or a task the voice bank cannot voice.
    """
    if not args.scenario:
        return None
    from worlds.api import load_world
    from worlds.granny_annie import episode
    from worlds.scenario import load_scenario

    world = load_world(args.world)
    try:
        scenario = load_scenario(args.scenario, world)
    except WorldError as exc:
        written_for = _scenario_world(args.scenario)
        if written_for is None or written_for == world.name:
            raise
        raise WorldError(
            f"scenario {args.scenario} is written for world {written_for}, not {world.name} ({exc}); for the"
            f" Granny Annie task there run: knic bench granny-annie --world {args.world} --episodes 1"
        ) from None
    return episode(scenario, args.seed) if scenario.task is not None else None


def _scenario_world(scenario: str) -> str | None:
    """The world a scenario file says it was written for (its ``world:``), or None."""
    from core.inputs import read_yaml
    from worlds.scenario import resolve_scenario_path

    try:
        data = read_yaml(resolve_scenario_path(scenario), "scenario", WorldError)
    except WorldError:
        return None
    return str(data["world"]) if isinstance(data, dict) and data.get("world") else None


def task_summary(flow: Any) -> dict[str, Any]:
    """The ``--json`` record of a task flow: where it ended, what was asked and which goals it added."""
    return {
        "phase": str(flow.phase),
        "outcome": flow.outcome,
        "goals": [str(g) for g in flow.goals],
        "asks": flow.asks,
    }


def judge_task(result: Any, flow: Any, request: str) -> None:
    """A task run succeeds only when the robot told Annie it was done and had understood ``request`` as she
    meant it (:func:`knic.system.granny_annie.understood_right`), besides the referee's verdict on the
    goals; ``result`` is updated in place."""
    from knic.system.granny_annie import understood_right

    if not result.success:
        return
    if flow.outcome != "done":
        result.success = False
        result.reason = f"the task ended {flow.outcome or 'unfinished'} ({flow.phase})"
    elif not understood_right(flow, request):
        result.success = False
        result.reason = "the robot understood something else than Annie asked"


def default_speaker(world: Any) -> str:
    """Who "me" is without ``--speaker``: :func:`worlds.granny_annie.first_person`, else annie."""
    from worlds.api import load_world
    from worlds.granny_annie import DEFAULT_PERSON, first_person

    return first_person(load_world(world)) or DEFAULT_PERSON


class TaskReferee:
    """The benchmark's referee watching a task scenario's run (``knic run --scenario granny_annie``): its
    running score goes to the journal's score file while the run goes (:mod:`knic.bench.granny_annie.
    livescore`; the web view shows it), its verdict to the run's output at the end.

    Lifecycle: construct after the task flow is started and before the run; :meth:`verdict` after it.
    """

    def __init__(self, system: KnicSystem, episode: Any, flow: Any, journal: Path | None) -> None:
        from actions.erl.devices import spoken
        from knic.bench.granny_annie.flow import dialogue
        from knic.bench.granny_annie.livescore import LiveScore, episode_of_task, score_path
        from knic.bench.granny_annie.recording import Recorder

        text = episode.request.text
        try:
            meant = [str(g) for g in flow.intake.understand(text, speaker=flow.person).goals]
        except KnicError:
            meant = []
        self.episode = episode_of_task(system.world, text, episode.seat, episode.seed, meant, flow.person)
        self.flow = flow
        self.recorder = Recorder(system.sim, system.sim, system.kb, system.pipeline.bus)
        self.recorder.attach(system.scheduler)
        self.recorder.sample(system.sim.time)
        self.understood = lambda: dialogue(flow).understood
        self.live = LiveScore(
            self.recorder,
            self.episode,
            self.understood,
            score_path(journal) if journal is not None else None,
            spoken,
        )
        self.live.attach(system.scheduler)
        self.spoken = spoken

    def verdict(self, end: float, *, finished: bool) -> dict[str, Any]:
        """The referee's final score sheet (published to the score file too)."""
        from knic.bench.granny_annie.referee import judge

        timeline = self.recorder.finish(end, finished=finished, understood=self.understood())
        self.recorder.close()
        score = judge(self.episode, timeline, self.spoken)
        return self.live.finish(score, end)["score"]


def score_line(score: dict[str, Any]) -> str:
    """One line of the referee's score sheet."""
    penalties = ", ".join(f"{k} {v}" for k, v in score["penalties"].items())
    offered = {k: n for k, n in score["achievable"].items() if n}
    kinds = ", ".join(f"{k} {score['achieved'][k]}/{n}" for k, n in offered.items())
    out = f"referee: {score['achievements']} of {score['possible']} achievements ({kinds})"
    out += f"; penalties: {penalties}"
    return out + (" (disqualified)" if score["disqualified"] else "")
