"""The robot seam: what a robot reports and what it accepts, and nothing it cannot know.

Everything above the robot -- the KGM-1 providers reading its sensors, the actions commanding it -- talks to
one :class:`Robot`. The simulator (:class:`worlds.simulation.Simulation`) implements it today; a ROS 2
adapter or a real robot implements the same protocol. The value types here carry **no ground truth**: a
camera frame holds what the camera and the detector produced, a pose is the localisation's estimate, a sound
is where the robot heard it. What really happened (true poses, which bodies were in view, who rang) belongs
to the referee's oracle (:class:`worlds.oracle.Oracle`), which only referees and benchmarks receive.

Who calls what, and when:

* **Sensor readings** (:meth:`Robot.camera_frame`, :meth:`Robot.robot_pose`, :meth:`Robot.poll_sounds`,
  :meth:`Robot.poll_utterances`, :meth:`Robot.device_states`, :meth:`Robot.held_item`,
  :meth:`Robot.nav_status`) are read by the KGM-1 providers in their ``step`` and by actions in
  ``activation`` / ``step``. They never block and never move the robot. The ``poll_*`` readings are
  consuming (each event is returned once), so exactly one provider polls each of them.
* **Commands** (base goals, velocity, stop, gripper, camera pan, devices, speech, escort) are sent by actions
  from ``activation``, ``step`` and ``deactivation`` (see :mod:`actions.base`). They return at once: a base
  goal returns its id and is then followed through :meth:`Robot.nav_status`; the gripper, device and escort
  commands take effect immediately and return a :class:`CommandResult`. A physically impossible request is a
  failed result, never an exception; a name the robot's map does not know (room, furniture, item, person,
  device) raises :class:`core.errors.WorldError` and changes nothing.
* Time passes outside the seam: the simulator is stepped by the run loop, a real robot by the wall clock.
  :attr:`Robot.time` says where it is.

Conventions:

* **World frame**: right-handed, metres, ``z`` up, floor at ``z = 0``; ``yaw`` in radians, counter-clockwise
  from ``+x``, in ``(-pi, pi]``.
* **Time base**: :attr:`Robot.time`, seconds since the start of the episode (simulated seconds in the
  simulator); every stamp in a reading is in that base, never wall-clock time.
* **Camera optical frame**: ``x`` right, ``y`` down, ``z`` forward; image rows go down, columns right, pixel
  ``(u, v)`` = (column, row).
* **Names**: the PDDL symbols of the world (``glasses``, ``annie``, ``r2d2``, ``kitchen``,
  ``bedroom_left_light``).

The sensors are declared as small protocols (:class:`Camera`, :class:`Localisation`, :class:`SoundDetector`,
:class:`SpeechInput`, :class:`DeviceSensors`) that :class:`Robot` extends, so a KGM-1 provider that reads one
sensor asks for that part of the robot and a test double of one sensor is checked against the same
declaration.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
import numpy.typing as npt

__all__ = [
    "CAUSE_HAND",
    "CAUSE_NOT_AT_BELIEF",
    "CAUSE_OUT_OF_REACH",
    "Camera",
    "CameraFrame",
    "CameraIntrinsics",
    "CommandResult",
    "Detection",
    "DeviceReading",
    "DeviceSensors",
    "Localisation",
    "NavState",
    "NavStatus",
    "Pose2D",
    "Pose3D",
    "Quat",
    "Robot",
    "SoundDetector",
    "SoundEvent",
    "SpeechInput",
    "Utterance",
    "Vec3",
]

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
#: a device reading: lights and the bell ``bool`` (on, ringing now), dimmers and blinds percent 0-100
DeviceReading = float | bool


# --------------------------------------------------------------------------------------------- poses


@dataclass(frozen=True, slots=True)
class Pose2D:
    """A planar pose in the world frame.

    Attributes:
        x: metres.
        y: metres.
        yaw: radians, counter-clockwise from +x, in (-pi, pi].
        stamp: time (seconds, :attr:`Robot.time` base) at which the pose was measured.
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
        orientation: unit quaternion ``(qx, qy, qz, qw)``.
        stamp: time in seconds (:attr:`Robot.time` base).
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
    """One element the robot's detector reports in a camera frame (it may be wrong: a miss is simply absent,
    a false positive or a confused label looks like any other detection).

    Attributes:
        label: class label, e.g. ``"glasses"``, ``"mug"``, ``"person"``.
        confidence: detector score in [0, 1].
        mask: boolean ``(height, width)`` pixel mask of the detection.
        identity: for people, the name face recognition gave (``"annie"``), else ``None``; always ``None``
            for objects.
    """

    label: str
    confidence: float
    mask: npt.NDArray[np.bool_]
    identity: str | None = None

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
    """One RGB-D frame of the robot's camera with the detector's output.

    Attributes:
        stamp: time in seconds (:attr:`Robot.time` base) at which the frame was taken.
        width: image width in pixels.
        height: image height in pixels.
        rgb: ``(height, width, 3)`` uint8 colour image.
        depth: ``(height, width)`` float32 depth in metres along the optical axis, with the sensor's noise;
            ``inf`` where nothing is within the far clipping distance.
        intrinsics: the camera's pinhole intrinsics.
        camera_pose: pose of the **optical frame** (x right, y down, z forward) in the world frame, as the
            robot knows it (base pose, pan and the camera's mounting); what deprojection uses.
        detections: what the detector reported (misses, false positives, label confusion included).

    ``rgb`` may be shared between frames of an unchanged scene: treat it as read-only, copy to modify.
    """

    stamp: float
    width: int
    height: int
    rgb: npt.NDArray[np.uint8]
    depth: npt.NDArray[np.float32]
    intrinsics: CameraIntrinsics
    camera_pose: Pose3D
    detections: list[Detection] = field(default_factory=list)

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


# --------------------------------------------------------------------------------------------- audio


@dataclass(frozen=True, slots=True)
class SoundEvent:
    """A sound the robot's microphone array detected.

    Attributes:
        kind: what was heard, a PDDL ``sound`` symbol such as ``"doorbell"``.
        position: world-frame position, metres, where the robot localised the sound.
        stamp: time in seconds when the sound started.
    """

    kind: str
    position: Vec3
    stamp: float


@dataclass(frozen=True, slots=True)
class Utterance:
    """Speech heard by the robot's microphone, or said by the robot (:meth:`Robot.say`).

    Attributes:
        text: the words, lower case without punctuation for heard speech; exact text for the robot's own.
        speaker: who spoke, as the robot's speaker recognition tells (``"annie"``), or the robot itself.
        stamp: time in seconds.
        audio_path: a WAV file of the utterance when one was recorded, else ``None``.
        position: world-frame position, metres, where the robot localised the voice.
    """

    text: str
    speaker: str
    stamp: float
    audio_path: str | None = None
    position: Vec3 = (0.0, 0.0, 0.0)


# --------------------------------------------------------------------------------------------- commands


class NavState(enum.Enum):
    """State of the latest base goal."""

    IDLE = "idle"
    ACTIVE = "active"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"


@dataclass(frozen=True, slots=True)
class NavStatus:
    """Status of the latest base goal, polled with :meth:`Robot.nav_status`.

    Attributes:
        state: see :class:`NavState`.
        goal_id: increasing id of the goal (0 before the first goal).
        target: human-readable target (``"room kitchen"``, ``"furniture bed"``, ``"point (1.00, 2.00)"``).
        reason: why it failed or was cancelled (``"path blocked"``, ``"no path"``, ``"preempted"``,
            ``"stopped"``), empty otherwise.
        goal: the final base pose the navigation aims at (world frame), ``None`` when there is none.
        path: the planned path as world-frame ``(x, y)`` waypoints (empty when none).
    """

    state: NavState
    goal_id: int = 0
    target: str = ""
    reason: str = ""
    goal: Pose2D | None = None
    path: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True, slots=True)
class CommandResult:
    """Outcome of an immediate command (pick, place, release, give, device commands, escort).

    Attributes:
        ok: True when the command took effect.
        reason: one line saying why not (``"mug is 2.31 m away, reach is 0.90 m"``), empty on success.
        cause: the failure's kind, one of the ``CAUSE_*`` names (empty on success or when unnamed);
            :data:`CAUSE_NOT_AT_BELIEF` tells the caller its belief of where the entity is was wrong.
    """

    ok: bool
    reason: str = ""
    cause: str = ""

    def __bool__(self) -> bool:
        return self.ok


#: a gripper, hand-over or escort command found nothing at the believed position it was given
CAUSE_NOT_AT_BELIEF = "not_at_belief"
#: the believed position (or the entity) is beyond the arm's reach from where the base stands
CAUSE_OUT_OF_REACH = "out_of_reach"
#: the hand (the robot's or the person's) is not in the state the command needs
CAUSE_HAND = "hand"


# --------------------------------------------------------------------------------------------- the seam


@runtime_checkable
class Camera(Protocol):
    """The robot's RGB-D camera with its object and person detector."""

    def camera_frame(self) -> CameraFrame:
        """The latest frame (a camera at ``f`` Hz returns the same frame until the next one is due).

        Read by the camera KPs in their ``step`` and by benchmarks; never moves anything.
        """
        ...


@runtime_checkable
class Localisation(Protocol):
    """The robot's self-localisation."""

    def robot_pose(self) -> Pose2D:
        """The pose estimate now (world frame, noisy), stamped with :attr:`Robot.time`."""
        ...


@runtime_checkable
class SoundDetector(Protocol):
    """The microphone's sound-event detector."""

    def poll_sounds(self) -> list[SoundEvent]:
        """Sounds heard since the previous call, oldest first; each is returned once (one reader only)."""
        ...


@runtime_checkable
class SpeechInput(Protocol):
    """The microphone's speech channel."""

    def poll_utterances(self) -> list[Utterance]:
        """Speech by people heard since the previous call, oldest first; each is returned once."""
        ...


@runtime_checkable
class DeviceSensors(Protocol):
    """The home automation's readings."""

    def device_states(self) -> dict[str, DeviceReading]:
        """Every device's reading now, by device symbol (see :data:`DeviceReading`)."""
        ...


@runtime_checkable
class Robot(Camera, Localisation, SoundDetector, SpeechInput, DeviceSensors, Protocol):
    """One robot: its sensor readings out, its commands in (see the module docstring for who calls what).

    Readings never block; commands return at once. Base goals run in the background: a new goal (or
    :meth:`set_base_velocity`, :meth:`stop`) preempts the previous one, whose state becomes CANCELLED. An
    action that starts a goal owns the base until its ``deactivation``, which should :meth:`stop` the base
    unless the action succeeded.
    """

    @property
    def time(self) -> float:
        """Seconds since the start of the episode: the time base of every stamp (simulated in simulation)."""
        ...

    @property
    def robot_name(self) -> str:
        """The robot's PDDL symbol (``r2d2``)."""
        ...

    def held_item(self) -> str | None:
        """The item in the gripper, by the gripper's own sensor, or ``None``."""
        ...

    def nav_status(self) -> NavStatus:
        """Status of the latest base goal."""
        ...

    # base
    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        """Start a goal to the world point ``(x, y)`` metres (final heading ``yaw`` radians if given).

        Returns the goal id; a target that is not free fails at once (state FAILED, same id).
        """
        ...

    def navigate_to_room(self, room: str) -> int:
        """Start a goal to a free pose near the room's waypoint (robot's map). Returns the goal id."""
        ...

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        """Start a goal to a free pose within gripper reach of the furniture, facing it; returns the goal id.

        With ``near`` (a world point on or by the furniture, e.g. a perceived item), the pose is chosen within
        reach of that point when one exists, so a following :meth:`pick` can succeed on long furniture.
        """
        ...

    def navigate_to_person(self, person: str) -> int:
        """Start a goal to a free pose about 1 m from the person, facing them. Returns the goal id."""
        ...

    def set_base_velocity(self, linear: float, angular: float) -> None:
        """Drive the base directly (m/s forward, rad/s counter-clockwise), clipped to the velocity limits.

        Cancels an active goal; held until :meth:`stop` or another base command. Does not avoid obstacles.
        """
        ...

    def stop(self) -> None:
        """Stop the base and cancel any goal (its state becomes CANCELLED, reason ``"stopped"``)."""
        ...

    # gripper and camera mount
    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        """Grasp ``item`` if the hand is empty and the item is within reach and free.

        ``at`` is where the robot believes the item is (world frame, metres, as its own localisation puts
        it): the arm goes there, and the grasp closes on the item only if it really is within the gripper's
        tolerance of that point; otherwise the result fails with cause :data:`CAUSE_NOT_AT_BELIEF`. Without
        ``at`` the arm's close-range sensing finds the item itself.
        """
        ...

    def place(self, furniture: str) -> CommandResult:
        """Put the held item on the furniture's surface at the free spot nearest the robot, within reach."""
        ...

    def release(self) -> CommandResult:
        """Open the gripper where it is: the held item falls."""
        ...

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Hand the held item to a person within reach.

        ``at``: where the robot believes the person is (as for :meth:`pick`); the arm reaches there and the
        hand-over fails with cause :data:`CAUSE_NOT_AT_BELIEF` when the person is not within hand-over
        tolerance of it.
        """
        ...

    def pan_camera(self, angle: float) -> None:
        """Set the camera pan: radians relative to the base heading, clipped to +-pi/2; the next frame is
        taken at the new angle."""
        ...

    # home automation, speech, escort
    def set_light(self, device: str, on: bool) -> CommandResult:
        """Switch a light on or off."""
        ...

    def set_level(self, device: str, percent: float) -> CommandResult:
        """Set a dimmer or blinds to ``percent`` (0-100, clipped)."""
        ...

    def say(self, text: str) -> None:
        """Speak ``text`` through the robot's loudspeaker."""
        ...

    def escort(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Ask a person within 2 m to follow the robot until :meth:`stop_escort`.

        ``at``: where the robot believes the person is; the robot addresses that spot, and the request fails
        with cause :data:`CAUSE_NOT_AT_BELIEF` when nobody of that name stands within 1 m of it.
        """
        ...

    def stop_escort(self) -> None:
        """Tell the escorted person to stop following (they stay where they are)."""
        ...
