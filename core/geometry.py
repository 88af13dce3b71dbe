"""Planar geometry shared by every package: the one point-in-polygon test and the distance to a polygon's
outline (world frame, metres).

:func:`inside_polygon` takes one point (two floats) or many (two numpy arrays of the same shape) with the same
arithmetic, so the simulator's scalar checks and KnIC's vectorised rasterisation agree to the last bit. Pure
Python: numpy arrays work through their operators, nothing here imports numpy.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, TypeAlias, overload

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

#: a closed polygon: (x, y) vertices in order, the last joined to the first (pairs or an (M, 2) array)
PolygonLike: TypeAlias = "Sequence[Sequence[float]] | npt.NDArray[np.float64]"


@overload
def inside_polygon(x: float, y: float, polygon: PolygonLike) -> bool: ...


@overload
def inside_polygon(
    x: npt.NDArray[np.float64], y: npt.NDArray[np.float64], polygon: PolygonLike
) -> npt.NDArray[np.bool_]: ...


def inside_polygon(x: Any, y: Any, polygon: PolygonLike) -> Any:
    """Even-odd rule: whether the point(s) ``(x, y)`` lie inside the closed ``polygon``.

    A horizontal ray from the point to +x crosses the boundary an odd number of times from inside. Points
    exactly on an edge fall on either side (callers that need edges to count decide it themselves, e.g.
    :func:`worlds.geometry.point_in_polygon`). Horizontal edges are never crossed.

    Args:
        x: x coordinate(s), a float or an array.
        y: y coordinate(s), same type and shape as ``x``.
        polygon: three or more (x, y) vertices (a list of pairs or an (M, 2) array).

    Returns:
        A bool for float input, a boolean array of ``x``'s shape for array input.
    """
    inside = x < x  # False, or an all-False array of x's shape
    count = len(polygon)
    for i in range(count):
        x1, y1 = polygon[i]
        x2, y2 = polygon[(i + 1) % count]
        if y1 == y2:
            continue
        crosses = (y1 > y) != (y2 > y)
        x_at = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
        inside = inside ^ (crosses & (x < x_at))
    return inside


def distance_to_outline(x: float, y: float, polygon: PolygonLike) -> float:
    """Distance from the point ``(x, y)`` to the nearest edge of the closed ``polygon`` (inside or out)."""
    best = float("inf")
    count = len(polygon)
    for i in range(count):
        x1, y1 = polygon[i]
        x2, y2 = polygon[(i + 1) % count]
        dx, dy = x2 - x1, y2 - y1
        length2 = dx * dx + dy * dy
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((x - x1) * dx + (y - y1) * dy) / length2))
        best = min(best, ((x - x1 - t * dx) ** 2 + (y - y1 - t * dy) ** 2) ** 0.5)
    return float(best)
