"""Common ground of the KGM-1 knowledge providers (KP): one sensor in, LLKUs out on the bus.

Lifecycle: construct with the sensor source, the bus and (optionally) the knowledge base; register with the
scheduler; each ``step(now)`` reads the sensor once and publishes one LLKU per perceived element on
``percept.<modality>.<kind>.<label>``. The first time a KP meets an individual it recognises (a symbol the
knowledge base does not hold yet) it adds the instance to the knowledge base, once (seed 004, III.C).
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from core.errors import KnowledgeBaseError
from knic.bus import Bus, topic_level
from knic.scheduler import Component
from knic.units import LLKU

if TYPE_CHECKING:
    from knowledge_base import KnowledgeBase

log = logging.getLogger(__name__)


class KnowledgeProvider(Component):
    """A KGM-1 provider. Subclasses implement ``step`` and call :meth:`publish` and :meth:`meet`.

    Args:
        name: component name, also the ``source`` of its LLKUs and of the instances it adds.
        frequency: Hz of simulated time.
        bus: where LLKUs go.
        kb: knowledge base for first-meeting instances; None to never add instances.
        modality: second topic level (``vision``, ``pose``, ``audio``, ``device``, ``map``).
    """

    def __init__(
        self, name: str, frequency: float, bus: Bus, kb: KnowledgeBase | None, modality: str
    ) -> None:
        self.name = name
        self.frequency = frequency
        self.bus = bus
        self.kb = kb
        self.modality = modality
        self.published = 0
        self._met: set[str] = set()

    def publish(self, unit: LLKU) -> None:
        """Publish an LLKU on ``percept.<modality>.<kind>.<label>`` at the unit's time stamp."""
        topic = f"percept.{self.modality}.{unit.kind.value}.{topic_level(unit.label)}"
        self.bus.publish(topic, unit, source=self.name, stamp=unit.stamp)
        self.published += 1

    def meet(self, pddl_type: str, symbol: str, now: float, support: tuple[str, ...] = ()) -> None:
        """Add ``symbol`` as an instance of ``pddl_type`` the first time this KP meets it.

        A refused write (unknown type, name clash) is logged and not retried; perception goes on.
        """
        if symbol in self._met or self.kb is None:
            return
        self._met.add(symbol)
        if self.kb.type_of(symbol) is not None:
            return
        from knowledge_base import BeliefStatus

        try:
            self.kb.add_instance(
                pddl_type, symbol, source=self.name, at=now, status=BeliefStatus.OBSERVED, support=support
            )
        except KnowledgeBaseError as exc:
            log.warning("%s: cannot add instance %s - %s: %s", self.name, symbol, pddl_type, exc)
