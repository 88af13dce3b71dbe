"""The task flow's report to Annie agrees with the dispatcher's book of goals.

A real knowledge base of the ERL apartment and a real dispatcher (with a stub planner that finds every goal
unreachable, and the run's retry rule: a dropped goal comes back on new knowledge about its subject) under
the flow, without the simulator."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, cast

import pytest

from knic.system.granny_annie import GrannyAnnieFlow, Phase
from knowledge_base import Fact, KnowledgeBase
from planner.dispatch import Dispatcher
from planner.recovery import GoalRetry, RecoveryPolicy
from planner.trace import EventKind, Trace
from tests.planner.doubles import SimClock, StubPlanner, World, erl_kb, scripted_registry
from worlds.api import load_world
from worlds.model import World as WorldModel

if TYPE_CHECKING:
    from knic.system import KnicSystem

GOAL = Fact("has", ("annie", "glasses"))


class Silent:
    """A robot whose microphone hears nothing."""

    def poll_utterances(self) -> list[object]:
        return []


@dataclass
class Voice:
    """The context's voice: what the robot said."""

    robot_name: str = "r2d2"
    said: list[str] = field(default_factory=list)

    def say(self, text: str) -> None:
        self.said.append(text)


@dataclass
class Parts:
    robot: Silent


@dataclass
class Config:
    give_up_s: float = 10.0


@dataclass
class FlowSystem:
    """The parts of a run the flow uses."""

    kb: KnowledgeBase
    dispatcher: Dispatcher
    trace: Trace
    parts: Parts = field(default_factory=lambda: Parts(Silent()))
    context: Voice = field(default_factory=Voice)
    config: Config = field(default_factory=Config)
    world: WorldModel = field(default_factory=lambda: load_world("erl_home"))  # its lexicon and device rooms


def _working_flow() -> tuple[SimClock, FlowSystem, GrannyAnnieFlow]:
    clock = SimClock(dt=0.1)
    kb = erl_kb(clock, goals=[str(GOAL)])
    trace = Trace()
    policy = RecoveryPolicy(goal_retry=GoalRetry(times=20, after_s=math.inf))
    dispatcher = Dispatcher(kb, StubPlanner([]), scripted_registry(kb, World()), policy=policy, trace=trace)
    system = FlowSystem(kb, dispatcher, trace)
    flow = GrannyAnnieFlow(cast("KnicSystem", system), person="annie")
    flow.goals, flow.phase, flow.since = (GOAL,), Phase.WORK, 0.0  # her request was confirmed at t=0
    return clock, system, flow


def _run(clock: SimClock, system: FlowSystem, flow: GrannyAnnieFlow, until: float) -> None:
    while clock.t < until:
        system.dispatcher.step()
        flow.step(clock.t)
        clock.tick()


def test_the_flow_gives_up_only_after_the_goal_stayed_dropped_and_then_for_good() -> None:
    clock, system, flow = _working_flow()
    kb, trace = system.kb, system.trace
    _run(clock, system, flow, 5.0)
    assert str(GOAL) in system.dispatcher.report().dropped and flow.phase == Phase.WORK
    # news about the glasses: the dispatcher retries the goal (and drops it again); the wait starts again
    kb.add_fact("object_at", "glasses", "kitchen", source="kp_camera")
    _run(clock, system, flow, 12.0)
    retries = [e for e in trace.of_kind(EventKind.REPLAN) if (e.reason or "").startswith("retrying goal")]
    assert len(retries) == 1 and 5.0 <= retries[0].time < 5.5
    assert flow.phase == Phase.WORK  # 12 s after the first drop, but not 10 s after the last
    _run(clock, system, flow, 17.0)
    done = [e for e in trace.of_kind(EventKind.TASK) if e.action == "done"]
    assert flow.phase == Phase.DONE and flow.outcome == "partly" and len(done) == 1
    assert done[0].data["given_up"] == [str(GOAL)] and done[0].time >= retries[0].time + 10.0
    assert system.context.said[-1].startswith("Annie, I could not do everything you asked")
    # what Annie was told is final: the goal is dropped for good, new knowledge brings it back no more
    assert str(GOAL) in system.dispatcher.dropped_for_good()
    kb.remove_fact("object_at", "glasses", "kitchen", source="kp_camera")
    kb.add_fact("object_at", "glasses", "bedroom", source="kp_camera")
    _run(clock, system, flow, 30.0)
    late = [e for e in trace.of_kind(EventKind.REPLAN) if e.time > done[0].time]
    assert late == [] and str(GOAL) in system.dispatcher.report().dropped


def test_a_goal_that_holds_is_reported_done_not_given_up() -> None:
    clock, system, flow = _working_flow()
    _run(clock, system, flow, 3.0)
    system.kb.add_fact("has", "annie", "glasses", source="kp_camera")
    _run(clock, system, flow, 4.0)
    assert flow.phase == Phase.DONE and flow.outcome == "done"
    done = [e for e in system.trace.of_kind(EventKind.TASK) if e.action == "done"]
    assert len(done) == 1 and "given_up" not in done[0].data


@dataclass
class Heard:
    text: str
    in_grammar: bool = True


class FakeNgram:
    """Stands in for the n-gram decoder: hears every recording as ``glass``."""

    def __init__(self, vocabulary: object) -> None:
        self.vocabulary = vocabulary

    def recognize(self, wav: str) -> Heard:
        return Heard("bring me the glass")


def test_after_a_no_her_next_request_goes_to_the_other_decoder(monkeypatch: pytest.MonkeyPatch) -> None:
    import knic.language.lmspeech

    monkeypatch.setattr(knic.language.lmspeech, "NgramRecognizer", FakeNgram)
    _, system, flow = _working_flow()
    flow.phase = Phase.WAIT_CALL
    grammar = flow.intake.recognise_command  # the intake's default (built on first use)
    flow._ask(0.0)
    ngram = flow.intake.recognise_command
    assert ngram is not grammar and ngram is not None and ngram("a.wav") == "bring me the glass"
    flow._ask_again(1.0, "answered no")  # the n-gram decoder's reading was refused: the grammar decoder next
    assert flow.intake.recognise_command is grammar
    flow._ask_again(2.0, "answered no")  # refused again: back to the n-gram decoder
    assert flow.intake.recognise_command is ngram
    switches = [e.reason for e in system.trace.of_kind(EventKind.TASK) if e.action == "decoder"]
    assert switches == [
        "the next request is decoded with the grammar decoder",
        "the next request is decoded with the n-gram model",
    ]
    assert flow.asks == 3 and flow.phase == Phase.LISTEN
