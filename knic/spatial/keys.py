"""Octomap voxel keys: the key space every octomap of KnIC shares, and vectorised voxel sets over it.

Key space: octomap's, ``key = floor(coordinate / resolution) + 32768`` per axis, world frame (metres, z up).
Entities use :data:`DEFAULT_RESOLUTION`; a volume built at a coarser resolution ``r * 2**s`` converts fine
keys with :func:`coarsen` (an arithmetic shift, exactly what octomap does between depths). A voxel set is an
(N, 3) int64 array of keys (:data:`knic.units.Keys`); the functions here never modify their inputs.
"""

from __future__ import annotations

import numpy as np

from core.errors import InferenceError
from knic.units import Keys, Points

#: Entity octomap resolution, metres.
DEFAULT_RESOLUTION = 0.05
#: Room octomap resolution, metres (DEFAULT_RESOLUTION * 2).
ROOM_RESOLUTION = 0.1
#: Octomap's key offset (tree_max_val for the default depth 16).
KEY_OFFSET = 32768

EMPTY_KEYS: Keys = np.zeros((0, 3), dtype=np.int64)
EMPTY_KEYS.setflags(write=False)


def keys_of(points: Points, resolution: float = DEFAULT_RESOLUTION) -> Keys:
    """Octomap voxel keys of world-frame points (octomap's formula), shape (N, 3).

    The points are keyed in double precision; octomap's trees key single-precision coordinates, which for a
    point a hair below a voxel boundary can be the next voxel (round the points through ``np.float32`` to
    get the tree's keys).
    """
    if len(points) == 0:
        return EMPTY_KEYS
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
