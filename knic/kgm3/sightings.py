"""The perception the robot's actions steer by, fed from KGM-2's entity CKUs.

:class:`BusPerception` is the inference side's implementation of :class:`actions.erl.perception.Perception`:
it subscribes to ``cognition.object`` and ``cognition.person`` and records every CKU's centroid, stamp and
``lost`` flag as the entity's latest sighting. Updates happen synchronously when KGM-2 publishes, inside the
scheduler's one thread; :meth:`BusPerception.close` unsubscribes.
"""

from __future__ import annotations

from actions.erl.perception import Sighting, SightingBook
from knic.bus import Bus, Message, Subscription
from knic.units import CKU
from knowledge_base import KnowledgeBase

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
        self._subs: list[Subscription] = [bus.subscribe(p, self._on_cku) for p in SIGHTING_TOPICS]

    def _on_cku(self, message: Message) -> None:
        cku = message.payload
        if not isinstance(cku, CKU):
            return
        x, y, z = (float(v) for v in cku.position)
        self.record(cku.symbol, Sighting((x, y, z), float(cku.stamp), bool(cku.attributes.get("lost"))))

    def close(self) -> None:
        """Stop listening to the bus (idempotent)."""
        for sub in self._subs:
            sub.cancel()
        self._subs = []
