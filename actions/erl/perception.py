"""What the ERL actions may ask perception: the perception seam between ``actions/`` and the inference side.

The actions steer by where the robot last *perceived* an item or a person. They do not subscribe to KnIC's
message bus (``actions/`` sits below ``knic/``): the inference side hands them an object satisfying
:class:`Perception` (in the closed loop :class:`knic.kgm3.sightings.BusPerception`, fed by KGM-2's CKUs),
and tests hand them :class:`AnchorPerception` or a double.

Frames and time: positions are in the world frame (metres, ``z`` up); stamps are simulated seconds.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from knowledge_base import KnowledgeBase

Point3 = tuple[float, float, float]


@dataclass
class Sighting:
    """The latest perceived state of one entity.

    Attributes:
        position: world-frame centroid in metres.
        stamp: simulated time of the observation.
        lost: True when perception dropped the entity's track (repeatedly missed where the camera could
            see it).
    """

    position: Point3
    stamp: float
    lost: bool = False


@runtime_checkable
class Perception(Protocol):
    """Perceived poses of items and people, as the actions read them.

    Every method is a query: it is called from an action's ``activation``/``step`` inside the scheduler's one
    thread, returns at once, and changes nothing. Answers change between two calls only because perception
    ran in between (a KnIC component's step), never during a call.
    """

    def sighting(self, symbol: str) -> Sighting | None:
        """The latest sighting of ``symbol`` this run (lost or not), or None when it was never perceived."""
        ...

    def position(self, symbol: str) -> Point3 | None:
        """Where ``symbol`` was last perceived: the latest live sighting, else its knowledge-base anchor."""
        ...

    def seen_since(self, symbol: str, since: float) -> Sighting | None:
        """The sighting of ``symbol`` if it was perceived (not lost) at or after simulated time ``since``."""
        ...

    def lost_since(self, symbol: str, since: float) -> bool:
        """True when perception dropped ``symbol``'s track at or after simulated time ``since``."""
        ...

    def refute(self, symbol: str, position: Point3, stamp: float, reason: str) -> None:
        """An action found ``symbol`` not at ``position`` (world frame), where it was believed at simulated
        time ``stamp`` (the gripper closed on nothing, nobody took the item): evidence against the belief.

        The one call that is not a query: perception records the entity as lost there, so the place belief
        behind the failed action is retracted and the next plan looks for the entity instead of repeating the
        action. Called from an action's ``step`` in the scheduler's thread.
        """
        ...


class SightingBook:
    """A :class:`Perception` answering from sightings recorded with :meth:`record`, anchors as the fallback.

    Whoever perceives (the inference side, a test) calls :meth:`record`; the actions only query.

    Args:
        kb: the knowledge base whose anchors answer :meth:`position` for entities not seen this run.
    """

    def __init__(self, kb: KnowledgeBase) -> None:
        self.kb = kb
        self.sightings: dict[str, Sighting] = {}
        #: every refutation received: (symbol, position, stamp, reason)
        self.refuted: list[tuple[str, Point3, float, str]] = []

    def record(self, symbol: str, sighting: Sighting) -> None:
        """Remember ``sighting`` as the latest of ``symbol``."""
        self.sightings[symbol] = sighting

    def sighting(self, symbol: str) -> Sighting | None:
        """See :meth:`Perception.sighting`."""
        return self.sightings.get(symbol)

    def position(self, symbol: str) -> Point3 | None:
        """See :meth:`Perception.position`."""
        seen = self.sightings.get(symbol)
        if seen is not None and not seen.lost:
            return seen.position
        return anchor_position(self.kb, symbol)

    def seen_since(self, symbol: str, since: float) -> Sighting | None:
        """See :meth:`Perception.seen_since`."""
        seen = self.sightings.get(symbol)
        if seen is not None and not seen.lost and seen.stamp >= since - 1e-9:
            return seen
        return None

    def lost_since(self, symbol: str, since: float) -> bool:
        """See :meth:`Perception.lost_since`."""
        seen = self.sightings.get(symbol)
        return seen is not None and seen.lost and seen.stamp >= since - 1e-9

    def refute(self, symbol: str, position: Point3, stamp: float, reason: str) -> None:
        """See :meth:`Perception.refute`: the entity's sighting becomes lost at ``position``."""
        self.refuted.append((symbol, position, stamp, reason))
        self.record(symbol, Sighting(position, stamp, lost=True))


#: a perception that knows only the knowledge base's anchors (nothing is recorded into it)
AnchorPerception = SightingBook


def anchor_position(kb: KnowledgeBase, symbol: str) -> Point3 | None:
    """The world-frame position in ``symbol``'s anchor (``pose.position`` or ``pose.x/y``), or None."""
    geometry = kb.anchor(symbol)
    if not geometry:
        return None
    pose = geometry.get("pose")
    if not isinstance(pose, dict):
        return None
    if "position" in pose:
        px, py, *rest = (float(v) for v in pose["position"])
        return (px, py, rest[0] if rest else 0.0)
    if "x" in pose and "y" in pose:
        return (float(pose["x"]), float(pose["y"]), 0.0)
    return None
