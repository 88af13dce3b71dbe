"""The spatial floor: octomaps of rooms (from the 2D map) and of tracked entities, key arithmetic against
pyoctomap, the places model a level builds from location units."""

from __future__ import annotations

import numpy as np
import pyoctomap
import pytest

from core.errors import InferenceError
from knic.spatial import (
    DEFAULT_RESOLUTION,
    FURNITURE,
    ROOM,
    EntityOctomap,
    Location,
    LocationModel,
    Prism,
    VolumeSet,
    coarsen,
    key_centers,
    keys_of,
    unique_keys,
)
from tests.knic.synthetic import blob


def test_numpy_keys_match_octomap_keys() -> None:
    tree = pyoctomap.OcTree(DEFAULT_RESOLUTION)
    points = np.random.default_rng(1).uniform(-5, 9, size=(200, 3))
    ours = keys_of(points)
    theirs = np.array([list(tree.coordToKey(p)) for p in points])
    assert (ours == theirs).all()
    assert np.allclose(keys_of(key_centers(ours)), ours)
    coarse = pyoctomap.OcTree(DEFAULT_RESOLUTION * 4)
    assert (coarsen(ours, 2) == np.array([list(coarse.coordToKey(p)) for p in points])).all()
    assert len(unique_keys(np.vstack([ours, ours]))) == len(unique_keys(ours))


def test_one_octomap_per_room_from_the_2d_map(paper_locations: LocationModel) -> None:
    rooms = paper_locations.rooms
    assert rooms.names() == ["bedroom", "kitchen", "entrance", "living_room"]
    for name, prism in rooms.prisms.items():
        # 4 m x 4 m floor, 2.5 m walls, 0.1 m voxels
        assert prism.voxel_count == 40 * 40 * 25
        tree = prism.octree()
        wx, wy = paper_locations.waypoints[name]
        node = tree.search(np.array([wx, wy, 1.0]))
        assert node is not None and tree.isNodeOccupied(node)
        assert tree.search(np.array([wx + 10.0, wy, 1.0])) is None
        assert paper_locations.room_at(wx, wy) == name
    assert paper_locations.room_at(20.0, 20.0) is None


def test_room_membership_by_voxel_intersection(paper_locations: LocationModel) -> None:
    rooms = paper_locations.rooms
    assert rooms.best(keys_of(blob((6.0, 6.6, 0.8)))) == ("kitchen", 1.0)
    straddling = keys_of(blob((4.0, 6.0, 1.0), n=200, spread=0.3))
    counts = rooms.overlaps(straddling)
    assert set(counts) == {"bedroom", "kitchen"}
    assert rooms.best(np.zeros((0, 3), dtype=np.int64)) == (None, 0.0)


def test_furniture_support_volume(paper_locations: LocationModel) -> None:
    on_shelf = keys_of(blob((7.75, 1.5, 0.92), spread=0.02))
    assert paper_locations.furniture.best(on_shelf)[0] == "entrance_shelf"
    on_floor = keys_of(blob((6.0, 2.0, 0.05), spread=0.02))
    assert paper_locations.furniture.best(on_floor)[0] is None


def test_entity_octomap_follows_the_entity() -> None:
    octo = EntityOctomap(reset_distance=0.5)
    origin = (0.0, 0.0, 1.2)
    a = blob((2.0, 0.0, 0.8), spread=0.02)
    octo.update(a, (2.0, 0.0, 0.8), origin)
    assert octo.occupied_at((2.0, 0.0, 0.8))
    assert {tuple(k) for k in octo.keys} == {tuple(k) for k in unique_keys(keys_of(a))}
    b = blob((3.5, 1.0, 0.8), spread=0.02)
    octo.update(b, (3.5, 1.0, 0.8), origin)
    assert octo.resets == 1
    assert octo.occupied_at((3.5, 1.0, 0.8)) and not octo.occupied_at((2.0, 0.0, 0.8))


def test_entity_octomap_accumulates_evidence_and_yields_to_misses() -> None:
    origin = (0.0, 0.0, 1.2)
    a = blob((2.0, 0.0, 0.8), spread=0.02)
    once, often = EntityOctomap(), EntityOctomap()
    once.update(a, (2.0, 0.0, 0.8), origin)
    for _ in range(6):
        often.update(a, (2.0, 0.0, 0.8), origin)
    # the keys are the tree's occupied voxels: misses lower their log-odds (clamped), a one-off goes first
    misses_once = next(i for i in range(1, 20) if once.miss() == 0)
    misses_often = next(i for i in range(1, 20) if often.miss() == 0)
    assert misses_once < misses_often <= 8
    assert len(often.keys) == 0 and not often.occupied_at((2.0, 0.0, 0.8))


def test_entity_keys_are_read_from_the_tree() -> None:
    octo = EntityOctomap()
    a = blob((2.0, 0.0, 0.8), spread=0.02)
    octo.update(a, (2.0, 0.0, 0.8), (0.0, 0.0, 1.2))
    # corrupt the tree: the entity's voxels freed, others elsewhere made occupied
    elsewhere = blob((2.0, 0.3, 0.8), spread=0.02)
    for _ in range(5):
        octo.tree.updateNodes(key_centers(octo.occupied_keys()), False)
        octo.tree.updateNodes(elsewhere, True)
    keys = octo.occupied_keys()
    assert {tuple(k) for k in keys} == {tuple(k) for k in unique_keys(keys_of(elsewhere))}


def test_entity_keys_are_a_query_made_when_read() -> None:
    octo = EntityOctomap()
    origin = (0.0, 0.0, 1.2)
    clouds = [blob((2.0, 0.0, 0.8), spread=0.02, seed=i) for i in range(4)]
    for cloud in clouds:
        octo.update(cloud, (2.0, 0.0, 0.8), origin)
    assert (octo.full_scans, octo.searches) == (0, 0)  # inserting reads nothing back from the tree
    first = octo.keys
    assert octo.full_scans == 1 and octo.keys is first  # cached until the tree changes
    hit = unique_keys(keys_of(np.concatenate(clouds)))
    assert {tuple(k) for k in first} == {tuple(k) for k in octo.occupied_keys()} <= {tuple(k) for k in hit}
    # three clouds inserted unread: one search of the voxels they hit and the ones occupied before
    later = [blob((2.05, 0.0, 0.8), spread=0.02, seed=10 + i) for i in range(3)]
    for cloud in later:
        octo.update(cloud, (2.05, 0.0, 0.8), origin)
    keys = octo.keys
    assert (octo.full_scans, octo.searches) == (1, 1)
    assert {tuple(k) for k in keys} == {tuple(k) for k in octo.occupied_keys()}


def test_a_point_on_a_voxel_boundary_is_searched_where_the_tree_put_it() -> None:
    octo = EntityOctomap()
    origin = (-1.0, 1.0, 1.2)
    octo.update(blob((0.1, 1.0, 1.0), spread=0.01), (0.1, 1.0, 1.0), origin)
    assert octo.full_scans == 0 and len(octo.keys) > 0 and octo.full_scans == 1
    # a hair below x = 0.15 in double precision, but 0.15000000596 in the single precision octomap keys in
    edge = np.array([[0.15 - 1e-9, 1.0125, 1.0125]] * 5)
    assert keys_of(edge)[0, 0] + 1 == octo.tree.coordToKey(edge[0])[0]
    for _ in range(3):
        octo.update(edge, (0.12, 1.0, 1.0), origin)
    keys = octo.keys
    assert octo.searches == 1  # not a full read: the search found the voxel the tree keyed
    assert {tuple(k) for k in keys} == {tuple(k) for k in octo.occupied_keys()}


def test_unread_clouds_are_not_kept_once_a_full_read_is_due() -> None:
    octo = EntityOctomap()
    cloud = blob((2.0, 0.0, 0.8), spread=0.02)
    for _ in range(3 * octo.full_scan_every):
        octo.update(cloud, (2.0, 0.0, 0.8), (0.0, 0.0, 1.2))
    assert not octo._inserted  # nobody read the keys: memory stays bounded
    assert len(octo.keys) > 0 and octo.full_scans == 1


def test_bad_prisms_are_refused() -> None:
    with pytest.raises(InferenceError, match="polygon"):
        Prism("x", np.array([[0.0, 0.0], [1.0, 1.0]]), 0.0, 1.0)
    with pytest.raises(InferenceError, match="z_max"):
        Prism("x", np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]), 1.0, 1.0)


SQUARE = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])


def test_places_are_learnt_one_unit_at_a_time_in_map_order(paper_locations: LocationModel) -> None:
    model = LocationModel()
    for location in paper_locations:
        model.add(location)
    assert model.rooms.names() == paper_locations.rooms.names()
    assert model.furniture.names() == paper_locations.furniture.names()
    assert model.footprints.keys() == paper_locations.footprints.keys()
    assert model.furniture_room == paper_locations.furniture_room
    assert model.waypoints == paper_locations.waypoints
    # every piece of furniture is a place; only surfaces carry a support volume
    pieces = [p for p in paper_locations if p.cls == FURNITURE]
    assert len(pieces) == len(paper_locations.footprints) >= len(paper_locations.furniture)
    # a place published again replaces the old one in its position
    first = model.rooms.names()[0]
    again = Location(first, ROOM, SQUARE, Prism(first, SQUARE, 0.0, 2.5), waypoint=(1.0, 1.0))
    model.add(again)
    assert model.rooms.names() == paper_locations.rooms.names()
    assert model.rooms.prisms[first] is again.volume and model.waypoints[first] == (1.0, 1.0)


def test_volume_sets_take_their_resolution_from_the_first_volume() -> None:
    rooms = VolumeSet()
    assert rooms.resolution == DEFAULT_RESOLUTION and len(rooms) == 0
    rooms.add(Prism("a", SQUARE, 0.0, 2.5, 0.1))
    assert rooms.resolution == 0.1
    assert rooms.best(keys_of(blob((1.0, 1.0, 1.0)))) == ("a", 1.0)
    with pytest.raises(InferenceError, match="resolution"):
        rooms.add(Prism("b", SQUARE + 3.0, 0.0, 2.5, 0.05))
    assert rooms.names() == ["a"]
    with pytest.raises(InferenceError, match="power of two"):
        VolumeSet([Prism("c", SQUARE, 0.0, 1.0, 0.07)])


def test_bad_places_are_refused() -> None:
    with pytest.raises(InferenceError, match="not room or furniture"):
        Location("x", "door", SQUARE)
    with pytest.raises(InferenceError, match="needs its volume"):
        Location("x", ROOM, SQUARE)
