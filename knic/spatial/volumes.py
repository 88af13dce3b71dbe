"""Volumes of the static map: vertical prisms rasterised into voxel masks, and named sets of them.

* :class:`Prism`: a vertical prism (a 2D polygon between two heights), the shape of a room from the 2D map
  (seed 004, Fig. 2) and of a piece of furniture's support region. Rasterised once into a boolean mask over
  its key bounding box; :meth:`Prism.count_inside` counts how many of an entity's voxels fall inside, and
  :meth:`Prism.octree` is the prism as an octomap.
* :class:`VolumeSet`: named prisms at one resolution (every room, or every surface) answering which volume
  holds an entity's voxels or a point.

Coordinates are world-frame metres; keys are octomap keys (:mod:`knic.spatial.keys`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
import pyoctomap

from core.errors import InferenceError
from core.geometry import inside_polygon
from knic.spatial.keys import (
    DEFAULT_RESOLUTION,
    KEY_OFFSET,
    ROOM_RESOLUTION,
    coarsen,
    key_centers,
    keys_of,
    shift_between,
    unique_keys,
)
from knic.units import Keys


def points_in_polygon(xy: npt.NDArray[np.float64], polygon: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
    """Which of the (N, 2) points lie inside the closed polygon (M, 2), by
    :func:`core.geometry.inside_polygon`."""
    return inside_polygon(xy[:, 0], xy[:, 1], polygon)


@dataclass(eq=False)
class Prism:
    """A named vertical prism: ``polygon`` (world-frame x, y in metres) extruded from ``z_min`` to ``z_max``.

    Rasterised at ``resolution`` on construction: a voxel belongs to the prism when its centre does.

    Raises:
        InferenceError: fewer than three finite vertices, or ``z_max`` not above ``z_min``.
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

    Queries visit the volumes in the order they were added (ties go to the first).

    Args:
        prisms: the first volumes; names must be unique; more come with :meth:`add`.
        entity_resolution: the resolution of the keys callers pass in (converted with :func:`coarsen`).
        resolution: the volumes' resolution; None: the first prism's (the entity resolution while empty).

    Raises:
        InferenceError: duplicate names, mixed resolutions, or a resolution that is not the entity
            resolution times a power of two.
    """

    def __init__(
        self,
        prisms: Sequence[Prism] = (),
        entity_resolution: float = DEFAULT_RESOLUTION,
        *,
        resolution: float | None = None,
    ) -> None:
        names = [p.name for p in prisms]
        if len(set(names)) != len(names):
            raise InferenceError(f"volume names must be unique: {sorted(names)}")
        self.prisms: dict[str, Prism] = {}
        self.entity_resolution = entity_resolution
        self._fixed = resolution is not None or bool(prisms)
        self.resolution = resolution if resolution is not None else entity_resolution
        if prisms and resolution is None:
            self.resolution = prisms[0].resolution
        self._shift = shift_between(entity_resolution, self.resolution)
        for prism in prisms:
            self.add(prism)

    def add(self, prism: Prism) -> None:
        """Add a volume, or replace the one of the same name in its place.

        Raises:
            InferenceError: its resolution differs from the set's; nothing changes.
        """
        if not self._fixed:
            self._shift = shift_between(self.entity_resolution, prism.resolution)
            self.resolution = prism.resolution
            self._fixed = True
        elif prism.resolution != self.resolution:
            raise InferenceError(
                f"volume {prism.name!r}: resolution {prism.resolution} is not the set's {self.resolution}"
            )
        self.prisms[prism.name] = prism

    def __contains__(self, name: object) -> bool:
        return name in self.prisms

    def __len__(self) -> int:
        return len(self.prisms)

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

    def nearest(self, point: Sequence[float], within: float) -> str | None:
        """The volume containing a world-frame point, else the one whose outline passes nearest it in the
        plane, if no farther than ``within`` metres (a point a little outside every room: a noisy estimate
        of a source near a wall); None when there is none that near."""
        inside = self.at_point(point)
        if inside is not None or within <= 0:
            return inside
        x, y = float(point[0]), float(point[1])
        best, best_d = None, float(within)
        for name, prism in self.prisms.items():
            d = _distance_to_outline(x, y, prism.polygon)
            if d <= best_d:
                best, best_d = name, d
        return best


def _distance_to_outline(x: float, y: float, polygon: npt.NDArray[np.float64]) -> float:
    """Planar distance from (x, y) to the closed polygon's edges (M, 2)."""
    a = np.asarray(polygon, dtype=np.float64)[:, :2]
    b = np.roll(a, -1, axis=0)
    ab = b - a
    length2 = np.maximum((ab**2).sum(axis=1), 1e-12)
    t = np.clip(((x - a[:, 0]) * ab[:, 0] + (y - a[:, 1]) * ab[:, 1]) / length2, 0.0, 1.0)
    dx = a[:, 0] + t * ab[:, 0] - x
    dy = a[:, 1] + t * ab[:, 1] - y
    return float(np.sqrt(dx**2 + dy**2).min())
