"""The camera frame at the ROS 2 boundary: ``frame_to_ros`` / ``frame_from_ros``.

One :class:`core.robot.CameraFrame` travels as six messages with the same stamp (:class:`CameraMessages`):

* ``image``: ``sensor_msgs/Image`` ``rgb8``;
* ``depth``: ``sensor_msgs/Image`` ``32FC1``, metres along the optical axis, ``inf`` where nothing is seen;
* ``masks``: ``sensor_msgs/Image`` ``mono8`` of height ``N * height``: the N detections' masks stacked top to
  bottom (255 inside), so overlapping detections (a false positive over an object) stay apart;
* ``labels``: ``std_msgs/String`` JSON ``{"detections": [{"label", "confidence", "identity"}, ...], "near",
  "far"}`` in the masks' order;
* ``info``: ``sensor_msgs/CameraInfo``. ROS puts pixel centres at integer coordinates, :mod:`core.robot` at
  ``+0.5``: the principal point is shifted by half a pixel each way;
* ``pose``: ``geometry_msgs/PoseStamped`` of the optical frame in ``map``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from core.robot import CameraFrame, CameraIntrinsics, Detection
from knic.ros.convert import (
    MessageError,
    json_object,
    json_to_ros,
    pose3d_from_ros,
    pose3d_to_ros,
    time_from_ros,
    time_to_ros,
)
from knic.ros.topics import CAMERA_FRAME


@dataclass
class CameraMessages:
    """The six messages of one camera frame (see the module docstring); a field is None until received."""

    image: Any = None
    depth: Any = None
    masks: Any = None
    labels: Any = None
    info: Any = None
    pose: Any = None

    def complete(self) -> bool:
        """Whether all six messages are here."""
        return all(
            m is not None for m in (self.image, self.depth, self.masks, self.labels, self.info, self.pose)
        )


def _image(data: np.ndarray, encoding: str, t: float, step: int) -> Any:
    from sensor_msgs.msg import Image
    from std_msgs.msg import Header

    msg = Image(
        header=Header(stamp=time_to_ros(t), frame_id=CAMERA_FRAME),
        height=int(data.shape[0]),
        width=int(data.shape[1]),
        encoding=encoding,
        is_bigendian=0,
        step=step,
    )
    msg.data = np.ascontiguousarray(data).tobytes()
    return msg


def frame_to_ros(frame: CameraFrame) -> CameraMessages:
    """The messages of one frame, all stamped ``frame.stamp``."""
    from sensor_msgs.msg import CameraInfo
    from std_msgs.msg import Header

    t, w, h, k = frame.stamp, frame.width, frame.height, frame.intrinsics
    if frame.detections:
        stacked = np.concatenate([d.mask for d in frame.detections], axis=0).astype(np.uint8) * 255
    else:
        stacked = np.zeros((0, w), dtype=np.uint8)
    labels = json_to_ros(
        {
            "stamp": t,
            "near": k.near,
            "far": k.far,
            "detections": [
                {"label": d.label, "confidence": d.confidence, "identity": d.identity}
                for d in frame.detections
            ],
        }
    )
    cx, cy = k.cx - 0.5, k.cy - 0.5
    info = CameraInfo(
        header=Header(stamp=time_to_ros(t), frame_id=CAMERA_FRAME),
        height=h,
        width=w,
        distortion_model="plumb_bob",
        d=[0.0] * 5,
        k=[k.fx, 0.0, cx, 0.0, k.fy, cy, 0.0, 0.0, 1.0],
        r=[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
        p=[k.fx, 0.0, cx, 0.0, 0.0, k.fy, cy, 0.0, 0.0, 0.0, 1.0, 0.0],
    )
    pose = pose3d_to_ros(frame.camera_pose)
    pose.header.stamp = time_to_ros(t)
    return CameraMessages(
        image=_image(np.asarray(frame.rgb, dtype=np.uint8), "rgb8", t, w * 3),
        depth=_image(np.asarray(frame.depth, dtype="<f4"), "32FC1", t, w * 4),
        masks=_image(stacked, "mono8", t, w),
        labels=labels,
        info=info,
        pose=pose,
    )


def _array(msg: Any, dtype: str, channels: int, what: str) -> np.ndarray:
    raw = np.frombuffer(bytes(msg.data), dtype=dtype)
    expected = msg.height * msg.width * channels
    if raw.size != expected:
        raise MessageError(f"{what}: {raw.size} values for {msg.width}x{msg.height}x{channels}")
    shape = (msg.height, msg.width, channels) if channels > 1 else (msg.height, msg.width)
    return raw.reshape(shape)


def frame_from_ros(messages: CameraMessages) -> CameraFrame:
    """The frame the six messages carry.

    Raises:
        MessageError: a message is missing, has another stamp, the wrong encoding or size.
    """
    if not messages.complete():
        raise MessageError("camera frame: incomplete")
    stamp = time_from_ros(messages.image.header.stamp)
    for m in (messages.depth, messages.masks, messages.info, messages.pose):
        if abs(time_from_ros(m.header.stamp) - stamp) > 1e-6:
            raise MessageError("camera frame: the messages have different stamps")
    for m, enc in ((messages.image, "rgb8"), (messages.depth, "32FC1"), (messages.masks, "mono8")):
        if m.encoding != enc:
            raise MessageError(f"camera frame: encoding {m.encoding}, expected {enc}")
    rgb = _array(messages.image, "u1", 3, "image")
    depth = _array(messages.depth, "<f4", 1, "depth").astype(np.float32)
    h, w = depth.shape
    labels = json_object(messages.labels, "detection labels", "detections", "near", "far")
    entries = labels["detections"]
    masks = _array(messages.masks, "u1", 1, "detections")
    if masks.shape != (h * len(entries), w):
        raise MessageError(f"detections: masks of {masks.shape} for {len(entries)} detections of {w}x{h}")
    detections = []
    for i, entry in enumerate(entries):
        identity = entry.get("identity")
        detections.append(
            Detection(
                label=str(entry["label"]),
                confidence=float(entry["confidence"]),
                mask=masks[i * h : (i + 1) * h] > 0,
                identity=None if identity is None else str(identity),
            )
        )
    kk = messages.info.k
    intrinsics = CameraIntrinsics(
        width=w,
        height=h,
        fx=float(kk[0]),
        fy=float(kk[4]),
        cx=float(kk[2]) + 0.5,
        cy=float(kk[5]) + 0.5,
        near=float(labels["near"]),
        far=float(labels["far"]),
    )
    return CameraFrame(
        stamp=stamp,
        width=w,
        height=h,
        rgb=rgb,
        depth=depth,
        intrinsics=intrinsics,
        camera_pose=pose3d_from_ros(messages.pose),
        detections=detections,
    )
