"""Publishing the places of a map as the pipeline does, for tests of one level at a time."""

from __future__ import annotations

from knic.bus import Bus, topic_level
from knic.kgm1.locations import LocationsKP
from knic.spatial import EMPTY_KEYS, LocationModel
from knic.units import CKU, Kind


def publish_place_percepts(bus: Bus, model: LocationModel, stamp: float = 0.0) -> None:
    """KGM-1's side: the locations KP publishes one location LLKU per place (what KGM-2 learns rooms from)."""
    LocationsKP(model, bus).step(stamp)


def publish_place_ckus(bus: Bus, model: LocationModel, stamp: float = 0.0) -> None:
    """KGM-2's side: one location CKU per place on ``cognition.location.<name>`` (what the KP' learn from)."""
    for location in model:
        unit = CKU(
            symbol=location.name,
            cls=location.cls,
            kind=Kind.LOCATION,
            octomap=None,
            keys=EMPTY_KEYS,
            position=(0.0, 0.0, 0.0),
            role_priority=0,
            stamp=stamp,
            confidence=1.0,
            attributes={"location": location},
        )
        bus.publish(
            f"cognition.location.{topic_level(location.name)}", unit, source="kgm2.cognition", stamp=stamp
        )
