"""Publishing synthetic CKU streams for the KP' tests."""

from __future__ import annotations

from typing import Any

import numpy as np

from knic.bus import Bus
from knic.spatial import keys_of, unique_keys
from knic.units import CKU, Kind
from tests.knic.synthetic import blob


def cku(
    symbol: str,
    kind: Kind,
    center: tuple[float, float, float],
    stamp: float,
    *,
    cls: str | None = None,
    confidence: float = 0.9,
    **attributes: Any,
) -> CKU:
    """A CKU whose voxels are a small blob around ``center``."""
    keys = unique_keys(keys_of(blob(center, spread=0.03))) if kind in (Kind.OBJECT, Kind.PERSON) else None
    return CKU(
        symbol=symbol,
        cls=cls or symbol,
        kind=kind,
        octomap=None,
        keys=keys if keys is not None else np.zeros((0, 3), dtype=np.int64),
        position=center,
        role_priority=1,
        stamp=stamp,
        confidence=confidence,
        support=(f"llku:test:{symbol}:{stamp}",),
        attributes=attributes,
    )


def send(bus: Bus, unit: CKU) -> None:
    bus.publish(f"cognition.{unit.kind.value}.{unit.symbol}", unit, source="kgm2.cognition", stamp=unit.stamp)
