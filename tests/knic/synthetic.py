"""Synthetic sensor data for the inference tests: camera frames, LLKU streams, a KB on the ERL domain."""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from core.robot import CameraFrame, CameraIntrinsics, Detection, Pose2D, Pose3D, SoundEvent
from knic.units import LLKU, Kind

DOMAIN = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "domain.pddl"

INTRINSICS = CameraIntrinsics(width=80, height=60, fx=60.0, fy=60.0, cx=40.0, cy=30.0, near=0.1, far=8.0)

_seq = itertools.count()


def optical_pose(x: float, y: float, z: float, yaw: float, stamp: float = 0.0) -> Pose3D:
    """Pose of a level camera's optical frame (x right, y down, z forward) looking along ``yaw``."""
    forward = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    right = np.array([math.sin(yaw), -math.cos(yaw), 0.0])
    down = np.array([0.0, 0.0, -1.0])
    rot = np.column_stack([right, down, forward])
    return Pose3D((x, y, z), _quaternion(rot), stamp)


def _quaternion(m: npt.NDArray[np.float64]) -> tuple[float, float, float, float]:
    """(qx, qy, qz, qw) of a rotation matrix."""
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        return ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    if m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2]) * 2
        return (0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    if m[1, 1] > m[2, 2]:
        s = math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2]) * 2
        return ((m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    s = math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1]) * 2
    return ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s)


def frame(
    stamp: float,
    camera: tuple[float, float, float, float],
    *,
    depth: float = math.inf,
    boxes: Sequence[tuple[str, tuple[int, int, int, int], float, str | None]] = (),
) -> CameraFrame:
    """A frame from a camera at (x, y, z, yaw): uniform ``depth`` everywhere except the detection boxes.

    Each box is (label, (u0, v0, u1, v1) exclusive, depth in metres, identity).
    """
    k = INTRINSICS
    depth_img = np.full((k.height, k.width), depth, dtype=np.float32)
    detections = []
    for label, (u0, v0, u1, v1), d, identity in boxes:
        mask = np.zeros((k.height, k.width), dtype=bool)
        mask[v0:v1, u0:u1] = True
        depth_img[mask] = d
        detections.append(Detection(label, 0.9, mask, identity=identity))
    x, y, z, yaw = camera
    return CameraFrame(
        stamp=stamp,
        width=k.width,
        height=k.height,
        rgb=np.zeros((k.height, k.width, 3), dtype=np.uint8),
        depth=depth_img,
        intrinsics=k,
        camera_pose=optical_pose(x, y, z, yaw, stamp),
        detections=detections,
    )


def blob(center: tuple[float, float, float], n: int = 30, spread: float = 0.03, seed: int = 0) -> np.ndarray:
    """``n`` world points scattered around ``center``."""
    rng = np.random.default_rng(seed)
    return np.asarray(center) + rng.uniform(-spread, spread, size=(n, 3))


def percept(
    kind: Kind,
    label: str,
    center: tuple[float, float, float],
    stamp: float,
    *,
    identity: str | None = None,
    confidence: float = 0.9,
    n: int = 30,
) -> LLKU:
    """One camera LLKU with a small point blob (sensor at the origin of the room, 1.2 m high)."""
    return LLKU(
        kind=kind,
        label=label,
        source="test",
        sensor="camera",
        stamp=stamp,
        confidence=confidence,
        position=center,
        points=blob(center, n, seed=next(_seq)),
        sensor_origin=(center[0] - 1.0, center[1], 1.2),
        identity=identity,
    )


class FakeSensors:
    """A scripted sensor suite satisfying :class:`knic.pipeline.SensorSuite` (and the KGM-1 protocols)."""

    def __init__(self) -> None:
        self.time = 0.0
        self.next_frame: CameraFrame = frame(0.0, (0.0, 0.0, 1.2, 0.0))
        self.pose = Pose2D(0.0, 0.0, 0.0)
        self.sounds: list[SoundEvent] = []
        self.devices: dict[str, float | bool] = {}
        self.frames_rendered = 0

    def camera_frame(self) -> CameraFrame:
        self.frames_rendered += 1
        return self.next_frame

    def robot_pose(self) -> Pose2D:
        return Pose2D(self.pose.x, self.pose.y, self.pose.yaw, self.time)

    def poll_sounds(self) -> list[SoundEvent]:
        out, self.sounds = self.sounds, []
        return out

    def device_states(self) -> dict[str, float | bool]:
        return dict(self.devices)


class SeesEverything:
    """A frame view from ``position`` along ``axis`` that could see every point (a scan without a detection
    is a miss)."""

    def __init__(self, position: Sequence[float], axis: Sequence[float]) -> None:
        self.position = np.array(position, dtype=float)
        self._axis = np.array(axis, dtype=float)

    def visible(self, points: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
        return np.ones(len(points), dtype=bool)

    def optical_axis(self) -> npt.NDArray[np.float64]:
        return self._axis
