"""Planar geometry: the one point-in-polygon test (scalar and vectorised calls agree, concave shapes and holes
in the map) and the distance to an outline."""

from __future__ import annotations

import numpy as np
import pytest

from core.geometry import distance_to_outline, inside_polygon

#: an L-shaped (concave) room
L_SHAPE = [(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)]


def test_concave_polygon() -> None:
    assert inside_polygon(0.5, 2.5, L_SHAPE)
    assert inside_polygon(3.5, 0.5, L_SHAPE)
    assert not inside_polygon(2.5, 2.0, L_SHAPE)  # the notch of the L
    assert not inside_polygon(-0.1, 0.5, L_SHAPE)


def test_scalar_and_array_calls_agree() -> None:
    xy = np.random.default_rng(7).uniform(-1.0, 5.0, size=(500, 2))
    many = inside_polygon(xy[:, 0], xy[:, 1], np.asarray(L_SHAPE))
    one_by_one = [inside_polygon(float(x), float(y), L_SHAPE) for x, y in xy]
    assert many.dtype == np.bool_ and many.shape == (500,)
    assert many.tolist() == one_by_one
    assert 0 < int(many.sum()) < 500


def test_degenerate_polygon_holds_nothing() -> None:
    flat = [(0.0, 1.0), (2.0, 1.0), (1.0, 1.0)]
    assert not inside_polygon(1.0, 1.0, flat)
    assert inside_polygon(np.array([1.0]), np.array([1.0]), flat).tolist() == [False]


def test_distance_to_outline_inside_outside_and_at_a_corner() -> None:
    square = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]
    assert distance_to_outline(1.0, 2.0, square) == pytest.approx(1.0)  # nearest wall x = 0
    assert distance_to_outline(2.0, 5.5, square) == pytest.approx(1.5)  # outside, above
    assert distance_to_outline(7.0, 8.0, square) == pytest.approx(5.0)  # nearest the corner (4, 4)
    assert distance_to_outline(4.0, 1.0, square) == 0.0  # on an edge
