"""Common ground of the KGM-3 KP' components: CKU streams in, PDDL facts asserted and retracted in the KB.

Lifecycle: construct with the bus and the knowledge base; register with the scheduler; each ``step(now)``
drains the CKUs received since the previous step and writes what changed. A KP' that needs the places of the
map (rooms, furniture) learns them from the location CKUs (``cognition.location``): each one is added to the
KP''s own :class:`~knic.spatial.LocationModel` the moment KGM-2 publishes it, before any KP' steps. A KP'
writes only on change (re-asserting a fact that holds with the same status is not a write), with provenance:
status OBSERVED (ASSUMED for search candidates), ``source`` = the KP' name, ``support`` = ids of the CKUs and
LLKUs behind the fact, ``at`` = simulated time.

Noise never flips a fact on one reading: a :class:`Confirmer` asks for ``needed`` consecutive consistent
observations, each within ``window_s`` of the previous one (with a mean confidence of at least
``min_confidence``), before a belief switches from what the knowledge base holds to something else. A write
the knowledge base refuses (an unknown symbol) is logged and counted, never raised into the loop: perception
goes on.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Generic, TypeVar

from core.errors import KnowledgeBaseError
from knic.bus import Bus, Inbox, Message
from knic.scheduler import Component
from knic.spatial import DEFAULT_RESOLUTION, Location, LocationModel
from knic.units import CKU
from knowledge_base import BeliefStatus, Fact, KnowledgeBase

log = logging.getLogger(__name__)

#: where KGM-2 publishes the places of the map
LOCATION_CKUS = "cognition.location"

V = TypeVar("V")


@dataclass
class _Candidate(Generic[V]):
    value: V
    count: int
    confidence_sum: float
    last: float


class Confirmer(Generic[V]):
    """Hysteresis for one single-valued belief per subject (where an entity is, a device's level ...).

    Args:
        needed: consecutive observations of a new value needed before it replaces the current one (>= 1).
        min_confidence: least mean confidence of those observations.
        window_s: most simulated seconds between two observations that count as consecutive; sporadic
            false positives far apart in time never add up (None: no limit).
    """

    def __init__(self, needed: int = 2, min_confidence: float = 0.0, window_s: float | None = 2.0) -> None:
        if needed < 1:
            raise ValueError("Confirmer needs needed >= 1")
        self.needed = needed
        self.min_confidence = min_confidence
        self.window_s = window_s
        self._pending: dict[str, _Candidate[V]] = {}

    def observe(
        self,
        subject: str,
        value: V,
        confidence: float,
        current: V | None,
        stamp: float = 0.0,
        weight: int = 1,
        decisive: bool = True,
    ) -> bool:
        """Record one observation made at simulated time ``stamp``; True when ``value`` is now confirmed and
        differs from ``current``.

        ``weight`` is how many consistent sightings the observation stands for (KGM-2 moves a recognised
        entity's track to a far spot only after several sightings there; they count here too). An observation
        that is not ``decisive`` counts toward its value but cannot confirm it (the source's own evidence is
        still too thin, e.g. a young track): a later decisive one does.
        """
        if value == current:
            self._pending.pop(subject, None)
            return False
        cand = self._pending.get(subject)
        fresh = cand is not None and (self.window_s is None or stamp - cand.last <= self.window_s)
        weight = max(1, weight)
        if cand is not None and fresh and cand.value == value:
            cand.count += weight
            cand.confidence_sum += confidence * weight
            cand.last = stamp
        else:
            cand = _Candidate(value, weight, confidence * weight, stamp)
            self._pending[subject] = cand
        if decisive and cand.count >= self.needed and cand.confidence_sum / cand.count >= self.min_confidence:
            del self._pending[subject]
            return True
        return False

    def forget(self, subject: str) -> None:
        """Drop the pending evidence about a subject."""
        self._pending.pop(subject, None)


@dataclass
class WriteStats:
    """Writes a KP' made: facts asserted, facts retracted, writes the knowledge base refused."""

    asserted: int = 0
    retracted: int = 0
    rejected: int = 0


class KPPrime(Component):
    """Base of the KP' components: inbox, KB write helpers, statistics.

    Args:
        name: component name (the facts' ``source``).
        frequency: Hz of simulated time.
        bus: where the CKUs come from.
        kb: the knowledge base written.
        pattern: bus pattern of the CKU stream consumed (None: no inbox).
        places: also consume the location CKUs into :attr:`locations`.
        resolution: metres, the octomap resolution of the entity keys in the CKUs consumed (what the volume
            queries of :attr:`locations` convert from).
    """

    def __init__(
        self,
        name: str,
        frequency: float,
        bus: Bus,
        kb: KnowledgeBase,
        pattern: str | None,
        *,
        places: bool = False,
        resolution: float = DEFAULT_RESOLUTION,
    ) -> None:
        self.name = name
        self.frequency = frequency
        self.bus = bus
        self.kb = kb
        self.inbox: Inbox | None = bus.inbox(pattern, capacity=5000) if pattern else None
        #: the rooms and furniture received as location CKUs (empty unless ``places``)
        self.locations = LocationModel(resolution)
        if places:  # the places published before this KP' was built are on the bus's whiteboard
            for message in bus.latest(LOCATION_CKUS):
                self._on_location(message)
            bus.subscribe(LOCATION_CKUS, self._on_location)
        self.writes = WriteStats()
        self._types: dict[str, str | None] = {}

    def _on_location(self, message: Message) -> None:
        cku = message.payload
        location = cku.attributes.get("location") if isinstance(cku, CKU) else None
        if isinstance(location, Location):
            self.locations.add(location)

    def is_a(self, symbol: str, pddl_type: str) -> bool:
        """Whether the knowledge base holds ``symbol`` as an instance of ``pddl_type`` (or a subtype)."""
        found = self.kb.type_of(symbol)
        return found is not None and self.kb.domain.is_subtype(found, pddl_type)

    def value_of(self, predicate: str, subject: str) -> str | None:
        """The second argument of the first ``(predicate subject ?x)`` fact, or None."""
        facts = self.kb.facts(predicate, subject)
        return facts[0].args[1] if facts else None

    def assert_fact(
        self,
        predicate: str,
        *args: str,
        at: float,
        support: tuple[str, ...] = (),
        confidence: float = 1.0,
        assumed: bool = False,
    ) -> bool:
        """Make a fact hold with this KP' as source; True if a write happened.

        No write when it already holds with the same belief status (observed, or assumed when ``assumed``).
        """
        status = BeliefStatus.ASSUMED if assumed else BeliefStatus.OBSERVED
        prov = self.kb.why(Fact(predicate, tuple(args)))
        if prov is not None and prov.status == status:
            return False
        try:
            self.kb.add_fact(
                predicate,
                *args,
                source=self.name,
                at=at,
                status=status,
                confidence=max(0.0, min(1.0, confidence)),
                support=support,
            )
        except KnowledgeBaseError as exc:
            self.writes.rejected += 1
            log.warning("%s: refused (%s %s): %s", self.name, predicate, " ".join(args), exc)
            return False
        self.writes.asserted += 1
        return True

    def retract_fact(self, predicate: str, *args: str, at: float, support: tuple[str, ...] = ()) -> bool:
        """Make a fact not hold; True if it held and was retracted."""
        try:
            done = self.kb.remove_fact(
                predicate, *args, source=self.name, at=at, status=BeliefStatus.OBSERVED, support=support
            )
        except KnowledgeBaseError as exc:
            self.writes.rejected += 1
            log.warning("%s: refused retraction (%s %s): %s", self.name, predicate, " ".join(args), exc)
            return False
        if done:
            self.writes.retracted += 1
        return done

    def retract_all(
        self,
        predicate: str,
        *pattern: str | None,
        at: float,
        keep: Fact | None = None,
        support: tuple[str, ...] = (),
    ) -> int:
        """Retract every fact matching ``pattern`` except ``keep``; return how many went."""
        count = 0
        for fact in self.kb.facts(predicate, *pattern):
            if fact != keep and self.retract_fact(fact.predicate, *fact.args, at=at, support=support):
                count += 1
        return count
