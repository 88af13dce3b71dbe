"""Bumps into furniture and hits on people are counted once per contact; the base stops at contact."""

from __future__ import annotations

import math
from collections.abc import Callable

from core.robot import NavState
from worlds.simulation import Simulation


def drive(sim: Simulation, linear: float, seconds: float) -> None:
    sim.set_base_velocity(linear, 0.0)
    sim.step(seconds)
    sim.stop()


def face(sim: Simulation, x: float, y: float, yaw: float) -> None:
    sim.navigate_to_point(x, y, yaw)
    while sim.nav_status().state is NavState.ACTIVE and sim.time < 120:
        sim.step(0.5)
    assert sim.nav_status().state is NavState.SUCCEEDED


def test_bumps_into_furniture_are_counted(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    face(sim, 4.8, 1.0, 0.0)  # facing the entrance shelf (west edge at x = 5.55)
    drive(sim, 0.4, 4.0)
    assert sim.counters().bumps == 1
    pose = sim.true_robot_pose()
    shelf = sim.world.furniture["entrance_shelf"]
    assert shelf.distance(pose.x, pose.y) >= sim.world.robot.radius - 0.021  # stopped at the bumper
    drive(sim, 0.4, 2.0)  # still pushing: the same contact
    assert sim.counters().bumps == 1
    drive(sim, -0.3, 1.0)
    drive(sim, 0.3, 2.0)
    assert sim.counters().bumps == 2
    assert sim.counters().person_hits == 0


def test_hits_on_people_are_counted(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    tracy = sim.true_pose("tracy").position
    face(sim, tracy[0], tracy[1] - 1.3, math.pi / 2)
    drive(sim, 0.5, 3.0)
    assert sim.counters().person_hits == 1
    assert sim.counters().bumps == 0


def test_navigation_waits_for_people_rather_than_hitting_them(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home", scenario="visitors", seed=3)
    sim.navigate_to_room("living_room")
    while sim.time < 150:
        sim.step(0.5)
        if sim.nav_status().state is not NavState.ACTIVE:
            sim.navigate_to_room(
                "entrance_hall" if sim.nav_status().target.endswith("living_room") else "living_room"
            )
    assert sim.counters().person_hits == 0
    assert sim.counters().bumps == 0
