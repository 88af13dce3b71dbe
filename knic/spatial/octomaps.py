"""Entity octomaps: the octomap (``pyoctomap.OcTree``, world frame) of one tracked entity (seed 004, III.B).

KGM-2 owns one :class:`EntityOctomap` per track and feeds it the depth points of each sighting; the CKU it
publishes carries the tree (read it, do not write) and the query of its occupied voxel keys
(:meth:`EntityOctomap.read_keys`), which KP' intersect with the volumes of :mod:`knic.spatial.volumes`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import pyoctomap

from knic.spatial.keys import DEFAULT_RESOLUTION, EMPTY_KEYS, KEY_OFFSET, key_centers, keys_of, unique_keys
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

    The tree carries the evidence: each cloud raises the log-odds of the voxels it hits (and lowers those its
    rays cross), :meth:`miss` lowers the log-odds of every occupied voxel when the entity was not seen where
    the camera could see it, and octomap's clamping (``clamp_min`` .. ``clamp_max`` probability) bounds both,
    so long-standing evidence still yields to a few views without the entity.

    :attr:`keys` (:meth:`read_keys`) is a query of the tree, made when asked, not on every update: the
    distinct keys of its occupied voxels. Once ``full_scan_every`` updates have passed since the last full
    read, the query reads every leaf (:meth:`occupied_keys`, so a voxel changed by anyone else is seen too);
    otherwise it searches the tree for the voxels that can be occupied (:meth:`occupied_among`): those
    occupied at the previous read and those the clouds inserted since then hit (the clouds are kept, not
    their keys, until the next read). What the KP' intersect with the room and furniture volumes is therefore
    the octomap's own state at the moment they reason, not the latest cloud. While the entity has no occupied
    voxel after an update (the map was just reset), the keys are the centroid's; after a miss they are empty.
    """

    def __init__(
        self,
        resolution: float = DEFAULT_RESOLUTION,
        *,
        reset_distance: float = 0.5,
        ray_length: float = 1.0,
        discretize: bool = True,
        clamp_min: float = 0.12,
        clamp_max: float = 0.9,
    ) -> None:
        self.resolution = resolution
        self.discretize = discretize
        self.ray_length = ray_length
        self.reset_distance = reset_distance
        self.tree = pyoctomap.OcTree(resolution)
        self.tree.setClampingThresMin(clamp_min)
        self.tree.setClampingThresMax(clamp_max)
        self.anchor: tuple[float, float, float] | None = None
        self.updates = 0
        self.resets = 0
        self.misses = 0
        #: once this many updates passed since the last read of every leaf, the next query reads them all
        self.full_scan_every = 10
        #: how many queries answered from every leaf / from the candidate voxels (for tests and benchmarks)
        self.full_scans = 0
        self.searches = 0
        self._occupied: Keys = EMPTY_KEYS  # the occupied voxels at the last query
        self._inserted: list[Points] = []  # the clouds inserted since then
        self._changed = False  # the tree changed since the last query
        self._scanned_at: int | None = None  # ``updates`` at the last full read
        self._keys: Keys = EMPTY_KEYS
        self._centroid: tuple[float, float, float] | None = None  # the keys' fallback after an update
        self._start = np.zeros(3, dtype=np.float64)  # where the rays of the cloud being inserted start

    def update(
        self, points: Points, centroid: tuple[float, float, float], origin: Sequence[float] | None
    ) -> None:
        """Insert ``points`` (world frame) seen from ``origin`` (None: the points are occupied, no rays).

        Nothing is read back from the tree here: :attr:`keys` asks it when a consumer needs the voxels.
        """
        if self.anchor is None or math.dist(centroid, self.anchor) > self.reset_distance:
            if self.anchor is not None:
                self.tree.clear()
                self._occupied = EMPTY_KEYS
                self._inserted.clear()
                self.resets += 1
            self.anchor = centroid
        # after this update, the next query reads every leaf when due: the clouds are then not needed
        updates = self.updates + 1
        full_scan_due = self._scanned_at is None or updates - self._scanned_at >= self.full_scan_every
        if len(points):
            if origin is None:
                self.tree.updateNodes(points, True)
            else:
                self.tree.insertPointCloud(
                    points, self._ray_start(centroid, origin), -1.0, False, self.discretize
                )
            if not full_scan_due:
                self._inserted.append(points)
        if full_scan_due and self._inserted:
            self._inserted.clear()
        self._changed = True
        self._centroid = centroid
        self.updates = updates

    def _full_scan_due(self) -> bool:
        return self._scanned_at is None or self.updates - self._scanned_at >= self.full_scan_every

    @property
    def keys(self) -> Keys:
        """The distinct keys of the voxels the tree holds occupied now (see :meth:`read_keys`)."""
        return self.read_keys()

    def read_keys(self) -> Keys:
        """Query the tree for its occupied voxels (cached until the tree changes); what a CKU's keys read.

        Returns the centroid's key when the last update left no occupied voxel, nothing after a miss did.
        """
        if self._changed:
            self._query()
            occupied = self._occupied
            if len(occupied) == 0 and self._centroid is not None:
                occupied = keys_of(np.array([self._centroid], dtype=np.float64), self.resolution)
            self._keys = occupied
        return self._keys

    def _query(self) -> None:
        """Refresh :attr:`_occupied` from the tree: every leaf when due, else the candidate voxels."""
        if self._full_scan_due():
            self._occupied = self.occupied_keys()
            self._scanned_at = self.updates
            self.full_scans += 1
        else:
            # octomap keys the points as single-precision coordinates: a point a hair below a voxel
            # boundary in double precision lies in the next voxel for the tree
            hit = (keys_of(p.astype(np.float32).astype(np.float64), self.resolution) for p in self._inserted)
            candidates = [self._occupied, *hit]
            self._occupied = self.occupied_among(np.concatenate(candidates))
            self.searches += 1
        self._inserted.clear()
        self._changed = False

    def miss(self) -> int:
        """Evidence against the entity: one miss update (octomap's ``prob_miss``) on every occupied voxel.

        Called when a camera frame could see where the entity is and did not detect it. Returns how many
        voxels are still occupied (both counts are tree queries); :attr:`keys` is empty when none is left.
        """
        self._changed = True  # the tree is searched afresh, whoever changed it since the last query
        self._query()
        if len(self._occupied):
            self.tree.updateNodes(key_centers(self._occupied, self.resolution), False)
        self.misses += 1
        self._centroid = None
        self._changed = True
        return len(self.read_keys())

    def occupied_among(self, keys: Keys) -> Keys:
        """The distinct ones of ``keys`` whose voxel the tree holds occupied (a tree search per voxel)."""
        if len(keys) == 0:
            return EMPTY_KEYS
        candidates = unique_keys(keys)
        search, occupied = self.tree.search, self.tree.isNodeOccupied
        keep = []
        for i, centre in enumerate(key_centers(candidates, self.resolution).tolist()):
            node = search(centre)
            if node is not None and occupied(node):
                keep.append(i)
        return candidates[keep] if len(keep) < len(candidates) else candidates

    def occupied_keys(self) -> Keys:
        """Distinct keys of the tree's occupied voxels (a pruned leaf stands for all the voxels under it)."""
        out: list[tuple[int, int, int]] = []
        res = self.resolution
        for leaf in self.tree.begin_leafs():
            if not self.tree.isNodeOccupied(leaf):
                continue
            x, y, z = leaf.getCoordinate()
            size = leaf.getSize()
            if size <= res * 1.5:
                out.append((math.floor(x / res), math.floor(y / res), math.floor(z / res)))
                continue
            n = round(size / res)
            lo = [math.floor((c - size / 2) / res + 0.5) for c in (x, y, z)]
            out.extend(
                (lo[0] + i, lo[1] + j, lo[2] + k) for i in range(n) for j in range(n) for k in range(n)
            )
        if not out:
            return EMPTY_KEYS
        return np.asarray(out, dtype=np.int64) + KEY_OFFSET

    def ray_origin(self, centroid: Sequence[float], origin: Sequence[float]) -> npt.NDArray[np.float64]:
        """Where rays start: the sensor, or the point ``ray_length`` metres from the centroid towards it."""
        return self._ray_start(centroid, origin).copy()

    def _ray_start(self, centroid: Sequence[float], origin: Sequence[float]) -> npt.NDArray[np.float64]:
        # :meth:`ray_origin` written into one buffer this octomap reuses (octomap copies it at once)
        start = self._start
        ox, oy, oz = origin
        distance = math.dist(origin, centroid)
        if self.ray_length <= 0 or distance <= self.ray_length:
            start[0], start[1], start[2] = ox, oy, oz
            return start
        f = self.ray_length / distance
        cx, cy, cz = centroid
        start[0], start[1], start[2] = cx + (ox - cx) * f, cy + (oy - cy) * f, cz + (oz - cz) * f
        return start

    def occupied_at(self, point: Sequence[float]) -> bool:
        """Whether the octree holds an occupied voxel at a world-frame point (reads the tree itself)."""
        node = self.tree.search(np.asarray(point, dtype=np.float64))
        return node is not None and bool(self.tree.isNodeOccupied(node))
