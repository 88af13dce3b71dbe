"""Knowledge units: what flows between the three knowledge generation mechanisms (seed 004, section II.A).

* :class:`LLKU` (low-level knowledge unit), made by a KGM-1 knowledge provider (KP) from one sensor: one
  perceived element (object, person, robot pose, sound, device reading, location) with its time stamp, the
  sensor and provider it came from, a confidence and its geometry in the **world frame** (metres, the
  simulator's global ``map`` frame; z up).
* :class:`Scan`, made by a KGM-1 camera KP after a frame's LLKUs: the end of the frame, with what it could
  see (a :class:`ViewModel`), so that KGM-2 counts misses and KGM-3 measures how much of a room was seen.
* :class:`CKU` (cognitive knowledge unit), made by KGM-2: an LLKU put in context. It names the entity's PDDL
  symbol, its class, the octomap that represents the space it occupies (in the world frame), the voxel keys
  currently occupied in that octomap, the priority the robot's role gives it, and the ids of the LLKUs behind
  it (for provenance: the KB's ``support``). The keys of a tracked entity are an octomap query made when a
  consumer first reads them (:class:`CKU`), not work done for every unit published.

Time stamps are **simulated seconds** (the scheduler's clock), never wall-clock time. Units are immutable once
made; the arrays they carry are marked read-only so a consumer cannot change what another consumer sees.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TYPE_CHECKING, Any, Protocol, cast, overload

import numpy as np
import numpy.typing as npt

from core.errors import InferenceError

if TYPE_CHECKING:
    import pyoctomap

#: Float arrays of world-frame points, shape (N, 3), metres.
Points = npt.NDArray[np.float64]
#: Integer arrays of octomap voxel keys, shape (N, 3) (octomap's 16-bit keys, stored as int64).
Keys = npt.NDArray[np.int64]

_EMPTY_POINTS: Points = np.zeros((0, 3), dtype=np.float64)
_EMPTY_POINTS.setflags(write=False)
_EMPTY_KEYS: Keys = np.zeros((0, 3), dtype=np.int64)
_EMPTY_KEYS.setflags(write=False)

_ids = itertools.count(1)

#: sets the ``__dict__`` of a frozen dataclass instance (its own ``__setattr__`` refuses)
_set_dict = object.__setattr__


def new_unit_id(prefix: str) -> str:
    """Return a process-unique id such as ``"llku:17"``; ids are what fact provenance cites as support."""
    return f"{prefix}:{next(_ids)}"


class Kind(StrEnum):
    """What a knowledge unit is about; also the second level of its bus topic (``percept.<kind>...``)."""

    OBJECT = "object"
    PERSON = "person"
    ROBOT = "robot"
    SOUND = "sound"
    DEVICE = "device"
    LOCATION = "location"


def as_points(value: Any, where: str) -> Points:
    """Return ``value`` as a read-only (N, 3) float64 array of finite world-frame points.

    Raises:
        InferenceError: the value is not an (N, 3) array of finite numbers; ``where`` names the caller.
    """
    if value is None:
        return _EMPTY_POINTS
    if isinstance(value, np.ndarray) and value.dtype == np.float64 and not value.flags.writeable:
        arr: Points = value
    else:
        arr = np.array(value, dtype=np.float64)
    if arr.size == 0:
        return _EMPTY_POINTS
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise InferenceError(f"{where}: points must have shape (N, 3), got {arr.shape}")
    if not np.isfinite(arr).all():
        raise InferenceError(f"{where}: points contain NaN or infinite values")
    arr.setflags(write=False)
    return arr


@dataclass(frozen=True, eq=False)
class LLKU:
    """A low-level knowledge unit: one element perceived by one sensor at one instant.

    Attributes:
        kind: what was perceived.
        label: its class as the sensor names it (``"glasses"``, ``"person"``, ``"doorbell"``, ``"robot"``).
        source: the KP that made it (``"kp.camera_objects"``); the sensor is in ``sensor``.
        sensor: the sensor the reading came from (``"head_camera"``, ``"microphone"``, ``"odometry"``).
        stamp: simulated time of the reading, seconds.
        confidence: the KP's confidence in [0, 1].
        position: representative point in the world frame (centroid, pose or source position), metres.
        points: world-frame points behind the unit, shape (N, 3); empty when the sensor gives none.
        sensor_origin: world-frame position of the sensor when it measured ``points`` (for ray casting).
        identity: the PDDL symbol of the individual when the sensor recognises it (``"jack"``), else None.
        attributes: further readings (yaw in radians, a device's state, a room reported by the sensor ...).
        uid: unique id, cited as provenance ``support``.
    """

    kind: Kind
    label: str
    source: str
    sensor: str
    stamp: float
    confidence: float
    position: tuple[float, float, float]
    points: Points = field(default_factory=lambda: _EMPTY_POINTS)
    sensor_origin: tuple[float, float, float] | None = None
    identity: str | None = None
    attributes: Mapping[str, Any] = field(default_factory=dict)
    uid: str = field(default_factory=lambda: new_unit_id("llku"))

    def __post_init__(self) -> None:
        where = f"LLKU {self.kind.value}/{self.label} from {self.source}"
        if not self.label:
            raise InferenceError(f"{where}: empty label")
        if not 0.0 <= self.confidence <= 1.0:
            raise InferenceError(f"{where}: confidence {self.confidence} outside [0, 1]")
        if len(self.position) != 3 or not all(np.isfinite(self.position)):
            raise InferenceError(f"{where}: position {self.position!r} is not a finite 3D point")
        object.__setattr__(self, "points", as_points(self.points, where))
        object.__setattr__(self, "position", tuple(float(v) for v in self.position))

    @property
    def symbol(self) -> str:
        """The symbol the unit names: its identity when recognised, else its class label."""
        return self.identity or self.label


class ViewModel(Protocol):
    """What one scan could see (:class:`knic.kgm1.sources.FrameView` for camera frames; doubles in tests)."""

    position: npt.NDArray[np.float64]

    def visible(self, points: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
        """Which of the world-frame points (N, 3) the scan could have seen."""
        ...

    def optical_axis(self) -> npt.NDArray[np.float64]:
        """The viewing direction in the world frame (unit vector)."""
        ...


@dataclass(frozen=True)
class Scan:
    """End of one frame's units of one kind: the frame's time stamp, and what it could see.

    Published by a camera KP on ``percept.vision.scan.<kind>`` after the frame's LLKUs. ``withheld`` names the
    tracker classes whose detections the KP neither deprojected nor published for this frame because the
    role's early filter said they were not due: KGM-2 must not associate them nor count misses for them.
    """

    kind: Kind
    stamp: float
    view: ViewModel
    sensor: str
    withheld: frozenset[str] = field(default_factory=frozenset)


#: A CKU's voxel keys as given to it: the keys themselves, or the query that reads them (called at most once).
KeySource = Keys | Callable[[], Keys]


def _checked_keys(value: Any, symbol: str) -> Keys:
    keys = np.asarray(value, dtype=np.int64)
    if keys.size == 0:
        return _EMPTY_KEYS
    if keys.ndim != 2 or keys.shape[1] != 3:
        raise InferenceError(f"CKU {symbol}: keys must have shape (N, 3), got {keys.shape}")
    keys.setflags(write=False)
    return keys


class _LazyKeys:
    """The ``keys`` field of :class:`CKU`: holds the keys, or the query that reads them until first read.

    A data descriptor (dataclasses' descriptor-typed field): ``CKU(..., keys=array)`` checks the array at
    once; ``CKU(..., keys=query)`` keeps the zero-argument callable and calls it on the first ``cku.keys``,
    then checks and keeps its answer (every later read returns the same array).
    """

    def __set_name__(self, owner: type, name: str) -> None:
        self._slot = f"_{name}_source"

    @overload
    def __get__(self, obj: None, objtype: type | None = None) -> None: ...

    @overload
    def __get__(self, obj: CKU, objtype: type | None = None) -> Keys: ...

    def __get__(self, obj: CKU | None, objtype: type | None = None) -> Keys | None:
        if obj is None:
            return None  # the field's default (dataclasses ask the class): no voxels
        value = obj.__dict__[self._slot]
        if callable(value):
            value = _checked_keys(value(), obj.symbol)
            obj.__dict__[self._slot] = value
        return cast(Keys, value)

    def __set__(self, obj: CKU, value: KeySource | None) -> None:
        if value is None:
            obj.__dict__[self._slot] = _EMPTY_KEYS
        else:
            obj.__dict__[self._slot] = value if callable(value) else _checked_keys(value, obj.symbol)


@dataclass(frozen=True, eq=False, init=False)
class CKU:
    """A cognitive knowledge unit: a tracked entity or a location in its spatial and motivational context.

    Attributes:
        symbol: the entity's PDDL symbol (``"glasses"``, ``"jack"``, ``"kitchen"``, ``"r2d2"``).
        cls: its class (``"glasses"``, ``"person"``, ``"room"``, ``"robot"``).
        kind: what it is about.
        octomap: the entity's ``pyoctomap.OcTree`` in the world frame (owned and updated by KGM-2; read it, do
            not write), or None for units without volume (pose, sound, device).
        position: the entity's tracked centroid in the world frame, metres.
        role_priority: priority the active role gives this class / room (higher first).
        stamp: simulated time of the last update, seconds.
        confidence: KGM-2's confidence in the association, in [0, 1].
        keys: the voxel keys the entity occupies (default None: none), in the octomap key space of
            :data:`knic.spatial.DEFAULT_RESOLUTION`; what KP' intersect with room and furniture volumes.
            Given as an (N, 3) array, or (KGM-2's tracked entities) as a query of the entity's octomap that
            runs when ``keys`` is first read: the answer is the voxels the tree holds occupied at that moment
            (a unit read after its track was updated again sees the newer tree, as its ``octomap`` does), kept
            for every later read. A unit nobody reads the keys of costs no query. Reads return a read-only
            array.
        support: ids of the LLKUs behind this update.
        track_id: KGM-2's track id (stable while the entity is tracked).
        attributes: copied from the LLKU (device state, sound source, yaw ...).
        uid: unique id, cited as provenance ``support``.
    """

    symbol: str
    cls: str
    kind: Kind
    octomap: pyoctomap.OcTree | None
    position: tuple[float, float, float]
    role_priority: int
    stamp: float
    confidence: float
    keys: _LazyKeys = _LazyKeys()
    support: tuple[str, ...] = ()
    track_id: int = 0
    attributes: Mapping[str, Any] = field(default_factory=dict)
    uid: str = field(default_factory=lambda: new_unit_id("cku"))

    def __init__(
        self,
        symbol: str,
        cls: str,
        kind: Kind,
        octomap: pyoctomap.OcTree | None,
        position: tuple[float, float, float],
        role_priority: int,
        stamp: float,
        confidence: float,
        keys: KeySource | None = None,
        support: tuple[str, ...] = (),
        track_id: int = 0,
        attributes: Mapping[str, Any] | None = None,
        uid: str | None = None,
    ) -> None:
        # the dataclass's own __init__, less its per-field frozen ``object.__setattr__`` calls: KGM-2 makes
        # one unit per tracked sighting, and those calls were most of what making one cost; the attributes
        # are given as one dict
        _set_dict(
            self,
            "__dict__",
            _cku_state(
                symbol,
                cls,
                kind,
                octomap,
                position,
                role_priority,
                stamp,
                confidence,
                _EMPTY_KEYS if keys is None else keys if callable(keys) else _checked_keys(keys, symbol),
                support,
                track_id,
                {} if attributes is None else attributes,
                f"cku:{next(_ids)}" if uid is None else uid,
            ),
        )


def _cku_state(*values: Any) -> dict[str, Any]:
    """A CKU's attribute dict from its field values in order (keys already checked or a query)."""
    return dict(zip(_CKU_FIELDS, values, strict=True))


_CKU_FIELDS = (
    "symbol",
    "cls",
    "kind",
    "octomap",
    "position",
    "role_priority",
    "stamp",
    "confidence",
    "_keys_source",
    "support",
    "track_id",
    "attributes",
    "uid",
)


_new_object = object.__new__


def make_cku(
    symbol: str,
    cls: str,
    kind: Kind,
    octomap: pyoctomap.OcTree | None,
    position: tuple[float, float, float],
    role_priority: int,
    stamp: float,
    confidence: float,
    keys: KeySource,
    support: tuple[str, ...],
    track_id: int,
    attributes: Mapping[str, Any],
) -> CKU:
    """``CKU(symbol, cls, ..., attributes)`` with every argument given by position, for KGM-2's per-sighting
    path: the same unit (keys checked, or kept as the query they are, and a new ``uid``), made without the
    class call's keyword and ``__init__`` machinery, which was most of what making one cost."""
    unit: CKU = _new_object(CKU)
    keys_source = keys if callable(keys) else _checked_keys(keys, symbol)
    _set_dict(
        unit,
        "__dict__",
        _cku_state(
            symbol,
            cls,
            kind,
            octomap,
            position,
            role_priority,
            stamp,
            confidence,
            keys_source,
            support,
            track_id,
            attributes,
            f"cku:{next(_ids)}",
        ),
    )
    return unit
