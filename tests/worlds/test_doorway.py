"""A person standing in a doorway: the robot waits, finds no way around, asks them to make way, and passes
without touching them; someone who does not move makes the goal fail after a bounded wait, never a push."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from core.robot import NavState
from worlds.loader import world_from_dict
from worlds.model import RobotSpec
from worlds.sim.navigation import GridMap
from worlds.sim.robot import GIVE_UP_AFTER, BaseController
from worlds.simulation import Simulation

BEDROOM_DOOR = (4.0, 7.0)  # the bedroom's only door (hallway side x < 4 is the bedroom)


def _run(sim: Simulation, limit: float = 120.0) -> list[float]:
    """Step until the goal ends; the robot's closest distance to Tracy at each step."""
    gaps = []
    while sim.nav_status().state is NavState.ACTIVE and sim.time < limit:
        sim.step(0.1)
        robot, tracy = sim.true_robot_pose(), sim.true_pose("tracy").position
        gaps.append(math.hypot(robot.x - tracy[0], robot.y - tracy[1]))
    return gaps


def test_a_person_in_the_only_doorway_is_asked_and_steps_aside(
    make_sim: Callable[..., Simulation], doc: dict[str, Any]
) -> None:
    tracy = next(p for p in doc["people"] if p["name"] == "tracy")
    tracy["position"] = list(BEDROOM_DOOR)
    sim = make_sim(world_from_dict(doc))
    sim.navigate_to_room("bedroom")
    gaps = _run(sim)
    status = sim.nav_status()
    assert status.state is NavState.SUCCEEDED, status.reason
    truth = sim.ground_truth_facts()
    assert ("robot_at", "r2d2", "bedroom") in truth
    # she was asked once, moved off the doorway, and the robot never touched her nor anything else
    assert [u.text for u in sim.spoken()] == ["Excuse me, may I pass?"]
    where = sim.true_pose("tracy").position
    assert math.hypot(where[0] - BEDROOM_DOOR[0], where[1] - BEDROOM_DOOR[1]) > 0.5
    radius = sim.world.robot.radius + sim.world.people["tracy"].radius
    assert min(gaps) >= radius - 1e-6
    counters = sim.counters()
    assert counters.person_hits == 0 and counters.bumps == 0


def test_a_person_in_a_doorway_with_a_way_around_is_not_asked(
    make_sim: Callable[..., Simulation], doc: dict[str, Any]
) -> None:
    tracy = next(p for p in doc["people"] if p["name"] == "tracy")
    tracy["position"] = [6.0, 8.0]  # the hallway-kitchen door; the kitchen is also reached by the dining room
    sim = make_sim(world_from_dict(doc))
    sim.navigate_to_room("kitchen")
    gaps = _run(sim)
    assert sim.nav_status().state is NavState.SUCCEEDED, sim.nav_status().reason
    assert ("robot_at", "r2d2", "kitchen") in sim.ground_truth_facts()
    assert sim.spoken() == []  # it went round, nobody was bothered
    assert min(gaps) >= sim.world.robot.radius + sim.world.people["tracy"].radius - 1e-6
    assert sim.counters().person_hits == 0 and sim.counters().bumps == 0


def test_a_person_who_does_not_move_fails_the_goal_after_a_bounded_wait(
    make_sim: Callable[..., Simulation],
) -> None:
    sim = make_sim("erl_home")  # only its grid and robot: the base alone, with a person who never moves
    spec: RobotSpec = sim.world.robot
    base = BaseController(spec, GridMap.from_world(sim.world))
    asked: list[str] = []
    base.ask_way = lambda person, path: asked.append(person)
    people = [("statue", BEDROOM_DOOR[0], BEDROOM_DOOR[1], 0.25)]
    base.start_goal("room bedroom", [(3.0, 6.2)], lambda _x, _y: None)
    t = 0.0
    closest = math.inf
    while base.status().state is NavState.ACTIVE and t < 120.0:
        base.update(0.05, people, lambda _x, _y: True)
        t += 0.05
        closest = min(closest, math.hypot(base.x - BEDROOM_DOOR[0], base.y - BEDROOM_DOOR[1]))
    status = base.status()
    assert status.state is NavState.FAILED and status.reason == "path blocked by statue"
    assert asked == ["statue"]  # asked once, then waited
    assert t < 60.0 + GIVE_UP_AFTER  # bounded: the approach plus the wait
    assert closest >= spec.radius + 0.25 - 1e-6  # never pushed into them
