"""Occupancy grid derived from the world, and a grid path planner (A* / Dijkstra, 8-connected).

The grid covers the world's bounds plus a margin. A cell is an obstacle when it lies outside every room, on a
wall (outside the door gaps) or under furniture. Obstacles are inflated by the robot's radius plus a safety
margin; cells close to obstacles get an extra traversal cost so paths keep to the middle of corridors
and doors.
Planning is pure Python with numpy; a plan over the seven-room apartment takes a few tens of milliseconds.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from worlds.geometry import Point, segment_distance
from worlds.model import World

Segment = tuple[Point, Point]

#: weighted A*: paths at most this factor longer than optimal, found much faster
HEURISTIC_WEIGHT = 1.5
#: step cost factor within 25 cm of the inflated obstacles (keeps paths in the middle of doors)
NEAR_OBSTACLE_COST = 1.5


def wall_segments(world: World) -> list[Segment]:
    """Wall centre lines of every room edge with the door openings cut out; a wall shared by two rooms
    once."""
    return _merge_collinear(_raw_wall_segments(world))


def _merge_collinear(segments: list[Segment]) -> list[Segment]:
    """Union of collinear overlapping segments (each line's intervals merged)."""
    lines: dict[tuple[float, float, float], list[tuple[float, float]]] = {}
    for a, b in segments:
        ang = math.atan2(b[1] - a[1], b[0] - a[0]) % math.pi
        if ang > math.pi - 1e-6:
            ang = 0.0
        ux, uy = math.cos(ang), math.sin(ang)
        offset = -uy * a[0] + ux * a[1]
        key = (round(ang, 4), round(offset, 3), 0.0)
        ta, tb = ux * a[0] + uy * a[1], ux * b[0] + uy * b[1]
        lines.setdefault(key, []).append((min(ta, tb), max(ta, tb)))
    out: list[Segment] = []
    for (ang, offset, _), intervals in lines.items():
        ux, uy = math.cos(ang), math.sin(ang)
        intervals.sort()
        merged = [list(intervals[0])]
        for lo, hi in intervals[1:]:
            if lo <= merged[-1][1] + 1e-6:
                merged[-1][1] = max(merged[-1][1], hi)
            else:
                merged.append([lo, hi])
        for lo, hi in merged:
            out.append(
                (
                    (ux * lo - uy * offset, uy * lo + ux * offset),
                    (ux * hi - uy * offset, uy * hi + ux * offset),
                )
            )
    return out


def _raw_wall_segments(world: World) -> list[Segment]:
    out: list[Segment] = []
    for room in world.rooms.values():
        poly = room.polygon
        for i in range(len(poly)):
            a, b = poly[i], poly[(i + 1) % len(poly)]
            length = math.dist(a, b)
            if length < 1e-9:
                continue
            cuts: list[tuple[float, float]] = []
            for door in world.doors:
                if room.name not in door.rooms:
                    continue
                if segment_distance(door.position[0], door.position[1], a, b) > 0.05:
                    continue
                t = (
                    (door.position[0] - a[0]) * (b[0] - a[0]) + (door.position[1] - a[1]) * (b[1] - a[1])
                ) / (length * length)
                half = door.width / 2 / length
                cuts.append((t - half, t + half))
            cuts.sort()
            start = 0.0
            for lo, hi in [*cuts, (1.0, 1.0)]:
                lo, hi = max(lo, 0.0), min(hi, 1.0)
                if lo - start > 1e-6:
                    out.append((_lerp(a, b, start), _lerp(a, b, lo)))
                start = max(start, hi)
    return out


def _lerp(a: Point, b: Point, t: float) -> Point:
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)


def _disk_offsets(radius_cells: float) -> list[tuple[int, int]]:
    r = math.ceil(radius_cells)
    return [
        (dy, dx) for dy in range(-r, r + 1) for dx in range(-r, r + 1) if dx * dx + dy * dy <= radius_cells**2
    ]


def dilate(mask: npt.NDArray[np.bool_], radius_cells: float) -> npt.NDArray[np.bool_]:
    """Binary dilation of ``mask`` by a disk of ``radius_cells``."""
    h, w = mask.shape
    out = mask.copy()
    for dy, dx in _disk_offsets(radius_cells):
        if dy == 0 and dx == 0:
            continue
        ys0, ys1 = max(0, dy), min(h, h + dy)
        xs0, xs1 = max(0, dx), min(w, w + dx)
        out[ys0:ys1, xs0:xs1] |= mask[ys0 - dy : ys1 - dy, xs0 - dx : xs1 - dx]
    return out


@dataclass
class GridMap:
    """Occupancy grid of a world.

    Attributes:
        origin: world ``(x, y)`` of the lower-left corner of cell ``(0, 0)``.
        resolution: cell size in metres.
        occupied: ``(rows, cols)`` raw obstacles (walls, furniture, outside); row = y, column = x.
        blocked: obstacles inflated by the robot radius plus margin (not traversable by the robot centre).
        cost: traversal cost multiplier per cell (>= 1).
    """

    origin: Point
    resolution: float
    occupied: npt.NDArray[np.bool_]
    blocked: npt.NDArray[np.bool_]
    cost: npt.NDArray[np.float64]
    _padded_cache: tuple[list[int], list[float]] | None = None

    @classmethod
    def from_world(
        cls, world: World, *, resolution: float = 0.05, inflation: float | None = None, margin: float = 0.5
    ) -> GridMap:
        """Rasterise the world; ``inflation`` defaults to the robot radius plus 5 cm."""
        xmin, ymin, xmax, ymax = world.bounds()
        origin = (xmin - margin, ymin - margin)
        cols = math.ceil((xmax - xmin + 2 * margin) / resolution)
        rows = math.ceil((ymax - ymin + 2 * margin) / resolution)
        xs = origin[0] + (np.arange(cols) + 0.5) * resolution
        ys = origin[1] + (np.arange(rows) + 0.5) * resolution
        gx, gy = np.meshgrid(xs, ys)
        inside = np.zeros((rows, cols), dtype=bool)
        for room in world.rooms.values():
            inside |= _polygon_mask(room.polygon, gx, gy)
        occ = ~inside
        half_t = world.wall_thickness / 2
        for a, b in wall_segments(world):
            occ |= _segment_mask(a, b, half_t, gx, gy)
        for f in world.furniture.values():
            occ |= _polygon_mask(f.footprint(), gx, gy)
        infl = world.robot.radius + 0.05 if inflation is None else inflation
        blocked = dilate(occ, infl / resolution)
        near = dilate(occ, (infl + 0.25) / resolution) & ~blocked
        cost = np.where(near, NEAR_OBSTACLE_COST, 1.0)
        return cls(origin=origin, resolution=resolution, occupied=occ, blocked=blocked, cost=cost)

    @property
    def shape(self) -> tuple[int, int]:
        """``(rows, cols)``."""
        return (int(self.occupied.shape[0]), int(self.occupied.shape[1]))

    def cell(self, x: float, y: float) -> tuple[int, int]:
        """``(row, col)`` of a world point (may be outside the grid)."""
        return (
            math.floor((y - self.origin[1]) / self.resolution),
            math.floor((x - self.origin[0]) / self.resolution),
        )

    def centre(self, row: int, col: int) -> Point:
        """World point at the centre of a cell."""
        return (
            self.origin[0] + (col + 0.5) * self.resolution,
            self.origin[1] + (row + 0.5) * self.resolution,
        )

    def in_grid(self, row: int, col: int) -> bool:
        """True when the cell index is inside the grid."""
        return 0 <= row < self.shape[0] and 0 <= col < self.shape[1]

    def is_free(self, x: float, y: float, blocked: npt.NDArray[np.bool_] | None = None) -> bool:
        """True when the robot centre may be at ``(x, y)``."""
        r, c = self.cell(x, y)
        grid = self.blocked if blocked is None else blocked
        return self.in_grid(r, c) and not bool(grid[r, c])

    def nearest_free(
        self, x: float, y: float, max_dist: float = 1.0, blocked: npt.NDArray[np.bool_] | None = None
    ) -> Point | None:
        """The free cell centre nearest to ``(x, y)`` within ``max_dist``, or ``None``."""
        grid = self.blocked if blocked is None else blocked
        r0, c0 = self.cell(x, y)
        k = math.ceil(max_dist / self.resolution)
        best: tuple[float, Point] | None = None
        for r in range(max(0, r0 - k), min(self.shape[0], r0 + k + 1)):
            for c in range(max(0, c0 - k), min(self.shape[1], c0 + k + 1)):
                if grid[r, c]:
                    continue
                p = self.centre(r, c)
                d = math.dist(p, (x, y))
                if d <= max_dist and (best is None or d < best[0]):
                    best = (d, p)
        return None if best is None else best[1]

    def with_discs(self, discs: Iterable[tuple[float, float, float]]) -> npt.NDArray[np.bool_]:
        """The blocked grid plus discs ``(x, y, radius)`` (e.g. people), inflated like the rest."""
        extra = np.zeros_like(self.blocked)
        rows, cols = self.shape
        ys = self.origin[1] + (np.arange(rows) + 0.5) * self.resolution
        xs = self.origin[0] + (np.arange(cols) + 0.5) * self.resolution
        for x, y, rad in discs:
            extra |= ((xs[None, :] - x) ** 2 + (ys[:, None] - y) ** 2) <= rad * rad
        return self.blocked | extra

    def plan(
        self,
        start: Point,
        goals: Sequence[Point],
        blocked: npt.NDArray[np.bool_] | None = None,
    ) -> list[Point] | None:
        """Shortest path from ``start`` to the nearest of ``goals`` (world points), smoothed.

        A* on the 8-connected grid, weighted by the cell costs; with several goals the heuristic is the
        distance to the goals' centre less their spread (admissible). A start inside an obstacle (e.g. after
        a bump) is allowed: the search leaves it by the cheapest way. Returns world waypoints ending at the
        reached goal cell centre, or ``None`` when no goal is reachable.
        """
        grid = self.blocked if blocked is None else blocked
        cols = self.shape[1]
        width = cols + 2  # the search runs on a copy padded with one blocked cell all round
        goal_cells: set[int] = set()
        for gx, gy in goals:
            r, c = self.cell(gx, gy)
            if self.in_grid(r, c) and not grid[r, c]:
                goal_cells.add((r + 1) * width + c + 1)
        sr, sc = self.cell(*start)
        if not self.in_grid(sr, sc) or not goal_cells:
            return None
        flat_blocked, flat_cost = self._padded(grid)
        start_idx = (sr + 1) * width + sc + 1
        goal_rc = [divmod(i, width) for i in goal_cells]
        gr = sum(r for r, _ in goal_rc) / len(goal_rc)
        gc = sum(c for _, c in goal_rc) / len(goal_rc)
        spread = max(math.hypot(r - gr, c - gc) for r, c in goal_rc)
        diag = math.sqrt(2)
        steps = [
            (-width - 1, diag),
            (-width, 1.0),
            (-width + 1, diag),
            (-1, 1.0),
            (1, 1.0),
            (width - 1, diag),
            (width, 1.0),
            (width + 1, diag),
        ]
        start_code = flat_blocked[start_idx]
        dist: dict[int, float] = {start_idx: 0.0}
        parent: dict[int, int] = {}
        heap = [(0.0, 0.0, start_idx)]
        found = -1
        k = diag - 2.0
        while heap:
            _, g, idx = heapq.heappop(heap)
            if g > dist[idx]:
                continue
            if idx in goal_cells:
                found = idx
                break
            here = flat_blocked[idx]
            for off, length in steps:
                n = idx + off
                nb = flat_blocked[n]
                # codes: 0 free, 1 map obstacle, 2 border, 3 extra obstacle (a person); a blocked start may
                # only be left across cells of its own kind (or any obstacle, if it is a map obstacle)
                if nb and (nb == 2 or not here or (nb == 1 and start_code != 1) or not start_code):
                    continue
                ng = g + length * flat_cost[n]
                if ng < dist.get(n, math.inf):
                    dist[n] = ng
                    parent[n] = idx
                    dr = abs(n // width - gr)
                    dc = abs(n % width - gc)
                    h = dr + dc + k * (dr if dr < dc else dc) - spread
                    heapq.heappush(heap, (ng + (HEURISTIC_WEIGHT * h if h > 0 else 0.0), ng, n))
        if found < 0:
            return None
        cells = [found]
        while cells[-1] != start_idx:
            cells.append(parent[cells[-1]])
        cells.reverse()
        pts = [self.centre(i // width - 1, i % width - 1) for i in cells]
        return self._smooth([start, *pts[1:]] if len(pts) > 1 else [start, pts[0]], grid)

    def _padded(self, grid: npt.NDArray[np.bool_]) -> tuple[list[int], list[float]]:
        """Flat lists of the grid padded by one border cell: cell codes (0 free, 1 map obstacle, 2 border,
        3 obstacle added to the map's own, e.g. a person) and step costs (obstacle cells cost 20 times more,
        for leaving one). Cached for the map's own grid."""
        if grid is self.blocked and self._padded_cache is not None:
            return self._padded_cache
        rows, cols = self.shape
        codes = np.full((rows + 2, cols + 2), 2, dtype=np.int8)
        codes[1:-1, 1:-1] = np.where(self.blocked, 1, np.where(grid, 3, 0))
        cost = np.ones((rows + 2, cols + 2))
        cost[1:-1, 1:-1] = self.cost * np.where(grid, 20.0, 1.0)
        out = (codes.ravel().tolist(), cost.ravel().tolist())
        if grid is self.blocked:
            self._padded_cache = out
        return out

    def _smooth(self, pts: list[Point], grid: npt.NDArray[np.bool_]) -> list[Point]:
        """Drop waypoints while the straight line stays free and low-cost (string pulling)."""
        if len(pts) <= 2:
            return pts
        out = [pts[0]]
        i = 0
        while i < len(pts) - 1:
            j = len(pts) - 1
            while j > i + 1 and not self._line_ok(pts[i], pts[j], grid):
                j -= 1
            out.append(pts[j])
            i = j
        return out

    def _line_ok(self, a: Point, b: Point, grid: npt.NDArray[np.bool_]) -> bool:
        """True when the straight line a-b stays on free cells no costlier than the cell at ``a``."""
        n = max(2, int(math.dist(a, b) / (self.resolution / 2)))
        rows, cols = self.occupied.shape
        ra, ca_ = self.cell(*a)
        cost_a = self.cost[ra, ca_] if 0 <= ra < rows and 0 <= ca_ < cols else 1.0
        t = np.arange(1, n) / n
        r = np.floor((a[1] + (b[1] - a[1]) * t - self.origin[1]) / self.resolution).astype(int)
        c = np.floor((a[0] + (b[0] - a[0]) * t - self.origin[0]) / self.resolution).astype(int)
        if r.min() < 0 or c.min() < 0 or r.max() >= rows or c.max() >= cols:
            return False
        return not bool(grid[r, c].any() or (self.cost[r, c] > cost_a).any())


def _polygon_mask(
    poly: Sequence[Point], gx: npt.NDArray[np.float64], gy: npt.NDArray[np.float64]
) -> npt.NDArray[np.bool_]:
    inside = np.zeros(gx.shape, dtype=bool)
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if y1 == y2:
            continue
        cond = (y1 > gy) != (y2 > gy)
        xin = x1 + (gy - y1) * (x2 - x1) / (y2 - y1)
        inside ^= cond & (gx < xin)
    return inside


def _segment_mask(
    a: Point, b: Point, half: float, gx: npt.NDArray[np.float64], gy: npt.NDArray[np.float64]
) -> npt.NDArray[np.bool_]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = np.clip(((gx - a[0]) * dx + (gy - a[1]) * dy) / length2, 0.0, 1.0)
    d2 = (gx - a[0] - t * dx) ** 2 + (gy - a[1] - t * dy) ** 2
    return np.asarray(d2 <= half * half)
