"""The Granny Annie benchmark in an apartment without annie: the served person ("me") is annie when the world
knows her, else its first known person in file order, or the one named with ``--person``; the generator, the
events, Annie's side of the dialogue and the referee all use that person. The test bungalow
(``worlds/test_bungalow``) has walter and rosa and no annie."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from core.errors import WorldError
from knic.bench.granny_annie.episodes import (
    generate_episode,
    generate_episodes,
    voice_bank,
    world_vocabulary,
)
from knic.bench.granny_annie.referee import Sample, Timeline, judge
from knic.bench.granny_annie.runner import Task, run_task, write_world_files
from knic.cli import main
from knic.language.vocabulary import normalize
from worlds.api import load_world
from worlds.granny_annie import first_person, served_person
from worlds.model import World

BUNGALOW = str(Path(__file__).resolve().parents[2] / "worlds" / "test_bungalow" / "test_bungalow.yaml")


@pytest.fixture(scope="module")
def bungalow() -> World:
    return load_world(BUNGALOW)


def test_the_served_person_is_annie_else_the_first_known_person(bungalow: World) -> None:
    erl = load_world("erl_home")
    assert first_person(erl) == served_person(erl) == "annie"
    assert first_person(bungalow) == served_person(bungalow) == "walter"  # file order, not alphabetical
    assert served_person(bungalow, "rosa") == "rosa"
    with pytest.raises(WorldError, match=r"no known person 'annie' to serve \(known: walter, rosa\)"):
        served_person(bungalow, "annie")
    # a stranger (known: false) is never "me"; a world knowing nobody has no one to serve
    walter, rosa = bungalow.people["walter"], bungalow.people["rosa"]
    strangers = replace(bungalow, people={"walter": replace(walter, known=False), "rosa": rosa})
    assert first_person(strangers) == "rosa"
    with pytest.raises(WorldError, match="no known person 'walter'"):
        served_person(strangers, "walter")
    nobody = replace(bungalow, people={"walter": replace(walter, known=False)})
    assert first_person(nobody) is None
    with pytest.raises(WorldError, match="no known person to serve"):
        served_person(nobody)


def test_the_bungalow_seats_nobody_on_furniture_holding_items(bungalow: World) -> None:
    holding = {item.on for item in bungalow.items.values()}
    assert all(p.on not in holding for p in bungalow.people.values())
    assert bungalow.people["walter"].on == "armchair"
    assert bungalow.people["rosa"].on is None  # at the dining table, too high to sit on: she stands beside it
    assert "annie" not in bungalow.people


@pytest.mark.parametrize("person", [None, "rosa"])
def test_bungalow_episodes_serve_walter_or_rosa(bungalow: World, person: str | None) -> None:
    served = person or "walter"
    other = "rosa" if served == "walter" else "walter"
    episodes = generate_episodes(BUNGALOW, 40, 1, person)
    assert {e.person for e in episodes} == {served}
    seat = bungalow.people[served].on
    room = bungalow.furniture[seat].room if seat else bungalow.room_of(*bungalow.people[served].position)
    assert {(e.person_on, e.person_room) for e in episodes} == {(seat, room)}
    brings = [g for e in episodes for r in e.requests if r.kind == "bring" for g in r.goals[:1]]
    assert brings and all(g.startswith(f"(has {served} ") for g in brings)
    led = {t for e in episodes for r in e.requests if r.kind == "accompany" for t in r.targets}
    assert led <= {other} and any(r.kind == "accompany" for e in episodes for r in e.requests)
    for e in episodes:
        seated = {"at": 0.0, "type": "person_to", "person": served, "furniture": seat, "teleport": True}
        assert e.events == (
            (seated,) if seat else ()
        )  # a person standing stays where the world file puts her
        assert all(ev.get("person") != served for ev in e.after_command)  # the others walk and move things
    # every command is said in the bungalow's names: erl_home's voice bank has none it could use
    bank = {normalize(t) for t, _wav, _who in voice_bank()}
    assert all(e.audio is None and normalize(e.text) not in bank for e in episodes)
    # one episode alone is the same as in the batch
    again = generate_episode(bungalow, BUNGALOW, 1, 5, world_vocabulary(bungalow), person=served)
    assert again == episodes[5]


def test_a_bank_command_is_used_only_when_the_world_has_every_name_it_says() -> None:
    erl = load_world("erl_home")
    vocab = world_vocabulary(erl)
    bank = {normalize(t) for t, _wav, _who in voice_bank()}
    baseline = [generate_episode(erl, "erl_home", 0, i, vocab) for i in range(60)]
    assert any(normalize(e.text) in bank and e.audio for e in baseline)  # erl_home uses its bank
    assert any("glasses" in e.text for e in baseline if normalize(e.text) in bank)
    # without the glasses, no bank command naming them is drawn (nor any command naming them)
    items = {n: i for n, i in erl.items.items() if n != "glasses"}
    no_glasses = replace(erl, items=items)
    vocab = world_vocabulary(no_glasses)
    episodes = [generate_episode(no_glasses, "erl_home", 0, i, vocab) for i in range(60)]
    assert not any("glasses" in e.text for e in episodes)
    assert any(normalize(e.text) in bank for e in episodes)  # other bank commands still are
    # served as tracy, a bank command is hers ("me" is tracy) and typed: the bank's recordings are annie's
    episodes = [
        generate_episode(erl, "erl_home", 0, i, world_vocabulary(erl), person="tracy") for i in range(30)
    ]
    assert all(e.person == "tracy" and e.audio is None for e in episodes)
    assert any(normalize(e.text) in bank for e in episodes)
    assert all(
        "tracy" not in r.targets and (r.kind != "bring" or r.goals[0].startswith("(has tracy "))
        for e in episodes
        for r in e.requests
    )


def test_the_referee_judges_the_served_persons_room(bungalow: World) -> None:
    episode = generate_episode(bungalow, BUNGALOW, 2, 13, person="walter")
    people = {("person_at", "walter", "sitting_room"), ("person_at", "rosa", "kitchen_diner")}
    away = frozenset(people | {("robot_at", "r2d2", "hall")})
    with_walter = frozenset(people | {("robot_at", "r2d2", "sitting_room")})
    timeline = Timeline(
        samples=[Sample(0.0, away, (0.8, 2.0, 0.0)), Sample(5.0, with_walter, (6.0, 5.0, 0.0))]
    )
    timeline.end = 5.0
    assert judge(episode, timeline).achieved["entered_room"] == 1
    assert judge(replace(episode, person="rosa"), timeline).achieved["entered_room"] == 0


def test_a_bungalow_episode_runs_for_walter(tmp_path: Path) -> None:
    episode = generate_episode(load_world(BUNGALOW), BUNGALOW, 2, 13)
    assert episode.person == "walter" and episode.goals == ("(has walter pepper_mill)",)
    write_world_files(tmp_path, [episode])
    result = run_task(Task(episode.to_dict(), "oracle", "companion", str(tmp_path)))
    score = result["score"]
    assert result["understood"] == ["(has walter pepper_mill)"]
    assert score["achieved"]["entered_room"] == score["achieved"]["brought"] == 1
    assert any(d.startswith("entered_room: robot in walter's room") for d in score["details"])
    assert any(d == "brought: (has walter pepper_mill): yes" for d in score["details"])
    trace = [
        json.loads(line) for line in (tmp_path / "traces" / "ep013_oracle.jsonl").read_text().splitlines()
    ]
    calls = [e["reason"] for e in trace if e["kind"] == "task" and e["action"] == "call"]
    assert calls == ["walter calls from sitting_room"]


def test_the_command_line_refuses_a_person_the_world_lacks(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["bench", "granny-annie", "--world", BUNGALOW, "--person", "annie", "--out", "/nonexistent/x"]
    )
    err = capsys.readouterr().err.strip()
    assert code != 0 and len(err.splitlines()) == 1
    assert "no known person 'annie' to serve (known: walter, rosa)" in err


def test_knic_run_says_the_erl_task_scenario_is_not_the_bungalows(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--scenario", "granny_annie", "--world", BUNGALOW])
    err = capsys.readouterr().err.strip()
    assert code != 0 and len(err.splitlines()) == 1
    assert "scenario granny_annie is written for world erl_home, not bungalow" in err
    assert f"knic bench granny-annie --world {BUNGALOW}" in err
