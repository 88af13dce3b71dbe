"""Scenario events happen as written: door bell and visitors, objects moved by people, random placement."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import pytest

from core.errors import WorldError
from core.robot import NavState
from worlds.model import World
from worlds.scenario import SCENARIO_DIR, load_scenario, scenario_from_dict
from worlds.simulation import Simulation


def test_every_shipped_scenario_is_valid(erl_world: World) -> None:
    names = sorted(p.stem for p in SCENARIO_DIR.glob("*.yaml"))
    assert {"visitors", "moved_object", "random_placement", "annie_on_sofa"} <= set(names)
    for name in names:
        assert load_scenario(name, erl_world).events


def test_doorbell_and_visitor(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home", scenario="visitors")
    sim.navigate_to_room("hallway")  # out of the visitor's way
    sim.step(19.0)
    assert sim.poll_sounds() == []
    assert not sim.person_present("jack")
    sim.step(1.5)
    sounds = sim.poll_sounds()
    assert [s.kind for s in sounds] == ["doorbell"]
    assert sounds[0].position == sim.world.devices["door_bell"].position
    made = sim.sounds_made()  # who rang is the oracle's to tell
    assert [(m.kind, m.emitter, m.stamp) for m in made] == [("doorbell", "door_bell", sounds[0].stamp)]
    assert ("sound_at", "doorbell", "entrance_hall") in sim.ground_truth_facts()
    assert sim.poll_sounds() == []
    sim.step(3.0)
    assert ("sound_at", "doorbell", "entrance_hall") not in sim.ground_truth_facts()
    while sim.time < 80:
        sim.step(1.0)
    assert ("person_at", "jack", "living_room") in sim.ground_truth_facts()


def test_person_moves_an_object(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home", scenario="moved_object")
    carried = False
    while sim.time < 90:
        sim.step(1.0)
        carried |= ("has", "tracy", "glasses") in sim.ground_truth_facts()
    facts = sim.ground_truth_facts()
    assert carried
    assert {("object_on", "glasses", "dining_table"), ("object_at", "glasses", "dining_room")} <= facts


def test_a_person_who_cannot_reach_the_furniture_meant_puts_the_object_down_nearby(
    make_sim: Callable[..., Simulation],
) -> None:
    """The cellar's crate cannot be reached (no door): olga does not carry the book for good, she puts it on
    furniture she can reach."""
    from worlds.api import load_world

    flat = load_world(Path(__file__).resolve().parents[2] / "worlds" / "test_flat" / "test_flat.yaml")
    move = {"at": 1, "type": "move_object", "person": "olga", "item": "book", "to": "crate"}
    sim = make_sim(flat, scenario=scenario_from_dict({"name": "unreachable", "events": [move]}, flat))
    start = sim.true_pose("book").position
    sim.step(60.0)
    facts = sim.ground_truth_facts()
    assert sim.true_pose("book").position != start  # taken and put down again
    assert ("has", "olga", "book") not in facts
    on = {f[2] for f in facts if f[0] == "object_on" and f[1] == "book"}
    assert on and "crate" not in on


def test_annie_on_the_sofa_speaks(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home", scenario="annie_on_sofa")
    assert ("person_at", "annie", "living_room") in sim.ground_truth_facts()
    sim.step(1.5)
    [said] = sim.poll_utterances()
    assert (said.speaker, said.text) == ("annie", "bring me my glasses")


def _placement(make_sim: Callable[..., Simulation], seed: int) -> dict[str, tuple[float, ...]]:
    sim = make_sim("erl_home", scenario="random_placement", seed=seed)
    return {name: sim.true_pose(name).position for name in sim.world.items}


def test_random_placement_follows_the_seed(make_sim: Callable[..., Simulation]) -> None:
    first = _placement(make_sim, 7)
    assert first == _placement(make_sim, 7)
    assert first != _placement(make_sim, 8)
    sim = make_sim("erl_home", scenario="random_placement", seed=7)
    for item in sim.world.items.values():
        on = [f[2] for f in sim.ground_truth_facts() if f[0] == "object_on" and f[1] == item.name]
        assert on and on[0] in {p.furniture for p in item.priors}


def test_randomly_placed_items_are_within_the_robots_reach(make_sim: Callable[..., Simulation]) -> None:
    for seed in (11, 12, 13):
        sim = make_sim("erl_home", scenario="random_placement", seed=seed)
        reach = sim.world.robot.reach
        for fact in sim.ground_truth_facts():
            if fact[0] != "object_on":
                continue
            x, y, _ = sim.true_pose(fact[1]).position
            stands = sim.approach_points(fact[2], reach=reach)
            assert min(math.hypot(sx - x, sy - y) for sx, sy in stands) <= reach - 0.1, (seed, fact)


def test_invalid_scenarios_are_rejected(erl_world: World, tmp_path: Path) -> None:
    with pytest.raises(WorldError, match=r"bad.yaml: events\[0\]: unknown person 'nick'"):
        scenario_from_dict(
            {"name": "x", "events": [{"at": 1, "type": "say", "person": "nick", "text": "hi"}]},
            erl_world,
            file="bad.yaml",
        )
    with pytest.raises(WorldError, match=r"events\[0\]: missing field 'to' for a move_object event"):
        scenario_from_dict(
            {"name": "x", "events": [{"at": 1, "type": "move_object", "person": "tracy", "item": "mug"}]},
            erl_world,
        )
    with pytest.raises(WorldError, match="unknown scenario 'nope'"):
        load_scenario("nope", erl_world)


def test_robot_escorts_a_person(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    sim.navigate_to_person("tracy")
    while sim.nav_status().state is NavState.ACTIVE:
        sim.step(0.5)
    assert sim.escort("tracy").ok
    sim.navigate_to_room("hallway")
    while sim.nav_status().state is NavState.ACTIVE and sim.time < 200:
        sim.step(0.5)
    sim.step(5.0)
    sim.stop_escort()
    assert {("robot_at", "r2d2", "hallway"), ("person_at", "tracy", "hallway")} <= sim.ground_truth_facts()
    assert sim.counters().person_hits == 0
