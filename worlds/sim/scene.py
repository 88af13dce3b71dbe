"""The pybullet scene built from world data, and the camera rendering.

Every body is static and kinematic (mass 0, moved with ``resetBasePositionAndOrientation``); physics is never
stepped, so a scene is exactly reproducible. pybullet is used for what it does well here: rendering RGB, depth
and segmentation with real field of view and occlusion (``ER_TINY_RENDERER``, CPU, works in DIRECT mode).
Each world instance is one body, so the segmentation value of a pixel is the body id of one instance.
"""

from __future__ import annotations

import functools
import math
import os
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt
import pybullet as pb

from core.errors import WorldError
from core.robot import CameraIntrinsics, Pose3D
from worlds.geometry import Point
from worlds.model import World
from worlds.sim.navigation import wall_segments

WALL_COLOR = (0.92, 0.9, 0.85, 1.0)
FLOOR_COLOR = (0.75, 0.72, 0.65, 1.0)
ROBOT_COLOR = (0.85, 0.85, 0.9, 1.0)
WALL_PIECE = 100.0  # metres; longer walls are split into pieces (one piece renders fastest here)
HIDDEN_Z = -1000.0  # bodies left out of a picture wait this far below the floor
FAR_Z = np.float32(1.0 - 2.0**-24)  # depth-buffer values from here up (the top two float32s) hit nothing


class Scene:
    """pybullet bodies of a world: floor, walls, furniture, items, people, robot.

    Lifecycle: built once from a :class:`World` (connects its own pybullet client, DIRECT unless ``gui``);
    bodies are moved by the simulation; :meth:`close` disconnects.

    Attributes:
        body_of: instance name -> pybullet body id.
        name_of: body id -> instance name (walls and floor are absent).
    """

    def __init__(self, world: World, *, gui: bool = False, render_floor: bool = True) -> None:
        self.world = world
        self.render_floor = render_floor
        self._client: Any = _Client(pb.GUI if gui else pb.DIRECT)
        self.body_of: dict[str, int] = {}
        self.name_of: dict[int, str] = {}
        self._pose: dict[int, tuple[tuple[float, float, float], float]] = {}
        self._version = 0  # counts body moves, so an unchanged scene is not rendered twice
        self._last: tuple[tuple[Any, ...], tuple[Any, ...]] | None = None
        # Headless, only pictures look at the bodies, so a body left out of one stays parked below the floor
        # until a picture wants it (saves moving it away and back every frame); a GUI window shows it.
        self._park = not gui
        self._parked: set[int] = set()
        self._build()

    def close(self) -> None:
        """Disconnect the pybullet client (idempotent)."""
        if self._client is not None:
            self._client.disconnect()
            self._client = None

    # ------------------------------------------------------------------------------------------ building

    def _box(
        self,
        half: tuple[float, float, float],
        pos: tuple[float, float, float],
        yaw: float,
        color: tuple[float, float, float, float],
    ) -> int:
        c = self._client
        vis = c.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=color)
        col = c.createCollisionShape(pb.GEOM_BOX, halfExtents=half)
        return int(
            c.createMultiBody(
                baseMass=0,
                baseCollisionShapeIndex=col,
                baseVisualShapeIndex=vis,
                basePosition=pos,
                baseOrientation=c.getQuaternionFromEuler((0, 0, yaw)),
            )
        )

    def _cylinder(
        self,
        radius: float,
        height: float,
        pos: tuple[float, float, float],
        color: tuple[float, float, float, float],
    ) -> int:
        c = self._client
        vis = c.createVisualShape(pb.GEOM_CYLINDER, radius=radius, length=height, rgbaColor=color)
        col = c.createCollisionShape(pb.GEOM_CYLINDER, radius=radius, height=height)
        return int(
            c.createMultiBody(
                baseMass=0, baseCollisionShapeIndex=col, baseVisualShapeIndex=vis, basePosition=pos
            )
        )

    def _wall_mesh(self, a: Point, b: Point, thickness: float, height: float) -> None:
        """One wall as mesh bodies of at most :data:`WALL_PIECE` metres each, outward-facing faces only.

        Each piece has its two long faces; the two ends of the wall get end faces; no top or bottom (the
        camera is below the wall tops). Short pieces let :meth:`render` leave out what is outside the view.
        """
        half = thickness / 2
        length = math.dist(a, b)
        ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
        nx, ny = -uy * half, ux * half
        ax, ay = a[0] - ux * half, a[1] - uy * half
        bx, by = b[0] + ux * half, b[1] + uy * half
        pieces = max(1, math.ceil((length + thickness) / WALL_PIECE))
        c = self._client
        for k in range(pieces):
            t0, t1 = k / pieces, (k + 1) / pieces
            p0 = (ax + (bx - ax) * t0, ay + (by - ay) * t0)
            p1 = (ax + (bx - ax) * t1, ay + (by - ay) * t1)
            mid = ((p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2)
            corners = [(p0[0] + nx, p0[1] + ny), (p1[0] + nx, p1[1] + ny), (p1[0] - nx, p1[1] - ny),
                       (p0[0] - nx, p0[1] - ny)]  # fmt: skip
            local = [(x - mid[0], y - mid[1]) for x, y in corners]
            verts = [(x, y, 0.0) for x, y in local] + [(x, y, height) for x, y in local]
            faces = [0, 2] + ([3] if k == 0 else []) + ([1] if k == pieces - 1 else [])
            idx: list[int] = []
            for i in faces:  # side face i: bottom i, bottom i+1, top i+1, top i
                j = (i + 1) % 4
                idx += [i, 4 + j, j, i, 4 + i, 4 + j]
            vis = c.createVisualShape(pb.GEOM_MESH, vertices=verts, indices=idx, rgbaColor=WALL_COLOR)
            body = int(
                c.createMultiBody(baseMass=0, baseVisualShapeIndex=vis, basePosition=(mid[0], mid[1], 0))
            )
            self._pose[body] = ((mid[0], mid[1], 0.0), 0.0)

    def _register(self, name: str, body: int) -> None:
        self.body_of[name] = body
        self.name_of[body] = name
        pos, orn = self._client.getBasePositionAndOrientation(body)
        self._pose[body] = (tuple(pos), self._client.getEulerFromQuaternion(orn)[2])

    def _build(self) -> None:
        w = self.world
        xmin, ymin, xmax, ymax = w.bounds()
        c = self._client
        # The tiny renderer draws bodies in creation order and shades a pixel only when it passes the depth
        # test, so small things that usually stand in front (items, people, furniture) come first and the
        # walls and floor they hide are not shaded under them. The picture is the same in any order.
        for it in w.items.values():
            sx, sy, sz = it.size
            body = self._box((sx / 2, sy / 2, sz / 2), it.position, 0.0, it.color)
            self._register(it.name, body)
        for p in w.people.values():
            body = self._cylinder(p.radius, p.height, (p.position[0], p.position[1], -50.0), p.color)
            self._register(p.name, body)
        r = w.robot
        body = self._cylinder(r.radius, r.height, (r.start[0], r.start[1], r.height / 2), ROBOT_COLOR)
        self._register(r.name, body)
        for f in w.furniture.values():
            sx, sy, h = f.size
            body = self._box((sx / 2, sy / 2, h / 2), (f.position[0], f.position[1], h / 2), f.yaw, f.color)
            self._register(f.name, body)
        for a, b in wall_segments(w):
            self._wall_mesh(a, b, w.wall_thickness, w.wall_height)
        if self.render_floor:
            floor = [(xmin, ymin, 0.0), (xmax, ymin, 0.0), (xmax, ymax, 0.0), (xmin, ymax, 0.0)]
            vis = c.createVisualShape(
                pb.GEOM_MESH, vertices=floor, indices=[0, 1, 2, 0, 2, 3], rgbaColor=FLOOR_COLOR
            )
            c.createMultiBody(baseMass=0, baseVisualShapeIndex=vis, basePosition=(0, 0, 0))

    # ------------------------------------------------------------------------------------------ moving

    def instances(self) -> dict[int, tuple[str, str, bool]]:
        """Body id -> (instance name, item class or "person" or "" for furniture, is a person)."""
        w = self.world
        table: dict[int, tuple[str, str, bool]] = {}
        for name, body in self.body_of.items():
            if name in w.items:
                table[body] = (name, w.items[name].cls, False)
            elif name in w.people:
                table[body] = (name, "person", True)
            elif name in w.furniture:
                table[body] = (name, "", False)
        return table

    def move(self, name: str, pos: tuple[float, float, float], yaw: float = 0.0) -> None:
        """Place an instance's body at ``pos`` (body centre) with heading ``yaw`` (no-op when unchanged)."""
        body = self.body_of[name]
        if self._pose.get(body) == (pos, yaw):
            return
        self._pose[body] = (pos, yaw)
        self._version += 1
        if body not in self._parked:  # a parked body is put in place when a picture wants it again
            self._place(body, pos, yaw)

    def _place(self, body: int, pos: tuple[float, float, float], yaw: float) -> None:
        c = self._client
        c.resetBasePositionAndOrientation(body, pos, c.getQuaternionFromEuler((0, 0, yaw)))

    def render(
        self,
        eye: tuple[float, float, float],
        yaw: float,
        pitch: float,
        width: int,
        height: int,
        fov_deg: float,
        near: float = 0.1,
        far: float = 10.0,
        exclude: tuple[str, ...] = (),
    ) -> tuple[
        npt.NDArray[np.uint8], npt.NDArray[np.float32], npt.NDArray[np.int32], CameraIntrinsics, Pose3D
    ]:
        """Render RGB, metric depth and segmentation from a camera at ``eye`` looking along yaw/pitch.

        The arrays are read-only (an unchanged scene returns the same ones again).
        ``pitch`` is the downward tilt in radians. Depth beyond ``far`` (nothing hit) is ``inf``. Bodies
        named in ``exclude`` (the robot carrying the camera) are left out; headless, they stay parked below
        the floor until a later call no longer excludes them (a GUI scene puts them back at once).
        Returns ``(rgb, depth, segmentation, intrinsics, optical-frame pose)``.
        """
        c = self._client
        key = (eye, yaw, pitch, width, height, fov_deg, near, far, exclude, self._version)
        if self._last is not None and self._last[0] == key:  # nothing moved: the same picture
            return self._last[1]
        hidden = {self.body_of[n] for n in exclude}
        for body in self._parked - hidden:
            self._place(body, *self._pose[body])
        for body in hidden - self._parked:
            (x, y, _), byaw = self._pose[body]
            self._place(body, (x, y, HIDDEN_Z), byaw)
        self._parked = hidden
        cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
        up = np.array([sp * cy, sp * sy, cp])  # forward x left
        target = (eye[0] + cy * cp, eye[1] + sy * cp, eye[2] - sp)
        view = c.computeViewMatrix(eye, target, up.tolist())
        proj = c.computeProjectionMatrixFOV(fov_deg, width / height, near, far)
        _, _, rgba, zbuf, seg = c.getCameraImage(width, height, view, proj, renderer=pb.ER_TINY_RENDERER)
        rgb = np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)[:, :, :3]  # a view, not a copy
        z = np.asarray(zbuf, dtype=np.float32).reshape(height, width)
        depth = z * np.float32(far - near)  # linear depth from the [0, 1] buffer, in place, float32
        np.subtract(np.float32(far), depth, out=depth)
        np.divide(np.float32(far * near), depth, out=depth)
        depth[z >= FAR_Z] = np.inf
        segm = np.asarray(seg, dtype=np.int32).reshape(height, width)
        if not self._park:
            for body in hidden:
                self._place(body, *self._pose[body])
            self._parked = set()
        fy = (height / 2) / math.tan(math.radians(fov_deg) / 2)
        intr = CameraIntrinsics(
            width=width, height=height, fx=fy, fy=fy, cx=width / 2, cy=height / 2, near=near, far=far
        )
        pose = optical_pose(eye, yaw, pitch)
        for array in (rgb, depth, segm):  # shared with later calls while nothing moves
            array.flags.writeable = False
        self._last = (key, (rgb, depth, segm, intr, pose))
        return rgb, depth, segm, intr, pose


def optical_pose(eye: Sequence[float], yaw: float, pitch: float, stamp: float = 0.0) -> Pose3D:
    """Pose of the optical frame (x right, y down, z forward) of a camera at ``eye`` (world frame, metres)
    looking along ``yaw`` (radians from +x) tilted down by ``pitch`` radians."""
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    fwd = np.array([cy * cp, sy * cp, -sp])
    left = np.array([-sy, cy, 0.0])
    up = np.array([sp * cy, sp * sy, cp])
    rot = np.stack([-left, -up, fwd], axis=1)
    position = (float(eye[0]), float(eye[1]), float(eye[2]))
    return Pose3D(position=position, orientation=_quat_from_matrix(rot), stamp=stamp)


class _Client:
    """One pybullet connection; attribute access returns pybullet functions bound to it.

    (pybullet_utils' BulletClient passes ``options=''``, which makes pybullet print ``argv[0]=`` on stdout.)
    """

    def __init__(self, mode: int) -> None:
        name = "GUI" if mode == pb.GUI else "DIRECT"
        if mode == pb.GUI and not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
            raise WorldError("gui=True needs a display (DISPLAY is not set); use the default DIRECT mode")
        self._id = pb.connect(mode)
        if self._id < 0:
            raise WorldError(f"pybullet cannot connect in {name} mode")

    def __getattr__(self, name: str) -> Any:
        attr = getattr(pb, name)
        if callable(attr) and name not in ("connect",):
            return functools.partial(attr, physicsClientId=self._id)
        return attr

    def disconnect(self) -> None:
        """Close the connection (idempotent)."""
        if self._id >= 0:
            pb.disconnect(physicsClientId=self._id)
            self._id = -1


def _quat_from_matrix(m: npt.NDArray[np.float64]) -> tuple[float, float, float, float]:
    """Unit quaternion ``(x, y, z, w)`` of a rotation matrix."""
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        w, x = 0.25 * s, (m[2, 1] - m[1, 2]) / s
        y, z = (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2]) * 2
        w, x = (m[2, 1] - m[1, 2]) / s, 0.25 * s
        y, z = (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s
    elif m[1, 1] > m[2, 2]:
        s = math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2]) * 2
        w, x = (m[0, 2] - m[2, 0]) / s, (m[0, 1] + m[1, 0]) / s
        y, z = 0.25 * s, (m[1, 2] + m[2, 1]) / s
    else:
        s = math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1]) * 2
        w, x = (m[1, 0] - m[0, 1]) / s, (m[0, 2] + m[2, 0]) / s
        y, z = (m[1, 2] + m[2, 1]) / s, 0.25 * s
    return (float(x), float(y), float(z), float(w))
