"""Fusion: one belief per fact from several sources, weighed by status, confidence and age (seed 003).

Every writer of the knowledge base (the KP', the dispatcher's effects, priors, the user) makes *claims*
about facts: the fact holds, or it does not. The knowledge base keeps one belief per fact; :class:`Fusion`
decides, at each write that would replace or retract a belief held on another source's authority, whether
the new claim outweighs the standing one:

``weight = STATUS_WEIGHT[status] * confidence * 0.5 ** (age / half_life_s)``

with the age in simulated seconds since the claim was made. A source may always revise its own belief. So
a weak assumption (ASSUMED, low confidence) never overrides a fresh observation, while an observation made
long ago yields to newer evidence (belief in time: the standing belief's weight halves every
``half_life_s``). Installed as the knowledge base's arbiter (:attr:`knowledge_base.KnowledgeBase.arbiter`)
by :func:`install`; the refused writes are counted in :attr:`Fusion.refused`.

:func:`claims` lists every source that ever claimed something about a fact, with its latest claim and its
weight now: what ``knic facts --why`` shows as the fact's sources.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from knowledge_base.model import Change, Provenance

#: how much a claim of each status counts, before confidence and age
STATUS_WEIGHT: dict[BeliefStatus, float] = {
    BeliefStatus.GIVEN: 1.0,
    BeliefStatus.OBSERVED: 1.0,
    BeliefStatus.EFFECT: 0.6,
    BeliefStatus.ASSUMED: 0.3,
}


def weight(prov: Provenance, now: float, half_life_s: float) -> float:
    """The weight of a claim with provenance ``prov`` at simulated time ``now`` (see the module docstring)."""
    age = max(0.0, now - prov.since)
    return STATUS_WEIGHT.get(BeliefStatus(prov.status), 0.5) * prov.confidence * 0.5 ** (age / half_life_s)


class Fusion:
    """The arbiter of the knowledge base's writes (see the module docstring).

    Args:
        clock: simulated time now, seconds.
        half_life_s: simulated seconds over which a standing belief's weight halves.
        arbitrated: the statuses of writes that must outweigh the standing belief (default: assumptions and
            effects; observations and the user's given facts always pass, so perception and the operator
            are never silenced).
    """

    def __init__(
        self,
        clock: Callable[[], float],
        *,
        half_life_s: float = 60.0,
        arbitrated: frozenset[BeliefStatus] = frozenset({BeliefStatus.ASSUMED}),
    ) -> None:
        self.clock = clock
        self.half_life_s = half_life_s
        self.arbitrated = arbitrated
        self.refused = 0
        #: (fact, standing source, refused source) of the latest refusals, most recent last (at most 100)
        self.log: list[tuple[Fact, str, str]] = []

    def __call__(self, fact: Fact, standing: Provenance, new: Provenance) -> bool:
        """Whether the write with provenance ``new`` may replace or retract ``fact``'s standing belief."""
        if new.source == standing.source or BeliefStatus(new.status) not in self.arbitrated:
            return True
        now = self.clock()
        if weight(new, now, self.half_life_s) >= weight(standing, now, self.half_life_s):
            return True
        self.refused += 1
        self.log = [*self.log[-99:], (fact, standing.source, new.source)]
        return False


def install(kb: KnowledgeBase, clock: Callable[[], float], half_life_s: float = 60.0) -> Fusion:
    """Make a :class:`Fusion` the knowledge base's arbiter and return it."""
    fusion = Fusion(clock, half_life_s=half_life_s)
    kb.arbiter = fusion
    return fusion


@dataclass(frozen=True)
class Claim:
    """The latest claim of one source about a fact.

    Attributes:
        source: who made it.
        holds: True for an assertion, False for a retraction.
        status: its belief status.
        confidence: in [0, 1].
        since: simulated time of the claim.
        weight: its weight at the time asked (see :func:`weight`).
        current: whether this claim is the knowledge base's belief now.
    """

    source: str
    holds: bool
    status: str
    confidence: float
    since: float
    weight: float
    current: bool


def claims(kb: KnowledgeBase, fact: Fact, now: float, half_life_s: float = 60.0) -> list[Claim]:
    """Every source's latest claim about ``fact`` from the knowledge base's history, heaviest first."""
    return claims_from(kb.changes(), fact, kb.why(fact), now, half_life_s)


def claims_from(
    changes: Iterable[Change],
    fact: Fact,
    standing: Provenance | None,
    now: float,
    half_life_s: float = 60.0,
) -> list[Claim]:
    """Every source's latest claim about ``fact`` in ``changes`` (a history, oldest first), heaviest at
    ``now`` first; ``standing`` is the fact's belief (None: it does not hold)."""
    latest: dict[str, tuple[bool, Provenance]] = {}
    for change in changes:
        if change.name == fact.predicate and change.args == fact.args and change.kind.value.endswith("_fact"):
            latest[change.provenance.source] = (change.kind.value == "add_fact", change.provenance)
    out = [
        Claim(
            source,
            holds,
            BeliefStatus(prov.status).value,
            prov.confidence,
            prov.since,
            round(weight(prov, now, half_life_s), 4),
            holds and standing is not None and standing.source == source and standing.since == prov.since,
        )
        for source, (holds, prov) in latest.items()
    ]
    return sorted(out, key=lambda c: (-c.weight, -c.since, c.source))
