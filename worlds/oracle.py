"""The referee's view: ground truth the robot cannot sense, for referees, benchmarks and tests only.

The robot seam (:class:`core.robot.Robot`) carries what the robot's sensors report; this module declares what
really happened. :class:`Oracle` is handed to the benchmark's referee (``knic bench``), to the run's verdict
and to tests -- never to the KGM-1 providers nor to the actions, which must do with the robot's readings.
:class:`worlds.simulation.Simulation` implements both protocols.

Every method is a pure reading: calling it never advances time, draws no random number and changes nothing,
so a referee that reads more or less often leaves the run unchanged. Positions are in the world frame
(metres), times in simulated seconds, names are the world's PDDL symbols.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
import numpy.typing as npt

from core.robot import DeviceReading, Pose2D, Pose3D, Utterance, Vec3

__all__ = ["Counters", "FrameTruth", "Oracle", "SoundTruth"]


@dataclass(frozen=True, slots=True)
class Counters:
    """What the ERL score sheet penalises, counted by the simulator.

    Attributes:
        bumps: times the robot's base started touching a piece of furniture or a wall.
        person_hits: times the robot's base started touching a person (disqualifying in the ERL rules).
        drops: objects released in mid-air (they fall).
    """

    bumps: int = 0
    person_hits: int = 0
    drops: int = 0


@dataclass(frozen=True)
class FrameTruth:
    """The truth behind one camera frame (:meth:`core.robot.Camera.camera_frame`).

    Attributes:
        stamp: the frame's stamp (simulated seconds).
        segmentation: ``(height, width)`` int32 body id per pixel (``-1``: background), rendered without
            noise; read-only.
        labels: body id -> instance name for every world instance with a body (the segmentation's legend).
        visible: names of the instances with at least the detector's minimum number of pixels in the frame.
        detected: for each of the frame's detections, in order, the instance behind its mask (``None`` for a
            false positive).
    """

    stamp: float
    segmentation: npt.NDArray[np.int32]
    labels: Mapping[int, str]
    visible: frozenset[str]
    detected: tuple[str | None, ...]


@dataclass(frozen=True, slots=True)
class SoundTruth:
    """A sound that was made, and by what.

    Attributes:
        kind: the PDDL ``sound`` symbol (``doorbell``).
        emitter: the device or person that made it (``door_bell``).
        position: the emitter's world-frame position, metres.
        stamp: simulated seconds when it started.
    """

    kind: str
    emitter: str
    position: Vec3
    stamp: float


@runtime_checkable
class Oracle(Protocol):
    """Ground truth of a running simulation (see the module docstring: pure readings, referees only)."""

    @property
    def time(self) -> float:
        """Simulated seconds since the start of the episode."""
        ...

    def true_robot_pose(self) -> Pose2D:
        """The robot's true pose (no localisation noise), stamped now."""
        ...

    def true_pose(self, name: str) -> Pose3D:
        """True pose of an item, person, furniture or the robot by name.

        Raises:
            core.errors.WorldError: no instance of that name.
        """
        ...

    def person_present(self, name: str) -> bool:
        """True when the person is inside the apartment."""
        ...

    def frame_truth(self) -> FrameTruth | None:
        """The truth behind the latest camera frame, ``None`` before the first frame."""
        ...

    def sounds_made(self) -> list[SoundTruth]:
        """Every sound made since the start, oldest first (not consumed: the same list grows)."""
        ...

    def true_device_states(self) -> dict[str, DeviceReading]:
        """Every device's true state: lights on, dimmer and blinds percent, bell ringing now."""
        ...

    def ground_truth_facts(self, include_static: bool = False) -> set[tuple[str, ...]]:
        """The true dynamic facts of the ERL domain as tuples, e.g. ``("object_at", "glasses", "entrance")``.

        Predicates: robot_at, person_at, object_at (items not held), object_on (items resting on a surface),
        holding, hand_empty, has, light_on / light_off, device_level (dimmer and blinds rounded to the nearest
        of l0 l25 l50 l75 l100), person_near (people within 1.5 m, both orders), sound_at (for 2 s after a
        ring). With ``include_static`` also connected and furniture_in.
        """
        ...

    def counters(self) -> Counters:
        """Penalty counters so far."""
        ...

    def spoken(self) -> list[Utterance]:
        """Everything the robot has said, oldest first."""
        ...
