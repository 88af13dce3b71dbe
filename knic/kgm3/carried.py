"""Items in people's hands: which recognised person, if any, holds an item the camera sees off every surface.

A person carrying something holds it in front of their body at hand height; the robot sees the item there,
next to the person's octomap, resting on no surface. :class:`PeopleHands` keeps the latest place of every
recognised person from KGM-2's person CKUs (``cognition.person``) and answers :meth:`PeopleHands.holder`
for an item sighting. The object place KP' (:class:`knic.kgm3.places.ObjectPlaceKP`) confirms the holder
like any other place and writes ``(has ?p ?o)`` -- the item is with that person, at no place of its own --
instead of ``object_at`` / ``object_on``.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from knic.bus import Bus, Message
from knic.units import CKU

#: KGM-2's person CKUs
PERSON_CKUS = "cognition.person.*"


class PeopleHands:
    """The recognised people's latest places, for telling an item in someone's hands.

    Args:
        bus: where KGM-2 publishes the person CKUs (subscribed at once).
        is_person: whether a symbol is a known person instance (anonymous tracks are left out: ``has``
            needs a person symbol).
        reach_m: most metres on the floor between the item and the person's octomap centre (a held item is
            about 0.35 m in front of the body's axis; the centre of the voxels the camera saw lies on the
            body's near side).
        fresh_s: most simulated seconds between the person's latest sighting and the item's.
        min_height: least height, metres, of a held item's centre (below: on the floor, or a low surface).
        max_height: greatest height, metres, of a held item's centre.
    """

    def __init__(
        self,
        bus: Bus,
        is_person: Callable[[str], bool],
        *,
        reach_m: float = 0.6,
        fresh_s: float = 1.0,
        min_height: float = 0.6,
        max_height: float = 1.4,
    ) -> None:
        self.is_person = is_person
        self.reach_m = reach_m
        self.fresh_s = fresh_s
        self.min_height = min_height
        self.max_height = max_height
        #: person -> (x, y, stamp) of their latest sighting
        self.people: dict[str, tuple[float, float, float]] = {}
        bus.subscribe(PERSON_CKUS, self._on_person)

    def _on_person(self, message: Message) -> None:
        cku = message.payload
        if not isinstance(cku, CKU):
            return
        if cku.attributes.get("lost"):
            self.people.pop(cku.symbol, None)
        elif self.is_person(cku.symbol):
            self.people[cku.symbol] = (cku.position[0], cku.position[1], cku.stamp)

    def holder(self, item: CKU) -> str | None:
        """The person whose hands an item sighting is in: the nearest recognised person seen within
        ``fresh_s`` of it, within ``reach_m`` on the floor, with the item at hand height; None otherwise.
        The caller asks only for an item resting on no surface."""
        x, y, z = item.position
        if not self.min_height <= z <= self.max_height:
            return None
        best: tuple[float, str] | None = None
        for person, (px, py, stamp) in self.people.items():
            if abs(item.stamp - stamp) > self.fresh_s:
                continue
            d = math.hypot(x - px, y - py)
            if d <= self.reach_m and (best is None or d < best[0]):
                best = (d, person)
        return best[1] if best is not None else None
