"""Round trips through the ROS 2 boundary: every ``*_to_ros`` has its ``*_from_ros`` (no DDS involved)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from core.robot import (
    CameraFrame,
    CameraIntrinsics,
    CommandResult,
    Detection,
    NavState,
    NavStatus,
    Pose2D,
    Pose3D,
    SoundEvent,
    Utterance,
)
from knic.ros import convert as cv
from knic.ros.camera import CameraMessages, frame_from_ros, frame_to_ros


def test_time_round_trip() -> None:
    for t in (0.0, 0.05, 12.4, 81.5, 3600.123456789):
        assert cv.time_from_ros(cv.time_to_ros(t)) == pytest.approx(t, abs=1e-9)


@pytest.mark.parametrize("yaw", [0.0, 0.7, -2.9, math.pi])
def test_pose_round_trip(yaw: float) -> None:
    pose = Pose2D(1.25, -3.5, yaw, stamp=42.1)
    back = cv.pose_from_ros(cv.pose_to_ros(pose))
    assert (back.x, back.y, back.stamp) == pytest.approx((1.25, -3.5, 42.1))
    assert math.cos(back.yaw - yaw) == pytest.approx(1.0)
    assert cv.pose_to_ros(pose).header.frame_id == "map"


def test_pose3d_round_trip() -> None:
    q = np.array([0.1, -0.2, 0.3, 0.9])
    q /= np.linalg.norm(q)
    pose = Pose3D((1.0, 2.0, 1.1), (float(q[0]), float(q[1]), float(q[2]), float(q[3])), 7.5)
    back = cv.pose3d_from_ros(cv.pose3d_to_ros(pose))
    assert back.position == pytest.approx(pose.position)
    assert back.orientation == pytest.approx(pose.orientation)
    assert back.stamp == pytest.approx(7.5)


def test_path_round_trip() -> None:
    points = [(0.0, 0.0), (1.0, 0.5), (2.0, 2.0)]
    msg = cv.path_to_ros(points, 3.0)
    assert np.allclose(cv.path_from_ros(msg), points)
    assert cv.quat_to_yaw(tuple(getattr(msg.poses[0].pose.orientation, a) for a in "xyzw")) == pytest.approx(
        math.atan2(0.5, 1.0)
    )


def test_grid_round_trip() -> None:
    occupied = np.zeros((7, 11), dtype=bool)
    occupied[2, 3:8] = True
    occupied[:, 0] = True
    msg = cv.grid_to_ros(occupied, (-1.5, 2.0), 0.05, 1.0)
    assert (msg.info.width, msg.info.height) == (11, 7)
    back, origin, resolution = cv.grid_from_ros(msg)
    assert np.array_equal(back, occupied)
    assert origin == pytest.approx((-1.5, 2.0))
    assert resolution == pytest.approx(0.05)


def test_voxels_round_trip() -> None:
    centres = np.array([[1.0, 2.0, 0.5], [1.1, 2.0, 0.5], [1.1, 2.1, 0.6]])
    name, back, resolution = cv.voxels_from_ros(cv.voxels_to_ros("people_jack", centres, 0.1, 5.0))
    assert name == "people_jack"
    assert np.allclose(back, centres)
    assert resolution == pytest.approx(0.1)


def test_json_values_round_trip() -> None:
    status = NavStatus(
        NavState.ACTIVE, 3, "room kitchen", "", Pose2D(1.0, 2.0, 0.5, 4.0), ((0.0, 0.0), (1.0, 2.0))
    )
    assert cv.nav_status_from_json(cv.nav_status_to_json(status)) == status
    idle = NavStatus(NavState.IDLE)
    assert cv.nav_status_from_json(cv.nav_status_to_json(idle)) == idle
    sound = SoundEvent("doorbell", (0.5, 1.0, 1.2), 9.0)
    assert cv.sound_from_json(cv.sound_to_json(sound)) == sound
    heard = Utterance("bring me my glasses", "annie", 3.0, None, (1.0, 1.0, 1.5))
    assert cv.utterance_from_json(cv.utterance_to_json(heard)) == heard
    failed = CommandResult(False, "mug is 2.31 m away, reach is 0.90 m")
    assert cv.result_from_json(cv.result_to_json(failed)) == failed
    payload = {"id": 3, "op": "pick", "args": {"item": "glasses"}}
    assert cv.json_from_ros(cv.json_to_ros(payload)) == payload


def test_malformed_messages_name_what() -> None:
    from std_msgs.msg import String

    with pytest.raises(cv.MessageError, match="goal reply: not JSON"):
        cv.json_from_ros(String(data="{oops"), "goal reply")
    with pytest.raises(cv.MessageError, match="missing op"):
        cv.json_object(String(data='{"id": 1}'), "command", "id", "op")
    with pytest.raises(cv.MessageError, match="navigation status"):
        cv.nav_status_from_json({"state": "flying", "goal_id": 1})


def _frame() -> CameraFrame:
    rng = np.random.default_rng(0)
    h, w = 12, 16
    depth = rng.uniform(0.5, 4.0, size=(h, w)).astype(np.float32)
    depth[0, :3] = np.inf
    a = np.zeros((h, w), dtype=bool)
    a[2:6, 3:9] = True
    b = np.zeros((h, w), dtype=bool)
    b[4:8, 5:10] = True  # overlaps a: a false positive over the object
    return CameraFrame(
        stamp=12.4,
        width=w,
        height=h,
        rgb=rng.integers(0, 255, size=(h, w, 3), dtype=np.uint8),
        depth=depth,
        intrinsics=CameraIntrinsics(w, h, 14.0, 14.5, 8.0, 6.0, 0.05, 8.0),
        camera_pose=Pose3D((1.0, 2.0, 1.1), (0.5, -0.5, 0.5, -0.5), 12.4),
        detections=[Detection("glasses", 0.9, a), Detection("person", 0.8, b, identity="annie")],
    )


def test_camera_frame_round_trip() -> None:
    frame = _frame()
    back = frame_from_ros(frame_to_ros(frame))
    assert back.stamp == pytest.approx(frame.stamp)
    assert back.intrinsics == frame.intrinsics
    assert np.array_equal(back.rgb, frame.rgb)
    assert np.array_equal(back.depth, frame.depth)
    assert [(d.label, d.confidence, d.identity) for d in back.detections] == [
        ("glasses", 0.9, None),
        ("person", 0.8, "annie"),
    ]
    assert all(np.array_equal(x.mask, y.mask) for x, y in zip(back.detections, frame.detections, strict=True))
    # the same world points come out of both (deprojection uses the shifted principal point consistently)
    assert np.allclose(back.points_world(back.detections[0]), frame.points_world(frame.detections[0]))
    msgs = frame_to_ros(frame)
    assert msgs.info.k[2] == pytest.approx(7.5)  # ROS: pixel centres on integers


def test_camera_frame_without_detections_and_broken_parts() -> None:
    frame = _frame()
    empty = CameraFrame(
        frame.stamp,
        frame.width,
        frame.height,
        frame.rgb,
        frame.depth,
        frame.intrinsics,
        frame.camera_pose,
        [],
    )
    assert frame_from_ros(frame_to_ros(empty)).detections == []
    msgs = frame_to_ros(frame)
    with pytest.raises(cv.MessageError, match="incomplete"):
        frame_from_ros(CameraMessages(image=msgs.image))
    msgs.depth.header.stamp = cv.time_to_ros(1.0)
    with pytest.raises(cv.MessageError, match="different stamps"):
        frame_from_ros(msgs)
