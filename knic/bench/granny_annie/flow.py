"""Starting a benchmark episode the way the rulebook does: the Granny Annie task flow.

:func:`start_with_task_flow` is the runner's :data:`~.runner.Starter`. It schedules two parts in the
assembled run:

* Annie (world side; the episode's served person, ``annie`` or whoever the world's is): a
  :class:`JudgingAnnie`, who makes the tablet call at :data:`CALL_AT_S`, says her
  command when the robot asks what she needs (the voice bank recording when the generator picked one, else
  the words, as typed), and answers the robot's repeat-back: yes only when what it repeated means her
  request, no otherwise (a recording of the bank when her command was spoken, else the word);
* the robot's :class:`~knic.system.granny_annie.GrannyAnnieFlow` (call, come to her room, ask, hear,
  confirm, work, report), under the run's role.

Every baseline runs the same flow: the static and oracle baselines change only where the robot's facts come
from (:mod:`.baselines`). Annie judges a repeat-back as a listener does: she takes the words after "You
asked me to", turns them back to her own point of view ("to you" is "to me"), understands them with the
world's vocabulary and compares their meaning (PDDL goals) with what she meant (the episode's goals). She
never reads the robot's knowledge base or its intake.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from knic.bench.granny_annie.events import NO_COMMAND_BY_S
from knic.system import TaskFlow
from worlds.granny_annie import ASKS_ANSWER, ASKS_PLAIN_ANSWER, AnnieActor, SpeechWorld, VoiceClip

if TYPE_CHECKING:
    from knic.bench.granny_annie.episodes import Episode
    from knic.bench.granny_annie.recording import Recorder
    from knic.intake import Submission
    from knic.language.vocabulary import Vocabulary
    from knic.system import KnicSystem
    from knic.system.granny_annie import GrannyAnnieFlow
    from worlds.granny_annie import Episode as TaskEpisode
    from worlds.scenario import Event
    from worlds.simulation import Simulation

#: when Annie makes the tablet call (simulated seconds)
CALL_AT_S = 2.0
_REPEATED = re.compile(r"you asked me to (?P<what>.*?)[.!]?\s*is that right")


def from_her_side(words: str) -> str:
    """The robot's words as Annie would say them ("bring the remote to you" -> "bring the remote to me")."""
    return re.sub(r"\byou\b", "me", re.sub(r"\byour\b", "my", words))


def repeat_back_means(said: str, goals: tuple[str, ...], vocabulary: Vocabulary, person: str) -> bool:
    """Whether the robot's repeat-back ``said`` ("You asked me to ... Is that right?") means exactly
    ``goals`` (PDDL strings) when ``person`` understands it."""
    from knic.language.understanding import understand

    match = _REPEATED.search(said.lower())
    if match is None:
        return False
    meant = understand(from_her_side(match["what"]), vocabulary, speaker=person)
    return meant.accepted and {str(g) for g in meant.goals} == set(goals)


@dataclass(frozen=True)
class Dialogue:
    """How the episode's dialogue went, read after the run.

    Attributes:
        understood: the goals the robot announced it took from the command (PDDL strings), None when it
            took none.
        ending: how the robot's task ended (``done``, ``partly``, ``not understood``), or the phase it was
            still in when the run stopped.
    """

    understood: tuple[str, ...] | None
    ending: str = ""


class JudgingAnnie(AnnieActor):
    """Annie of a benchmark episode (see the module docstring).

    Args:
        world: the simulation (what the robot said; her voice).
        episode: her call time, request and yes answers (``answer``, ``plain_answer``).
        no, plain_no: what she says for no, and plainly when the robot asks her to answer yes or no.
        agrees: the robot's repeat-back (lower case) -> whether it means her request.
    """

    def __init__(
        self,
        world: SpeechWorld,
        episode: TaskEpisode,
        *,
        no: VoiceClip,
        plain_no: VoiceClip,
        agrees: Callable[[str], bool],
    ) -> None:
        super().__init__(world, episode)
        self.no, self.plain_no = no, plain_no
        self.agrees = agrees
        self.verdicts: list[bool] = []  # her verdict on each repeat-back, in order

    def _react(self, text: str, now: float) -> None:
        if any(p in text for p in ASKS_ANSWER):
            self.verdicts.append(self.agrees(text))
            clip = self.episode.answer if self.verdicts[-1] else self.no
        elif any(p in text for p in ASKS_PLAIN_ANSWER) and self.verdicts:
            clip = self.episode.plain_answer if self.verdicts[-1] else self.plain_no
        else:
            super()._react(text, now)
            return
        self._due.append((now + self.delay_s, clip))


class AnnieInRun(TaskFlow):
    """Annie stepped by the run's scheduler (10 Hz); never busy: she does not keep the run going."""

    name = "world.annie"
    frequency = 10.0

    def __init__(self, annie: AnnieActor) -> None:
        self.annie = annie

    def step(self, now: float) -> None:
        """Let Annie call, react and speak."""
        self.annie.step(now)

    def busy(self) -> bool:
        """Never."""
        return False


class EventsAfterCommand(TaskFlow):
    """Carries out an episode's events timed from the command (see the module docstring).

    Args:
        sim: the simulation that carries them out.
        events: validated scenario events whose ``at`` is seconds after the command.
        no_command_by: simulated seconds after which the events start even without a command.

    Lifecycle: scheduled in the run like a flow (never busy: it does not keep the run going);
    :meth:`command_taken` starts the clock of the events the first time it is called; later calls (a
    command asked again) change nothing, so the events of a seed happen at the same times in every baseline
    that hears the command at the same time.
    """

    name = "world.episode_events"
    frequency = 10.0

    def __init__(
        self, sim: Simulation, events: Sequence[Event], no_command_by: float = NO_COMMAND_BY_S
    ) -> None:
        self.sim = sim
        self.events = tuple(events)
        self.no_command_by = no_command_by
        self.started_at: float | None = None

    def command_taken(self, now: float) -> None:
        """The robot took the command at ``now``: schedule the events from then (once)."""
        if self.started_at is not None:
            return
        from worlds.scenario import Event

        self.started_at = now
        self.sim.add_events(Event(round(now + e.at, 3), e.type, dict(e.args)) for e in self.events)

    def step(self, now: float) -> None:
        """Start the events at :attr:`no_command_by` when no command came."""
        if self.started_at is None and now >= self.no_command_by:
            self.command_taken(now)

    def busy(self) -> bool:
        """Never."""
        return False


def task_episode(episode: Episode) -> tuple[TaskEpisode, VoiceClip, VoiceClip]:
    """The task flow's episode for a benchmark episode, with her no answers: (episode, no, plain no).

    A spoken command comes with spoken answers (the voice bank's, one picked per episode); a typed command
    with typed answers."""
    from worlds.granny_annie import DEFAULT_BANK, load_bank
    from worlds.granny_annie import Episode as TaskEpisodeType
    from worlds.scenario import Scenario

    person = episode.person

    def answers(kind: str) -> tuple[VoiceClip, VoiceClip]:
        if episode.audio is None:
            word = VoiceClip(Path(), person, kind, kind)
            return word, word
        clips = [c for c in load_bank(DEFAULT_BANK) if c.speaker == person and c.kind == kind]
        if not clips:
            word = VoiceClip(Path(), person, kind, kind)
            return word, word
        plain = min(clips, key=lambda c: (len(c.text.split()), c.text))
        return clips[episode.sim_seed % len(clips)], plain

    request = VoiceClip(Path(episode.audio) if episode.audio else Path(), person, "request", episode.text)
    yes, plain_yes = answers("yes")
    no, plain_no = answers("no")
    scenario = Scenario(f"granny_annie_{episode.name}", "", ())
    seat = episode.person_on or ""
    task = TaskEpisodeType(episode.sim_seed, person, seat, request, yes, plain_yes, scenario, CALL_AT_S)
    return task, no, plain_no


def start_with_task_flow(system: KnicSystem, episode: Episode, recorder: Recorder) -> Callable[[], Dialogue]:
    """Schedule Annie and the robot's task flow in ``system`` (see the module docstring); returns what to
    ask after the run for how the dialogue went."""
    from knic.bench.granny_annie.episodes import world_vocabulary
    from knic.system.granny_annie import GrannyAnnieFlow
    from worlds.scenario import scenario_from_dict

    lexicon = Path(episode.lexicon) if episode.lexicon else None
    vocabulary = world_vocabulary(system.world, lexicon)
    task, no, plain_no = task_episode(episode)
    annie = JudgingAnnie(
        system.sim,
        task,
        no=no,
        plain_no=plain_no,
        agrees=lambda said: repeat_back_means(said, episode.goals, vocabulary, episode.person),
    )
    system.add_flow(AnnieInRun(annie))
    later = scenario_from_dict(episode.later_scenario(), system.world)
    events = EventsAfterCommand(system.sim, later.events)
    system.add_flow(events)
    flow = GrannyAnnieFlow(system, person=episode.person, role=system.config.role, lexicon=lexicon)

    def taken(submission: Submission) -> None:
        recorder.command(system.sim.time, submission.text)
        events.command_taken(system.sim.time)

    flow.intake.on_added = taken
    system.add_flow(flow)
    return lambda: dialogue(flow)


def dialogue(flow: GrannyAnnieFlow) -> Dialogue:
    """How the flow's dialogue went: the goals the robot took (those confirmed, else the last it repeated
    back, else None) and how its task ended (else the phase it is in)."""

    if flow.goals:
        understood: tuple[str, ...] | None = tuple(str(g) for g in flow.goals)
    else:
        announced = [r.submission.goals for r in flow.intake.history if r.submission.goals]
        understood = tuple(str(g) for g in announced[-1]) if announced else None
    return Dialogue(understood, flow.outcome or str(flow.phase))
