"""KGM-1 locations provider: the 2D map becomes one octomap per room and per surface (seed 004, Fig. 2).

:func:`build_location_model` reads the world's map: each room's floor polygon becomes a vertical prism from
the floor to the wall height (at :data:`~knic.spatial.ROOM_RESOLUTION`), each piece of furniture a
:class:`~knic.spatial.Location` with its footprint and, for a surface, the prism just above its top where
items rest (at the entity resolution). :class:`LocationsKP` publishes one location LLKU per place once, at its
first step; KGM-2 turns them into location CKUs and the levels above build their own
:class:`~knic.spatial.LocationModel` from those units.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from knic.bus import Bus
from knic.kgm1.base import KnowledgeProvider
from knic.spatial import (
    DEFAULT_RESOLUTION,
    FURNITURE,
    ROOM,
    ROOM_RESOLUTION,
    Location,
    LocationModel,
    Prism,
)
from knic.units import LLKU, Kind

if TYPE_CHECKING:
    from knowledge_base import KnowledgeBase
    from worlds.model import World


def build_location_model(
    world: World,
    *,
    room_resolution: float = ROOM_RESOLUTION,
    entity_resolution: float = DEFAULT_RESOLUTION,
    support_below: float = 0.05,
    support_above: float = 0.35,
) -> LocationModel:
    """The world's rooms, then its furniture, as places (see :class:`~knic.spatial.LocationModel`).

    A surface's support prism reaches from ``support_below`` metres under its top to ``support_above``
    metres over it.
    """
    model = LocationModel(entity_resolution)
    for r in world.rooms.values():
        polygon = np.array(r.polygon, dtype=np.float64)
        model.add(
            Location(
                r.name,
                ROOM,
                polygon,
                Prism(r.name, polygon, 0.0, world.wall_height, room_resolution),
                waypoint=(float(r.waypoint[0]), float(r.waypoint[1])),
            )
        )
    for f in world.furniture.values():
        footprint = np.array(f.footprint(), dtype=np.float64)
        support = None
        if f.surface:
            z_min, z_max = max(0.0, f.height - support_below), f.height + support_above
            support = Prism(f.name, footprint, z_min, z_max, entity_resolution)
        model.add(Location(f.name, FURNITURE, footprint, support, room=f.room))
    return model


class LocationsKP(KnowledgeProvider):
    """Publishes one location LLKU per place (``percept.map.location.<name>``) at its first step, then idles.

    The unit's ``attributes["location"]`` is the :class:`~knic.spatial.Location` (its volume's octomap via
    ``location.volume.octree()``, built here); ``label`` and ``identity`` are the place's symbol; ``position``
    is a room's waypoint, or a piece of furniture's footprint centre, at z = 0. Rooms are met in the knowledge
    base (added as instances when it does not hold them).
    """

    def __init__(
        self,
        model: LocationModel,
        bus: Bus,
        kb: KnowledgeBase | None = None,
        *,
        name: str = "kp.locations",
        frequency: float = 0.1,
    ) -> None:
        super().__init__(name, frequency, bus, kb, "map")
        self.model = model
        self.done = False

    def step(self, now: float) -> None:
        """First call: build each place's octomap and publish it; later calls do nothing."""
        if self.done:
            return
        self.done = True
        for location in self.model:
            attributes: dict[str, object] = {"location": location}
            if location.volume is not None:
                location.volume.octree()
                attributes["voxels"] = location.volume.voxel_count
            if location.cls == ROOM:
                x, y = location.waypoint or (0.0, 0.0)
                self.meet(ROOM, location.name, now)
            else:
                x, y = (float(v) for v in location.footprint.mean(axis=0))
            self.publish(
                LLKU(
                    kind=Kind.LOCATION,
                    label=location.name,
                    source=self.name,
                    sensor="map",
                    stamp=now,
                    confidence=1.0,
                    position=(x, y, 0.0),
                    identity=location.name,
                    attributes=attributes,
                )
            )
