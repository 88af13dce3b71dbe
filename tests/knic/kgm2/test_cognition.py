"""KGM-2's CKUs carry their entity's octomap and the query of its occupied voxels, not voxels computed for
every unit: the layer's updates read nothing back from the trees, and a KP' reading a unit's keys gets what
the tree holds at that moment."""

from __future__ import annotations

import numpy as np

from knic.bus import Bus
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import Policy, Role
from knic.spatial import LocationModel, keys_of, unique_keys
from knic.units import CKU, Kind
from tests.knic.places import publish_place_percepts
from tests.knic.synthetic import percept

SHELF_TOP = (7.75, 1.5, 0.92)


def _feed(frames: int, locations: LocationModel) -> tuple[CognitiveLayer, list[CKU]]:
    bus = Bus()
    layer = CognitiveLayer(bus, Role("test", "every frame", Policy(10.0, 1)))
    publish_place_percepts(bus, locations)
    box = bus.inbox("cognition.object.glasses")
    for i in range(frames):
        t = 0.1 * (i + 1)
        unit = percept(Kind.OBJECT, "glasses", SHELF_TOP, t, identity="glasses")
        bus.publish("percept.vision.object.glasses", unit, source="kp", stamp=t)
        layer.step(t)
    return layer, [m.payload for m in box.drain()]


def test_updates_query_no_tree_until_a_unit_is_read(paper_locations: LocationModel) -> None:
    layer, ckus = _feed(5, paper_locations)
    track = layer.trackers["glasses"].by_symbol("glasses")
    assert track is not None and len(ckus) == 5
    octo = track.octomap
    assert (octo.updates, octo.full_scans, octo.searches) == (5, 0, 0)
    keys = ckus[-1].keys  # what a KP' does: one query of the tree
    assert octo.full_scans + octo.searches == 1
    assert paper_locations.rooms.best(keys)[0] == "entrance"
    assert {tuple(k) for k in keys} == {tuple(k) for k in octo.occupied_keys()}
    assert ckus[0].keys.tolist() == keys.tolist()  # an older unit read now sees the same tree, no new query
    assert octo.full_scans + octo.searches == 1


def test_a_unit_reads_the_tree_as_it_is_when_read(paper_locations: LocationModel) -> None:
    _, (control, _) = _feed(2, paper_locations)
    assert paper_locations.furniture.best(control.keys)[0] == "entrance_shelf"
    layer, (first, second) = _feed(2, paper_locations)
    track = layer.trackers["glasses"].by_symbol("glasses")
    assert track is not None
    track.octomap.tree.clear()  # corrupt the tree after publication, before any KP' read the units
    # no occupied voxel left: the query answers the centroid's key alone, for both units
    centroid = unique_keys(keys_of(np.array([track.centroid], dtype=np.float64)))
    assert first.keys.tolist() == second.keys.tolist() == centroid.tolist()
