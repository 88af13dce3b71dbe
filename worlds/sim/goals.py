"""Where a symbolic base goal ends: the free grid points that count as "in the room", "at the furniture",
"beside the person".

The simulated navigation stack (:class:`worlds.sim.robot.BaseController`) drives to the nearest reachable one
of these points. All points are grid-cell centres of :class:`~worlds.sim.navigation.GridMap` (world frame,
metres), in row-major order, so the choice among equally near points is deterministic.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from worlds.geometry import Point
from worlds.model import World
from worlds.sim.navigation import GridMap

ROOM_GOAL_RADIUS = 0.5  # metres: "go to a room" ends within this distance of the room's waypoint
Cells = tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.bool_]]
#: a person's footprint for the goal choice: (name, x, y, radius)
Disc = tuple[str, float, float, float]


def free_cells(grid: GridMap) -> Cells:
    """``(xs, ys, free)``: the x and y of every cell centre and whether the cell is free, as grid arrays."""
    rows, cols = grid.shape
    xs = np.broadcast_to(grid.origin[0] + (np.arange(cols) + 0.5) * grid.resolution, (rows, cols))
    ys = np.broadcast_to((grid.origin[1] + (np.arange(rows) + 0.5) * grid.resolution)[:, None], (rows, cols))
    return xs, ys, ~grid.blocked


def room_points(world: World, grid: GridMap, room: str, people: Sequence[Disc]) -> list[Point]:
    """Free points within :data:`ROOM_GOAL_RADIUS` of the room's waypoint and not where somebody stands;
    the nearest free point within 1.5 m when there is none; empty when there is not even that."""
    wx, wy = world.rooms[room].waypoint
    xs, ys, free = free_cells(grid)
    sel = free & (np.hypot(xs - wx, ys - wy) <= ROOM_GOAL_RADIUS)
    for _, px, py, pr in people:
        sel &= np.hypot(xs - px, ys - py) > pr + world.robot.radius + 0.15
    goals = list(zip(xs[sel].tolist(), ys[sel].tolist(), strict=True))
    if not goals:
        near = grid.nearest_free(wx, wy, 1.5)
        goals = [near] if near is not None else []
    return goals


def approach_points(
    world: World, grid: GridMap, furniture: str, near: Point | None, reach: float
) -> list[Point]:
    """Free points within ``reach - 0.2`` m of the furniture's footprint; of those, the ones within
    ``reach - 0.1`` m of ``near`` when ``near`` is given and any qualifies."""
    f = world.furniture[furniture]
    xs, ys, free = free_cells(grid)
    c, s = math.cos(f.yaw), math.sin(f.yaw)
    lx, ly = (
        c * (xs - f.position[0]) + s * (ys - f.position[1]),
        -s * (xs - f.position[0]) + c * (ys - f.position[1]),
    )
    dist = np.hypot(np.maximum(np.abs(lx) - f.size[0] / 2, 0), np.maximum(np.abs(ly) - f.size[1] / 2, 0))
    sel = free & (dist <= reach - 0.2)
    if near is not None:
        close = sel & (np.hypot(xs - near[0], ys - near[1]) <= reach - 0.1)
        if close.any():
            sel = close
    return list(zip(xs[sel].tolist(), ys[sel].tolist(), strict=True))


def person_points(grid: GridMap, x: float, y: float, far: float) -> list[Point]:
    """Free points between 0.5 m and ``far`` metres from a person standing at ``(x, y)``."""
    xs, ys, free = free_cells(grid)
    d = np.hypot(xs - x, ys - y)
    sel = free & (d <= far) & (d >= 0.5)
    return list(zip(xs[sel].tolist(), ys[sel].tolist(), strict=True))


def reachable_cells(grid: GridMap, start: Point) -> npt.NDArray[np.bool_]:
    """The free cells the robot can drive to from ``start`` (8-connected, as :meth:`GridMap.plan` moves),
    as a grid mask; all False when the start cell is not free."""
    rows, cols = grid.shape
    free = ~grid.blocked
    seen = np.zeros((rows, cols), dtype=bool)
    r0, c0 = grid.cell(*start)
    if not (grid.in_grid(r0, c0) and free[r0, c0]):
        return seen
    seen[r0, c0] = True
    frontier = [(r0, c0)]
    while frontier:
        nxt = []
        for r, c in frontier:
            for dr in (-1, 0, 1):
                for dc in (-1, 0, 1):
                    rr, cc = r + dr, c + dc
                    if 0 <= rr < rows and 0 <= cc < cols and free[rr, cc] and not seen[rr, cc]:
                        seen[rr, cc] = True
                        nxt.append((rr, cc))
        frontier = nxt
    return seen


def unreachable(world: World, grid: GridMap) -> tuple[list[str], list[str]]:
    """What the robot cannot drive to from its start pose, people aside: ``(rooms, furniture)``, each in
    file order. A room counts when no point of :func:`room_points` is reachable (a door blocked by
    furniture, or no door at all); a piece of furniture in a room it reaches when no point within the
    gripper's reach of it is (a shelf against a wall behind a sofa). A world file may mean some of it (a
    locked cellar); a check reports it rather than refusing the world."""
    seen = reachable_cells(grid, (world.robot.start[0], world.robot.start[1]))

    def any_reached(points: list[Point]) -> bool:
        return any(seen[grid.cell(x, y)] for x, y in points)

    rooms = [r for r in world.rooms if not any_reached(room_points(world, grid, r, ()))]
    furniture = [
        f.name
        for f in world.furniture.values()
        if f.room not in rooms
        and not any_reached(approach_points(world, grid, f.name, None, world.robot.reach))
    ]
    return rooms, furniture
