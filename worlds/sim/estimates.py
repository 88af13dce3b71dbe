"""What the simulated robot knows of where things are, against where they are: its sensors' estimates.

Pure functions over poses (world frame, metres, radians) used by the simulation:

* :func:`believed_to_true`: a point the robot places by its localisation estimate, where it really is (so
  localisation error becomes grasp error);
* :func:`camera_eye`: the camera position for a base pose and pan (the true one renders, the estimated one
  is what the robot deprojects with);
* :func:`heard_at`: where the microphone array localises a sound.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from core.errors import WorldError
from core.robot import Pose2D, Vec3
from worlds.api import NoiseConfig

#: metres from the base centre to the camera, along the pan direction
CAMERA_FORWARD = 0.2


def believed_to_true(at: Sequence[float], estimate: Pose2D, true: Pose2D) -> Vec3:
    """The true world point of ``at``, a point the robot placed relative to its base by ``estimate``.

    Raises:
        WorldError: ``at`` is not three finite numbers.
    """
    if len(at) != 3 or not all(math.isfinite(float(v)) for v in at):
        raise WorldError(f"believed position must be three finite numbers, got {at!r}")
    dx, dy = float(at[0]) - estimate.x, float(at[1]) - estimate.y
    c, s = math.cos(-estimate.yaw), math.sin(-estimate.yaw)
    lx, ly = c * dx - s * dy, s * dx + c * dy  # in the estimated base frame
    c, s = math.cos(true.yaw), math.sin(true.yaw)
    return (true.x + c * lx - s * ly, true.y + s * lx + c * ly, float(at[2]))


def camera_eye(base: Pose2D, pan: float, height: float) -> tuple[tuple[float, float, float], float]:
    """The camera's position and heading (radians) for a base pose, a pan angle and the camera height."""
    heading = base.yaw + pan
    return (
        base.x + CAMERA_FORWARD * math.cos(heading),
        base.y + CAMERA_FORWARD * math.sin(heading),
        height,
    ), heading


def heard_at(source: Vec3, robot: tuple[float, float], noise: NoiseConfig, rng: np.random.Generator) -> Vec3:
    """Where the microphone array localises a sound made at ``source``: Gaussian error per axis of
    ``noise.sound_noise_xy`` metres plus ``noise.sound_noise_per_m`` per metre between robot and source."""
    sigma = noise.sound_noise_xy + noise.sound_noise_per_m * math.hypot(
        source[0] - robot[0], source[1] - robot[1]
    )
    dx, dy = rng.normal(0.0, 1.0, size=2) * sigma
    return (source[0] + float(dx), source[1] + float(dy), source[2])
