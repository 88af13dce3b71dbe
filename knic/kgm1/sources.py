"""The sensor sources KGM-1 consumes: the sensor parts of the robot seam (:class:`core.robot.Robot`).

A KP depends only on the part of the robot it reads (:class:`core.robot.Camera`,
:class:`~core.robot.Localisation`, :class:`~core.robot.SoundDetector`, :class:`~core.robot.DeviceSensors`;
:class:`~core.robot.Robot` extends them all), so tests feed recorded or synthetic readings through a double
that mypy checks against the same declaration. The names below are the KGM-1 names of those parts.

Also here: :class:`SharedCamera`, which renders a camera frame at most once per simulated instant for the two
camera KPs, and :class:`FrameView`, the visibility test of one frame (what the camera could have seen, walls
and furniture included) that KGM-2 uses to count misses.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from core.robot import Camera, CameraFrame, CameraIntrinsics, DeviceSensors, Localisation, SoundDetector

#: the camera KPs' source: an RGB-D camera with detections
CameraSource = Camera
#: the robot-pose KP's source: the self-localisation
PoseSource = Localisation
#: the sound KP's source: the microphone's sound-event detector
SoundSource = SoundDetector
#: the device KP's source: the home automation's readings
DeviceSource = DeviceSensors


class SharedCamera:
    """A :class:`CameraSource` that renders once per simulated instant and hands the same frame to every KP.

    Args:
        camera: the real source.
        clock: simulated time now (``lambda: sim.time``); a new frame is rendered when it has changed.
    """

    def __init__(self, camera: CameraSource, clock: Callable[[], float]) -> None:
        self._camera = camera
        self._clock = clock
        self._stamp: float | None = None
        self._frame: CameraFrame | None = None
        self.renders = 0
        self.render_wall_s = 0.0

    def camera_frame(self) -> CameraFrame:
        """The frame of the current simulated instant (rendered on the first request at that instant).

        :attr:`render_wall_s` accumulates the seconds spent in the source (the simulator's rendering), so a
        benchmark can tell the pipeline's own CPU from the simulator's; they are process CPU seconds
        (``time.process_time``), like the benchmark's component times they are subtracted from: wall-clock
        seconds would also count the time the process waits for a core on a shared machine. (The attribute
        keeps its name for the benchmark that reads it.)
        """
        now = self._clock()
        if self._frame is None or self._stamp != now:
            start = time.process_time()
            self._frame = self._camera.camera_frame()
            self.render_wall_s += time.process_time() - start
            self._stamp = now
            self.renders += 1
        return self._frame


class FrameView:
    """What one camera frame could see: the visibility test behind KGM-2's miss counter (a
    :class:`knic.units.ViewModel`).

    A world-frame point is visible when it projects inside the image, lies between the near plane and
    ``max_range`` metres along the optical axis, and is not hidden: the frame's depth at its pixel is at least
    the point's depth minus ``margin`` metres (a wall, a person or a closed cupboard in front hides it).

    Args:
        frame: the camera frame (its depth image, intrinsics and optical-frame pose are used).
        max_range: farthest depth, metres, at which an entity of this kind is reliably detected.
        margin: depth tolerance, metres.
        edge_px: pixels at each image border treated as outside the image (an entity there is only partly in
            view and may not be detected).
        footprint_m: metres, the half size of the entity around a point: the point is visible only when the
            pixels at that distance around its projection (left, right, above, below) are not hidden either.
            An entity partly hidden (a small glass behind a bottle, an item at a person's side) shows too few
            pixels to be detected reliably, so not seeing it there is no evidence of its absence. 0: the
            point's own pixel only.
    """

    def __init__(
        self,
        frame: CameraFrame,
        max_range: float,
        margin: float = 0.2,
        edge_px: int = 0,
        footprint_m: float = 0.0,
    ) -> None:
        self.stamp = frame.stamp
        self.footprint_m = max(0.0, footprint_m)
        self.position = np.asarray(frame.camera_pose.position, dtype=np.float64)
        self._rot = frame.camera_pose.rotation_matrix()
        self._k: CameraIntrinsics = frame.intrinsics
        self._depth = frame.depth
        self.max_range = max_range
        self.margin = margin
        self.edge_px = max(0, edge_px)

    def optical_axis(self) -> npt.NDArray[np.float64]:
        """The camera's viewing direction (optical z axis) in the world frame, a unit vector."""
        return np.asarray(self._rot[:, 2], dtype=np.float64)

    def visible(self, points: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
        """Which of the world-frame points (N, 3) this frame could have seen."""
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        optical = (pts - self.position) @ self._rot
        z = optical[:, 2]
        k = self._k
        ok = (z > k.near) & (z <= self.max_range)
        safe_z = np.where(ok, z, 1.0)
        u = np.floor(k.fx * optical[:, 0] / safe_z + k.cx).astype(np.int64)
        v = np.floor(k.fy * optical[:, 1] / safe_z + k.cy).astype(np.int64)
        e = self.edge_px
        ok &= (u >= e) & (u < k.width - e) & (v >= e) & (v < k.height - e)
        result = np.zeros(len(pts), dtype=bool)
        idx = np.flatnonzero(ok)
        if idx.size:
            seen_depth = self._depth[v[idx], u[idx]].astype(np.float64)
            result[idx] = seen_depth >= z[idx] - self.margin
        if self.footprint_m > 0:
            idx = np.flatnonzero(result)
            if idx.size:
                result[idx] = self._unhidden_around(u[idx], v[idx], z[idx])
        return result

    def _unhidden_around(
        self, u: npt.NDArray[np.int64], v: npt.NDArray[np.int64], z: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.bool_]:
        """Whether the pixels ``footprint_m`` around each projection (clipped to the image) are not hidden."""
        k = self._k
        du = np.maximum(1, np.round(k.fx * self.footprint_m / z)).astype(np.int64)
        dv = np.maximum(1, np.round(k.fy * self.footprint_m / z)).astype(np.int64)
        clear = np.ones(len(z), dtype=bool)
        for su, sv in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            uu = np.clip(u + su * du, 0, k.width - 1)
            vv = np.clip(v + sv * dv, 0, k.height - 1)
            clear &= self._depth[vv, uu].astype(np.float64) >= z - self.margin
        return clear
