"""The Granny Annie task flow (ERL "Catering for Granny Annie's Comfort") on the robot's side.

:class:`GrannyAnnieFlow` is a scheduled component beside the dispatcher. It hears only what the robot's
microphone hears (:meth:`core.robot.Robot.poll_utterances`) and acts only through the knowledge base's goals
and the robot's voice:

1. ``wait_call``: Annie's tablet call arrives (:data:`worlds.scenario.CALL_TEXT`, localised where she tapped);
   the room holding that point becomes ``(person_at annie room)`` (source ``tablet``; annie, or whoever the
   flow serves) and the goal
   ``(robot_at r2d2 room)`` joins the running goals;
2. ``go``: once the robot believes it is in her room, that goal is withdrawn and the robot asks what she
   needs;
3. ``listen``: her spoken request (a recording) goes to the :class:`~knic.intake.GoalIntake`, which repeats
   back what it understood and asks "Is that right?" (``confirm``);
4. ``confirm``: her spoken yes adds the goals in one batch while the robot runs; a no (or nothing understood)
   makes the robot ask again, at most ``max_asks`` times. Her requests are decoded with the n-gram model of
   :mod:`knic.language.lmspeech` (it hears phrasings the grammar does not; on the development set
   ``tests/fixtures/speech_people/dev`` frame+args 0.74 against 0.50 for the grammar decoder); after a no
   (or nothing understood) her next request goes to the other decoder, grammar and n-gram in turn (the
   same decoder would hear her same words the same way again);
5. ``work``: the dispatcher carries out the goals (with whatever else is going on); when they all hold, the
   robot tells Annie it is done; when the rest stayed dropped with the dispatcher idle for ``give_up_s``
   (a retry on new knowledge restarts that wait), it tells her what it could not do, and that is final: the
   dispatcher gives those goals up for good (:meth:`planner.Dispatcher.give_up`), no retry brings them back;
6. ``done``.

The door bell is heard as ``(sound_at doorbell ?room)``; the reaction is data per role
(:data:`DOORBELL_REACTION`): ``note`` (a trace event), ``tell`` (tell Annie), ``go`` (go to the door: a goal
joining the running plan, withdrawn when reached). The visitor is nobody the robot knows: perception makes
them a new person instance when it first sees them (``visitor_1``, ...; :mod:`knic.kgm3.people`); the flow
notes every person met that way (a ``visitor`` event naming the instance and the room it is believed in) and,
under ``tell`` and ``go``, tells Annie where the visitor is. Every step is a ``task`` trace event (``action``
names it). Times are simulated seconds.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from actions.erl.context import room_of
from actions.erl.devices import spoken
from core.errors import KnicError
from knic.intake import GoalIntake, Outcome
from knic.system import TaskFlow
from knowledge_base import BeliefStatus, Fact
from planner.dispatch import DispatcherState
from planner.trace import EventKind, TraceEvent
from worlds.granny_annie import AnnieActor, Episode, served_person
from worlds.scenario import CALL_TEXT

if TYPE_CHECKING:
    from knic.system import KnicSystem

#: how the robot reacts to the door bell, per role (roles not listed: ``tell``)
DOORBELL_REACTION = {
    "companion": "tell",
    "service_autonomous": "go",
    "service_semi_autonomous": "tell",
    "teleoperated": "note",
}
#: what the robot asks once in Annie's room
ASK = "Hello {name}, what can I do for you?"


class Phase(enum.StrEnum):
    """Where the flow is (see the module docstring)."""

    WAIT_CALL = "wait_call"
    GO = "go"
    LISTEN = "listen"
    CONFIRM = "confirm"
    WORK = "work"
    DONE = "done"


class GrannyAnnieFlow(TaskFlow):
    """The task flow (see the module docstring).

    Args:
        system: the assembled run (knowledge base, robot, dispatcher, trace, voice).
        person: who calls and asks (default: :func:`worlds.granny_annie.served_person` of the run's world:
            annie, else its first known person).
        role: the robot's role name (for the door bell reaction).
        max_asks: how often the robot asks for the request in all.
        answer_timeout_s: simulated seconds without an answer after which the robot asks again.
        lexicon: the world's spoken names file (default: the ERL lexicon when present).
        recognise_command, recognise_answer: WAV path -> words (defaults: pocketsphinx grammars).
    """

    name = "task.granny_annie"
    frequency = 5.0

    def __init__(
        self,
        system: KnicSystem,
        *,
        person: str | None = None,
        role: str = "companion",
        max_asks: int = 3,
        answer_timeout_s: float = 20.0,
        lexicon: Path | None = None,
        recognise_command: Callable[[str], str] | None = None,
        recognise_answer: Callable[[str], str] | None = None,
    ) -> None:
        from knic.system.names import run_vocabulary

        self.system = system
        self.kb = system.kb
        self.robot = system.parts.robot
        self.person = person if person is not None else served_person(system.world)
        self.reaction = DOORBELL_REACTION.get(role, "tell")
        self.max_asks = max_asks
        self.answer_timeout_s = answer_timeout_s
        vocabulary = run_vocabulary(system, lexicon)
        self.intake = GoalIntake(
            self.kb,
            vocabulary,
            say=self.say,
            confirm=True,
            recognise_command=recognise_command,
            recognise_answer=recognise_answer,
        )
        self.phase = Phase.WAIT_CALL
        self.since = 0.0
        self.asks = 0
        self.room: str | None = None
        self.goals: tuple[Fact, ...] = ()
        self.outcome = ""  # how the request ended: "done", "partly", "not understood"
        self._transient: set[Fact] = set()
        self._switched = False
        self._ngram: Callable[[str], str] | None = None  # the n-gram decoder, once built
        self._grammar: Callable[[str], str] | None = None  # the one before (None: the intake default)
        self._custom_recogniser = recognise_command is not None
        self._bells: set[float] = set()
        #: the people the robot knew when the flow started, then every visitor it noted since
        self._people: set[str] = set(self.kb.instances("person"))
        self._now = 0.0
        self._given_up_from: float | None = None  # since when every open goal is dropped and nothing runs
        system.trace.subscribe(self._goal_news)

    # ------------------------------------------------------------------ component

    def busy(self) -> bool:
        """True until the robot has told Annie the request is done (or given up asking)."""
        return self.phase != Phase.DONE

    def holds_robot(self) -> bool:
        """While the robot goes to Annie and talks with her, it stays on that (no revisit starts)."""
        return self.phase in (Phase.GO, Phase.LISTEN, Phase.CONFIRM)

    def step(self, now: float) -> None:
        """Hear, react to the door bell, withdraw reached transient goals, advance the phase."""
        self._now = now
        for utterance in self.robot.poll_utterances():
            self._heard(utterance.text, utterance.speaker, utterance.audio_path, utterance.position, now)
        self._doorbell(now)
        self._visitors(now)
        for goal in [g for g in self._transient if self.kb.holds(g)]:
            self._transient.discard(goal)
            self.kb.remove_goal(goal.predicate, *goal.args, source="task")
        if (
            self.phase == Phase.GO
            and self.room is not None
            and self.kb.holds("robot_at", self._me(), self.room)
        ):
            self._ask(now)
        elif self.phase in (Phase.LISTEN, Phase.CONFIRM) and now - self.since > self.answer_timeout_s:
            if self.phase == Phase.CONFIRM:
                self.intake.hear(None)  # no answer: the intake asks again or declines
                if self.intake.awaiting_answer is not None:
                    self.since = now
                    return
            self._ask_again(now, "no answer")
        elif self.phase == Phase.WORK:
            self._check_work(now)

    # ------------------------------------------------------------------ phases

    def _heard(self, text: str, speaker: str, audio: str | None, position: Any, now: float) -> None:
        if text == CALL_TEXT and self.phase == Phase.WAIT_CALL:
            self._called(speaker, position, now)
            return
        if speaker != self.person or self.phase not in (Phase.LISTEN, Phase.CONFIRM):
            return
        self.event("heard", now, reason=text, data={"audio": audio} if audio else {})
        reply = self.intake.submit_audio(audio, speaker=self.person) if audio else self._typed(text)
        self.event(
            f"intake {reply.outcome.value}", now, reason=reply.reason, data={"goals": list(reply.goals)}
        )
        if reply.outcome == Outcome.ASKED:
            self._enter(Phase.CONFIRM, now)
        elif reply.outcome == Outcome.ASKED_AGAIN:
            self.since = now
        elif reply.outcome == Outcome.ADDED:
            submission = self.intake.history[-1].submission
            self.goals = submission.goals
            self.event("confirmed", now, data={"goals": [str(g) for g in self.goals]})
            self._enter(Phase.WORK, now)
        else:
            self._ask_again(now, reply.reason or reply.outcome.value)

    def _typed(self, text: str) -> Any:
        if self.intake.awaiting_answer is not None:
            return self.intake.hear(text)
        return self.intake.submit(text, speaker=self.person)

    def _called(self, speaker: str, position: Any, now: float) -> None:
        room = room_of(self.kb, float(position[0]), float(position[1])) if position is not None else None
        self.event("call", now, reason=f"{speaker} calls from {room or 'an unknown place'}")
        if room is None:
            self._ask(now)  # nowhere to go: ask from here
            return
        self.room = room
        if self.kb.type_of(speaker) == "person":
            self.kb.add_fact(
                "person_at", speaker, room, source="tablet", status=BeliefStatus.OBSERVED, confidence=0.9
            )
        self.add_transient(Fact("robot_at", (self._me(), room)))
        self._enter(Phase.GO, now)

    def _ask(self, now: float) -> None:
        self._second_decoder(now)  # her requests go to the n-gram decoder (dev frame+args 0.74, grammar 0.50)
        self.asks += 1
        self.say(ASK.format(name=spoken(self.person).capitalize()))
        self.event("ask", now, reason=f"ask {self.asks}/{self.max_asks}")
        self._enter(Phase.LISTEN, now)

    def _ask_again(self, now: float, why: str) -> None:
        if self.asks >= self.max_asks:
            self.outcome = "not understood"
            self.say(f"Sorry {spoken(self.person).capitalize()}, I could not understand your request.")
            self.event("done", now, reason=f"gave up asking: {why}")
            self._enter(Phase.DONE, now)
            return
        self._other_decoder(now)
        self._ask(now)

    def _other_decoder(self, now: float) -> None:
        """After a misunderstanding (answered no, nothing recognised): her next request goes to the other
        decoder (the n-gram model and the grammar decoder hear different phrasings; the same decoder would
        hear her same words the same way again)."""
        if self._custom_recogniser or self._ngram is None:
            return
        if self.intake.recognise_command is self._ngram:
            self.intake.recognise_command = self._grammar  # None: the intake builds its grammar decoder
            self.event("decoder", now, reason="the next request is decoded with the grammar decoder")
        else:
            self._grammar = self.intake.recognise_command
            self.intake.recognise_command = self._ngram
            self.event("decoder", now, reason="the next request is decoded with the n-gram model")

    def _second_decoder(self, now: float) -> None:
        """From the first request on: decode her requests with the n-gram recogniser (built once; a failure
        to build it keeps the grammar decoder)."""
        if self._switched or self._custom_recogniser:
            return
        self._switched = True
        from core.errors import LanguageError
        from knic.language.lmspeech import NgramRecognizer

        try:
            recognizer = NgramRecognizer(self.intake.vocabulary)
        except LanguageError as exc:
            self.event("second decoder unavailable", now, reason=str(exc))
            return

        def recognise(wav: str) -> str:
            transcript = recognizer.recognize(wav)
            if not transcript.text or not transcript.in_grammar:
                raise LanguageError(f"{wav}: no command recognised by the n-gram decoder")
            return str(transcript.text)

        self._grammar, self._ngram = self.intake.recognise_command, recognise
        self.intake.recognise_command = recognise

    def _check_work(self, now: float) -> None:
        open_goals = [g for g in self.goals if not self.kb.holds(g)]
        name = spoken(self.person).capitalize()
        if not open_goals:
            self.outcome = "done"
            self.say(f"{name}, I have done what you asked.")
            self.event("done", now, data={"goals": [str(g) for g in self.goals]})
            self._enter(Phase.DONE, now)
            return
        dispatcher = self.system.dispatcher
        dropped = dispatcher.report().dropped
        idle = dispatcher.state == DispatcherState.IDLE
        if not (idle and all(str(g) in dropped for g in open_goals)):
            self._given_up_from = None  # working, or a goal came back: the wait starts again
            return
        if self._given_up_from is None:
            self._given_up_from = now
        if now - self._given_up_from < self.system.config.give_up_s:
            return
        # what the robot tells Annie is final: the dispatcher retries none of these goals any more
        for goal in open_goals:
            dispatcher.give_up((goal.predicate, *goal.args), dropped[str(goal)])
        self.outcome = "partly"
        names = ", ".join(str(g) for g in open_goals)
        self.say(f"{name}, I could not do everything you asked: {names} is not done.")
        self.event("done", now, reason="gave up on " + names, data={"given_up": [str(g) for g in open_goals]})
        self._enter(Phase.DONE, now)

    def _goal_news(self, event: TraceEvent) -> None:
        """A goal of the request dropped again or retried (both may happen within one dispatcher step): the
        wait before giving up starts again."""
        kinds = (EventKind.GOAL_DROPPED, EventKind.REPLAN)
        if event.goal and event.kind in kinds and any(str(g) == event.goal for g in self.goals):
            self._given_up_from = None

    def _doorbell(self, now: float) -> None:
        for fact in self.kb.facts("sound_at", "doorbell"):
            prov = self.kb.why(fact)
            stamp = prov.since if prov is not None else now
            if stamp in self._bells:
                continue
            self._bells.add(stamp)
            room = fact.args[1]
            self.event("doorbell", now, reason=f"{self.reaction}: the door bell rang in the {spoken(room)}")
            if self.reaction == "tell":
                self.say(f"{spoken(self.person).capitalize()}, someone rang the door bell.")
            elif self.reaction == "go":
                self.say("Someone rang the door bell; I am going to the door.")
                self.add_transient(Fact("robot_at", (self._me(), room)))

    def _visitors(self, now: float) -> None:
        """Note each person instance met since the start (a visitor) once it is believed in a room."""
        for person in self.kb.instances("person"):
            if person in self._people:
                continue
            rooms = [f.args[1] for f in self.kb.facts("person_at", person)]
            if not rooms:
                continue
            self._people.add(person)
            room = rooms[0]
            self.event(
                "visitor",
                now,
                reason=f"met {person} in the {spoken(room)}",
                data={"person": person, "room": room},
            )
            if self.reaction in ("tell", "go"):
                self.say(f"{spoken(self.person).capitalize()}, a visitor is in the {spoken(room)}.")

    # ------------------------------------------------------------------ helpers

    def add_transient(self, goal: Fact) -> None:
        """Add a goal that is withdrawn once it holds (going somewhere is a means, not a result)."""
        if self.kb.holds(goal):
            return
        for other in [
            g for g in self._transient if g.predicate == goal.predicate and g.args[0] == goal.args[0]
        ]:
            self._transient.discard(other)  # a newer destination replaces an older one
            self.kb.remove_goal(other.predicate, *other.args, source="task")
        self._transient.add(goal)
        self.kb.add_goal(goal.predicate, *goal.args, source="task")

    def say(self, text: str) -> None:
        """Speak through the robot (and keep it in the context's record)."""
        self.system.context.say(text)

    def event(self, what: str, now: float, *, reason: str = "", data: dict[str, Any] | None = None) -> None:
        """A ``task`` trace event named ``what``."""
        self.system.trace.emit(
            TraceEvent(EventKind.TASK, now, action=what, reason=reason or None, data=data or {})
        )

    def _enter(self, phase: Phase, now: float) -> None:
        self.phase, self.since = phase, now

    def _me(self) -> str:
        return self.system.context.robot_name


class _Actor(TaskFlow):
    """Annie (the simulated person) stepped by the scheduler; never busy (she does not keep the run going)."""

    name = "world.annie"
    frequency = 10.0

    def __init__(self, actor: AnnieActor) -> None:
        self.actor = actor

    def step(self, now: float) -> None:
        """Let Annie react and speak."""
        self.actor.step(now)

    def busy(self) -> bool:
        """Never."""
        return False


def start_granny_annie(system: KnicSystem, episode: Episode, *, role: str | None = None) -> GrannyAnnieFlow:
    """Start a Granny Annie episode in an assembled system whose scenario is ``episode.scenario``: Annie
    (world side, :class:`worlds.granny_annie.AnnieActor`) and the robot's :class:`GrannyAnnieFlow` are
    scheduled; :meth:`KnicSystem.run` then runs the episode (no goal is needed up front)."""
    flow = GrannyAnnieFlow(system, person=episode.person, role=role or system.config.role)
    system.add_flow(
        _Actor(AnnieActor(system.sim, episode, judge=repeat_back_judge(flow, episode.request.text)))
    )
    system.add_flow(flow)
    return flow


def repeat_back_judge(flow: GrannyAnnieFlow, request: str) -> Callable[[str], bool] | None:
    """Annie's ear: whether the robot's repeat-back is what the robot would repeat for her words ``request``
    as she meant them (None when her words are not understood at all: she then always says her answer)."""
    try:
        expected = flow.intake.understand(request, speaker=flow.person).said.lower().rstrip(".")
    except KnicError:
        return None
    return lambda said: expected in said.lower()


def granny_annie_system(
    seed: int,
    *,
    role: str = "companion",
    request: str | None = None,
    seat: str | None = None,
    world: str | Path = "erl_home",
    scenario: str | Path = "granny_annie",
    **config: Any,
) -> tuple[KnicSystem, GrannyAnnieFlow, Episode]:
    """Build and start one Granny Annie episode: the world, the task scenario drawn for ``seed`` (Annie's
    seat and request, or the given ``request`` text of the voice bank and ``seat``), the run under ``role``.

    Returns the system (call ``run()``, then ``close()``), the robot's flow (``phase``, ``outcome``,
    ``goals``) and the episode (what Annie says).

    Raises:
        core.errors.WorldError: unknown world or scenario, a scenario without a task, a request not in the
            voice bank.
    """
    from knic.system import KnicSystem as System
    from knic.system import RunConfig
    from worlds.api import load_world
    from worlds.granny_annie import episode as draw
    from worlds.scenario import load_scenario

    loaded = load_world(world)
    drawn = draw(load_scenario(scenario, loaded), seed, request=request, seat=seat)
    system = System(RunConfig(world=world, scenario=drawn.scenario, seed=seed, role=role, **config))
    try:
        flow = start_granny_annie(system, drawn, role=role)
    except BaseException:
        system.close()
        raise
    return system, flow, drawn


def start_with_request(
    system: KnicSystem,
    request: str,
    *,
    person: str | None = None,
    request_audio: str | Path | None = None,
    answer: str = "yes",
    call_at: float = 2.0,
    role: str | None = None,
) -> GrannyAnnieFlow:
    """Start a Granny Annie episode in a run set up elsewhere (a benchmark's own world file and scenario):
    ``person`` (default: the world's served person, annie or its first known person) calls at ``call_at``,
    asks ``request`` (the recording ``request_audio``, else the voice bank's
    recording of those words, else the words as text) and answers ``answer`` (yes or no) when the robot
    repeats the request back. Call ``system.run()`` afterwards; the flow tells how it ended."""
    from worlds.granny_annie import custom_episode

    who = person or served_person(system.world)
    episode = custom_episode(who, request, request_audio=request_audio, answer=answer, call_at=call_at)
    return start_granny_annie(system, episode, role=role)


def understood_right(flow: GrannyAnnieFlow, request: str) -> bool:
    """Whether the goals the robot took (``flow.goals``) are what ``request`` (Annie's words, as she meant
    them) means: the judge's check that the robot understood her, beside the referee's check that the goals
    hold in the ground truth."""
    try:
        meant = flow.intake.understand(request, speaker=flow.person)
    except KnicError:
        return False
    return {str(g) for g in meant.goals} == {str(g) for g in flow.goals}
