"""The Granny Annie task scenario: episodes drawn per seed, validation, and Annie answering the robot."""

from __future__ import annotations

from dataclasses import dataclass, field

import pytest

from core.errors import WorldError
from core.robot import Utterance
from worlds.api import load_world
from worlds.granny_annie import AnnieActor, episode
from worlds.scenario import CALL_TEXT, load_scenario, scenario_from_dict


def test_episodes_are_drawn_per_seed_from_the_voice_bank() -> None:
    world = load_world("erl_home")
    scenario = load_scenario("granny_annie", world)
    assert scenario.task is not None
    first, again, other = episode(scenario, 3), episode(scenario, 3), episode(scenario, 4)
    assert first == again and first.request != other.request
    assert first.request.file.is_file() and first.answer.kind == "yes" and first.plain_answer.text == "yes"
    assert first.seat in ("bed", "sofa")
    kinds = [(e.type, e.args.get("person")) for e in first.scenario.events]
    assert ("person_to", "annie") in kinds and first.call_at == 2.0
    fixed = episode(scenario, 0, request="get me the tablet", seat="sofa")
    assert fixed.request.text == "get me the tablet" and fixed.seat == "sofa"
    with pytest.raises(WorldError, match="no request 'sing a song'"):
        episode(scenario, 0, request="sing a song")


def test_a_task_section_is_checked_against_the_world() -> None:
    world = load_world("erl_home")
    doc = {"name": "t", "events": [], "task": {"person": "annie", "seats": ["throne"]}}
    with pytest.raises(WorldError, match="task: seats must be furniture"):
        scenario_from_dict(doc, world)
    doc["task"] = {"person": "nobody"}
    with pytest.raises(WorldError, match="task: unknown person 'nobody'"):
        scenario_from_dict(doc, world)
    doc["task"] = {"person": "annie", "answer": "maybe"}
    with pytest.raises(WorldError, match="answer must be yes or no"):
        scenario_from_dict(doc, world)


@dataclass
class Room:
    """A room where the robot speaks and Annie answers."""

    time: float = 0.0
    robot: list[Utterance] = field(default_factory=list)
    heard: list[tuple[str, str, str | None]] = field(default_factory=list)

    def spoken(self) -> list[Utterance]:
        return list(self.robot)

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        self.heard.append((text, speaker, audio_path))


def test_annie_answers_the_robot_with_her_recordings() -> None:
    scenario = load_scenario("granny_annie", load_world("erl_home"))
    ep = episode(scenario, 1)
    room = Room()
    annie = AnnieActor(room, ep, delay_s=1.0)
    annie.step(0.0)
    assert room.heard == []
    annie.step(2.0)  # her tablet call
    assert room.heard == [(CALL_TEXT, "annie", None)]
    room.heard.clear()
    room.robot.append(Utterance("Hello Annie, what can I do for you?", "r2d2", 0.0))
    annie.step(2.0)
    assert room.heard == []  # she takes a moment
    annie.step(3.0)
    assert room.heard == [(ep.request.text, "annie", str(ep.request.file))]
    room.robot.append(Utterance("You asked me to switch on the lights. Is that right?", "r2d2", 2.0))
    annie.step(2.0)
    annie.step(3.0)
    room.robot.append(Utterance("Please answer yes or no.", "r2d2", 4.0))
    annie.step(4.0)
    annie.step(5.0)
    assert [h[0] for h in room.heard[1:]] == [ep.answer.text, "yes"]


def test_annie_says_no_when_the_robot_repeats_something_else() -> None:
    ep = episode(load_scenario("granny_annie", load_world("erl_home")), 3)
    assert ep.no_answer is not None and ep.no_answer.text == "no"
    room = Room()
    annie = AnnieActor(room, ep, delay_s=0.0, judge=lambda said: "tracy to the bedroom" in said)
    room.robot.append(Utterance("You asked me to lead jack to the bedroom. Is that right?", "r2d2", 3.0))
    annie.step(3.0)
    room.robot.append(Utterance("You asked me to lead tracy to the bedroom. Is that right?", "r2d2", 4.0))
    annie.step(4.0)
    assert [h[0] for h in room.heard[1:]] == ["no", ep.answer.text]
