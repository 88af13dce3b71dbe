"""The knowledge units' contracts: CKU keys are checked, read-only, and may be a query run when first read."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from core.errors import InferenceError
from knic.units import CKU, Keys, Kind


def _cku(keys: object = None) -> CKU:
    return CKU(
        symbol="glasses",
        cls="glasses",
        kind=Kind.OBJECT,
        octomap=None,
        position=(1.0, 2.0, 0.8),
        role_priority=1,
        stamp=3.0,
        confidence=0.9,
        keys=keys,  # type: ignore[arg-type]
    )


def test_keys_given_as_an_array_are_checked_and_read_only() -> None:
    unit = _cku(np.array([[32788, 32808, 32784]]))
    assert unit.keys.dtype == np.int64 and unit.keys.shape == (1, 3)
    assert not unit.keys.flags.writeable
    assert _cku().keys.shape == (0, 3)  # no keys: no voxels
    with pytest.raises(InferenceError, match="CKU glasses: keys must have shape"):
        _cku(np.zeros((2, 2), dtype=np.int64))


def test_keys_given_as_a_query_run_once_when_first_read() -> None:
    calls: list[int] = []

    def query() -> Keys:
        calls.append(1)
        return np.array([[1, 2, 3], [4, 5, 6]], dtype=np.int64)

    unit = _cku(query)
    assert calls == []  # publishing the unit asked nothing
    assert unit.keys.tolist() == [[1, 2, 3], [4, 5, 6]]
    assert unit.keys is unit.keys and calls == [1]
    assert not unit.keys.flags.writeable
    renamed = dataclasses.replace(unit, symbol="glasses_1")
    assert renamed.keys.tolist() == unit.keys.tolist() and calls == [1]
    with pytest.raises(dataclasses.FrozenInstanceError):
        unit.keys = np.zeros((0, 3), dtype=np.int64)  # type: ignore[misc]


def test_a_query_answering_a_bad_shape_is_an_error_naming_the_unit() -> None:
    unit = _cku(lambda: np.zeros((3, 2), dtype=np.int64))
    with pytest.raises(InferenceError, match="CKU glasses: keys must have shape"):
        _ = unit.keys
