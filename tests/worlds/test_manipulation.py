"""Pick, place, release and give change the ground truth as the ERL domain says."""

from __future__ import annotations

import math
from collections.abc import Callable

from core.robot import NavState
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
