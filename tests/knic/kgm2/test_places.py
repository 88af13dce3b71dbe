"""KGM-2 and the places of the map: learnt from the location LLKUs, republished as location CKUs."""

from __future__ import annotations

from knic.bus import Bus
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import load_role
from knic.spatial import FURNITURE, ROOM, LocationModel
from knic.units import CKU, LLKU, Kind
from tests.knic.places import publish_place_percepts


def test_location_units_become_location_ckus_and_rooms_of_the_role(paper_locations: LocationModel) -> None:
    bus = Bus()
    layer = CognitiveLayer(bus, load_role("companion"))
    out = bus.inbox("cognition.location")
    # no places yet: the camera is outside every room, so the role lets every class through
    assert layer.locations.room_at(7.0, 1.5) is None
    assert layer.admits("mug", (7.0, 1.5, 1.2), 0.0)
    publish_place_percepts(bus, paper_locations)
    assert layer.locations.room_at(7.0, 1.5) == "entrance"  # learnt when published, before any step
    layer.step(0.0)
    ckus: list[CKU] = [m.payload for m in out.drain()]
    assert [c.symbol for c in ckus] == [p.name for p in paper_locations]
    bedroom = ckus[0]
    assert (bedroom.cls, bedroom.kind) == (ROOM, Kind.LOCATION)
    assert bedroom.octomap is paper_locations.rooms.prisms["bedroom"].octree()
    assert bedroom.role_priority == load_role("companion").policy(ROOM, "bedroom").priority
    shelf = next(c for c in ckus if c.symbol == "entrance_shelf")
    assert shelf.cls == FURNITURE and shelf.octomap is not None and len(shelf.support) == 1


def test_a_location_unit_without_a_place_is_skipped(paper_locations: LocationModel) -> None:
    bus = Bus()
    layer = CognitiveLayer(bus, load_role("companion"))
    out = bus.inbox("cognition.location")
    stray = LLKU(Kind.LOCATION, "attic", "kp.test", "map", 0.0, 1.0, (0.0, 0.0, 0.0), identity="attic")
    bus.publish("percept.map.location.attic", stray, source="kp.test", stamp=0.0)
    layer.step(0.0)
    assert len(out) == 0 and layer.stats.skipped == 1 and len(layer.locations) == 0
