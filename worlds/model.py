"""The world as data: rooms, doors, furniture, items, people, devices, the robot's start.

Instances of these classes are immutable and already validated (built by :mod:`worlds.loader`). All
coordinates are in the world frame (metres, z up, yaw radians counter-clockwise from +x).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from worlds.geometry import Point, point_in_polygon, polygon_centroid, rect_corners, rect_distance

#: the highest furniture top a person sits or lies on (a bed, a sofa, an armchair); at a higher piece
#: (a table, a counter, a desk) a person stands beside it
SEAT_MAX_HEIGHT = 0.65

#: device kinds and the PDDL type they have
DEVICE_KINDS = ("light", "dimmer", "blinds", "bell")


@dataclass(frozen=True, slots=True)
class Room:
    """A room: a simple floor polygon (counter-clockwise or not) and the waypoint the robot goes to.

    Attributes:
        name: PDDL room symbol.
        polygon: floor outline vertices.
        waypoint: free point inside the room used by "go to room" (default: the centroid).
    """

    name: str
    polygon: tuple[Point, ...]
    waypoint: Point

    def contains(self, x: float, y: float) -> bool:
        """True when ``(x, y)`` is on the room's floor (boundary included)."""
        return point_in_polygon(x, y, self.polygon)

    @property
    def centroid(self) -> Point:
        """Area centroid of the floor polygon."""
        return polygon_centroid(self.polygon)


@dataclass(frozen=True, slots=True)
class Door:
    """An opening in a wall. ``rooms`` are the two rooms it connects; an entrance door has one room.

    Attributes:
        rooms: the connected rooms (``(room,)`` for the apartment's front door to the outside).
        position: centre of the opening, on the shared wall.
        width: clear width in metres.
    """

    rooms: tuple[str, ...]
    position: Point
    width: float = 0.9


@dataclass(frozen=True, slots=True)
class Furniture:
    """A piece of furniture: a box on the floor whose top may carry items.

    Attributes:
        name: PDDL furniture symbol.
        room: the room it stands in.
        position: centre of its footprint.
        size: ``(sx, sy, height)`` in metres (sx along the furniture's own x axis).
        yaw: heading of its own x axis.
        surface: True when items can be placed on its top (at z = height).
        color: RGBA in 0..1.
    """

    name: str
    room: str
    position: Point
    size: tuple[float, float, float]
    yaw: float = 0.0
    surface: bool = True
    color: tuple[float, float, float, float] = (0.6, 0.45, 0.3, 1.0)

    @property
    def height(self) -> float:
        """Height of the top surface in metres."""
        return self.size[2]

    @property
    def seat(self) -> bool:
        """True when a person sits or lies on its top (no higher than :data:`SEAT_MAX_HEIGHT`)."""
        return self.size[2] <= SEAT_MAX_HEIGHT

    def seat_spot(self, radius: float, items: list[tuple[Point, float]]) -> Point:
        """Where a person of body ``radius`` sits on it: its middle, unless one of ``items`` (their centre
        and half length) stands there; then the place along its long side farthest from every item."""

        def room_left(p: Point) -> float:
            return min((math.dist(p, q) - half - radius for q, half in items), default=math.inf)

        if room_left(self.position) >= 0.05:
            return self.position
        long_x = self.size[0] >= self.size[1]
        free = max(0.0, (self.size[0] if long_x else self.size[1]) / 2 - radius)
        offsets = [free * (k / 4 - 1) for k in range(9)]
        spots = [self.to_world(t, 0.0) if long_x else self.to_world(0.0, t) for t in offsets]
        return max(spots, key=lambda p: (room_left(p), -math.dist(p, self.position)))

    def beside(self, radius: float, clearance: float = 0.1) -> list[Point]:
        """Where a person of body ``radius`` stands next to it: the middle of each side, ``clearance`` m off
        the edge, long sides first (the caller keeps those that are free)."""
        sx, sy = self.size[0] / 2, self.size[1] / 2
        sides = [(0.0, sy + radius + clearance), (0.0, -sy - radius - clearance)]
        ends = [(sx + radius + clearance, 0.0), (-sx - radius - clearance, 0.0)]
        order = sides + ends if sx >= sy else ends + sides
        return [self.to_world(dx, dy) for dx, dy in order]

    def footprint(self) -> list[Point]:
        """Footprint corners (counter-clockwise)."""
        return rect_corners(self.position[0], self.position[1], self.size[0], self.size[1], self.yaw)

    def distance(self, x: float, y: float) -> float:
        """Distance from ``(x, y)`` to the footprint (0 inside)."""
        return rect_distance(x, y, self.position[0], self.position[1], self.size[0], self.size[1], self.yaw)

    def to_world(self, dx: float, dy: float) -> Point:
        """World point of the furniture-frame offset ``(dx, dy)`` from its centre."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return (self.position[0] + c * dx - s * dy, self.position[1] + s * dx + c * dy)


@dataclass(frozen=True, slots=True)
class Prior:
    """One likely location of an item or person, as the ERL task gives the robot.

    Attributes:
        room: the room.
        probability: in (0, 1].
        furniture: the furniture in that room, when the prior names one.
    """

    room: str
    probability: float
    furniture: str | None = None


@dataclass(frozen=True, slots=True)
class Item:
    """A movable object.

    Attributes:
        name: PDDL item symbol.
        cls: detector class label (usually the name).
        position: initial centre ``(x, y, z)`` (resolved from ``on`` by the loader).
        on: the furniture it starts on, or ``None`` (on the floor).
        size: ``(sx, sy, sz)`` box size in metres.
        color: RGBA in 0..1.
        priors: up to three likely locations (the robot's prior knowledge).
    """

    name: str
    cls: str
    position: tuple[float, float, float]
    on: str | None
    size: tuple[float, float, float] = (0.08, 0.08, 0.1)
    color: tuple[float, float, float, float] = (0.2, 0.4, 0.9, 1.0)
    priors: tuple[Prior, ...] = ()


@dataclass(frozen=True, slots=True)
class Person:
    """A person of the scenario.

    Attributes:
        name: PDDL person symbol.
        position: initial ``(x, y)`` (resolved from ``on`` by the loader).
        on: furniture the person sits or lies on (``bed``, ``sofa``), or ``None`` (standing). A person a
            world file puts at furniture too high to sit on (:attr:`Furniture.seat`) stands beside it.
        behaviour: ``"static"`` (stays unless a scenario moves them) or ``"wander"`` (walks between room
            waypoints at random, seeded).
        present: False for a visitor outside the apartment until a scenario lets them in.
        known: False for a stranger: the robot does not know them beforehand (no symbol in its knowledge base,
            no face its recogniser can name); it meets them as a new instance.
        radius: body radius in metres.
        height: body height in metres.
        color: RGBA in 0..1.
        priors: up to three likely rooms (the robot's prior knowledge).
    """

    name: str
    position: Point
    on: str | None = None
    behaviour: str = "static"
    present: bool = True
    known: bool = True
    radius: float = 0.22
    height: float = 1.65
    color: tuple[float, float, float, float] = (0.9, 0.7, 0.55, 1.0)
    priors: tuple[Prior, ...] = ()


@dataclass(frozen=True, slots=True)
class Device:
    """A home device.

    Attributes:
        name: PDDL device symbol.
        kind: one of ``light``, ``dimmer``, ``blinds``, ``bell``.
        room: the room it is in.
        position: ``(x, y, z)`` of the device (the bell's position is where its sound comes from).
        initial: initial state: bool for a light (on), percent for dimmer/blinds, ignored for a bell.
    """

    name: str
    kind: str
    room: str
    position: tuple[float, float, float]
    initial: float = 0.0


@dataclass(frozen=True, slots=True)
class RobotSpec:
    """The robot and its start.

    Attributes:
        name: PDDL robot symbol.
        start: initial ``(x, y, yaw)``.
        radius: base radius in metres.
        height: base height in metres.
        max_linear: linear velocity limit, m/s.
        max_angular: angular velocity limit, rad/s.
        reach: gripper reach, metres from the base centre (horizontal).
        camera_height: height of the camera above the floor.
        camera_pitch: downward tilt of the camera in radians.
        camera_fov: vertical field of view in degrees.
        grasp_tolerance: metres (horizontal) between where the arm is sent and the item's centre within which
            the gripper still closes on it; twice this vertically.
    """

    name: str
    start: tuple[float, float, float]
    radius: float = 0.25
    height: float = 1.0
    max_linear: float = 0.6
    max_angular: float = 1.2
    reach: float = 0.9
    camera_height: float = 1.25
    camera_pitch: float = 0.35
    camera_fov: float = 58.0
    grasp_tolerance: float = 0.12


#: Points whose room :meth:`World.room_of` remembers before it starts afresh.
ROOM_OF_MEMORY = 4096


@dataclass(frozen=True)
class World:
    """A validated world.

    Attributes:
        name: world name (``erl_home``).
        rooms: rooms by name.
        doors: doors (room-room openings and front doors).
        furniture: furniture by name.
        items: items by name.
        people: people by name.
        devices: devices by name.
        robot: the robot and its start.
        wall_height: wall height in metres.
        wall_thickness: wall thickness in metres.
        source: the file it was read from, if any.
    """

    name: str
    rooms: dict[str, Room]
    doors: tuple[Door, ...]
    furniture: dict[str, Furniture]
    items: dict[str, Item]
    people: dict[str, Person]
    devices: dict[str, Device]
    robot: RobotSpec
    wall_height: float = 2.5
    wall_thickness: float = 0.1
    source: Path | None = None
    _cache: dict[str, object] = field(default_factory=dict, repr=False, compare=False)

    def device_rooms(self) -> dict[str, str]:
        """The room of each device (the domain has no fact for it; the language reads it from here)."""
        return {name: device.room for name, device in self.devices.items()}

    def room_of(self, x: float, y: float) -> str | None:
        """The room whose floor contains ``(x, y)``, or ``None`` outside every room.

        On a shared wall the first room in file order wins. Answers are remembered per point (what stands
        still is asked about at every step), at most :data:`ROOM_OF_MEMORY` points at a time.
        """
        known = self._cache.setdefault("room_of", {})
        assert isinstance(known, dict)
        if (x, y) in known:
            return known[(x, y)]
        if len(known) >= ROOM_OF_MEMORY:
            known.clear()
        found = next((room.name for room in self.rooms.values() if room.contains(x, y)), None)
        known[(x, y)] = found
        return found

    def connected(self) -> list[tuple[str, str]]:
        """Room pairs joined by a door, each once, in file order."""
        return [(d.rooms[0], d.rooms[1]) for d in self.doors if len(d.rooms) == 2]

    def entrances(self) -> list[str]:
        """The rooms a door to the outside (a front door) opens into, each once, in file order; where several
        do, the one with the doorbell, if only one has a bell (a garden door is no front door)."""
        rooms = self._outside_rooms()
        rung = [r for r in rooms if any(d.kind == "bell" and d.room == r for d in self.devices.values())]
        return rung if len(rooms) > 1 and len(rung) == 1 else rooms

    def back_entrances(self) -> list[str]:
        """The rooms other doors to the outside open into, where :meth:`entrances` tells the front door from
        them (a back door, a garden door), each once, in file order."""
        front = self.entrances()
        return [r for r in self._outside_rooms() if r not in front]

    def _outside_rooms(self) -> list[str]:
        """The rooms a door to the outside opens into, each once, in file order."""
        return list(dict.fromkeys(d.rooms[0] for d in self.doors if len(d.rooms) == 1))

    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` of all room polygons."""
        xs = [p[0] for r in self.rooms.values() for p in r.polygon]
        ys = [p[1] for r in self.rooms.values() for p in r.polygon]
        return (min(xs), min(ys), max(xs), max(ys))

    def static_facts(self) -> set[tuple[str, ...]]:
        """Facts that never change: ``connected`` (both orders) and ``furniture_in``."""
        facts: set[tuple[str, ...]] = set()
        for a, b in self.connected():
            facts.add(("connected", a, b))
            facts.add(("connected", b, a))
        for f in self.furniture.values():
            facts.add(("furniture_in", f.name, f.room))
        return facts

    def symbols(self) -> dict[str, str]:
        """Every instance name with its PDDL type (room, furniture, item, person, robot, device kinds)."""
        out: dict[str, str] = {r: "room" for r in self.rooms}
        out.update({f: "furniture" for f in self.furniture})
        out.update({i: "item" for i in self.items})
        out.update({p: "person" for p in self.people})
        out.update({d.name: d.kind for d in self.devices.values()})
        out[self.robot.name] = "robot"
        return out
