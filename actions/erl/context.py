"""What the ERL actions share: the robot interface they command, the perceived poses they steer by, the map.

The actions of :mod:`actions.erl` decide *where to go* only from what the robot knows: the knowledge base's
anchors (room regions and waypoints, furniture poses, written by :func:`knic.seed.seed_kb_from_world`; item
positions anchored by the object KP') and the poses perception reports through the perception seam
(:class:`~actions.erl.perception.Perception`, fed by the inference side). They command the robot through the
robot seam, :class:`core.robot.Robot`, whose readings carry no ground truth; they import nothing from the
simulator nor from the inference bus.

Frames and time: every position is in the world frame (metres, ``z`` up, yaw in radians counter-clockwise
from ``+x``); every time is the robot's clock (:attr:`core.robot.Robot.time`, simulated seconds in
simulation).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from actions.erl.perception import Perception
from core.geometry import distance_to_outline
from core.robot import Pose2D, Robot
from knowledge_base import KnowledgeBase

Point = tuple[float, float]

#: PDDL level constant -> percent for dimmers and blinds
LEVEL_PERCENT = {"l0": 0.0, "l25": 25.0, "l50": 50.0, "l75": 75.0, "l100": 100.0}


@dataclass(frozen=True)
class RoomMap:
    """A room as the robot knows it from its anchor: floor polygon and waypoints (world frame)."""

    name: str
    region: tuple[Point, ...]
    waypoints: tuple[Point, ...]

    def contains(self, x: float, y: float) -> bool:
        """True when ``(x, y)`` lies inside the region (ray casting; boundary points may go either way)."""
        inside = False
        pts = self.region
        for i, (ax, ay) in enumerate(pts):
            bx, by = pts[i - 1]
            if (ay > y) != (by > y) and x < (bx - ax) * (y - ay) / (by - ay) + ax:
                inside = not inside
        return inside

    def depth(self, x: float, y: float) -> float:
        """How far ``(x, y)`` lies inside the region, metres: the distance to the nearest wall, negative
        outside."""
        nearest = distance_to_outline(x, y, self.region)
        return nearest if self.contains(x, y) else -nearest

    def inner_points(self, share: float = 0.5) -> list[Point]:
        """Points inside the room besides its waypoints: the centre, and each corner pulled ``share`` of the
        way towards the centre (alternative targets when a waypoint is taken), those inside the region."""
        cx, cy = self.centre
        pts = [(cx, cy)] + [(x + (cx - x) * share, y + (cy - y) * share) for x, y in self.region]
        return [p for p in pts if self.contains(*p)]

    @property
    def centre(self) -> Point:
        """Mean of the region's vertices (a rough centre, enough to face into the room)."""
        n = len(self.region)
        return (sum(p[0] for p in self.region) / n, sum(p[1] for p in self.region) / n)


@dataclass(frozen=True)
class FurnitureMap:
    """A piece of furniture as the robot knows it from its anchor."""

    name: str
    position: Point
    size: tuple[float, float, float]
    yaw: float
    room: str

    @property
    def height(self) -> float:
        """Height of its top surface, metres."""
        return self.size[2]


def room_map(kb: KnowledgeBase, room: str) -> RoomMap | None:
    """The room's anchor as a :class:`RoomMap`, or None when it has no usable anchor."""
    geometry = kb.anchor(room) or {}
    region = geometry.get("region")
    waypoints = geometry.get("waypoints") or []
    if not region:
        return None
    poly = tuple((float(p[0]), float(p[1])) for p in region)
    wps = tuple((float(p[0]), float(p[1])) for p in waypoints)
    if not wps:
        n = len(poly)
        wps = ((sum(p[0] for p in poly) / n, sum(p[1] for p in poly) / n),)
    return RoomMap(room, poly, wps)


def furniture_map(kb: KnowledgeBase, name: str) -> FurnitureMap | None:
    """The furniture's anchor as a :class:`FurnitureMap`, or None."""
    geometry: dict[str, Any] = kb.anchor(name) or {}
    pose = geometry.get("pose")
    if not isinstance(pose, dict) or "x" not in pose:
        return None
    size = tuple(float(v) for v in geometry.get("size", (0.5, 0.5, 0.5)))
    return FurnitureMap(
        name,
        (float(pose["x"]), float(pose["y"])),
        (size[0], size[1], size[2]),
        float(pose.get("yaw", 0.0)),
        str(geometry.get("room", "")),
    )


def room_of(kb: KnowledgeBase, x: float, y: float) -> str | None:
    """The room whose anchored region contains ``(x, y)``, or None."""
    for room in kb.instances("room"):
        known = room_map(kb, room)
        if known is not None and known.contains(x, y):
            return room
    return None


def bearing(pose: Pose2D, x: float, y: float) -> float:
    """Angle in radians from the robot's heading to the point ``(x, y)``, in (-pi, pi]."""
    return wrap(math.atan2(y - pose.y, x - pose.x) - pose.yaw)


def wrap(angle: float) -> float:
    """``angle`` wrapped to (-pi, pi]."""
    a = math.fmod(angle + math.pi, 2 * math.pi)
    if a <= 0:
        a += 2 * math.pi
    return a - math.pi


def standoff_points(target: Point, distance: float, origin: Point, count: int = 12) -> list[Point]:
    """``count`` points on a circle of ``distance`` metres around ``target``, nearest to ``origin`` first."""
    pts = [
        (
            target[0] + distance * math.cos(2 * math.pi * i / count),
            target[1] + distance * math.sin(2 * math.pi * i / count),
        )
        for i in range(count)
    ]
    return sorted(pts, key=lambda p: math.dist(p, origin))


@dataclass
class ErlContext:
    """Everything an ERL action closes over: robot, knowledge base, perceived poses, tunables.

    Attributes:
        robot: the robot's commands and sensors (the simulator in the closed loop).
        kb: the knowledge base (read only for the actions: the dispatcher writes the PDDL effects).
        perceived: where perception last saw items and people (:class:`~actions.erl.perception.Perception`).
        robot_name: the robot's PDDL symbol.
        dwell_s: seconds the camera rests at each pan angle while searching (>= 2 camera periods).
        search_pans: camera pan angles (radians) swept at each search viewpoint.
        look_timeout_s: seconds an action waits for perception to (re)confirm an entity before it acts.
        follow_timeout_s: seconds ``guide`` waits for the escorted person to arrive.
    """

    robot: Robot
    kb: KnowledgeBase
    perceived: Perception
    robot_name: str = "r2d2"
    dwell_s: float = 0.7
    search_pans: Sequence[float] = (-1.3, -0.65, 0.0, 0.65, 1.3)
    look_timeout_s: float = 2.5
    follow_timeout_s: float = 15.0
    said: list[str] = field(default_factory=list)

    @property
    def now(self) -> float:
        """Simulated seconds."""
        return self.robot.time

    def say(self, text: str) -> None:
        """Speak through the robot and remember it."""
        self.said.append(text)
        self.robot.say(text)
