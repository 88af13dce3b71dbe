"""The simulated apartment's public interface: world loading, sensor noise, and what the simulator implements.

The robot seam lives at the bottom of the project, in :mod:`core.robot` (sensor value types without ground
truth, the :class:`~core.robot.Robot` protocol); the referee's ground truth in :mod:`worlds.oracle`
(:class:`~worlds.oracle.Oracle`). :class:`SimulationAPI` is both plus what only a simulator has: the world
data it was built from, a clock to step, people to make speak, pybullet to close. Project code imports
the value types from :mod:`core.robot`; the names re-exported here keep older imports working.

Lifecycle of a simulation::

    world = load_world("erl_home")                       # validated data, no pybullet yet
    sim = Simulation(world, seed=3, scenario="visitors")  # builds the pybullet scene (DIRECT unless gui=True)
    sim.navigate_to_room("kitchen")                       # goal command, returns at once
    while sim.nav_status().state is NavState.ACTIVE:
        sim.step(0.1)                                     # advances clock, robot, people, scenario events
        frame = sim.camera_frame()                        # rendered at the current simulated time
    sim.close()                                           # disconnects pybullet; the object is unusable after

The simulation is single-threaded and deterministic: the same world, seed, scenario and sequence of calls give
the same readings, poses and ground truth.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, runtime_checkable

from core.robot import (
    CameraFrame,
    CameraIntrinsics,
    CommandResult,
    Detection,
    NavState,
    NavStatus,
    Pose2D,
    Pose3D,
    Robot,
    SoundEvent,
    Utterance,
)
from worlds.oracle import Counters, FrameTruth, Oracle, SoundTruth

if TYPE_CHECKING:
    from worlds.model import World

__all__ = [
    "ActionResult",
    "CameraFrame",
    "CameraIntrinsics",
    "CommandResult",
    "Counters",
    "Detection",
    "FrameTruth",
    "NavState",
    "NavStatus",
    "NoiseConfig",
    "Oracle",
    "Pose2D",
    "Pose3D",
    "Robot",
    "SimulationAPI",
    "SoundEvent",
    "SoundTruth",
    "Utterance",
    "load_world",
]

#: the former name of :class:`core.robot.CommandResult`
ActionResult = CommandResult


def load_world(name_or_path: str | Path) -> World:
    """Load and validate a world.

    Args:
        name_or_path: a world name (``"erl_home"``: the seven-room apartment; ``"erl_home_paper"``: the
            paper's four-room variant) or the path of a world YAML file.

    Returns:
        The validated, immutable :class:`worlds.model.World`.

    Raises:
        core.errors.WorldError: unknown name, unreadable file, or invalid content; the message names the entry
            (e.g. ``doors[2]``) and the problem.
    """
    from worlds.loader import load_world as _load

    return _load(name_or_path)


# --------------------------------------------------------------------------------------------- noise


@dataclass(frozen=True, slots=True)
class NoiseConfig:
    """Sensor noise. All probabilities are per detection per frame unless stated; zero everywhere = perfect.

    Attributes:
        miss_rate: probability that a visible item or person is not detected.
        false_positive_rate: probability per frame of one spurious detection (random item class, mask on a
            random patch of the image with valid depth).
        confusion_rate: probability that an item's label is replaced by a confusable class (``mug``/``cup``,
            ``apple``/``lemon``, ``water``/``juice``, ...; otherwise any other item class).
        person_id_rate: probability that a visible person is recognised (``identity`` set); people seen with
            fewer than ``min_person_id_pixels`` pixels are never recognised.
        min_person_id_pixels: see above.
        depth_noise: standard deviation of the depth noise per metre of depth (sigma = depth_noise * depth).
        pose_noise_xy: standard deviation of the localisation noise in metres (per axis).
        pose_noise_yaw: standard deviation of the localisation heading noise in radians.
        min_pixels: smallest mask (pixels) an instance needs to count as visible and detectable.
        confidence_range: detector confidence of true detections is drawn in this range (higher for bigger
            masks); false positives get the lower half.
        sound_noise_xy: standard deviation (metres, per axis) of where the microphone array localises a sound.
        sound_noise_per_m: added to that standard deviation per metre between the robot and the sound.
        person_confusion_rate: probability that a recognised person is given another person's name.
        class_miss_rate: per-class miss probability (``"person"`` for people), overriding ``miss_rate``.
        confusions: per-class confusion row: class -> {class it is read as: probability}; a class without a
            row is confused with probability ``confusion_rate`` with any other item class.

    Masks are the pixels the renderer saw of each instance: a box or mask is cut by whatever stands in front.
    The model is data: :func:`worlds.sim.noise.load_noise` reads it from YAML (``worlds/noise.yaml`` is the
    default robot's).
    """

    miss_rate: float = 0.05
    false_positive_rate: float = 0.02
    confusion_rate: float = 0.03
    person_id_rate: float = 0.9
    min_person_id_pixels: int = 40
    depth_noise: float = 0.01
    pose_noise_xy: float = 0.02
    pose_noise_yaw: float = 0.01
    min_pixels: int = 4
    confidence_range: tuple[float, float] = (0.6, 0.98)
    sound_noise_xy: float = 0.1
    sound_noise_per_m: float = 0.02
    person_confusion_rate: float = 0.0
    class_miss_rate: dict[str, float] = field(default_factory=dict)
    confusions: dict[str, dict[str, float]] = field(default_factory=dict)

    @classmethod
    def perfect(cls) -> NoiseConfig:
        """No noise at all: every visible instance detected with its true label and identity."""
        return cls(
            miss_rate=0.0,
            false_positive_rate=0.0,
            confusion_rate=0.0,
            person_id_rate=1.0,
            min_person_id_pixels=0,
            depth_noise=0.0,
            pose_noise_xy=0.0,
            pose_noise_yaw=0.0,
            confidence_range=(1.0, 1.0),
            sound_noise_xy=0.0,
            sound_noise_per_m=0.0,
        )


@runtime_checkable
class SimulationAPI(Robot, Oracle, Protocol):
    """A simulated apartment: the robot in it (:class:`~core.robot.Robot`), the referee's ground truth
    (:class:`~worlds.oracle.Oracle`), and the simulator's own controls.

    Implemented by :class:`worlds.simulation.Simulation`. Only the run's assembly holds the whole object; it
    hands the robot part to perception and actions and the oracle part to referees.
    """

    @property
    def world(self) -> World:
        """The world data the scene was built from (rooms, doors, furniture, priors, ...)."""
        ...

    def step(self, dt: float = 0.1) -> None:
        """Advance simulated time by ``dt`` seconds (> 0): scenario events due, people, robot controllers.

        Internally integrates in sub-steps of at most the control period (0.05 s).
        """
        ...

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        """Make a person say ``text`` now (queued for :meth:`~core.robot.Robot.poll_utterances`)."""
        ...

    def close(self) -> None:
        """Disconnect from pybullet. Idempotent."""
        ...
