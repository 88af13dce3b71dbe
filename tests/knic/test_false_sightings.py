"""A never-seen item's place is confirmed by a track seen consistently, not by two spurious detections.

Issue 14 (the loft, "look for the soap"): the detector's false positives (a random patch of the image under a
random item class) twice put "soap" on the bench table, 5 cm and 1.8 s apart, while the camera looked at the
table and saw no soap in the frames between. KGM-2 made one track of the two; the place KP' counted two
sightings within its window and wrote ``(object_on soap bench_table)`` and ``(found soap)``. A real item in
view is detected in most frames: its track is confirmed a frame later than before, the spurious one never.
"""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import Policy, Role
from knic.kgm3.places import ObjectPlaceKP
from knic.spatial import LocationModel
from knic.units import Kind, Scan
from knowledge_base import Fact, KnowledgeBase
from tests.knic.places import publish_place_percepts
from tests.knic.synthetic import SeesEverything, percept

KITCHEN_TABLE = (6.0, 6.6, 0.78)


#: where the synthetic frames look from, and along which axis
_VIEW = SeesEverything((6.0, 5.0, 1.2), (0.0, 1.0, 0.0))


class _Run:
    """KGM-2 and the object place KP' on synthetic frames, every frame processed."""

    def __init__(self, kb: KnowledgeBase, locations: LocationModel) -> None:
        self.bus = Bus()
        self.layer = CognitiveLayer(self.bus, Role("test", "every frame", Policy(10.0, 1)))
        self.places = ObjectPlaceKP(self.bus, kb, needed=2)
        publish_place_percepts(self.bus, locations)
        self.layer.step(0.0)

    def frame(self, t: float, seen: tuple[float, float, float] | None) -> None:
        if seen is not None:
            unit = percept(Kind.OBJECT, "glasses", seen, t, identity="glasses", confidence=0.66)
            self.bus.publish("percept.vision.object.glasses", unit, source="kp", stamp=t)
        scan = Scan(Kind.OBJECT, t, _VIEW, "cam")
        self.bus.publish("percept.vision.scan.object", scan, source="kp", stamp=t)
        self.layer.step(t)
        self.places.step(t)


def test_two_false_positives_at_one_spot_confirm_no_place(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    assert not paper_kb.facts("object_at", "glasses")
    run = _Run(paper_kb, paper_locations)
    beside = (KITCHEN_TABLE[0] + 0.04, KITCHEN_TABLE[1] - 0.03, KITCHEN_TABLE[2])
    run.frame(1.0, KITCHEN_TABLE)  # a patch of the table read as "glasses"
    for i in range(1, 9):  # the table in view, nothing there
        run.frame(1.0 + 0.2 * i, None)
    run.frame(2.8, beside)  # another one, 5 cm from the first
    for i in range(1, 4):
        run.frame(2.8 + 0.2 * i, None)
    assert not paper_kb.facts("object_at", "glasses")
    assert not paper_kb.facts("object_on", "glasses")
    assert not paper_kb.holds("found", "glasses")


def test_a_false_positive_after_the_first_ones_track_was_lost_starts_afresh(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    run = _Run(paper_kb, paper_locations)
    run.frame(1.0, KITCHEN_TABLE)
    for i in range(1, 20):  # the table in view, nothing there: the track is dropped
        run.frame(1.0 + 0.2 * i, None)
    assert not run.layer.trackers["glasses"].tracks
    run.frame(5.0, KITCHEN_TABLE)  # within the place KP's window of the first one
    assert not paper_kb.facts("object_at", "glasses") and not paper_kb.holds("found", "glasses")


def test_an_item_seen_in_consecutive_frames_is_found(
    paper_kb: KnowledgeBase, paper_locations: LocationModel
) -> None:
    run = _Run(paper_kb, paper_locations)
    run.frame(1.0, KITCHEN_TABLE)
    run.frame(1.2, None)  # one miss, as the detector has
    for t in (1.4, 1.6):
        run.frame(t, KITCHEN_TABLE)
    assert paper_kb.facts("object_at", "glasses") == [Fact("object_at", ("glasses", "kitchen"))]
    assert paper_kb.holds("object_on", "glasses", "kitchen_table") and paper_kb.holds("found", "glasses")
