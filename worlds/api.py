"""Public, typed interface of the simulated ERL apartment.

Everything the rest of KnIC (perception providers, robot actions, benchmarks) needs from the simulator is
declared here: the sensor readings as dataclasses, the command results, the noise configuration and the
:class:`SimulationAPI` protocol that :class:`worlds.simulation.Simulation` implements. Code outside
``worlds/``
should import from this module (and construct the simulator through :func:`worlds.simulation.Simulation`),
so that test doubles can satisfy the same protocol under mypy.

Conventions used throughout:

* **World frame**: right-handed, metres, ``z`` up, floor at ``z = 0``; ``yaw`` in radians, counter-clockwise
  from ``+x``, normalised to ``(-pi, pi]``.
* **Time base**: simulated seconds since the start of the episode (:attr:`SimulationAPI.time`); every stamp in
  a reading is in that time base, never wall-clock time.
* **Camera optical frame**: ``x`` right, ``y`` down, ``z`` forward (the pinhole convention); image rows
  go down,
  columns go right, pixel ``(u, v)`` = (column, row).
* **Names**: instance names are exactly the PDDL symbols of the world (``glasses``, ``annie``, ``r2d2``,
  ``kitchen``, ``bedroom_left_light``); see ``/work/team/NOTES.md``.

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

import enum
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from worlds.model import World

__all__ = [
    "ActionResult",
    "CameraFrame",
    "CameraIntrinsics",
    "Counters",
    "Detection",
    "NavState",
    "NavStatus",
    "NoiseConfig",
    "Pose2D",
    "Pose3D",
    "SimulationAPI",
    "SoundEvent",
    "Utterance",
    "load_world",
]

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]


def load_world(name_or_path: str | Path) -> World:
    """Load and validate a world.

    Args:
        name_or_path: a world name (``"erl_home"``: the seven-room apartment; ``"erl_home_paper"``: the
        paper's
            four-room variant) or the path of a world YAML file.

    Returns:
        The validated, immutable :class:`worlds.model.World`.

    Raises:
        core.errors.WorldError: unknown name, unreadable file, or invalid content; the message names the entry
            (e.g. ``doors[2]``) and the problem.
    """
    from worlds.loader import load_world as _load

    return _load(name_or_path)


# --------------------------------------------------------------------------------------------- poses


@dataclass(frozen=True, slots=True)
class Pose2D:
    """A planar pose in the world frame.

    Attributes:
        x: metres.
        y: metres.
        yaw: radians, counter-clockwise from +x, in (-pi, pi].
        stamp: simulated time in seconds at which the pose was measured.
    """

    x: float
    y: float
    yaw: float
    stamp: float = 0.0

    def distance_to(self, x: float, y: float) -> float:
        """Euclidean distance in metres from this pose to the point ``(x, y)``."""
        return math.hypot(self.x - x, self.y - y)


@dataclass(frozen=True, slots=True)
class Pose3D:
    """A 3D pose in the world frame.

    Attributes:
        position: ``(x, y, z)`` in metres.
        orientation: unit quaternion ``(qx, qy, qz, qw)`` (pybullet's order).
        stamp: simulated time in seconds.
    """

    position: Vec3
    orientation: Quat = (0.0, 0.0, 0.0, 1.0)
    stamp: float = 0.0

    def rotation_matrix(self) -> npt.NDArray[np.float64]:
        """The 3x3 rotation matrix mapping vectors of this frame into the world frame."""
        qx, qy, qz, qw = self.orientation
        return np.array(
            [
                [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)],
            ]
        )


# --------------------------------------------------------------------------------------------- camera


@dataclass(frozen=True, slots=True)
class CameraIntrinsics:
    """Pinhole intrinsics of the robot's RGB-D camera (pixels), plus its clipping range (metres).

    A pixel ``(u, v)`` with depth ``d`` (metres along the optical axis) deprojects to the optical-frame point
    ``((u + 0.5 - cx) * d / fx, (v + 0.5 - cy) * d / fy, d)``.
    """

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    near: float
    far: float


@dataclass(frozen=True, slots=True)
class Detection:
    """One perceived element in a camera frame, after the configured noise.

    Attributes:
        label: class label, e.g. ``"glasses"``, ``"mug"``, ``"person"`` (possibly confused by noise).
        confidence: detector score in [0, 1].
        mask: boolean ``(height, width)`` pixel mask of the detection.
        identity: for people, the recognised name (``"annie"``) when recognition succeeded, else ``None``;
            always ``None`` for objects.
        segmentation_id: the segmentation value of the body the mask came from (``-1`` for a false positive).
        true_instance: ground truth name of the body behind the mask, ``None`` for a false positive.
            **For benchmarks and tests only**; perception must not read it.
    """

    label: str
    confidence: float
    mask: npt.NDArray[np.bool_]
    identity: str | None = None
    segmentation_id: int = -1
    true_instance: str | None = None

    @property
    def pixel_count(self) -> int:
        """Number of pixels in the mask."""
        return int(self.mask.sum())

    def bbox(self) -> tuple[int, int, int, int]:
        """Bounding box ``(u_min, v_min, u_max, v_max)`` of the mask, inclusive, in pixels."""
        rows = np.flatnonzero(self.mask.any(axis=1))
        cols = np.flatnonzero(self.mask.any(axis=0))
        if rows.size == 0:
            return (0, 0, -1, -1)
        return (int(cols[0]), int(rows[0]), int(cols[-1]), int(rows[-1]))


@dataclass(frozen=True)
class CameraFrame:
    """One RGB-D frame of the robot's camera.

    Attributes:
        stamp: simulated time in seconds at which the frame was rendered.
        width: image width in pixels.
        height: image height in pixels.
        rgb: ``(height, width, 3)`` uint8 colour image.
        depth: ``(height, width)`` float32 depth in metres along the optical axis, with the configured depth
            noise; ``inf`` where nothing is within the far clipping distance.
        segmentation: ``(height, width)`` int32 body ids (``-1``: background). Ground truth rendering,
        no noise.
        intrinsics: the camera's pinhole intrinsics.
        camera_pose: pose of the **optical frame** (x right, y down, z forward) in the world frame.
        detections: detections of items and people after noise (misses, false positives, label confusion).
        visible_instances: names of the world instances actually visible (at least the configured minimum
            number of pixels). **For benchmarks and tests only.**

    ``rgb`` and ``segmentation`` are read-only (frames of an unchanged scene share them); copy to modify.
    """

    stamp: float
    width: int
    height: int
    rgb: npt.NDArray[np.uint8]
    depth: npt.NDArray[np.float32]
    segmentation: npt.NDArray[np.int32]
    intrinsics: CameraIntrinsics
    camera_pose: Pose3D
    detections: list[Detection] = field(default_factory=list)
    visible_instances: frozenset[str] = frozenset()

    def points_world(
        self, detection: Detection, max_points: int = 64, seed: int = 0
    ) -> npt.NDArray[np.float64]:
        """Deproject a detection's pixels into 3D points in the world frame.

        Pixels without a finite depth are skipped. When the mask has more valid pixels than ``max_points``, a
        deterministic subsample (``seed``) of ``max_points`` pixels is used.

        Args:
            detection: a detection of this frame (its mask must have this frame's shape).
            max_points: the most points returned (>= 1).
            seed: seed of the subsampling.

        Returns:
            ``(N, 3)`` float64 array of world-frame points in metres, ``N <= max_points`` (``N`` may be 0).
        """
        rows, cols = np.nonzero(detection.mask & np.isfinite(self.depth))
        if rows.size > max_points:
            pick = np.random.default_rng(seed).choice(rows.size, size=max_points, replace=False)
            pick.sort()
            rows, cols = rows[pick], cols[pick]
        return self.deproject(cols.astype(np.float64), rows.astype(np.float64), self.depth[rows, cols])

    def deproject(
        self, u: npt.NDArray[np.float64], v: npt.NDArray[np.float64], depth: npt.ArrayLike
    ) -> npt.NDArray[np.float64]:
        """World-frame points ``(N, 3)`` of pixel columns ``u``, rows ``v`` and depths (metres)."""
        k = self.intrinsics
        d = np.asarray(depth, dtype=np.float64)
        optical = np.stack([(u + 0.5 - k.cx) * d / k.fx, (v + 0.5 - k.cy) * d / k.fy, d], axis=1)
        rot = self.camera_pose.rotation_matrix()
        return np.asarray(optical @ rot.T + np.asarray(self.camera_pose.position), dtype=np.float64)


# --------------------------------------------------------------------------------------------- audio, devices


@dataclass(frozen=True, slots=True)
class SoundEvent:
    """A sound heard by the robot's microphone.

    Attributes:
        kind: what was heard, a PDDL ``sound`` symbol such as ``"doorbell"``.
        position: world-frame position of the source in metres.
        stamp: simulated time in seconds when the sound started.
        source: the device or person that made it (``"door_bell"``), for benchmarks.
    """

    kind: str
    position: Vec3
    stamp: float
    source: str = ""


@dataclass(frozen=True, slots=True)
class Utterance:
    """Speech heard by the robot's microphone, or said by the robot (:meth:`SimulationAPI.say`).

    Attributes:
        text: the words, lower case without punctuation for heard speech; exact text for the robot's own.
        speaker: who spoke (``"annie"``, ``"r2d2"``).
        stamp: simulated time in seconds.
        audio_path: a WAV file of the utterance when the scenario provides one, else ``None``.
        position: world-frame position of the speaker in metres.
    """

    text: str
    speaker: str
    stamp: float
    audio_path: str | None = None
    position: Vec3 = (0.0, 0.0, 0.0)


# --------------------------------------------------------------------------------------------- commands


class NavState(enum.Enum):
    """State of the navigation goal."""

    IDLE = "idle"
    ACTIVE = "active"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"


@dataclass(frozen=True, slots=True)
class NavStatus:
    """Status of the latest navigation goal, polled with :meth:`SimulationAPI.nav_status`.

    Attributes:
        state: see :class:`NavState`.
        goal_id: increasing id of the goal (0 before the first goal).
        target: human-readable target (``"room kitchen"``, ``"furniture bed"``, ``"point (1.00, 2.00)"``).
        reason: why it failed or was cancelled (``"path blocked"``, ``"no path"``, ``"unknown room 'x'"``,
            ``"preempted"``, ``"stopped"``), empty otherwise.
        goal: the final base pose the planner aims at (world frame), ``None`` when no goal pose exists.
        path: the planned path as world-frame ``(x, y)`` waypoints (empty when none).
    """

    state: NavState
    goal_id: int = 0
    target: str = ""
    reason: str = ""
    goal: Pose2D | None = None
    path: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True, slots=True)
class ActionResult:
    """Outcome of an immediate command (pick, place, release, give, device commands).

    Attributes:
        ok: True when the command took effect.
        reason: one line saying why not (``"mug is 2.31 m away, reach is 0.90 m"``), empty on success.
    """

    ok: bool
    reason: str = ""

    def __bool__(self) -> bool:
        return self.ok


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
        )


# --------------------------------------------------------------------------------------------- the simulator


@runtime_checkable
class SimulationAPI(Protocol):
    """What a simulated (or real) apartment offers to perception, actions and benchmarks.

    Implemented by :class:`worlds.simulation.Simulation`. Commands return at once: navigation is a goal whose
    status is polled while :meth:`step` advances time; pick, place, release, give and device commands take
    effect immediately and return an :class:`ActionResult`. Commands never raise for a physically impossible
    request (that is a failed result); they raise :class:`core.errors.WorldError` only for names that do not
    exist in the world, and then change nothing.
    """

    @property
    def world(self) -> World:
        """The world data the scene was built from (rooms, doors, furniture, priors, ...)."""
        ...

    @property
    def time(self) -> float:
        """Simulated seconds since the start of the episode."""
        ...

    @property
    def robot_name(self) -> str:
        """The robot's PDDL symbol (``r2d2``)."""
        ...

    def step(self, dt: float = 0.1) -> None:
        """Advance simulated time by ``dt`` seconds (> 0): scenario events due, people, robot controllers.

        Internally integrates in sub-steps of at most the control period (0.05 s).
        """
        ...

    # sensors
    def camera_frame(self) -> CameraFrame:
        """Render the robot camera at the current time and return the frame with noisy detections."""
        ...

    def robot_pose(self) -> Pose2D:
        """The robot's localisation estimate: true pose plus Gaussian noise, stamped with :attr:`time`."""
        ...

    def poll_sounds(self) -> list[SoundEvent]:
        """Sounds heard since the previous call (oldest first); each is returned once."""
        ...

    def poll_utterances(self) -> list[Utterance]:
        """Speech by people heard since the previous call (oldest first); each is returned once."""
        ...

    def device_states(self) -> dict[str, float | bool]:
        """Every device's state: lights ``bool`` (on), dimmer and blinds ``float`` percent 0-100, bell
        ``bool``
        (ringing now)."""
        ...

    # navigation
    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        """Start a goal to the world point ``(x, y)`` (final heading ``yaw`` if given). Returns the goal
        id."""
        ...

    def navigate_to_room(self, room: str) -> int:
        """Start a goal to the room's waypoint. Returns the goal id."""
        ...

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        """Start a goal to a free pose within reach of the furniture, facing it. Returns the goal id.

        With ``near`` (a world point on or by the furniture, e.g. a perceived item), the pose is chosen within
        reach of that point when one exists, so a following :meth:`pick` can succeed on long furniture.
        """
        ...

    def navigate_to_person(self, person: str) -> int:
        """Start a goal to a free pose near the person (about 1 m), facing them. Returns the goal id."""
        ...

    def nav_status(self) -> NavStatus:
        """Status of the latest navigation goal (a new goal preempts the previous one)."""
        ...

    def set_base_velocity(self, linear: float, angular: float) -> None:
        """Drive the base directly (m/s forward, rad/s counter-clockwise), clipped to the velocity limits.

        Cancels an active navigation goal; held until :meth:`stop` or another command. Does not avoid
        obstacles: bumps and hits are counted.
        """
        ...

    def stop(self) -> None:
        """Stop the base and cancel any navigation goal (its state becomes CANCELLED, reason
        ``"stopped"``)."""
        ...

    # manipulation and camera
    def pick(self, item: str) -> ActionResult:
        """Attach ``item`` to the gripper if the hand is empty and the item is within reach and free."""
        ...

    def place(self, furniture: str) -> ActionResult:
        """Put the held item on the furniture's surface at the free spot nearest the robot, if within
        reach."""
        ...

    def release(self) -> ActionResult:
        """Open the gripper where it is: the held item falls to the surface below and counts as dropped."""
        ...

    def give(self, person: str) -> ActionResult:
        """Hand the held item to a person within reach; then ``(has person item)`` holds."""
        ...

    def held_item(self) -> str | None:
        """Name of the item in the gripper, or ``None``."""
        ...

    def pan_camera(self, angle: float) -> None:
        """Set the camera pan (radians relative to the base heading, clipped to +-pi/2)."""
        ...

    # devices and speech
    def set_light(self, device: str, on: bool) -> ActionResult:
        """Switch a light on or off."""
        ...

    def set_level(self, device: str, percent: float) -> ActionResult:
        """Set a dimmer or blinds to ``percent`` (0-100, clipped)."""
        ...

    def say(self, text: str) -> None:
        """Record that the robot said ``text`` (see :meth:`spoken`)."""
        ...

    def spoken(self) -> list[Utterance]:
        """Everything the robot has said, oldest first."""
        ...

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        """Make a person say ``text`` now (queued for :meth:`poll_utterances`)."""
        ...

    # escorting
    def escort(self, person: str) -> ActionResult:
        """Ask a person within 2 m to follow the robot until :meth:`stop_escort`."""
        ...

    def stop_escort(self) -> None:
        """The escorted person stops following and stays where they are."""
        ...

    # ground truth (benchmarks and tests only)
    def true_robot_pose(self) -> Pose2D:
        """The robot's true pose (no noise)."""
        ...

    def true_pose(self, name: str) -> Pose3D:
        """True pose of an item, person, furniture or the robot by name."""
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

    def close(self) -> None:
        """Disconnect from pybullet. Idempotent."""
        ...
