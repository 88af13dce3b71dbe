"""Entity octomaps: the octomap (``pyoctomap.OcTree``, world frame) of one tracked entity (seed 004, III.B).

KGM-2 owns one :class:`EntityOctomap` per track and feeds it the depth points of each sighting; the CKU it
publishes carries the tree (read it, do not write) and the voxel keys of the latest sighting, which KP'
intersect with the volumes of :mod:`knic.spatial.volumes`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import pyoctomap

from knic.spatial.keys import DEFAULT_RESOLUTION, EMPTY_KEYS, keys_of
from knic.units import Keys, Points


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
        self.keys: Keys = EMPTY_KEYS
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
