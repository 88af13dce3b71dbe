"""The robot seam: value types without ground truth, deprojection, and the doubles that satisfy it."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from core.robot import (
    CameraFrame,
    CameraIntrinsics,
    CommandResult,
    Detection,
    Pose2D,
    Pose3D,
    Robot,
    SoundEvent,
    Utterance,
)
from tests.actions.erl.doubles import FakeRobot

K = CameraIntrinsics(width=8, height=6, fx=4.0, fy=4.0, cx=4.0, cy=3.0, near=0.1, far=10.0)
#: optical frame looking along world +x from (1, 2, 1): optical z = world x, optical x = -world y, y = -z
LOOK_X = Pose3D((1.0, 2.0, 1.0), (-0.5, 0.5, -0.5, 0.5))


def _frame(depth: float) -> CameraFrame:
    return CameraFrame(
        stamp=1.5,
        width=K.width,
        height=K.height,
        rgb=np.zeros((K.height, K.width, 3), dtype=np.uint8),
        depth=np.full((K.height, K.width), depth, dtype=np.float32),
        intrinsics=K,
        camera_pose=LOOK_X,
    )


def test_sensor_types_carry_no_ground_truth() -> None:
    truthy = {"true_instance", "segmentation_id", "segmentation", "visible_instances", "source", "emitter"}
    for cls in (CameraFrame, Detection, SoundEvent, Utterance, Pose2D, Pose3D):
        names = {f.name for f in dataclasses.fields(cls)}
        assert names.isdisjoint(truthy), cls.__name__


def test_deprojection_lands_in_the_world_frame() -> None:
    frame = _frame(2.0)
    mask = np.zeros((K.height, K.width), dtype=bool)
    mask[2:4, 3:5] = True  # the four pixels around the principal point
    points = frame.points_world(Detection("mug", 0.9, mask), max_points=10)
    assert points.shape == (4, 3)
    assert points[:, 0] == pytest.approx([3.0] * 4)  # 2 m ahead along +x
    assert np.abs(points[:, 1] - 2.0).max() <= 0.25 and np.abs(points[:, 2] - 1.0).max() <= 0.25
    assert Detection("mug", 0.9, mask).bbox() == (3, 2, 4, 3)


def test_pixels_without_depth_are_skipped_and_subsampling_is_seeded() -> None:
    frame = _frame(math.inf)
    mask = np.ones((K.height, K.width), dtype=bool)
    assert frame.points_world(Detection("mug", 0.9, mask)).shape == (0, 3)
    near = _frame(1.0)
    a = near.points_world(Detection("mug", 0.9, mask), max_points=5, seed=3)
    b = near.points_world(Detection("mug", 0.9, mask), max_points=5, seed=3)
    assert a.shape == (5, 3) and np.array_equal(a, b)


def test_command_result_is_truthy_only_on_success() -> None:
    assert CommandResult(True) and not CommandResult(False, "hand is empty")
    assert Pose2D(0.0, 0.0, 0.0).distance_to(3.0, 4.0) == 5.0


def test_the_action_double_is_a_robot() -> None:
    robot: Robot = FakeRobot()  # mypy checks the double against the seam here, isinstance at run time
    assert isinstance(robot, Robot)
    assert robot.camera_frame().detections == [] and robot.poll_sounds() == []
