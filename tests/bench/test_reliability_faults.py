"""Fault injection at the robot seam and in the planner, and the soak: what ``knic bench reliability``
reports about the closed loop (short runs; the benchmark itself runs every fault and an hour)."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from core.robot import NavState, Robot
from knic.bench.reliability_faults import FaultyRobot, InjectedFault, fault_runs
from knic.bench.reliability_soak import soak
from worlds.simulation import Simulation


@pytest.fixture
def sim() -> Iterator[Simulation]:
    simulation = Simulation("erl_home_paper", seed=0)
    yield simulation
    simulation.close()


def test_the_faulty_robot_is_a_robot(sim: Simulation) -> None:
    robot: Robot = FaultyRobot(sim, None)
    assert isinstance(robot, Robot)
    assert robot.robot_name == sim.robot_name and robot.time == sim.time


def test_a_hung_goal_stays_active_and_the_base_stays_put_until_stopped(sim: Simulation) -> None:
    robot = FaultyRobot(sim, "action_hangs", after_s=0.0)
    before = sim.robot_pose()
    goal = robot.navigate_to_room("kitchen")
    for _ in range(100):
        sim.step(0.1)
    status = robot.nav_status()
    assert (status.goal_id, status.state) == (goal, NavState.ACTIVE)
    assert sim.robot_pose().distance_to(before.x, before.y) < 0.2
    robot.stop()
    assert robot.nav_status().goal_id != goal
    again = robot.navigate_to_room("kitchen")  # the fault fired once: the next goal runs
    assert sim.nav_status().goal_id == again


def test_raises_and_false_fire_once(sim: Simulation) -> None:
    raising = FaultyRobot(sim, "action_raises", after_s=0.0)
    with pytest.raises(InjectedFault):
        raising.navigate_to_room("kitchen")
    assert raising.fired_at == 0.0
    assert raising.navigate_to_room("kitchen") == sim.nav_status().goal_id
    failing = FaultyRobot(sim, "action_false", after_s=0.0)
    result = failing.pick("glasses")
    assert not result.ok and "injected" in result.reason
    assert "injected" not in failing.pick("glasses").reason


def test_a_localisation_dropout_repeats_the_last_estimate_then_ends(sim: Simulation) -> None:
    robot = FaultyRobot(sim, "localisation_dropout", after_s=1.0, dropout_s=5.0)
    sim.step(1.0)
    frozen = robot.robot_pose()
    sim.step(2.0)
    assert robot.robot_pose() == frozen  # stale stamp included
    sim.step(4.0)
    fresh = robot.robot_pose()
    assert fresh.stamp == pytest.approx(sim.time) and fresh.stamp > frozen.stamp


@pytest.mark.parametrize("fault", ["localisation_dropout", "planner_dies"])
def test_the_goal_is_reached_after_the_fault(fault: str) -> None:
    figures = fault_runs((fault,), max_sim_time=400.0)
    episode = figures["episodes"][fault]
    assert episode["injected"], episode
    assert episode["goal_reached"] and episode["recovered"], episode
    assert episode["replans"] >= 1  # the fault was noticed and planned around
    assert (figures["injected"], figures["recovered"], figures["crashed"]) == (1, 1, 0)


def test_a_short_soak_runs_errands_and_samples_memory() -> None:
    figures = soak(60.0, sample_s=10.0)
    assert figures["sim_s"] >= 60.0
    assert figures["errands"] >= 1 and figures["samples"] >= 5
    assert 0 < figures["rss_start_mb"] <= figures["rss_peak_mb"]
    assert figures["journal_events"] > 0
