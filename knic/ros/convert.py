"""Conversions between KnIC's types (:mod:`core.robot`, maps, octomaps) and ROS 2 messages.

Symmetric pairs, each with a round-trip test in ``tests/ros/test_convert.py``: ``time_to_ros`` /
``time_from_ros``, ``pose_to_ros`` / ``pose_from_ros`` (planar pose as ``PoseStamped``), ``pose3d_to_ros`` /
``pose3d_from_ros``, ``path_to_ros`` / ``path_from_ros``, ``grid_to_ros`` / ``grid_from_ros``
(``OccupancyGrid``), ``voxels_to_ros`` / ``voxels_from_ros`` (an octomap as a ``MarkerArray`` of cubes),
``json_to_ros`` / ``json_from_ros`` (``std_msgs/String``), and the JSON forms of the seam's small values
(``nav_status_to_json``, ``sound_to_json``, ``utterance_to_json``, ``result_to_json`` and their inverses).
Frames and units are those of :mod:`core.robot` (world frame ``map``, metres, radians, seconds).
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import numpy.typing as npt

from core.errors import KnicError
from core.robot import CommandResult, NavState, NavStatus, Pose2D, Pose3D, SoundEvent, Utterance
from knic.ros.topics import MAP_FRAME


class MessageError(KnicError):
    """A message that does not convert (malformed JSON, wrong shape); nothing is changed."""

    exit_code = 2


# --------------------------------------------------------------------------- time


def time_to_ros(t: float) -> Any:
    """Seconds as ``builtin_interfaces/Time`` (nanoseconds rounded; negative times clamp to 0)."""
    from builtin_interfaces.msg import Time

    ns = max(0, round(t * 1e9))
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def time_from_ros(stamp: Any) -> float:
    """``builtin_interfaces/Time`` as seconds."""
    return float(stamp.sec) + float(stamp.nanosec) * 1e-9


def _header(t: float, frame: str) -> Any:
    from std_msgs.msg import Header

    return Header(stamp=time_to_ros(t), frame_id=frame)


# --------------------------------------------------------------------------- poses


def yaw_to_quat(yaw: float) -> tuple[float, float, float, float]:
    """A rotation of ``yaw`` radians about +z as ``(qx, qy, qz, qw)``."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def quat_to_yaw(q: tuple[float, float, float, float]) -> float:
    """The heading (radians, ``(-pi, pi]``) of a quaternion ``(qx, qy, qz, qw)``."""
    qx, qy, qz, qw = q
    return math.atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))


def pose_to_ros(pose: Pose2D, frame: str = MAP_FRAME) -> Any:
    """A planar pose as ``geometry_msgs/PoseStamped`` (z = 0, rotation about z, stamped ``pose.stamp``)."""
    from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion

    qx, qy, qz, qw = yaw_to_quat(pose.yaw)
    return PoseStamped(
        header=_header(pose.stamp, frame),
        pose=Pose(position=Point(x=pose.x, y=pose.y, z=0.0), orientation=Quaternion(x=qx, y=qy, z=qz, w=qw)),
    )


def pose_from_ros(msg: Any) -> Pose2D:
    """``geometry_msgs/PoseStamped`` as a planar pose (height dropped, heading from the quaternion)."""
    o = msg.pose.orientation
    return Pose2D(
        msg.pose.position.x,
        msg.pose.position.y,
        quat_to_yaw((o.x, o.y, o.z, o.w)),
        time_from_ros(msg.header.stamp),
    )


def pose3d_to_ros(pose: Pose3D, frame: str = MAP_FRAME) -> Any:
    """A 3D pose as ``geometry_msgs/PoseStamped``."""
    from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion

    (x, y, z), (qx, qy, qz, qw) = pose.position, pose.orientation
    return PoseStamped(
        header=_header(pose.stamp, frame),
        pose=Pose(position=Point(x=x, y=y, z=z), orientation=Quaternion(x=qx, y=qy, z=qz, w=qw)),
    )


def pose3d_from_ros(msg: Any) -> Pose3D:
    """``geometry_msgs/PoseStamped`` as a 3D pose."""
    p, o = msg.pose.position, msg.pose.orientation
    return Pose3D((p.x, p.y, p.z), (o.x, o.y, o.z, o.w), time_from_ros(msg.header.stamp))


# --------------------------------------------------------------------------- paths and maps


def path_to_ros(points: tuple[tuple[float, float], ...] | list[tuple[float, float]], t: float) -> Any:
    """World ``(x, y)`` waypoints as ``nav_msgs/Path`` (each pose heading towards the next waypoint)."""
    from nav_msgs.msg import Path

    poses = []
    for i, (x, y) in enumerate(points):
        nx, ny = points[i + 1] if i + 1 < len(points) else (x, y)
        yaw = math.atan2(ny - y, nx - x) if (nx, ny) != (x, y) else 0.0
        poses.append(pose_to_ros(Pose2D(float(x), float(y), yaw, t)))
    return Path(header=_header(t, MAP_FRAME), poses=poses)


def path_from_ros(msg: Any) -> list[tuple[float, float]]:
    """``nav_msgs/Path`` as world ``(x, y)`` waypoints."""
    return [(p.pose.position.x, p.pose.position.y) for p in msg.poses]


def grid_to_ros(
    occupied: npt.NDArray[np.bool_], origin: tuple[float, float], resolution: float, t: float
) -> Any:
    """An occupancy grid (``(rows, cols)`` booleans, row = y, column = x) as ``nav_msgs/OccupancyGrid``
    (100 occupied, 0 free; the origin is the world corner of cell ``(0, 0)``)."""
    from geometry_msgs.msg import Point, Pose, Quaternion
    from nav_msgs.msg import MapMetaData, OccupancyGrid

    rows, cols = occupied.shape
    info = MapMetaData(
        map_load_time=time_to_ros(t),
        resolution=float(resolution),
        width=int(cols),
        height=int(rows),
        origin=Pose(
            position=Point(x=float(origin[0]), y=float(origin[1]), z=0.0), orientation=Quaternion(w=1.0)
        ),
    )
    data = np.where(occupied, 100, 0).astype(np.int8).ravel()
    msg = OccupancyGrid(header=_header(t, MAP_FRAME), info=info)
    msg.data = data.tobytes()
    return msg


def grid_from_ros(msg: Any) -> tuple[npt.NDArray[np.bool_], tuple[float, float], float]:
    """``nav_msgs/OccupancyGrid`` as ``(occupied, origin, resolution)``; unknown (-1) counts as occupied.

    Raises:
        MessageError: the data does not have ``width * height`` cells.
    """
    info = msg.info
    data = np.frombuffer(bytes(np.asarray(msg.data, dtype=np.int8)), dtype=np.int8)
    if data.size != info.width * info.height:
        raise MessageError(f"OccupancyGrid: {data.size} cells for {info.width}x{info.height}")
    occupied = (data.reshape(info.height, info.width) != 0).astype(np.bool_)
    return occupied, (info.origin.position.x, info.origin.position.y), float(info.resolution)


# --------------------------------------------------------------------------- octomaps


def voxels_to_ros(
    name: str,
    centres: npt.NDArray[np.float64],
    resolution: float,
    t: float,
    colour: tuple[float, ...] = (0.2, 0.6, 1.0, 0.8),
) -> Any:
    """An entity octomap's occupied voxels as ``visualization_msgs/MarkerArray``: a DELETEALL marker and one
    CUBE_LIST (namespace ``name``, cube size ``resolution`` metres, one point per voxel centre)."""
    from geometry_msgs.msg import Point, Quaternion, Vector3
    from std_msgs.msg import ColorRGBA
    from visualization_msgs.msg import Marker, MarkerArray

    clear = Marker(header=_header(t, MAP_FRAME), ns=name, action=Marker.DELETEALL)
    cubes = Marker(
        header=_header(t, MAP_FRAME),
        ns=name,
        id=0,
        type=Marker.CUBE_LIST,
        action=Marker.ADD,
        scale=Vector3(x=float(resolution), y=float(resolution), z=float(resolution)),
        color=ColorRGBA(r=colour[0], g=colour[1], b=colour[2], a=colour[3]),
    )
    cubes.pose.orientation = Quaternion(w=1.0)
    cubes.points = [
        Point(x=float(x), y=float(y), z=float(z)) for x, y, z in np.asarray(centres).reshape(-1, 3)
    ]
    return MarkerArray(markers=[clear, cubes])


def voxels_from_ros(msg: Any) -> tuple[str, npt.NDArray[np.float64], float]:
    """``MarkerArray`` from :func:`voxels_to_ros` as ``(name, centres (N, 3), resolution)``.

    Raises:
        MessageError: no CUBE_LIST marker in the array.
    """
    from visualization_msgs.msg import Marker

    for marker in msg.markers:
        if marker.type == Marker.CUBE_LIST and marker.action == Marker.ADD:
            centres = np.array([(p.x, p.y, p.z) for p in marker.points], dtype=np.float64).reshape(-1, 3)
            return marker.ns, centres, float(marker.scale.x)
    raise MessageError("MarkerArray holds no CUBE_LIST marker")


# --------------------------------------------------------------------------- JSON payloads


def json_to_ros(payload: Any) -> Any:
    """A JSON-able value as ``std_msgs/String`` (compact separators, keys sorted)."""
    from std_msgs.msg import String

    return String(data=json.dumps(payload, separators=(",", ":"), sort_keys=True))


def json_from_ros(msg: Any, what: str = "message") -> Any:
    """The JSON value of a ``std_msgs/String``.

    Raises:
        MessageError: the text is not JSON (names ``what``).
    """
    try:
        return json.loads(msg.data)
    except (json.JSONDecodeError, TypeError) as exc:
        raise MessageError(f"{what}: not JSON ({exc})") from None


def json_object(msg: Any, what: str, *required: str) -> dict[str, Any]:
    """The JSON object of a ``std_msgs/String`` with the ``required`` keys.

    Raises:
        MessageError: not a JSON object, or a required key is missing (names which).
    """
    value = json_from_ros(msg, what)
    if not isinstance(value, dict):
        raise MessageError(f"{what}: expected a JSON object, got {type(value).__name__}")
    missing = [k for k in required if k not in value]
    if missing:
        raise MessageError(f"{what}: missing {', '.join(missing)}")
    return value


def nav_status_to_json(status: NavStatus) -> dict[str, Any]:
    """A navigation status as a JSON object."""
    goal = status.goal
    return {
        "state": status.state.value,
        "goal_id": status.goal_id,
        "target": status.target,
        "reason": status.reason,
        "goal": None if goal is None else [goal.x, goal.y, goal.yaw, goal.stamp],
        "path": [[x, y] for x, y in status.path],
    }


def nav_status_from_json(data: dict[str, Any]) -> NavStatus:
    """The inverse of :func:`nav_status_to_json`.

    Raises:
        MessageError: unknown state or malformed fields.
    """
    try:
        goal = data.get("goal")
        return NavStatus(
            state=NavState(data["state"]),
            goal_id=int(data["goal_id"]),
            target=str(data.get("target", "")),
            reason=str(data.get("reason", "")),
            goal=None if goal is None else Pose2D(*(float(v) for v in goal)),
            path=tuple((float(x), float(y)) for x, y in data.get("path", ())),
        )
    except (KeyError, ValueError, TypeError) as exc:
        raise MessageError(f"navigation status: {exc}") from None


def sound_to_json(sound: SoundEvent) -> dict[str, Any]:
    """A sound event as a JSON object."""
    return {"kind": sound.kind, "position": list(sound.position), "stamp": sound.stamp}


def sound_from_json(data: dict[str, Any]) -> SoundEvent:
    """The inverse of :func:`sound_to_json` (raises :class:`MessageError` when malformed)."""
    try:
        x, y, z = (float(v) for v in data["position"])
        return SoundEvent(str(data["kind"]), (x, y, z), float(data["stamp"]))
    except (KeyError, ValueError, TypeError) as exc:
        raise MessageError(f"sound event: {exc}") from None


def utterance_to_json(u: Utterance) -> dict[str, Any]:
    """An utterance as a JSON object."""
    return {
        "text": u.text,
        "speaker": u.speaker,
        "stamp": u.stamp,
        "audio_path": u.audio_path,
        "position": list(u.position),
    }


def utterance_from_json(data: dict[str, Any]) -> Utterance:
    """The inverse of :func:`utterance_to_json` (raises :class:`MessageError` when malformed)."""
    try:
        x, y, z = (float(v) for v in data.get("position", (0.0, 0.0, 0.0)))
        audio = data.get("audio_path")
        return Utterance(
            str(data["text"]),
            str(data["speaker"]),
            float(data["stamp"]),
            None if audio is None else str(audio),
            (x, y, z),
        )
    except (KeyError, ValueError, TypeError) as exc:
        raise MessageError(f"utterance: {exc}") from None


def result_to_json(result: CommandResult) -> dict[str, Any]:
    """A command result as a JSON object."""
    out: dict[str, Any] = {"ok": result.ok, "reason": result.reason}
    cause = getattr(result, "cause", "")
    if cause:
        out["cause"] = cause
    return out


def result_from_json(data: dict[str, Any]) -> CommandResult:
    """The inverse of :func:`result_to_json`."""
    extra: dict[str, str] = {}
    if data.get("cause") and "cause" in getattr(CommandResult, "__dataclass_fields__", {}):
        extra["cause"] = str(data["cause"])  # the failure's kind, where the seam names it
    return CommandResult(bool(data.get("ok", False)), str(data.get("reason", "")), **extra)
