"""The perception the robot's actions steer by, fed from KGM-2's entity CKUs.

:class:`BusPerception` is the inference side's implementation of :class:`actions.erl.perception.Perception`:
it subscribes to ``cognition.object`` and ``cognition.person`` and records every CKU's centroid, stamp and
``lost`` flag as the entity's latest sighting. Updates happen synchronously when KGM-2 publishes, inside the
scheduler's one thread; :meth:`BusPerception.close` unsubscribes.
"""

from __future__ import annotations

import numpy as np

from actions.erl.perception import Point3, Sighting, SightingBook
from knic.bus import Bus, Message, Subscription, topic_level
from knic.spatial import DEFAULT_RESOLUTION, EMPTY_KEYS, keys_of
from knic.units import CKU, Kind
from knowledge_base import KnowledgeBase

#: source of the lost CKUs published for a refuted belief
REFUTED_SOURCE = "actions.refuted"
#: bus prefixes whose CKUs are entity sightings
SIGHTING_TOPICS = ("cognition.object", "cognition.person")


class BusPerception(SightingBook):
    """Latest perceived pose of every tracked item and person (see the module docstring).

    Args:
        kb: the knowledge base, whose anchors answer for entities not seen this run.
        bus: the run's message bus.
    """

    def __init__(self, kb: KnowledgeBase, bus: Bus) -> None:
        super().__init__(kb)
        self.bus = bus
        self._subs: list[Subscription] = [bus.subscribe(p, self._on_cku) for p in SIGHTING_TOPICS]

    def _on_cku(self, message: Message) -> None:
        cku = message.payload
        if not isinstance(cku, CKU):
            return
        x, y, z = (float(v) for v in cku.position)
        self.record(cku.symbol, Sighting((x, y, z), float(cku.stamp), bool(cku.attributes.get("lost"))))

    def refute(self, symbol: str, position: Point3, stamp: float, reason: str) -> None:
        """An action found ``symbol`` not at ``position``: publish it as lost there on its CKU stream
        (``cognition.<kind>.<symbol>``, ``attributes["refuted"]`` = the reason), as KGM-2 publishes a track it
        dropped, so the place KP' retract the belief; the sighting is recorded lost (see
        :meth:`actions.erl.perception.Perception.refute`)."""
        self.refuted.append((symbol, position, stamp, reason))
        kind = Kind.PERSON if self._is_person(symbol) else Kind.OBJECT
        cku = CKU(
            symbol=symbol,
            cls="person" if kind is Kind.PERSON else symbol,
            kind=kind,
            octomap=None,
            keys=EMPTY_KEYS,
            position=(float(position[0]), float(position[1]), float(position[2])),
            role_priority=0,
            stamp=stamp,
            confidence=1.0,
            attributes={
                "lost": True,
                "refuted": reason,
                "last_keys": keys_of(np.array([position], dtype=np.float64), DEFAULT_RESOLUTION),
            },
        )
        self.bus.publish(
            f"cognition.{kind.value}.{topic_level(symbol)}", cku, source=REFUTED_SOURCE, stamp=stamp
        )

    def _is_person(self, symbol: str) -> bool:
        found = self.kb.type_of(symbol)
        return found is not None and self.kb.domain.is_subtype(found, "person")

    def close(self) -> None:
        """Stop listening to the bus (idempotent)."""
        for sub in self._subs:
            sub.cancel()
        self._subs = []
