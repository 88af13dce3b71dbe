"""The spatial floor under the KGM levels: voxel keys, volumes, entity octomaps and the map's places.

Every level stands on it, none is below it: it imports only :mod:`knic.units` and :mod:`core`.

* :mod:`knic.spatial.keys` -- octomap key space and vectorised voxel-set operations.
* :mod:`knic.spatial.volumes` -- vertical prisms (rooms, furniture supports) and named sets of them; the
  array form of the one point-in-polygon test (:func:`core.geometry.inside_polygon`).
* :mod:`knic.spatial.octomaps` -- the octomap of one tracked entity.
* :mod:`knic.spatial.locations` -- the places of the static map (:class:`Location`) and the model a level
  builds from the location units it receives.
"""

from knic.spatial.keys import (
    DEFAULT_RESOLUTION,
    EMPTY_KEYS,
    KEY_OFFSET,
    ROOM_RESOLUTION,
    coarsen,
    key_centers,
    keys_of,
    shift_between,
    unique_keys,
)
from knic.spatial.locations import FURNITURE, ROOM, Location, LocationModel
from knic.spatial.octomaps import EntityOctomap
from knic.spatial.volumes import Prism, VolumeSet, points_in_polygon

__all__ = [
    "DEFAULT_RESOLUTION",
    "EMPTY_KEYS",
    "FURNITURE",
    "KEY_OFFSET",
    "ROOM",
    "ROOM_RESOLUTION",
    "EntityOctomap",
    "Location",
    "LocationModel",
    "Prism",
    "VolumeSet",
    "coarsen",
    "key_centers",
    "keys_of",
    "points_in_polygon",
    "shift_between",
    "unique_keys",
]
