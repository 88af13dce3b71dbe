"""Pick, place, release and give change the ground truth as the ERL domain says."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from core.errors import WorldError
from core.robot import CAUSE_NOT_AT_BELIEF, CAUSE_OUT_OF_REACH, NavState
from worlds.simulation import Simulation


def arrive(sim: Simulation) -> None:
    while sim.nav_status().state is NavState.ACTIVE and sim.time < 300:
        sim.step(0.5)
    assert sim.nav_status().state is NavState.SUCCEEDED, sim.nav_status().reason


def about(sim: Simulation, item: str) -> set[tuple[str, ...]]:
    return {f for f in sim.ground_truth_facts() if item in f[1:] or f[0] in ("hand_empty", "holding")}


def test_pick_and_place(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    assert about(sim, "glasses") == {
        ("object_at", "glasses", "kitchen"),
        ("object_on", "glasses", "kitchen_table"),
        ("hand_empty", "r2d2"),
    }
    far = sim.pick("glasses")
    assert not far.ok and "reach" in far.reason
    glasses = sim.true_pose("glasses").position
    sim.navigate_to_furniture("kitchen_table", near=(glasses[0], glasses[1]))
    arrive(sim)
    assert sim.pick("glasses").ok
    assert sim.held_item() == "glasses"
    assert about(sim, "glasses") == {("holding", "r2d2", "glasses")}
    busy = sim.pick("juice")
    assert not busy.ok and "not empty" in busy.reason
    sim.step(1.0)
    assert sim.place("kitchen_table").ok
    assert about(sim, "glasses") == {
        ("object_at", "glasses", "kitchen"),
        ("object_on", "glasses", "kitchen_table"),
        ("hand_empty", "r2d2"),
    }
    far_place = sim.place("bed")
    assert not far_place.ok and "hand is empty" in far_place.reason


def test_release_in_mid_air_drops_the_object(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    mug = sim.true_pose("mug").position
    sim.navigate_to_furniture("kitchen_counter", near=(mug[0], mug[1]))
    arrive(sim)
    assert sim.pick("mug").ok
    sim.navigate_to_point(7.0, 7.2, math.pi)  # the gripper over the free floor
    arrive(sim)
    assert sim.release().ok
    assert sim.counters().drops == 1
    sim.step(1.0)
    assert sim.true_pose("mug").position[2] < 0.1
    assert about(sim, "mug") == {("object_at", "mug", "kitchen"), ("hand_empty", "r2d2")}


def test_give_to_annie(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    tissues = sim.true_pose("tissues").position
    sim.navigate_to_furniture("bedside_table", near=(tissues[0], tissues[1]))
    arrive(sim)
    assert sim.pick("tissues").ok
    sim.navigate_to_person("annie")
    arrive(sim)
    assert sim.give("annie").ok
    facts = sim.ground_truth_facts()
    assert ("has", "annie", "tissues") in facts
    assert ("hand_empty", "r2d2") in facts
    assert not any(f[0] in ("object_at", "object_on") and f[1] == "tissues" for f in facts)
    assert ("robot_at", "r2d2", "bedroom") in facts and ("person_at", "annie", "bedroom") in facts


def test_devices(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    assert sim.set_light("bedroom_left_light", True).ok
    assert sim.set_level("living_room_dimmer", 60).ok
    assert sim.set_level("bedroom_blinds", 70).ok
    assert not sim.set_light("living_room_dimmer", True).ok
    facts = sim.ground_truth_facts()
    assert {
        ("light_on", "bedroom_left_light"),
        ("light_off", "bedroom_right_light"),
        ("device_level", "living_room_dimmer", "l50"),
        ("device_level", "bedroom_blinds", "l75"),
    } <= facts
    assert ("light_off", "bedroom_left_light") not in facts
    states = sim.device_states()
    assert states["bedroom_left_light"] is True and states["living_room_dimmer"] == 60.0
    sim.say("The light is on")
    assert [u.text for u in sim.spoken()] == ["The light is on"]


def test_pick_at_a_believed_position_needs_the_item_there(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    glasses = sim.true_pose("glasses").position
    sim.navigate_to_furniture("kitchen_table", near=(glasses[0], glasses[1]))
    arrive(sim)
    # a belief 0.3 m off along the table: the gripper closes on nothing, the glasses stay where they are
    wrong = (glasses[0] + 0.3, glasses[1], glasses[2])
    if math.hypot(wrong[0] - sim.true_robot_pose().x, wrong[1] - sim.true_robot_pose().y) > 0.9:
        wrong = (glasses[0] - 0.3, glasses[1], glasses[2])
    missed = sim.pick("glasses", wrong)
    assert not missed.ok and missed.cause == CAUSE_NOT_AT_BELIEF and "believed" in missed.reason
    assert sim.held_item() is None and ("object_on", "glasses", "kitchen_table") in sim.ground_truth_facts()
    # a belief beyond the arm's reach is refused as such
    far = sim.pick("glasses", (glasses[0] + 3.0, glasses[1], glasses[2]))
    assert not far.ok and far.cause == CAUSE_OUT_OF_REACH
    # a belief within the gripper's tolerance: grasped
    near = (glasses[0] + 0.05, glasses[1] - 0.04, glasses[2] + 0.05)
    assert sim.pick("glasses", near).ok and sim.held_item() == "glasses"


def test_localisation_error_becomes_grasp_error(make_sim: Callable[..., Simulation]) -> None:
    from worlds.api import NoiseConfig

    sim = make_sim("erl_home", noise=NoiseConfig.perfect())
    glasses = sim.true_pose("glasses").position
    sim.navigate_to_furniture("kitchen_table", near=(glasses[0], glasses[1]))
    arrive(sim)
    sim.noise = NoiseConfig(pose_noise_xy=0.5, pose_noise_yaw=0.0)
    est = sim.robot_pose()
    true = sim.true_robot_pose()
    # the true position, as the robot would place it through its (0.5 m off) estimate: the arm misses
    arm = sim.believed_to_true(glasses)
    assert arm is not None
    offset = math.hypot(est.x - true.x, est.y - true.y)
    assert math.hypot(arm[0] - glasses[0], arm[1] - glasses[1]) == pytest.approx(offset, abs=1e-6)
    # the same point expressed in the estimate's frame reaches the glasses
    believed = (glasses[0] + est.x - true.x, glasses[1] + est.y - true.y, glasses[2])
    assert sim.pick("glasses", believed).ok


def test_believed_position_must_be_three_finite_numbers(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home")
    with pytest.raises(WorldError, match="believed position"):
        sim.pick("glasses", (1.0, float("nan"), 0.5))
    assert sim.held_item() is None
