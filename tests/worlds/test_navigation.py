"""The robot reaches every room from its start, without bumping into anything."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from core.robot import NavState
from worlds.simulation import Simulation

ROOMS = ["entrance_hall", "hallway", "living_room", "dining_room", "kitchen", "bedroom", "bathroom"]


def run_until_done(sim: Simulation, limit: float = 120.0) -> None:
    start = sim.time
    while sim.nav_status().state is NavState.ACTIVE and sim.time - start < limit:
        sim.step(0.5)


@pytest.mark.parametrize("room", ROOMS)
def test_robot_reaches_every_room_from_the_start(make_sim: Callable[..., Simulation], room: str) -> None:
    sim = make_sim("erl_home")
    sim.navigate_to_room(room)
    run_until_done(sim)
    status = sim.nav_status()
    assert status.state is NavState.SUCCEEDED, status.reason
    assert ("robot_at", "r2d2", room) in sim.ground_truth_facts()
    assert sim.counters().bumps == 0
    assert sim.counters().person_hits == 0


def test_paper_world_tour(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home_paper")
    for room in ["kitchen", "entrance", "living_room", "bedroom"]:
        sim.navigate_to_room(room)
        run_until_done(sim)
        assert sim.nav_status().state is NavState.SUCCEEDED
        assert ("robot_at", "r2d2", room) in sim.ground_truth_facts()
    assert sim.counters().bumps == 0


def test_goal_status_and_preemption(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    first = sim.navigate_to_room("kitchen")
    sim.step(1.0)
    assert sim.nav_status().state is NavState.ACTIVE
    assert sim.nav_status().path, "an active goal exposes its planned path"
    second = sim.navigate_to_furniture("bed")
    assert second == first + 1
    run_until_done(sim)
    status = sim.nav_status()
    assert status.state is NavState.SUCCEEDED and status.goal_id == second
    pose = sim.true_robot_pose()
    assert sim.world.furniture["bed"].distance(pose.x, pose.y) <= sim.world.robot.reach
    sim.navigate_to_room("bathroom")
    sim.step(0.5)
    sim.stop()
    assert sim.nav_status().state is NavState.CANCELLED and sim.nav_status().reason == "stopped"


def test_unreachable_point_fails_with_a_reason(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    sim.navigate_to_point(1.05, 7.5)  # the middle of the bed
    assert sim.nav_status().state is NavState.FAILED
    assert "not free" in sim.nav_status().reason
