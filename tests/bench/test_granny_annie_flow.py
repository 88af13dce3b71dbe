"""The benchmark's episodes start with the task flow: Annie judges the robot's repeat-back by its meaning
(yes only when it means her request, spoken answers for a spoken command, typed for a typed one), and a
run where the robot keeps repeating a command she did not mean ends with it giving up asking."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from core.robot import Utterance
from knic.bench.granny_annie.commands import Request
from knic.bench.granny_annie.episodes import Episode, bank_recording, world_vocabulary
from knic.bench.granny_annie.flow import (
    EventsAfterCommand,
    JudgingAnnie,
    from_her_side,
    repeat_back_means,
    task_episode,
)
from knic.bench.granny_annie.runner import Task, run_task, write_world_files
from knic.language.vocabulary import Vocabulary
from worlds.api import load_world
from worlds.scenario import CALL_TEXT


@pytest.fixture(scope="module")
def vocabulary() -> Vocabulary:
    return world_vocabulary(load_world("erl_home"))


def episode(text: str, *requests: Request, audio: str | None = None, index: int = 0) -> Episode:
    """Annie on the sofa saying ``text`` (which the generator says means ``requests``)."""
    annie = {"at": 0.0, "type": "person_to", "person": "annie", "furniture": "sofa", "teleport": True}
    return Episode(
        index=index,
        seed=0,
        world="erl_home",
        lexicon=None,
        person_on="sofa",
        person_room="living_room",
        placements={"remote": "coffee_table", "tablet": "side_table"},
        off_prior=(),
        requests=requests,
        text=text,
        audio=audio,
        events=(annie,),
    )


REMOTE = Request("bring", "bring me the remote", ("(has annie remote)",), ("remote",))
TABLET = Request("bring", "bring me the tablet", ("(has annie tablet)",), ("tablet",))
APPLE = Request(
    "bring",
    "bring me an apple from the kitchen cabinet",
    ("(has annie apple)", "(taken_from apple kitchen_cabinet)"),
    ("apple",),
)


def test_a_repeat_back_is_judged_by_its_meaning(vocabulary: Vocabulary) -> None:
    assert from_her_side("bring the remote to you") == "bring the remote to me"
    said = "You asked me to bring the remote to you. Is that right?"
    assert repeat_back_means(said, ("(has annie remote)",), vocabulary, "annie")
    assert not repeat_back_means(said, ("(has annie tablet)",), vocabulary, "annie")
    assert not repeat_back_means(
        said, ("(has annie remote)", "(light_on hallway_light)"), vocabulary, "annie"
    )
    chain = "You asked me to switch on the hallway light and then bring the apple from the kitchen cabinet"
    chain += " to you."
    goals = ("(light_on hallway_light)", "(has annie apple)", "(taken_from apple kitchen_cabinet)")
    assert repeat_back_means(chain + " Is that right?", goals, vocabulary, "annie")
    assert not repeat_back_means(
        chain + " Is that right?", goals[:2], vocabulary, "annie"
    )  # the source is part of it
    assert not repeat_back_means("Sorry, I did not understand.", goals, vocabulary, "annie")


@dataclass
class Room:
    """Where the robot speaks and Annie answers."""

    time: float = 0.0
    robot: list[Utterance] = field(default_factory=list)
    heard: list[tuple[str, str | None]] = field(default_factory=list)

    def spoken(self) -> list[Utterance]:
        return list(self.robot)

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        assert speaker == "annie"
        self.heard.append((text, audio_path))

    def robot_says(self, text: str, annie: JudgingAnnie, now: float) -> None:
        self.robot.append(Utterance(text, "r2d2", now))
        annie.step(now)
        annie.step(now + 2.0)  # she answers after a moment


def annie_in(room: Room, ep: Episode, vocabulary: Vocabulary) -> JudgingAnnie:
    task, no, plain_no = task_episode(ep)
    return JudgingAnnie(
        room,
        task,
        no=no,
        plain_no=plain_no,
        agrees=lambda s: repeat_back_means(s, ep.goals, vocabulary, "annie"),
    )


def test_annie_says_her_spoken_command_and_answers_by_what_the_robot_repeated(vocabulary: Vocabulary) -> None:
    wav = bank_recording("bring me an apple from the kitchen cabinet")
    assert wav is not None
    ep = episode("bring me an apple from the kitchen cabinet", APPLE, audio=str(wav))
    room = Room()
    annie = annie_in(room, ep, vocabulary)
    annie.step(0.0)
    annie.step(2.0)
    assert room.heard == [(CALL_TEXT, None)]  # the tablet call
    room.robot_says("Hello Annie, what can I do for you?", annie, 20.0)
    assert room.heard[-1] == ("bring me an apple from the kitchen cabinet", str(wav))
    room.robot_says("You asked me to bring the apple to you. Is that right?", annie, 30.0)  # source lost
    room.robot_says("Please answer yes or no.", annie, 40.0)
    room.robot_says(
        "You asked me to bring the apple from the kitchen cabinet to you. Is that right?", annie, 50.0
    )
    said = room.heard[2:]
    assert [text.split()[0] for text, _ in said] == ["no", "no", "yes"] and annie.verdicts == [False, True]
    assert said[1] == ("no", said[1][1])  # plainly when asked to answer yes or no
    assert all(audio is not None and Path(audio).is_file() for _, audio in said)  # her recordings


def test_a_typed_command_gets_typed_answers(vocabulary: Vocabulary) -> None:
    room = Room()
    annie = annie_in(room, episode("bring me the remote", REMOTE), vocabulary)
    room.robot_says("Hello Annie, how can I help?", annie, 20.0)
    room.robot_says("You asked me to bring the remote to you. Is that right?", annie, 30.0)
    assert room.heard == [(CALL_TEXT, None), ("bring me the remote", None), ("yes", None)]


def test_the_robot_repeating_what_she_did_not_mean_gives_up_asking(tmp_path: Path) -> None:
    """She meant the tablet; the words say the remote: she answers no each time, the robot asks three times
    and gives up; it entered her room, understood nothing she meant, and brought nothing."""
    ep = episode("bring me the remote", TABLET, index=5)
    write_world_files(tmp_path, [ep])
    result = run_task(Task(ep.to_dict(), "knic", "companion", str(tmp_path)))
    score = result["score"]
    assert score["achieved"] == {
        "entered_room": 1,
        "understood": 0,
        "devices": 0,
        "found": 0,
        "brought": 0,
        "accompanied": 0,
    }
    assert result["understood"] == ["(has annie remote)"] and result["run"]["task"] == "not understood"
    trace = [json.loads(line) for line in (tmp_path / "traces" / "ep005_knic.jsonl").read_text().splitlines()]
    steps = [e["action"] for e in trace if e["kind"] == "task"]
    assert steps[0] == "call" and steps.count("ask") == 3 and steps[-1] == "done"
    assert steps.count("intake declined") == 3 and "confirmed" not in steps
    entered_line = next(d for d in score["details"] if d.startswith("entered_room"))
    entered = float(entered_line.split(" at ")[1].split()[0])
    first_ask = next(e["time"] for e in trace if e["kind"] == "task" and e["action"] == "ask")
    assert entered <= first_ask + 0.5  # it asked once in her room


def test_episode_events_start_when_the_robot_takes_the_command() -> None:
    """Events timed from the command happen that long after the command (once, whatever is asked again);
    without a command they start at the fallback time."""
    from worlds.scenario import scenario_from_dict
    from worlds.simulation import Simulation

    world = load_world("erl_home")
    later = {"at": 3.0, "type": "person_to", "person": "tracy", "furniture": "sofa", "teleport": True}
    ep = episode("bring me the remote", REMOTE)
    ep = Episode.from_dict({**ep.to_dict(), "after_command": [later]})
    events = scenario_from_dict(ep.later_scenario(), world).events
    with Simulation.from_world(world, seed=1) as sim:
        timed = EventsAfterCommand(sim, events, no_command_by=90.0)
        where = {("person_at", "tracy", "kitchen")}
        for _ in range(100):  # 10 s without a command: nothing happens
            sim.step(0.1)
            timed.step(sim.time)
        assert where <= sim.ground_truth_facts()
        timed.command_taken(sim.time)
        taken = sim.time
        timed.command_taken(sim.time + 1.0)  # asked again: the events keep their times
        while sim.time < taken + 2.9:
            sim.step(0.1)
        assert where <= sim.ground_truth_facts()
        sim.step(0.2)
        assert ("person_at", "tracy", "living_room") in sim.ground_truth_facts()
        assert timed.started_at == pytest.approx(taken)
    with Simulation.from_world(world, seed=1) as sim:
        timed = EventsAfterCommand(sim, events, no_command_by=5.0)
        while sim.time < 8.05:
            sim.step(0.1)
            timed.step(sim.time)
        assert timed.started_at == pytest.approx(5.0)
        assert ("person_at", "tracy", "living_room") in sim.ground_truth_facts()
