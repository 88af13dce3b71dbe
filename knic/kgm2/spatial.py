"""Spatial abstraction with octomaps (seed 004, section III.B): rooms, furniture and tracked entities.

Every location and every tracked entity is an octomap (``pyoctomap.OcTree``) in the **world frame** (metres, z
up). Besides the OcTree itself each map keeps a numpy mirror of its occupied voxel keys so that KP' components
can intersect maps with vectorised key operations instead of walking trees voxel by voxel.

Key space: octomap's, ``key = floor(coordinate / resolution) + 32768`` per axis. Entities use
:data:`DEFAULT_RESOLUTION`; a volume built at a coarser resolution ``r * 2**s`` converts fine keys with
:func:`coarsen` (an arithmetic shift, exactly what octomap does between depths).

* :class:`Prism`: a vertical prism (a 2D polygon between two heights), the shape of a room from the 2D map
  (the paper's Fig. 2) and of a piece of furniture's support region. Rasterised once into a boolean mask over
  its key bounding box; :meth:`Prism.count_inside` counts how many of an entity's voxels fall inside.
* :class:`EntityOctomap`: the octomap of one tracked entity, fed with depth points by ``insertPointCloud``
  (ray casting from the sensor origin clears free space); cleared when the entity has moved away.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
import pyoctomap

from core.errors import InferenceError
from knic.units import Keys, Points

#: Entity octomap resolution, metres.
DEFAULT_RESOLUTION = 0.05
#: Room octomap resolution, metres (DEFAULT_RESOLUTION * 2).
ROOM_RESOLUTION = 0.1
#: Octomap's key offset (tree_max_val for the default depth 16).
KEY_OFFSET = 32768

_EMPTY_KEYS: Keys = np.zeros((0, 3), dtype=np.int64)


def keys_of(points: Points, resolution: float = DEFAULT_RESOLUTION) -> Keys:
    """Octomap voxel keys of world-frame points (same rounding as ``OcTree.coordToKey``), shape (N, 3)."""
    if len(points) == 0:
        return _EMPTY_KEYS
    return np.floor(points * (1.0 / resolution)).astype(np.int64) + KEY_OFFSET


def unique_keys(keys: Keys) -> Keys:
    """Distinct keys (sorted), shape (M, 3)."""
    if len(keys) <= 1:
        return keys
    packed = np.unique((keys[:, 0] << 32) | (keys[:, 1] << 16) | keys[:, 2])
    return np.stack([packed >> 32, (packed >> 16) & 0xFFFF, packed & 0xFFFF], axis=1)


def key_centers(keys: Keys, resolution: float = DEFAULT_RESOLUTION) -> Points:
    """World-frame centres of voxels, shape (N, 3)."""
    return (keys - KEY_OFFSET + 0.5).astype(np.float64) * resolution


def coarsen(keys: Keys, shift: int) -> Keys:
    """Keys of the voxels ``2**shift`` times larger that contain the given voxels."""
    if shift == 0:
        return keys
    return ((keys - KEY_OFFSET) >> shift) + KEY_OFFSET


def shift_between(fine: float, coarse: float) -> int:
    """The ``s`` with ``coarse == fine * 2**s``.

    Raises:
        InferenceError: the coarse resolution is not a power-of-two multiple of the fine one.
    """
    ratio = coarse / fine
    shift = round(np.log2(ratio))
    if shift < 0 or abs(fine * 2**shift - coarse) > 1e-9:
        raise InferenceError(f"resolution {coarse} is not {fine} times a power of two")
    return int(shift)


def points_in_polygon(xy: npt.NDArray[np.float64], polygon: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
    """Even-odd rule: which of the (N, 2) points lie inside the closed polygon (M, 2); vectorised over
    points."""
    inside = np.zeros(len(xy), dtype=bool)
    x, y = xy[:, 0], xy[:, 1]
    count = len(polygon)
    for i in range(count):
        x1, y1 = polygon[i]
        x2, y2 = polygon[(i + 1) % count]
        if y1 == y2:
            continue
        crosses = (y1 > y) != (y2 > y)
        x_at = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
        inside ^= crosses & (x < x_at)
    return inside


@dataclass(eq=False)
class Prism:
    """A named vertical prism: ``polygon`` (world-frame x, y in metres) extruded from ``z_min`` to ``z_max``.

    Rasterised at ``resolution`` on construction: a voxel belongs to the prism when its centre does.
    """

    name: str
    polygon: npt.NDArray[np.float64]
    z_min: float
    z_max: float
    resolution: float = ROOM_RESOLUTION
    key_min: npt.NDArray[np.int64] = field(init=False)
    key_max: npt.NDArray[np.int64] = field(init=False)
    mask: npt.NDArray[np.bool_] = field(init=False)
    _octree: pyoctomap.OcTree | None = field(init=False, default=None)

    def __post_init__(self) -> None:
        poly = np.asarray(self.polygon, dtype=np.float64)
        if poly.ndim != 2 or poly.shape[1] != 2 or len(poly) < 3 or not np.isfinite(poly).all():
            raise InferenceError(f"volume {self.name!r}: polygon must be 3 or more finite (x, y) vertices")
        if not self.z_max > self.z_min:
            raise InferenceError(f"volume {self.name!r}: z_max {self.z_max} must exceed z_min {self.z_min}")
        self.polygon = poly
        lo = keys_of(np.array([[*poly.min(axis=0), self.z_min]]), self.resolution)[0]
        hi = keys_of(np.array([[*poly.max(axis=0), self.z_max]]), self.resolution)[0]
        self.key_min, self.key_max = lo, hi
        ix = np.arange(lo[0], hi[0] + 1)
        iy = np.arange(lo[1], hi[1] + 1)
        gx, gy = np.meshgrid(ix, iy, indexing="ij")
        centers = (np.stack([gx.ravel(), gy.ravel()], axis=1) - KEY_OFFSET + 0.5) * self.resolution
        cells = points_in_polygon(centers, poly).reshape(gx.shape)
        zc = (np.arange(lo[2], hi[2] + 1) - KEY_OFFSET + 0.5) * self.resolution
        zin = (zc >= self.z_min) & (zc <= self.z_max)
        self.mask = cells[:, :, None] & zin[None, None, :]

    @property
    def voxel_count(self) -> int:
        """Number of voxels in the prism."""
        return int(self.mask.sum())

    def keys(self) -> Keys:
        """Every voxel key of the prism at its resolution, shape (N, 3)."""
        return np.argwhere(self.mask).astype(np.int64) + self.key_min

    def inside(self, keys: Keys) -> npt.NDArray[np.bool_]:
        """Which of the keys (at this prism's resolution) are voxels of the prism."""
        if len(keys) == 0:
            return np.zeros(0, dtype=bool)
        rel = keys - self.key_min
        ok = np.all((rel >= 0) & (keys <= self.key_max), axis=1)
        result = np.zeros(len(keys), dtype=bool)
        r = rel[ok]
        result[ok] = self.mask[r[:, 0], r[:, 1], r[:, 2]]
        return result

    def count_inside(self, keys: Keys) -> int:
        """How many of the keys (at this prism's resolution) fall inside the prism."""
        return int(self.inside(keys).sum())

    def contains_point(self, point: Sequence[float]) -> bool:
        """Whether a world-frame point lies in one of the prism's voxels."""
        return bool(self.inside(keys_of(np.asarray([point], dtype=np.float64), self.resolution))[0])

    def octree(self) -> pyoctomap.OcTree:
        """The prism as an OcTree (every voxel occupied), built on first use and kept."""
        if self._octree is None:
            tree = pyoctomap.OcTree(self.resolution)
            tree.updateNodes(key_centers(self.keys(), self.resolution), True)
            self._octree = tree
        return self._octree


class VolumeSet:
    """Named prisms at one resolution (all rooms, or all furniture) with vectorised membership queries.

    Args:
        prisms: the volumes; names must be unique.
        entity_resolution: the resolution of the keys callers pass in (converted with :func:`coarsen`).
    """

    def __init__(self, prisms: Sequence[Prism], entity_resolution: float = DEFAULT_RESOLUTION) -> None:
        names = [p.name for p in prisms]
        if len(set(names)) != len(names):
            raise InferenceError(f"volume names must be unique: {sorted(names)}")
        resolutions = {p.resolution for p in prisms}
        if len(resolutions) > 1:
            raise InferenceError(f"volumes mix resolutions {sorted(resolutions)}")
        self.prisms = {p.name: p for p in prisms}
        self.resolution = resolutions.pop() if resolutions else entity_resolution
        self.entity_resolution = entity_resolution
        self._shift = shift_between(entity_resolution, self.resolution)

    def __contains__(self, name: object) -> bool:
        return name in self.prisms

    def names(self) -> list[str]:
        """Volume names in insertion order."""
        return list(self.prisms)

    def overlaps(self, entity_keys: Keys) -> dict[str, int]:
        """Voxels of an entity (keys at the entity resolution) falling in each volume; zero counts left
        out."""
        if len(entity_keys) == 0:
            return {}
        coarse = unique_keys(coarsen(entity_keys, self._shift))
        counts = {}
        for name, prism in self.prisms.items():
            if np.any(coarse.max(axis=0) < prism.key_min) or np.any(coarse.min(axis=0) > prism.key_max):
                continue
            n = prism.count_inside(coarse)
            if n:
                counts[name] = n
        return counts

    def best(self, entity_keys: Keys) -> tuple[str | None, float]:
        """The volume holding most of the entity's voxels and that share of its voxels (0 when none)."""
        counts = self.overlaps(entity_keys)
        if not counts:
            return None, 0.0
        total = len(unique_keys(coarsen(entity_keys, self._shift)))
        name = max(counts, key=lambda k: counts[k])
        return name, counts[name] / total

    def at_point(self, point: Sequence[float]) -> str | None:
        """The volume containing a world-frame point, or None."""
        key = tuple(math.floor(float(v) / self.resolution) + KEY_OFFSET for v in point)
        for name, prism in self.prisms.items():
            lo, hi = prism.key_min, prism.key_max
            if (
                all(lo[i] <= key[i] <= hi[i] for i in range(3))
                and prism.mask[key[0] - lo[0], key[1] - lo[1], key[2] - lo[2]]
            ):
                return name
        return None


class EntityOctomap:
    """The octomap of one tracked entity in the world frame.

    ``update`` inserts a point cloud with ray casting from the sensor origin; when the new cloud's centroid is
    more than ``reset_distance`` metres from the centroid the map was started at, the map is cleared
    first (the entity moved: its old voxels no longer describe it). With ``discretize`` (the default)
    octomap first reduces the cloud to distinct end voxels and casts one ray per voxel (octomap's own
    discretised insertion: a voxel hit by several points of one cloud gets one hit update), which is cheaper
    for dense depth clouds. Rays are cast over the last ``ray_length`` metres before the entity only (from the
    point that far from the centroid towards the sensor; 0 or less: from the sensor itself): an entity's own
    octomap needs the free space around the entity, not along the whole line of sight, and long rays are what
    insertion costs.

    :attr:`keys` mirrors the voxels hit by the latest cloud: one key per point (a voxel hit by several points
    appears several times; intersections count distinct voxels).
    """

    def __init__(
        self,
        resolution: float = DEFAULT_RESOLUTION,
        *,
        reset_distance: float = 0.5,
        ray_length: float = 1.0,
        discretize: bool = True,
    ) -> None:
        self.resolution = resolution
        self.discretize = discretize
        self.ray_length = ray_length
        self.reset_distance = reset_distance
        self.tree = pyoctomap.OcTree(resolution)
        self.keys: Keys = _EMPTY_KEYS
        self.anchor: tuple[float, float, float] | None = None
        self.updates = 0
        self.resets = 0

    def update(
        self, points: Points, centroid: tuple[float, float, float], origin: Sequence[float] | None
    ) -> Keys:
        """Insert ``points`` (world frame) seen from ``origin``; return and keep the voxel keys they hit."""
        if self.anchor is None or math.dist(centroid, self.anchor) > self.reset_distance:
            if self.anchor is not None:
                self.tree.clear()
                self.resets += 1
            self.anchor = centroid
        if len(points):
            if origin is None:
                self.tree.updateNodes(points, True)
            else:
                self.tree.insertPointCloud(
                    points, self.ray_origin(centroid, origin), -1.0, False, self.discretize
                )
            self.keys = keys_of(points, self.resolution)
        else:
            self.keys = keys_of(np.array([centroid], dtype=np.float64), self.resolution)
        self.updates += 1
        return self.keys

    def ray_origin(self, centroid: Sequence[float], origin: Sequence[float]) -> npt.NDArray[np.float64]:
        """Where rays start: the sensor, or the point ``ray_length`` metres from the centroid towards it."""
        distance = math.dist(origin, centroid)
        if self.ray_length <= 0 or distance <= self.ray_length:
            return np.array(origin, dtype=np.float64)
        f = self.ray_length / distance
        return np.array([c + (o - c) * f for c, o in zip(centroid, origin, strict=True)], dtype=np.float64)

    def occupied_at(self, point: Sequence[float]) -> bool:
        """Whether the octree holds an occupied voxel at a world-frame point (reads the tree itself)."""
        node = self.tree.search(np.asarray(point, dtype=np.float64))
        return node is not None and bool(self.tree.isNodeOccupied(node))
