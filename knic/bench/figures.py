"""Figures of ``knic bench grounding``: the predicate families and averaging runs over seeds."""

from __future__ import annotations

import math
from typing import Any

#: predicate families reported one by one (``families``): family -> its predicates; where an item is: in a
#: room (``object_at``) or, carried, in a person's hands (``has``)
FAMILIES: dict[str, frozenset[str]] = {
    "robot_at": frozenset({"robot_at"}),
    "object_at": frozenset({"object_at", "has"}),
    "object_on": frozenset({"object_on"}),
    "person_at": frozenset({"person_at"}),
    "person_near": frozenset({"person_near"}),
    "device": frozenset({"light_on", "light_off", "device_level"}),
}


def family_of(predicate: str) -> str | None:
    """The family of :data:`FAMILIES` holding ``predicate``, or None."""
    for family, predicates in FAMILIES.items():
        if predicate in predicates:
            return family
    return None


def percentile(values: list[float], q: float) -> float | None:
    """The ``q`` quantile (0..1, linear interpolation) of ``values``, rounded to milliseconds; None when
    empty."""
    if not values:
        return None
    ordered = sorted(values)
    k = (len(ordered) - 1) * q
    lo, hi = math.floor(k), math.ceil(k)
    return round(ordered[lo] + (ordered[hi] - ordered[lo]) * (k - lo), 3)


def average_figures(runs: list[dict[str, Any]]) -> dict[str, Any]:
    """The mean of several runs' figures, key by key: numbers averaged over the runs where they are not
    null (null when null in every run), nested objects averaged alike, counts (``changes_*``, ``samples``,
    ``*_samples``) summed."""
    out: dict[str, Any] = {}
    for key in runs[0]:
        values = [r.get(key) for r in runs]
        present = [v for v in values if v is not None]
        if not present:
            out[key] = None
        elif all(isinstance(v, dict) for v in present):
            keys = list(dict.fromkeys(k for v in present for k in v))
            out[key] = average_figures([{k: v.get(k) for k in keys} for v in present])
        elif all(isinstance(v, int | float) and not isinstance(v, bool) for v in present):
            summed = key.startswith("changes") or key.endswith("samples") or key == "changes"
            total = sum(present)
            out[key] = total if summed else round(total / len(present), 4)
        else:
            out[key] = present[0]
    return out
