"""KGM-1 locations provider: the 2D room map becomes one octomap per room (seed 004, Fig. 2).

:func:`build_location_model` turns the world's floor polygons into vertical prisms from the floor to the wall
height (rooms, at :data:`~knic.kgm2.spatial.ROOM_RESOLUTION`) and each surface-bearing piece of furniture into
the prism just above its top where items rest (at the entity resolution). :class:`LocationsKP` publishes one
location LLKU per room once, at its first step; the prisms' OcTrees are built then (every voxel occupied).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from knic.bus import Bus
from knic.kgm1.base import KnowledgeProvider
from knic.kgm2.spatial import DEFAULT_RESOLUTION, ROOM_RESOLUTION, Prism, VolumeSet
from knic.units import LLKU, Kind

if TYPE_CHECKING:
    from knowledge_base import KnowledgeBase
    from worlds.model import World


@dataclass
class LocationModel:
    """The static spatial model: room and furniture volumes, room waypoints and each furniture's room.

    Attributes:
        rooms: one prism per room (floor polygon from z = 0 to the wall height).
        furniture: one prism per surface: the furniture's footprint from ``support_below`` under its top to
            ``support_above`` over it (where items resting on it are).
        waypoints: room -> (x, y) the robot goes to.
        furniture_room: furniture -> room.
        footprints: furniture -> footprint polygon (M, 2), every piece (obstacles to the camera's view).
    """

    rooms: VolumeSet
    furniture: VolumeSet
    waypoints: dict[str, tuple[float, float]] = field(default_factory=dict)
    furniture_room: dict[str, str] = field(default_factory=dict)
    footprints: dict[str, npt.NDArray[np.float64]] = field(default_factory=dict)

    def room_at(self, x: float, y: float, z: float = 0.5) -> str | None:
        """The room containing a world point, or None (outside, or in a wall gap)."""
        return self.rooms.at_point((x, y, z))


def build_location_model(
    world: World,
    *,
    room_resolution: float = ROOM_RESOLUTION,
    entity_resolution: float = DEFAULT_RESOLUTION,
    support_below: float = 0.05,
    support_above: float = 0.35,
) -> LocationModel:
    """Rasterise the world's rooms and furniture surfaces into prisms (see :class:`LocationModel`)."""
    rooms = [
        Prism(r.name, np.array(r.polygon, dtype=np.float64), 0.0, world.wall_height, room_resolution)
        for r in world.rooms.values()
    ]
    surfaces = [
        Prism(
            f.name,
            np.array(f.footprint(), dtype=np.float64),
            max(0.0, f.height - support_below),
            f.height + support_above,
            entity_resolution,
        )
        for f in world.furniture.values()
        if f.surface
    ]
    return LocationModel(
        rooms=VolumeSet(rooms, entity_resolution),
        furniture=VolumeSet(surfaces, entity_resolution),
        waypoints={r.name: (float(r.waypoint[0]), float(r.waypoint[1])) for r in world.rooms.values()},
        furniture_room={f.name: f.room for f in world.furniture.values()},
        footprints={f.name: np.array(f.footprint(), dtype=np.float64) for f in world.furniture.values()},
    )


class LocationsKP(KnowledgeProvider):
    """Publishes one location LLKU per room (``percept.map.location.<room>``) at its first step, then idles.

    The unit's ``attributes["prism"]`` is the room's :class:`~knic.kgm2.spatial.Prism` (its octomap via
    ``prism.octree()``); ``position`` is the room's waypoint at z = 0.
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
        """First call: build each room's octomap and publish it; later calls do nothing."""
        if self.done:
            return
        self.done = True
        for name, prism in self.model.rooms.prisms.items():
            prism.octree()
            x, y = self.model.waypoints.get(name, (0.0, 0.0))
            self.meet("room", name, now)
            self.publish(
                LLKU(
                    kind=Kind.LOCATION,
                    label=name,
                    source=self.name,
                    sensor="map",
                    stamp=now,
                    confidence=1.0,
                    position=(x, y, 0.0),
                    identity=name,
                    attributes={"prism": prism, "voxels": prism.voxel_count},
                )
            )
