"""The entity octomaps carry the reasoning: corrupting a tree changes the facts the KP' derive from it.

KGM-2 (the cognitive layer) tracks the glasses on the entrance shelf from synthetic frames and keeps their
octomap; the place KP' derives ``object_at`` / ``object_on`` from the voxels the CKUs read from that tree. A
control run and a run whose tree is corrupted between two frames must end with different facts.
"""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import Policy, Role
from knic.kgm3.places import ObjectPlaceKP
from knic.spatial import EntityOctomap, LocationModel, key_centers
from knic.units import Kind, Scan
from knowledge_base import Fact, KnowledgeBase
from tests.knic.places import publish_place_percepts
from tests.knic.synthetic import SeesEverything, blob, percept

SHELF_TOP = (7.75, 1.5, 0.92)
KITCHEN_TABLE = (6.0, 6.6, 0.78)


#: where the synthetic frames look from, and along which axis
_VIEW = SeesEverything((6.5, 1.5, 1.2), (1.0, 0.0, 0.0))


class _Run:
    def __init__(self, kb: KnowledgeBase, locations: LocationModel) -> None:
        self.bus = Bus()
        self.layer = CognitiveLayer(self.bus, Role("test", "every frame", Policy(10.0, 1)))
        self.places = ObjectPlaceKP(self.bus, kb, needed=2)
        publish_place_percepts(self.bus, locations)
        self.layer.step(0.0)
        self.kb = kb

    def frame(self, t: float, seen: tuple[float, float, float] | None) -> None:
        if seen is not None:
            unit = percept(Kind.OBJECT, "glasses", seen, t, identity="glasses")
            self.bus.publish("percept.vision.object.glasses", unit, source="kp", stamp=t)
        scan = Scan(Kind.OBJECT, t, _VIEW, "cam")
        self.bus.publish("percept.vision.scan.object", scan, source="kp", stamp=t)
        self.layer.step(t)
        self.places.step(t)

    def tree(self) -> EntityOctomap:
        track = self.layer.trackers["glasses"].by_symbol("glasses")
        assert track is not None
        return track.octomap


def _on_the_shelf(kb: KnowledgeBase, locations: LocationModel) -> _Run:
    run = _Run(kb, locations)
    for i in range(6):
        run.frame(0.2 * (i + 1), SHELF_TOP)
    assert kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "entrance"))]
    assert kb.holds("object_on", "glasses", "entrance_shelf")
    return run


def test_an_emptied_tree_retracts_what_a_single_miss_would_not(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    run = _on_the_shelf(paper_kb, paper_locations)
    run.frame(5.0, None)  # control: one view without the glasses is not enough evidence against six sightings
    assert paper_kb.holds("object_at", "glasses", "entrance")
    run.tree().tree.clear()  # corrupt the tree: no occupied voxel left (the miss reads the tree)
    run.frame(5.2, None)
    assert not paper_kb.facts("object_at", "glasses") and not paper_kb.facts("object_on", "glasses")


def test_voxels_moved_in_the_tree_move_the_fact(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    run = _on_the_shelf(paper_kb, paper_locations)
    octo = run.tree()
    elsewhere = blob(KITCHEN_TABLE, n=400, spread=0.08)
    for _ in range(6):  # corrupt the tree: the shelf voxels freed, many voxels on the kitchen table occupied
        octo.tree.updateNodes(key_centers(octo.occupied_keys()), False)
        octo.tree.updateNodes(elsewhere, True)
    # the glasses are still seen on the shelf, but the tree now says kitchen (once the layer has read the
    # whole tree again: every few updates)
    for i in range(octo.full_scan_every + 2):
        run.frame(2.0 + 0.2 * i, SHELF_TOP)
    assert paper_kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "kitchen"))]


def test_control_without_corruption_keeps_the_facts(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    run = _on_the_shelf(paper_kb, paper_locations)
    for t in (2.0, 2.2):
        run.frame(t, SHELF_TOP)
    run.frame(5.0, None)
    assert paper_kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "entrance"))]
    assert paper_kb.holds("object_on", "glasses", "entrance_shelf")
