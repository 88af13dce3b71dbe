"""Planar geometry used by the world data and the simulator (pure Python, world frame, metres)."""

from __future__ import annotations

import math
from collections.abc import Sequence

from core.geometry import inside_polygon

Point = tuple[float, float]

EPS = 1e-9


def polygon_area(poly: Sequence[Point]) -> float:
    """Signed area (counter-clockwise positive) of a simple polygon."""
    s = 0.0
    for i, (x1, y1) in enumerate(poly):
        x2, y2 = poly[(i + 1) % len(poly)]
        s += x1 * y2 - x2 * y1
    return s / 2.0


def polygon_centroid(poly: Sequence[Point]) -> Point:
    """Area centroid of a simple polygon (vertex mean for a degenerate one)."""
    a = polygon_area(poly)
    if abs(a) < EPS:
        return (sum(p[0] for p in poly) / len(poly), sum(p[1] for p in poly) / len(poly))
    cx = cy = 0.0
    for i, (x1, y1) in enumerate(poly):
        x2, y2 = poly[(i + 1) % len(poly)]
        cross = x1 * y2 - x2 * y1
        cx += (x1 + x2) * cross
        cy += (y1 + y2) * cross
    return (cx / (6 * a), cy / (6 * a))


def point_in_polygon(x: float, y: float, poly: Sequence[Point]) -> bool:
    """True when ``(x, y)`` is inside the polygon (even-odd rule; points on an edge count as inside)."""
    return point_on_boundary(x, y, poly, tol=1e-7) or inside_polygon(x, y, poly)


def point_in_polygon_strict(x: float, y: float, poly: Sequence[Point], tol: float = 1e-6) -> bool:
    """True when ``(x, y)`` is inside the polygon and farther than ``tol`` from its boundary."""
    return point_in_polygon(x, y, poly) and not point_on_boundary(x, y, poly, tol)


def segment_distance(px: float, py: float, a: Point, b: Point) -> float:
    """Distance from the point to the segment ``a``-``b``."""
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 < EPS else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


def point_on_boundary(x: float, y: float, poly: Sequence[Point], tol: float = 0.05) -> bool:
    """True when the point lies within ``tol`` metres of one of the polygon's edges."""
    return any(segment_distance(x, y, poly[i], poly[(i + 1) % len(poly)]) <= tol for i in range(len(poly)))


def _orient(a: Point, b: Point, c: Point) -> float:
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool:
    """True when the segments ``a-b`` and ``c-d`` cross at a single interior point of both."""
    o1, o2 = _orient(a, b, c), _orient(a, b, d)
    o3, o4 = _orient(c, d, a), _orient(c, d, b)
    return (o1 * o2 < -EPS) and (o3 * o4 < -EPS)


def segments_touch(a: Point, b: Point, c: Point, d: Point) -> bool:
    """True when the closed segments ``a-b`` and ``c-d`` share at least one point."""
    if segments_cross(a, b, c, d):
        return True
    return (
        segment_distance(c[0], c[1], a, b) < 1e-9
        or segment_distance(d[0], d[1], a, b) < 1e-9
        or segment_distance(a[0], a[1], c, d) < 1e-9
        or segment_distance(b[0], b[1], c, d) < 1e-9
    )


def self_intersection(poly: Sequence[Point]) -> tuple[int, int] | None:
    """Indices ``(i, j)`` of two non-adjacent edges that touch, or ``None`` for a simple polygon.

    Edge ``i`` runs from vertex ``i`` to vertex ``i + 1``.
    """
    n = len(poly)
    for i in range(n):
        for j in range(i + 1, n):
            if j == i + 1 or (i == 0 and j == n - 1):
                continue
            if segments_touch(poly[i], poly[(i + 1) % n], poly[j], poly[(j + 1) % n]):
                return (i, j)
    return None


def polygons_overlap(p: Sequence[Point], q: Sequence[Point]) -> bool:
    """True when two simple polygons share interior area (sharing only edges or corners does not count)."""
    n, m = len(p), len(q)
    for i in range(n):
        for j in range(m):
            if segments_cross(p[i], p[(i + 1) % n], q[j], q[(j + 1) % m]):
                return True
    # no proper crossings: one may contain the other, or they coincide; test inner sample points
    for a, b in ((p, q), (q, p)):
        for pt in _inner_samples(a):
            if point_in_polygon_strict(pt[0], pt[1], b):
                return True
    return False


def _inner_samples(poly: Sequence[Point]) -> list[Point]:
    """A few points strictly inside the polygon: its centroid and points just inside each vertex."""
    samples: list[Point] = []
    c = polygon_centroid(poly)
    if point_in_polygon_strict(c[0], c[1], poly):
        samples.append(c)
    for vx, vy in poly:
        for t in (0.01, 0.1):
            sx, sy = vx + (c[0] - vx) * t, vy + (c[1] - vy) * t
            if point_in_polygon_strict(sx, sy, poly):
                samples.append((sx, sy))
                break
    return samples


def rect_corners(cx: float, cy: float, sx: float, sy: float, yaw: float) -> list[Point]:
    """Corners (counter-clockwise) of a rectangle of size ``sx`` x ``sy`` centred at ``(cx, cy)``."""
    c, s = math.cos(yaw), math.sin(yaw)
    out = []
    for dx, dy in ((-sx / 2, -sy / 2), (sx / 2, -sy / 2), (sx / 2, sy / 2), (-sx / 2, sy / 2)):
        out.append((cx + c * dx - s * dy, cy + s * dx + c * dy))
    return out


def rect_distance(px: float, py: float, cx: float, cy: float, sx: float, sy: float, yaw: float) -> float:
    """Distance from a point to a (rotated) rectangle; 0 inside."""
    c, s = math.cos(yaw), math.sin(yaw)
    dx, dy = px - cx, py - cy
    lx, ly = c * dx + s * dy, -s * dx + c * dy
    ox = max(abs(lx) - sx / 2, 0.0)
    oy = max(abs(ly) - sy / 2, 0.0)
    return math.hypot(ox, oy)


def wrap_angle(a: float) -> float:
    """The angle wrapped into (-pi, pi]."""
    a = math.fmod(a + math.pi, 2 * math.pi)
    if a <= 0:
        a += 2 * math.pi
    return a - math.pi
