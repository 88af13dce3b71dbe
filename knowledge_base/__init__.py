"""The knowledge base: PDDL model, instances, facts, goals, world-model anchors, provenance and history.

Architecture (one module per concern):

* :mod:`knowledge_base.model` -- value types: Fact, BeliefStatus, Provenance, Change, State.
* :mod:`knowledge_base.domain` -- DomainModel: a PDDL domain through unified-planning plus its meta sidecar.
* :mod:`knowledge_base.problem` -- checked loading of PDDL problems.
* :mod:`knowledge_base.kb` -- KnowledgeBase: validated writes, batches, subscribers.
* :mod:`knowledge_base.queries` -- the read side: queries, snapshots, state_at, export.
* :mod:`knowledge_base.store` -- the live state's indexes, write validation, undoable changes.
* :mod:`knowledge_base.journal` -- the append-only history (in memory or SQLite WAL), checkpoints, state_at.
* :mod:`knowledge_base.timeline` -- every record's validity interval, so state_at is one vectorised query.
* :mod:`knowledge_base.export` -- to and from unified-planning problems and PDDL text.
"""

from typing import TYPE_CHECKING, Any

from knowledge_base.model import BeliefStatus, Change, ChangeKind, Fact, Provenance, State

if TYPE_CHECKING:
    from knowledge_base.domain import DomainModel
    from knowledge_base.kb import KnowledgeBase


def __getattr__(name: str) -> Any:
    """The heavy parts on first use: code that only needs the value types (``knic goal``, ``knic say``)
    does not import the SQLite journal or the PDDL domain through unified-planning."""
    if name == "DomainModel":
        from knowledge_base.domain import DomainModel

        return DomainModel
    if name == "KnowledgeBase":
        from knowledge_base.kb import KnowledgeBase

        return KnowledgeBase
    raise AttributeError(f"module 'knowledge_base' has no attribute {name!r}")


__all__ = [
    "BeliefStatus",
    "Change",
    "ChangeKind",
    "DomainModel",
    "Fact",
    "KnowledgeBase",
    "Provenance",
    "State",
]
