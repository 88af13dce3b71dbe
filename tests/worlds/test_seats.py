"""People at furniture: they sit or lie on a bed, a sofa, an armchair; at a table or a counter (too high to
sit on) they stand beside it on the floor, in its room and clear of every piece of furniture."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from core.errors import WorldError
from worlds.loader import world_from_dict
from worlds.scenario import scenario_from_dict
from worlds.simulation import Simulation

BUNGALOW = str(Path(__file__).resolve().parents[2] / "worlds" / "test_bungalow" / "test_bungalow.yaml")


def _tracy_at(doc: dict[str, Any], furniture: str) -> dict[str, Any]:
    tracy = next(p for p in doc["people"] if p["name"] == "tracy")
    tracy.pop("position", None)
    tracy["furniture"] = furniture
    return doc


def test_a_person_at_a_table_stands_beside_it(doc: dict[str, Any]) -> None:
    world = world_from_dict(_tracy_at(doc, "dining_table"))
    tracy, table = world.people["tracy"], world.furniture["dining_table"]
    assert tracy.on is None
    assert world.room_of(*tracy.position) == "dining_room"
    assert all(f.distance(*tracy.position) >= tracy.radius for f in world.furniture.values())
    assert table.distance(*tracy.position) < 0.5  # beside it, not somewhere else in the room


def test_a_person_on_the_sofa_sits_on_it(doc: dict[str, Any]) -> None:
    world = world_from_dict(_tracy_at(doc, "sofa"))
    assert world.people["tracy"].on == "sofa"
    assert world.people["tracy"].position == world.furniture["sofa"].position


def test_no_room_beside_a_table_is_one_clear_error(doc: dict[str, Any]) -> None:
    # the bathroom drawer stands against two walls; two low chests take its two free sides
    doc["furniture"].append(
        {"name": "chest", "room": "bathroom", "position": [0.5, 3.0], "size": [1.0, 0.5, 0.4]}
    )
    doc["furniture"].append(
        {"name": "box", "room": "bathroom", "position": [1.3, 2.35], "size": [0.3, 0.5, 0.4]}
    )
    with pytest.raises(WorldError, match=re.escape("no free place beside 'bathroom_drawer'")) as info:
        world_from_dict(_tracy_at(doc, "bathroom_drawer"), file="bad.yaml")
    assert "\n" not in str(info.value)


def test_sent_to_a_table_a_person_stands_on_the_floor(
    make_sim: Callable[..., Simulation], doc: dict[str, Any]
) -> None:
    world = world_from_dict(doc)
    events = [
        {"at": 0, "type": "person_to", "person": "annie", "furniture": "kitchen_table", "teleport": True},
        {"at": 0, "type": "person_to", "person": "tracy", "furniture": "dining_table"},
    ]
    sim = make_sim(world, scenario=scenario_from_dict({"name": "tables", "events": events}, world))
    sim.step(60.0)
    for person, table in (("annie", "kitchen_table"), ("tracy", "dining_table")):
        x, y, z = sim.true_pose(person).position
        assert z == 0.0  # on the floor, not on the table top
        assert world.furniture[table].distance(x, y) > 0.1
        assert ("person_at", person, world.furniture[table].room) in sim.ground_truth_facts()


def test_a_person_sits_beside_what_lies_on_the_seat(
    make_sim: Callable[..., Simulation], doc: dict[str, Any]
) -> None:
    remote = next(i for i in doc["items"] if i["name"] == "remote")
    remote["furniture"] = "sofa"  # alone on the sofa: in its middle
    world = world_from_dict(_tracy_at(doc, "sofa"))
    tracy, item = world.people["tracy"], world.items["remote"]
    assert tracy.on == "sofa" and tracy.position != world.furniture["sofa"].position
    assert math.dist(tracy.position, item.position[:2]) > tracy.radius + max(item.size[:2]) / 2
    events = [{"at": 0, "type": "person_to", "person": "annie", "furniture": "sofa", "teleport": True}]
    sim = make_sim(world, scenario=scenario_from_dict({"name": "sofa", "events": events}, world))
    sim.step(1.0)
    annie = sim.true_pose("annie").position
    assert annie[2] == world.furniture["sofa"].height  # on the sofa
    tracy_now = sim.true_pose("tracy").position
    for who in (annie, tracy_now):  # neither sits on the remote
        assert math.dist(who[:2], sim.true_pose("remote").position[:2]) > 0.22 + 0.08
    assert math.dist(annie[:2], tracy_now[:2]) > 2 * 0.22  # nor on each other


def test_a_seated_person_escorted_gets_up_clear_of_the_robot() -> None:
    # walter sits in the bungalow's armchair, in a corner; the robot comes up close and asks him to follow
    # (getting up, he used to land on the nearest free point beside the chair: where the robot stood)
    from knic.system import build_system

    system = build_system(["(person_at walter hall)"], world=BUNGALOW, seed=1)
    try:
        system.run()
        assert system.sim.counters().person_hits == 0
        assert ("person_at", "walter", "hall") in system.sim.ground_truth_facts()
    finally:
        system.close()
