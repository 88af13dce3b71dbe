"""Octomap throughput of KGM-2 against raw pyoctomap (``octomap_throughput_ratio``).

Both sides insert the same camera-like point clouds (objects seen from a moving camera, each cloud one
detection's deprojected points, ray cast from the camera) into one octree per object at the same resolution:

* raw: ``OcTree.insertPointCloud`` called directly, cloud after cloud, from the camera with its default
  arguments; and once more in the mode KGM-2 uses (``discretize=True``, rays from 1 m before the entity,
  the entity octomaps' clamping thresholds, see :class:`~knic.spatial.EntityOctomap`) to isolate the cost of
  the Python around the insertion;
* KGM-2: the LLKUs of each frame published on the bus with their scan marker and processed by
  :class:`~knic.kgm2.cognition.CognitiveLayer` (association, octomap update, CKU publication) under a role
  that processes every class at every frame, so nothing is skipped. Nothing downstream reads the CKUs
  here, so their keys (a query of the entity's octomap run when a KP' reads them, see
  :class:`~knic.units.CKU`) are never asked: the comparison is the insertion path, the same insertions on
  both sides. A second KGM-2 run reads every CKU's keys as the place KP' do, to show what those octomap
  queries add.

The ratio is KGM-2 points per second over raw points per second (1.0: no overhead). Times are the process's
CPU time (``time.process_time``), the two sides run interleaved, and the best of ``repeats`` runs of each side
is kept, to damp the noise of other processes on a shared machine.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np
import pyoctomap

from knic.bus import Bus
from knic.kgm2.cognition import CognitiveLayer, TrackingConfig
from knic.kgm2.roles import Policy, Role
from knic.spatial import DEFAULT_RESOLUTION, ROOM, EntityOctomap, Location, Prism
from knic.units import LLKU, Kind, Scan


class _AllVisible:
    """A frame view that sees everything (the benchmark's objects are never missed)."""

    def __init__(self, position: np.ndarray) -> None:
        self.position = position

    def visible(self, points: np.ndarray) -> np.ndarray:
        return np.ones(len(points), dtype=bool)

    def optical_axis(self) -> np.ndarray:
        return np.array([1.0, 0.0, 0.0])


def _centre(cloud: np.ndarray) -> tuple[float, float, float]:
    c = np.median(cloud, axis=0)
    return (float(c[0]), float(c[1]), float(c[2]))


def _scene(
    objects: int, frames: int, points: int, seed: int
) -> list[tuple[np.ndarray, list[tuple[str, np.ndarray]]]]:
    """Per frame: the camera origin and (label, cloud) per object, world frame, metres."""
    rng = np.random.default_rng(seed)
    centres = np.column_stack(
        [rng.uniform(1.0, 7.0, objects), rng.uniform(1.0, 7.0, objects), rng.uniform(0.4, 1.0, objects)]
    )
    out = []
    for f in range(frames):
        angle = 2 * np.pi * f / max(frames, 1)
        origin = np.array([4.0 + 0.5 * np.cos(angle), 4.0 + 0.5 * np.sin(angle), 1.2])
        clouds = []
        for i, c in enumerate(centres):
            cloud = c + rng.normal(0.0, 0.03, size=(points, 3))
            clouds.append((f"class_{i}", cloud))
        out.append((origin, clouds))
    return out


def _raw(
    scene: list[tuple[np.ndarray, list[tuple[str, np.ndarray]]]],
    resolution: float,
    *,
    discretize: bool = False,
    ray_length: float = 0.0,
    clamping: tuple[float, float] | None = None,
) -> float:
    jobs = []
    for origin, clouds in scene:
        for label, cloud in clouds:
            start = origin
            if ray_length > 0:  # the same short rays as KGM-2, computed outside the timing
                centre = np.median(cloud, axis=0)
                offset = origin - centre
                distance = float(np.linalg.norm(offset))
                if distance > ray_length:
                    start = centre + offset * (ray_length / distance)
            jobs.append((label, cloud, np.asarray(start, dtype=np.float64)))
    trees: dict[str, Any] = {}
    begin = time.process_time()
    for label, cloud, start in jobs:
        tree = trees.get(label)
        if tree is None:
            tree = trees[label] = pyoctomap.OcTree(resolution)
            if clamping is not None:  # the same trees as KGM-2's entity octomaps
                tree.setClampingThresMin(clamping[0])
                tree.setClampingThresMax(clamping[1])
        tree.insertPointCloud(cloud, start, -1.0, False, discretize)
    return time.process_time() - begin


def _kgm2(
    scene: list[tuple[np.ndarray, list[tuple[str, np.ndarray]]]],
    resolution: float,
    *,
    read_keys: bool = False,
) -> float:
    bus = Bus()
    ckus = bus.inbox("cognition.object", capacity=20000) if read_keys else None
    outline = np.array([[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]])
    room = Location("room", ROOM, outline, Prism("room", outline, 0.0, 2.5), waypoint=(4.0, 4.0))
    role = Role("bench", "every class at every frame", Policy(1000.0, 1))
    layer = CognitiveLayer(bus, role, config=TrackingConfig(resolution=resolution))
    layer.locations.add(room)
    units = [
        (
            origin,
            [
                LLKU(
                    kind=Kind.OBJECT,
                    label=label,
                    source="bench",
                    sensor="camera",
                    stamp=0.1 * f,
                    confidence=0.9,
                    position=_centre(cloud),
                    points=cloud,
                    sensor_origin=(float(origin[0]), float(origin[1]), float(origin[2])),
                    identity=label,
                )
                for label, cloud in clouds
            ],
        )
        for f, (origin, clouds) in enumerate(scene)
    ]
    start = time.process_time()
    for f, (origin, frame_units) in enumerate(units):
        stamp = 0.1 * f
        for unit in frame_units:
            bus.publish(f"percept.vision.object.{unit.label}", unit, source="bench", stamp=stamp)
        scan = Scan(Kind.OBJECT, stamp, _AllVisible(origin), "camera")
        bus.publish("percept.vision.scan.object", scan, source="bench", stamp=stamp)
        layer.step(stamp)
        if ckus is not None:  # as the place KP' do: every CKU's keys, read after the layer's step
            for message in ckus.drain():
                _ = message.payload.keys
    elapsed = time.process_time() - start
    if layer.stats.processed != sum(len(u) for _, u in units):
        raise RuntimeError("benchmark role skipped units; the comparison would be unfair")
    return elapsed


def measure_octomap_throughput(
    *,
    objects: int = 8,
    frames: int = 60,
    points: int = 128,
    repeats: int = 5,
    resolution: float = DEFAULT_RESOLUTION,
    seed: int = 0,
) -> dict[str, float | int]:
    """Measure points per second through KGM-2's update path and through raw ``insertPointCloud``.

    Returns:
        ``octomap_throughput_ratio`` (against default ``insertPointCloud``),
        ``octomap_overhead_ratio_same_mode`` (against ``insertPointCloud`` in the mode KGM-2 uses: what the
        Python around the insertion costs), ``octomap_ratio_with_key_reads`` (the same, with every CKU's
        keys read as the place KP' read them: the octomap queries the reasoning adds), ``kgm2_points_per_s``,
        ``raw_points_per_s``, ``clouds``, ``points_per_cloud``, ``resolution_m``.
    """
    scene = _scene(objects, frames, points, seed)
    total = objects * frames * points
    ray_length = TrackingConfig().ray_length
    probe = EntityOctomap(resolution, ray_length=ray_length)
    clamping = (probe.tree.getClampingThresMin(), probe.tree.getClampingThresMax())
    raws, same, kgm2s, reads = [], [], [], []
    for _ in range(repeats):  # interleaved, so all sides see the same machine load
        raws.append(_raw(scene, resolution))
        same.append(_raw(scene, resolution, discretize=True, ray_length=ray_length, clamping=clamping))
        kgm2s.append(_kgm2(scene, resolution))
        reads.append(_kgm2(scene, resolution, read_keys=True))
    raw, raw_same, kgm2 = min(raws), min(same), min(kgm2s)
    return {
        "octomap_throughput_ratio": round(raw / kgm2, 3),
        "octomap_overhead_ratio_same_mode": round(raw_same / kgm2, 3),
        "octomap_ratio_with_key_reads": round(raw_same / min(reads), 3),
        "kgm2_points_per_s": round(total / kgm2),
        "raw_points_per_s": round(total / raw),
        "clouds": objects * frames,
        "points_per_cloud": points,
        "resolution_m": resolution,
    }


if __name__ == "__main__":  # pragma: no cover - manual run
    import json

    print(json.dumps(measure_octomap_throughput()))
