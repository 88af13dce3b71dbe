"""KGM-1 camera providers: objects and people from the robot's RGB-D camera.

Each step reads the current frame (shared between the two KPs, see :class:`~knic.kgm1.sources.SharedCamera`),
deprojects every relevant detection's mask into world-frame points with the frame's depth, and publishes one
LLKU per detection; then it publishes a scan marker (:class:`~knic.units.Scan` on
``percept.vision.scan.<kind>``) so KGM-2 knows the frame is complete and can count misses for what the frame
could have seen but did not report.

Object detections carry a class label only (``worlds.api.Detection.identity`` is None for objects); a class
that names exactly one item of the world is recognised as that item's symbol. Where a class names several
known items (a red mug and a blue mug), the colour the RGB image shows under the detection's mask tells
them apart when it is clearly nearest one item's known colour (:func:`colour_match`); else the unit stays
anonymous and KGM-2 makes an instance of it. People are recognised when the detector says who they are;
unrecognised people are published as anonymous ``person`` units.
"""

from __future__ import annotations

from abc import abstractmethod
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from knic.bus import Bus
from knic.kgm1.base import KnowledgeProvider
from knic.kgm1.sources import CameraSource, FrameView
from knic.units import LLKU, Kind, Scan

if TYPE_CHECKING:
    from core.robot import CameraFrame, Detection
    from knowledge_base import KnowledgeBase

PERSON_LABEL = "person"
#: largest angle, radians, between a seen colour and an item's known colour (RGB as a vector: shading
#: scales it, the direction stays) for the item to be recognised by colour
COLOUR_MAX_ANGLE = 0.2
#: the nearest item's angle must be at most this share of the next one's
COLOUR_MARGIN = 0.6


def colour_match(
    seen: npt.NDArray[np.float64], known: Mapping[str, tuple[float, float, float]]
) -> str | None:
    """The item whose known colour (RGB, 0..1) is nearest in direction to the ``seen`` mean colour, when it
    is near (:data:`COLOUR_MAX_ANGLE`) and clearly nearer than every other (:data:`COLOUR_MARGIN`)."""
    norm = float(np.linalg.norm(seen))
    if norm < 1e-6:
        return None
    angles = []
    for symbol, rgb in known.items():
        ref = np.asarray(rgb, dtype=np.float64)
        cos = float(ref @ seen) / max(float(np.linalg.norm(ref)) * norm, 1e-9)
        angles.append((float(np.arccos(min(1.0, max(-1.0, cos)))), symbol))
    angles.sort()
    best, symbol = angles[0]
    if best > COLOUR_MAX_ANGLE or (len(angles) > 1 and best > COLOUR_MARGIN * angles[1][0]):
        return None
    return symbol


#: Early role filter of a camera KP: (tracker class, camera position in the world frame (metres), frame stamp)
#: -> whether that class's detections are wanted from this frame. Asked at most once per class and frame,
#: before any deprojection (see :attr:`CameraKP.gate`).
ClassGate = Callable[[str, tuple[float, float, float], float], bool]


class CameraKP(KnowledgeProvider):
    """Base of the camera KPs: frame reading, deprojection, scan markers.

    Args:
        name: component name.
        camera: the frame source.
        bus: where LLKUs go.
        kb: knowledge base for first meetings (or None).
        frequency: Hz of simulated time.
        kind: which detections this KP reports.
        max_points: most world points per detection.
        detect_range: depth, metres, within which this kind is reliably detected: a detection whose median
            depth is farther is not a sighting (nothing is published), and the visibility test behind KGM-2's
            miss counter uses ``miss_range``.
        min_pixels: least mask size, pixels, of a detection that counts as a sighting (smaller: ignored).
        miss_range: depth, metres, within which a tracked entity that is not detected counts as missed
            (default ``0.8 * detect_range``: near the range limit an entity may fall under ``min_pixels``).
        edge_px: pixels at each image border where an entity counts as not visible (a partly visible entity
            at the frame edge may be missed without having gone).
        sensor: sensor name written into the units.
        miss_footprint_m: half size, metres, of the entities this kind reports, for the visibility test
            (:class:`~knic.kgm1.sources.FrameView` ``footprint_m``): a partly hidden entity is not missed.

    Deprojection: the mask's pixels (at most ``max_points``) become world points; points whose depth lies
    farther than ``depth_tolerance`` metres (or three median absolute deviations, whichever is larger) from
    the median depth are rejected (background seen through or beside a thin object, depth noise), and the
    unit's position is the median of the points kept.
    """

    def __init__(
        self,
        name: str,
        camera: CameraSource,
        bus: Bus,
        kb: KnowledgeBase | None,
        *,
        frequency: float,
        kind: Kind,
        max_points: int = 64,
        detect_range: float = 3.0,
        min_pixels: int = 1,
        miss_range: float | None = None,
        edge_px: int = 0,
        depth_tolerance: float = 0.15,
        sensor: str = "head_camera",
        miss_footprint_m: float = 0.0,
    ) -> None:
        super().__init__(name, frequency, bus, kb, "vision")
        self.camera = camera
        self.kind = kind
        self.max_points = max_points
        self.detect_range = detect_range
        self.min_pixels = min_pixels
        self.miss_range = 0.8 * detect_range if miss_range is None else miss_range
        self.edge_px = edge_px
        self.miss_footprint_m = miss_footprint_m
        self.depth_tolerance = depth_tolerance
        self.sensor = sensor
        self.frames = 0
        self.gated = 0
        #: detections withheld by :attr:`gate` (never deprojected)
        self.withheld = 0
        #: the role's early filter (None: every wanted detection is processed); set by the pipeline to
        #: :meth:`knic.kgm2.cognition.CognitiveLayer.admits`
        self.gate: ClassGate | None = None
        self._last_stamp: float | None = None

    def step(self, now: float) -> None:
        """Read the current frame once and publish its units and the scan marker (a repeated frame:
        nothing)."""
        frame = self.camera.camera_frame()
        if frame.stamp == self._last_stamp:
            return
        self._last_stamp = frame.stamp
        self.frames += 1
        origin = tuple(float(v) for v in frame.camera_pose.position)
        decided: dict[str, bool] = {}
        for index, det in enumerate(frame.detections):
            if not self.wants(det):
                continue
            if self.gate is not None:
                cls = self.track_class(det)
                admitted = decided.get(cls)
                if admitted is None:
                    admitted = decided[cls] = self.gate(cls, (origin[0], origin[1], origin[2]), frame.stamp)
                if not admitted:
                    self.withheld += 1
                    continue
            if det.pixel_count < self.min_pixels:
                self.gated += 1
                continue
            points = self.filter_points(frame.points_world(det, self.max_points, seed=index), origin)
            if len(points) == 0:
                continue
            centroid = np.median(points, axis=0)
            if float(np.linalg.norm(centroid - np.asarray(origin))) > self.detect_range:
                self.gated += 1
                continue
            unit = LLKU(
                kind=self.kind,
                label=det.label,
                source=self.name,
                sensor=self.sensor,
                stamp=frame.stamp,
                confidence=float(det.confidence),
                position=(float(centroid[0]), float(centroid[1]), float(centroid[2])),
                points=points,
                sensor_origin=(origin[0], origin[1], origin[2]),
                identity=self.identify(det, frame),
                attributes={"pixels": det.pixel_count},
            )
            if unit.identity is not None:
                self.meet(self.pddl_type, unit.identity, frame.stamp, (unit.uid,))
            self.publish(unit)
        self.publish_scan(frame, frozenset(c for c, ok in decided.items() if not ok))

    def track_class(self, det: Detection) -> str:
        """The KGM-2 tracker class of a detection (its label; every person is one class)."""
        return det.label

    def filter_points(
        self, points: npt.NDArray[np.float64], origin: tuple[float, ...]
    ) -> npt.NDArray[np.float64]:
        """The points whose range from the sensor is consistent with the detection's median range."""
        if len(points) < 3:
            return points
        ranges = np.linalg.norm(points - np.asarray(origin), axis=1)
        median = float(np.median(ranges))
        mad = float(np.median(np.abs(ranges - median)))
        keep = np.abs(ranges - median) <= max(self.depth_tolerance, 3.0 * 1.4826 * mad)
        return points[keep]

    def publish_scan(self, frame: CameraFrame, withheld: frozenset[str] = frozenset()) -> None:
        """Publish the end-of-frame marker for this KP's kind (``withheld``: classes the gate held back)."""
        view = FrameView(frame, self.miss_range, edge_px=self.edge_px, footprint_m=self.miss_footprint_m)
        scan = Scan(self.kind, frame.stamp, view, self.sensor, withheld)
        self.bus.publish(f"percept.vision.scan.{self.kind.value}", scan, source=self.name, stamp=frame.stamp)

    #: PDDL type of the individuals this KP recognises (for first-meeting instances).
    pddl_type = "entity"

    @abstractmethod
    def wants(self, det: Detection) -> bool:
        """Whether this KP reports the detection."""

    @abstractmethod
    def identify(self, det: Detection, frame: CameraFrame) -> str | None:
        """The PDDL symbol of the detected individual in ``frame``, or None."""


class CameraObjectsKP(CameraKP):
    """Objects (items) from the camera: every detection whose label is not ``person``.

    Args:
        class_symbols: detector class -> item symbol, for classes that name exactly one item.
        class_colours: detector class -> {item symbol: known RGB colour (0..1)}, for classes that name
            several items (told apart by colour, see :func:`colour_match`).
        miss_footprint_m: half size, metres, of an item for the visibility test (the household items are
            7 to 20 cm across): an item partly hidden is not counted missed.
        Others as :class:`CameraKP`.
    """

    pddl_type = "item"

    def __init__(
        self,
        camera: CameraSource,
        bus: Bus,
        kb: KnowledgeBase | None,
        class_symbols: Mapping[str, str],
        *,
        class_colours: Mapping[str, Mapping[str, tuple[float, float, float]]] | None = None,
        frequency: float = 5.0,
        name: str = "kp.camera_objects",
        max_points: int = 64,
        detect_range: float = 3.0,
        min_pixels: int = 1,
        miss_range: float | None = None,
        edge_px: int = 0,
        miss_footprint_m: float = 0.04,
    ) -> None:
        super().__init__(
            name,
            camera,
            bus,
            kb,
            frequency=frequency,
            kind=Kind.OBJECT,
            max_points=max_points,
            detect_range=detect_range,
            min_pixels=min_pixels,
            miss_range=miss_range,
            edge_px=edge_px,
            miss_footprint_m=miss_footprint_m,
        )
        self.class_symbols = dict(class_symbols)
        self.class_colours = {cls: dict(known) for cls, known in (class_colours or {}).items()}

    def wants(self, det: Detection) -> bool:
        """Every non-person detection."""
        return det.label != PERSON_LABEL

    def identify(self, det: Detection, frame: CameraFrame) -> str | None:
        """The item named by the detection's class when the class names exactly one item; among several
        items of the class, the one whose colour the masked pixels show."""
        symbol = self.class_symbols.get(det.label)
        known = self.class_colours.get(det.label)
        if symbol is not None or not known:
            return symbol
        seen = frame.rgb[det.mask].astype(np.float64).mean(axis=0) / 255.0
        return colour_match(seen, known)


class CameraPeopleKP(CameraKP):
    """People from the camera; recognised people carry their symbol as identity."""

    pddl_type = "person"

    def __init__(
        self,
        camera: CameraSource,
        bus: Bus,
        kb: KnowledgeBase | None,
        *,
        frequency: float = 5.0,
        name: str = "kp.camera_people",
        max_points: int = 64,
        detect_range: float = 6.0,
        min_pixels: int = 1,
        miss_range: float | None = None,
        edge_px: int = 0,
    ) -> None:
        super().__init__(
            name,
            camera,
            bus,
            kb,
            frequency=frequency,
            kind=Kind.PERSON,
            max_points=max_points,
            detect_range=detect_range,
            min_pixels=min_pixels,
            miss_range=miss_range,
            edge_px=edge_px,
        )

    def wants(self, det: Detection) -> bool:
        """Person detections only."""
        return det.label == PERSON_LABEL

    def track_class(self, det: Detection) -> str:
        """Every person is tracked in the one ``person`` class."""
        return PERSON_LABEL

    def identify(self, det: Detection, frame: CameraFrame) -> str | None:
        """The recognised name, or None for an unrecognised person."""
        return det.identity
