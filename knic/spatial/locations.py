"""The static places of the map: rooms and furniture as records, and the model a level builds from them.

A :class:`Location` is what one location unit carries (KGM-1's LLKU on ``percept.map.location.<name>``,
then KGM-2's CKU on ``cognition.location.<name>``): a room with its prism from the floor to the ceiling, or a
piece of furniture with its footprint and, for a surface, the prism just above its top where items rest. A
level that needs places (KGM-2 for the role's room policies, the KP' for where things are) adds every location
unit it receives to its own :class:`LocationModel`; nobody hands the model around.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from core.errors import InferenceError
from knic.spatial.keys import DEFAULT_RESOLUTION
from knic.spatial.volumes import Prism, VolumeSet

#: ``Location.cls`` of a room
ROOM = "room"
#: ``Location.cls`` of a piece of furniture
FURNITURE = "furniture"


@dataclass(frozen=True, eq=False)
class Location:
    """One place of the static map (world frame, metres).

    Attributes:
        name: the place's PDDL symbol (``"kitchen"``, ``"table"``).
        cls: :data:`ROOM` or :data:`FURNITURE`.
        footprint: the floor polygon (M, 2): the room's outline or the furniture's footprint.
        volume: a room's prism (floor to ceiling); a surface's support prism (where items resting on it are);
            None for furniture that carries nothing.
        waypoint: where the robot goes in a room (rooms only).
        room: the room a piece of furniture stands in (furniture only).
    """

    name: str
    cls: str
    footprint: npt.NDArray[np.float64]
    volume: Prism | None = None
    waypoint: tuple[float, float] | None = None
    room: str | None = None

    def __post_init__(self) -> None:
        if self.cls not in (ROOM, FURNITURE):
            raise InferenceError(f"location {self.name!r}: class {self.cls!r} is not {ROOM} or {FURNITURE}")
        if self.cls == ROOM and self.volume is None:
            raise InferenceError(f"location {self.name!r}: a room needs its volume")


class LocationModel:
    """Rooms and furniture volumes, room waypoints, each furniture's room and footprint.

    Filled with :meth:`add`, one location at a time, in the order the map lists them (queries break ties by
    that order).

    Args:
        entity_resolution: resolution, metres, of the entity keys the volume queries receive.

    Attributes:
        rooms: one prism per room (floor polygon from z = 0 to the wall height).
        furniture: one prism per surface: the furniture's footprint from a little under its top to the height
            items resting on it reach.
        waypoints: room -> (x, y) the robot goes to.
        furniture_room: furniture -> room (every piece).
        footprints: furniture -> footprint polygon (M, 2), every piece (obstacles to the camera's view).
    """

    def __init__(self, entity_resolution: float = DEFAULT_RESOLUTION) -> None:
        self.rooms = VolumeSet((), entity_resolution)
        self.furniture = VolumeSet((), entity_resolution)
        self.waypoints: dict[str, tuple[float, float]] = {}
        self.furniture_room: dict[str, str] = {}
        self.footprints: dict[str, npt.NDArray[np.float64]] = {}
        self._locations: dict[str, Location] = {}
        #: counts the changes (a consumer caching something derived from the model compares it)
        self.version = 0

    def add(self, location: Location) -> None:
        """Add a place (a place of the same name is replaced in its position).

        Raises:
            InferenceError: its volume's resolution differs from the others of its class; nothing changes.
        """
        if location.cls == ROOM:
            assert location.volume is not None
            self.rooms.add(location.volume)
            if location.waypoint is not None:
                self.waypoints[location.name] = location.waypoint
        else:
            if location.volume is not None:
                self.furniture.add(location.volume)
            if location.room is not None:
                self.furniture_room[location.name] = location.room
            self.footprints[location.name] = location.footprint
        self._locations[location.name] = location
        self.version += 1

    def __iter__(self) -> Iterator[Location]:
        """Every place, in the order added."""
        return iter(list(self._locations.values()))

    def __len__(self) -> int:
        return len(self._locations)

    def room_at(self, x: float, y: float, z: float = 0.5) -> str | None:
        """The room containing a world point, or None (outside, or in a wall gap)."""
        return self.rooms.at_point((x, y, z))

    def room_near(self, x: float, y: float, within: float, z: float = 0.5) -> str | None:
        """The room containing a world point, else the room nearest it within ``within`` metres, else
        None."""
        return self.rooms.nearest((x, y, z), within)
