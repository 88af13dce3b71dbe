"""The sensor model as data: :class:`worlds.api.NoiseConfig` read from YAML.

The file groups the fields by sensor (``detector``, ``people``, ``depth``, ``localisation``, ``sound``); every
field is optional (the dataclass default applies) and checked: an unknown key, a probability outside [0, 1],
a negative distance or a malformed confusion row is a :class:`core.errors.WorldError` naming the file and
the key, and nothing is loaded. ``worlds/noise.yaml`` is the default robot's model.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from core.errors import WorldError
from core.inputs import read_yaml
from worlds.api import NoiseConfig

#: the default robot's sensor model
DEFAULT_NOISE = Path(__file__).resolve().parent.parent / "noise.yaml"

_SECTIONS: dict[str, dict[str, str]] = {
    "detector": {
        "miss_rate": "prob",
        "class_miss_rate": "prob_map",
        "false_positive_rate": "prob",
        "min_pixels": "count",
        "confidence_range": "range",
        "confusion_rate": "prob",
        "confusions": "confusions",
    },
    "people": {"person_id_rate": "prob", "min_person_id_pixels": "count", "person_confusion_rate": "prob"},
    "depth": {"depth_noise": "nonneg"},
    "localisation": {"pose_noise_xy": "nonneg", "pose_noise_yaw": "nonneg"},
    "sound": {"sound_noise_xy": "nonneg", "sound_noise_per_m": "nonneg"},
}


def load_noise(path: str | Path = DEFAULT_NOISE) -> NoiseConfig:
    """Read a sensor model file (see the module docstring)."""
    where = str(path)
    raw = read_yaml(path, "noise model", WorldError)
    return noise_from_dict(raw if raw is not None else {}, where)


def noise_from_dict(raw: Any, where: str = "noise") -> NoiseConfig:
    """A :class:`NoiseConfig` from the parsed file (sections of fields), checked."""
    if not isinstance(raw, dict):
        raise WorldError(f"{where}: expected a mapping of sections ({', '.join(_SECTIONS)})")
    fields: dict[str, Any] = {}
    for section, body in raw.items():
        spec = _SECTIONS.get(str(section))
        if spec is None:
            raise WorldError(f"{where}: unknown section {section!r}; known: {', '.join(_SECTIONS)}")
        if body is None:
            continue
        if not isinstance(body, dict):
            raise WorldError(f"{where}: {section} must be a mapping")
        for key, value in body.items():
            kind = spec.get(str(key))
            if kind is None:
                raise WorldError(f"{where}: {section}.{key}: unknown key; known: {', '.join(spec)}")
            fields[str(key)] = _check(f"{where}: {section}.{key}", kind, value)
    return NoiseConfig(**fields)


def _number(what: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise WorldError(f"{what}: expected a finite number, got {value!r}")
    return float(value)


def _prob(what: str, value: Any) -> float:
    p = _number(what, value)
    if not 0.0 <= p <= 1.0:
        raise WorldError(f"{what}: a probability must lie in [0, 1], got {p}")
    return p


def _check(what: str, kind: str, value: Any) -> Any:
    if kind == "prob":
        return _prob(what, value)
    if kind == "nonneg":
        v = _number(what, value)
        if v < 0:
            raise WorldError(f"{what}: must not be negative, got {v}")
        return v
    if kind == "count":
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise WorldError(f"{what}: expected a non-negative integer, got {value!r}")
        return value
    if kind == "range":
        if not isinstance(value, list) or len(value) != 2:
            raise WorldError(f"{what}: expected [low, high], got {value!r}")
        lo, hi = _prob(what, value[0]), _prob(what, value[1])
        if lo > hi:
            raise WorldError(f"{what}: low {lo} exceeds high {hi}")
        return (lo, hi)
    if kind == "prob_map":
        if not isinstance(value, dict):
            raise WorldError(f"{what}: expected a mapping class -> probability")
        return {str(k): _prob(f"{what}.{k}", v) for k, v in value.items()}
    # confusions: class -> {other class: probability}, each row summing to at most 1
    if not isinstance(value, dict):
        raise WorldError(f"{what}: expected a mapping class -> {{class: probability}}")
    rows: dict[str, dict[str, float]] = {}
    for cls, row in value.items():
        if not isinstance(row, dict):
            raise WorldError(f"{what}.{cls}: expected a mapping class -> probability")
        rows[str(cls)] = {str(k): _prob(f"{what}.{cls}.{k}", v) for k, v in row.items()}
        if str(cls) in rows[str(cls)]:
            raise WorldError(f"{what}.{cls}: a class cannot be confused with itself")
        if sum(rows[str(cls)].values()) > 1.0 + 1e-9:
            raise WorldError(f"{what}.{cls}: the probabilities sum to more than 1")
    return rows
