"""The camera sees what is in front of it and not what a wall hides; detections deproject to the object."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from worlds.api import NoiseConfig
from worlds.loader import world_from_dict
from worlds.simulation import Simulation

TWO_ROOMS: dict[str, Any] = {
    "name": "two_rooms",
    "rooms": [
        {"name": "front", "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]},
        {"name": "back", "polygon": [[4, 0], [8, 0], [8, 4], [4, 4]]},
    ],
    "doors": [{"rooms": ["front", "back"], "position": [4, 3.5], "width": 0.8}],
    "furniture": [
        {"name": "near_table", "room": "front", "position": [3.0, 1.0], "size": [0.6, 0.6, 0.7]},
        {"name": "far_table", "room": "back", "position": [5.5, 1.0], "size": [0.6, 0.6, 0.7]},
    ],
    "items": [
        {"name": "mug", "furniture": "near_table", "size": [0.1, 0.1, 0.12]},
        {"name": "apple", "furniture": "far_table", "size": [0.1, 0.1, 0.1]},
    ],
    "people": [{"name": "annie", "position": [2.5, 2.6]}],
    "robot": {"name": "r2d2", "start": [0.8, 1.0, 0]},
}


def _project(frame: Any, point: np.ndarray) -> tuple[float, float, float]:
    """Pixel (u, v) and optical depth of a world point."""
    rot = frame.camera_pose.rotation_matrix()
    p = rot.T @ (point - np.asarray(frame.camera_pose.position))
    k = frame.intrinsics
    return (k.fx * p[0] / p[2] + k.cx, k.fy * p[1] / p[2] + k.cy, float(p[2]))


def _visible(sim: Simulation) -> frozenset[str]:
    """The names the oracle says are in the latest frame."""
    truth = sim.frame_truth()
    assert truth is not None
    return truth.visible


def test_sees_the_object_in_front_not_the_one_behind_the_wall(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"))
    frame = sim.camera_frame()
    visible = _visible(sim)
    assert "mug" in visible
    assert "apple" not in visible
    # the apple is inside the field of view: only the wall hides it
    u, v, z = _project(frame, np.array(sim.true_pose("apple").position))
    assert 0 <= u < frame.width and 0 <= v < frame.height and 0 < z < frame.intrinsics.far
    labels = {d.label for d in frame.detections}
    assert "mug" in labels and "apple" not in labels


def test_detection_points_are_on_the_object_in_the_world_frame(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"))
    frame = sim.camera_frame()
    mug = next(d for d in frame.detections if d.label == "mug")
    pts = frame.points_world(mug, max_points=20)
    assert 0 < len(pts) <= 20
    true = np.array(sim.true_pose("mug").position)
    assert np.all(np.linalg.norm(pts - true, axis=1) < 0.12)
    assert frame.rgb.shape == (120, 160, 3) and frame.depth.shape == (120, 160)


def test_people_are_recognised_and_pan_changes_the_view(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"))
    sim.pan_camera(np.pi / 4)  # annie is ahead to the left, the mug straight ahead
    sim.step(0.1)
    frame = sim.camera_frame()
    person = [d for d in frame.detections if d.label == "person"]
    assert [d.identity for d in person] == ["annie"]
    assert "mug" not in _visible(sim)


def test_noise_misses_and_false_positives(make_sim: Callable[..., Simulation]) -> None:
    world = world_from_dict(TWO_ROOMS, file="two_rooms.yaml")
    blind = make_sim(world, noise=NoiseConfig(miss_rate=1.0, false_positive_rate=0.0))
    assert blind.camera_frame().detections == []
    assert "mug" in _visible(blind)
    noisy = make_sim(world, noise=NoiseConfig(miss_rate=0.0, false_positive_rate=1.0, confusion_rate=1.0))
    frame = noisy.camera_frame()
    truth = noisy.frame_truth()
    assert truth is not None and truth.stamp == frame.stamp and len(truth.detected) == len(frame.detections)
    behind = dict(zip(truth.detected, frame.detections, strict=True))
    spurious = behind[None]
    assert [d for d in truth.detected if d is None] == [None] and spurious.mask.any()
    assert behind["mug"].label != "mug"


def test_the_frame_truth_stays_with_the_oracle(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"))
    assert sim.frame_truth() is None  # nothing rendered yet
    frame = sim.camera_frame()
    truth = sim.frame_truth()
    assert truth is not None and truth.segmentation.shape == (frame.height, frame.width)
    mug = next(d for d in frame.detections if d.label == "mug")
    mug_bodies = {b for b, name in truth.labels.items() if name == "mug"}
    assert set(np.unique(truth.segmentation[mug.mask]).tolist()) == mug_bodies
    # the robot's frame carries no ground truth
    assert not hasattr(frame, "segmentation") and not hasattr(frame, "visible_instances")
    assert not hasattr(mug, "true_instance")


def test_camera_rate_caches_frames(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"), camera_hz=10.0)
    first = sim.camera_frame()
    sim.step(0.05)
    assert sim.camera_frame() is first
    sim.step(0.05)
    assert sim.camera_frame().stamp == pytest.approx(0.1)


def test_simulation_satisfies_the_api_protocol(make_sim: Callable[..., Simulation]) -> None:
    from core.robot import Robot
    from worlds.api import SimulationAPI
    from worlds.oracle import Oracle

    sim: SimulationAPI = make_sim(world_from_dict(TWO_ROOMS, file="two_rooms.yaml"))
    robot: Robot = sim
    oracle: Oracle = sim
    assert isinstance(sim, SimulationAPI) and isinstance(robot, Robot) and isinstance(oracle, Oracle)
    assert sim.robot_name == "r2d2" and sim.time == 0.0


def test_camera_pose_comes_from_the_localisation_estimate(make_sim: Callable[..., Simulation]) -> None:
    import math

    from worlds.sim.estimates import CAMERA_FORWARD

    sim = make_sim("erl_home", noise=NoiseConfig(pose_noise_xy=0.3, pose_noise_yaw=0.05, miss_rate=0.0))
    frame = sim.camera_frame()
    true = sim.true_robot_pose()
    est = sim._estimate  # the estimate the frame was deprojected with
    assert est is not None and est.stamp == frame.stamp
    cx, cy, _ = frame.camera_pose.position
    assert cx == pytest.approx(est.x + CAMERA_FORWARD * math.cos(est.yaw))
    assert cy == pytest.approx(est.y + CAMERA_FORWARD * math.sin(est.yaw))
    offset = math.hypot(
        cx - (true.x + CAMERA_FORWARD * math.cos(true.yaw)),
        cy - (true.y + CAMERA_FORWARD * math.sin(true.yaw)),
    )
    assert offset == pytest.approx(math.hypot(est.x - true.x, est.y - true.y), abs=0.02) and offset > 0.0
    perfect = make_sim("erl_home")
    px, py, _ = perfect.camera_frame().camera_pose.position
    t = perfect.true_robot_pose()
    assert (px, py) == pytest.approx(
        (t.x + CAMERA_FORWARD * math.cos(t.yaw), t.y + CAMERA_FORWARD * math.sin(t.yaw))
    )


def test_sounds_are_localised_with_noise(make_sim: Callable[..., Simulation]) -> None:
    import math

    noisy = make_sim("erl_home", noise=NoiseConfig(sound_noise_xy=0.3, sound_noise_per_m=0.0))
    perfect = make_sim("erl_home")
    bell = next(d for d in noisy.world.devices.values() if d.kind == "bell")
    for sim in (noisy, perfect):
        sim.ring_bell()
    (heard,) = noisy.poll_sounds()
    (exact,) = perfect.poll_sounds()
    assert exact.position == bell.position
    assert 0.0 < math.dist(heard.position[:2], bell.position[:2]) < 1.5
    assert noisy.sounds_made()[0].position == bell.position  # the referee keeps the true source
