"""Contacts of the robot base with furniture, walls and people, counted for the ERL score sheet.

A contact starts when the base's circle overlaps a furniture footprint, a wall or a person's circle; each
start counts once (pressing on is the same bump). The base may press at most :data:`BUMPER` metres into
anything (its bumper); velocity commands that would go deeper are cut short.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from worlds.geometry import segment_distance
from worlds.model import World
from worlds.sim.navigation import wall_segments

BUMPER = 0.02  # metres the base may press into an obstacle


class ContactMonitor:
    """Tracks what the robot base touches and counts bumps (furniture, walls) and hits (people).

    Attributes:
        bumps: contacts started with furniture or walls.
        hits: contacts started with people.
        touching: names touched now (``"wall"``, furniture names, ``"person:<name>"``).
    """

    def __init__(self, world: World) -> None:
        self.world = world
        self.radius = world.robot.radius
        self._walls = wall_segments(world)
        self._half = world.wall_thickness / 2
        self.bumps = 0
        self.hits = 0
        self.touching: set[str] = set()

    def clearance(self, x: float, y: float) -> float:
        """Distance from a point to the nearest furniture or wall surface."""
        d = min((f.distance(x, y) for f in self.world.furniture.values()), default=math.inf)
        walls = (segment_distance(x, y, a, b) - self._half for a, b in self._walls)
        return min(d, min(walls, default=math.inf))

    def may_stand(self, x: float, y: float, people: Sequence[tuple[str, float, float, float]]) -> bool:
        """True when the base centre may be at ``(x, y)``, pressing no deeper than the bumper."""
        if self.clearance(x, y) < self.radius - BUMPER:
            return False
        return all(math.hypot(x - px, y - py) >= self.radius + pr - BUMPER for _, px, py, pr in people)

    def update(self, x: float, y: float, people: Sequence[tuple[str, float, float, float]]) -> None:
        """Record the contacts of the base at ``(x, y)``; count those that just started."""
        rad = self.radius - 1e-6
        touching = {f.name for f in self.world.furniture.values() if f.distance(x, y) < rad}
        if any(segment_distance(x, y, a, b) - self._half < rad for a, b in self._walls):
            touching.add("wall")
        for name, px, py, pr in people:
            if math.hypot(x - px, y - py) < rad + pr:
                touching.add("person:" + name)
        for new in touching - self.touching:
            if new.startswith("person:"):
                self.hits += 1
            else:
                self.bumps += 1
        self.touching = touching
