"""The Granny Annie episode generator: deterministic per (seed, index), driven by the world's data and priors,
its commands understood as the goals it wrote, and worlds without priors supported."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

from knic.bench.granny_annie.commands import candidate_requests, requests_of_text
from knic.bench.granny_annie.episodes import Episode, generate_episode, generate_episodes, world_vocabulary
from knic.bench.granny_annie.events import MOVE_AT, VISITOR_AT, WALK_AT
from knic.bench.granny_annie.placement import graspable, under_sitter, world_document
from knic.language.understanding import understand
from knic.language.vocabulary import Vocabulary
from worlds.api import load_world
from worlds.loader import world_from_dict
from worlds.model import World
from worlds.scenario import scenario_from_dict


@pytest.fixture(scope="module")
def world() -> World:
    return load_world("erl_home")


@pytest.fixture(scope="module")
def vocab(world: World) -> Vocabulary:
    return world_vocabulary(world)


@pytest.fixture(scope="module")
def episodes(world: World, vocab: Vocabulary) -> list[Episode]:
    return [generate_episode(world, "erl_home", 7, i, vocab) for i in range(40)]


def test_same_seed_and_index_give_the_same_episode(world: World, vocab: Vocabulary) -> None:
    first = [generate_episode(world, "erl_home", 3, i, vocab).to_dict() for i in range(6)]
    again = [generate_episode(world, "erl_home", 3, i, vocab).to_dict() for i in range(6)]
    assert first == again
    # episode i does not depend on how many episodes are drawn, and other seeds differ
    assert generate_episodes("erl_home", 3, 3)[2].to_dict() == first[2]
    other = [generate_episode(world, "erl_home", 4, i, vocab).to_dict() for i in range(6)]
    assert [e["text"] for e in other] != [e["text"] for e in first]
    # the JSON form round-trips
    assert Episode.from_dict(first[4]).to_dict() == first[4]


def test_episodes_cover_the_task(world: World, episodes: list[Episode]) -> None:
    kinds = {r.kind for e in episodes for r in e.requests}
    assert kinds == {"device", "find", "bring", "accompany"}
    assert {len(e.requests) for e in episodes} == {1, 2, 3}
    assert {e.person_on for e in episodes} == {"bed", "sofa"}
    assert all(e.person_room == world.furniture[e.person_on].room for e in episodes if e.person_on)
    spoken = [e for e in episodes if e.audio is not None]
    assert spoken and all(Path(e.audio).is_file() for e in spoken if e.audio)
    assert any(e.off_prior for e in episodes)
    for e in episodes:
        for item in e.off_prior:
            assert e.placements[item] not in {p.furniture for p in world.items[item].priors}
        for item, furniture in e.placements.items():
            assert graspable(world, e.placements, item), (e.index, item, furniture)
            assert not under_sitter(world, e.placements, item, e.person, e.person_on), (e.index, item)
    types = {ev["type"] for e in episodes for ev in e.after_command}
    assert {"person_to", "doorbell", "move_object"} <= types
    for e in episodes:  # every episode's events are a valid scenario of the world
        scenario_from_dict(e.scenario(), world)
        scenario_from_dict(e.later_scenario(), world)
        # at the start only Annie's seat; the rest is timed from the command, while the robot works
        assert [(ev["at"], ev["person"]) for ev in e.events] == [(0.0, "annie")]
        windows = {"doorbell": VISITOR_AT, "move_object": MOVE_AT, "person_to": WALK_AT}
        assert all(windows[ev["type"]][0] <= ev["at"] <= windows[ev["type"]][1] for ev in e.after_command)
        targets = [t for r in e.requests for t in r.targets]
        assert len(targets) == len(set(targets))
        assert sum(r.kind == "bring" for r in e.requests) <= 1  # a person holds one object
        for item in e.placements:  # low enough for the gripper
            assert world.furniture[e.placements[item]].height + world.items[item].size[2] / 2 <= 1.6


def test_device_and_accompany_requests_cannot_hold_at_the_start(
    world: World, episodes: list[Episode]
) -> None:
    for e in episodes:
        for r in e.requests:
            if r.kind == "device" and r.goals[0].startswith("(light_on"):
                assert all(not world.devices[d].initial for d in r.targets)
            if r.kind == "accompany":
                assert world.room_of(*world.people[r.targets[0]].position) != r.room


def test_generated_commands_are_understood_as_the_goals_written(
    vocab: Vocabulary, episodes: list[Episode]
) -> None:
    understood = [sorted(str(g) for g in understand(e.text, vocab, speaker="annie").goals) for e in episodes]
    right = [u == sorted(e.goals) for u, e in zip(understood, episodes, strict=True)]
    singles = [ok for ok, e in zip(right, episodes, strict=True) if len(e.requests) == 1]
    assert all(singles)
    assert sum(right) >= 0.85 * len(right)


def test_bank_commands_read_back_into_requests(world: World, vocab: Vocabulary) -> None:
    placements = {"apple": "kitchen_cabinet", "remote": "coffee_table", "glasses": "bedside_table"}
    candidates = candidate_requests(world, vocab, placements, "annie")
    chain = requests_of_text(
        "switch on the hallway light, find the remote and bring me my glasses", candidates
    )
    assert chain is not None
    assert [r.goals for r in chain] == [
        ("(light_on hallway_light)",),
        ("(reported remote)",),
        ("(has annie glasses)",),
    ]
    source = requests_of_text("bring me an apple from the kitchen cabinet", candidates)
    assert source is not None and source[0].goals == (
        "(has annie apple)",
        "(taken_from apple kitchen_cabinet)",
    )
    assert requests_of_text("bring me an apple from the bed", candidates) is None  # not where it stands
    assert requests_of_text("locate the tablet and bring it to me", candidates) is None  # pronoun
    assert requests_of_text("bring me the remote and get me the apple", candidates) is None  # one bring


def test_episode_world_file_puts_items_where_the_episode_says(world: World, episodes: list[Episode]) -> None:
    e = episodes[0]
    episode_world = world_from_dict(world_document(world, e.placements))
    assert {n: it.on for n, it in episode_world.items.items()} == e.placements
    assert episode_world.items["glasses"].priors == world.items["glasses"].priors  # the robot's priors stay


def _without(world: World, tmp_path: Path, *, priors: bool, devices: bool, people: bool) -> Path:
    assert world.source is not None
    data = yaml.safe_load(world.source.read_text(encoding="utf-8"))
    for entry in data["items"] + data["people"]:
        if not priors:
            entry.pop("priors", None)
    if not devices:
        data["devices"] = [d for d in data["devices"] if d["type"] == "bell"]
    if not people:
        data["people"] = [p for p in data["people"] if p["name"] == "annie"]
    path = tmp_path / "flat.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    return path


def test_a_world_without_priors_devices_or_other_people_works(world: World, tmp_path: Path) -> None:
    path = _without(world, tmp_path, priors=False, devices=False, people=False)
    flat = load_world(path)
    eps = generate_episodes(str(path), 12, 0)
    assert {r.kind for e in eps for r in e.requests} <= {"find", "bring"}
    assert all(e.person_on in ("bed", "sofa") for e in eps)
    for e in eps:
        for item, furniture in e.placements.items():  # without priors: the file's place unless off-prior
            assert (furniture == flat.items[item].on) != (item in e.off_prior)
        assert not any(ev["type"] in ("doorbell", "move_object") for ev in e.after_command)
        scenario_from_dict(e.scenario(), flat)
        scenario_from_dict(e.later_scenario(), flat)


def test_requests_name_only_people_the_robot_knows(world: World, episodes: list[Episode]) -> None:
    from dataclasses import replace

    from knic.bench.granny_annie.commands import draw_requests

    assert not world.people["jack"].known  # the door-bell visitor is a stranger to the robot
    visits = [ev for e in episodes for ev in e.after_command if ev["type"] == "doorbell"]
    assert visits and {ev["visitor"] for ev in visits} == {"jack"}  # he still rings (the truth's name)
    assert "jack" not in {t for e in episodes for r in e.requests for t in r.targets}
    # even standing in the living room, a stranger is never led anywhere; once known, he may be
    inside = replace(world.people["jack"], position=(8.0, 2.6), present=True)
    for known in (False, True):
        jack = replace(inside, known=known)
        w = replace(world, people={**world.people, "jack": jack})
        vocab = world_vocabulary(w)
        placements = {i: it.on for i, it in w.items.items() if it.on}
        led: set[str] = set()
        for i in range(60):
            requests = draw_requests(w, vocab, np.random.default_rng([11, i]), placements, "annie")
            led |= {t for r in requests if r.kind == "accompany" for t in r.targets}
        assert ("jack" in led) is known, (known, led)
