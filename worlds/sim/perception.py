"""Simulated object and person detector: turns a rendered segmentation into noisy :class:`Detection` s.

The detections are what the robot gets (:class:`core.robot.Detection`, no ground truth); the instance behind
each one and the names actually in view go back to the simulator separately, for its oracle.

The detector sees what the renderer saw (field of view and occlusion are real) and then applies the configured
:class:`NoiseConfig`: misses, label confusion, unrecognised people, spurious detections, depth noise.
All random
draws come from the generator handed in, in a fixed order (instances sorted by name), so runs are
reproducible.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from core.robot import Detection
from worlds.api import NoiseConfig


def detect(
    segmentation: npt.NDArray[np.int32],
    depth: npt.NDArray[np.float32],
    instances: dict[int, tuple[str, str, bool]],
    noise: NoiseConfig,
    rng: np.random.Generator,
    item_classes: list[str],
    strangers: frozenset[str] = frozenset(),
) -> tuple[list[Detection], tuple[str | None, ...], frozenset[str]]:
    """Detections of one frame, with the ground truth behind them.

    Args:
        segmentation: body id per pixel.
        depth: metric depth per pixel (``inf`` for nothing), used for false-positive masks.
        instances: body id -> ``(name, class label, is_person)`` for every world instance; furniture has
            ``class label == ""`` and is never detected, only reported visible.
        noise: the noise configuration.
        rng: the detector's random generator.
        item_classes: labels a false positive or confusion may take when no confusable class is listed.
        strangers: people the robot's recogniser does not know: detected as a person, never named.

    Returns:
        ``(detections, detected, visible)``: the detections; for each, the instance behind its mask (``None``
        for a false positive); the names of every instance with at least ``noise.min_pixels`` pixels.
    """
    counts = np.bincount(segmentation.ravel() + 1)  # body ids are small; -1 (background) -> bin 0
    visible: list[tuple[str, int, str, bool, int]] = []
    for body in np.flatnonzero(counts[1:]).tolist():
        count = int(counts[body + 1])
        if body in instances and count >= noise.min_pixels:
            name, label, person = instances[body]
            visible.append((name, body, label, person, count))
    visible.sort()
    lo, hi = noise.confidence_range
    people: list[str] = []
    if noise.person_confusion_rate > 0:
        people = sorted(n for n, _label, person in instances.values() if person and n not in strangers)
    detections: list[Detection] = []
    detected: list[str | None] = []
    for name, body, label, person, count in visible:
        if not label:
            continue
        if rng.random() < noise.class_miss_rate.get(label, noise.miss_rate):
            continue
        identity = None
        if person:
            known = name not in strangers
            if count >= noise.min_person_id_pixels and rng.random() < noise.person_id_rate and known:
                identity = name
                if people and rng.random() < noise.person_confusion_rate:
                    others = [p for p in people if p != name]
                    identity = others[int(rng.integers(len(others)))] if others else name
        else:
            label = _confused_label(label, noise, rng, item_classes)
        conf = lo + (hi - lo) * min(1.0, count / 300.0) * float(rng.uniform(0.85, 1.0))
        detections.append(
            Detection(
                label=label,
                confidence=round(conf, 4),
                mask=segmentation == body,
                identity=identity,
            )
        )
        detected.append(name)
    if item_classes and rng.random() < noise.false_positive_rate:
        fp = _false_positive(depth, rng, item_classes, lo, hi)
        if fp is not None:
            detections.append(fp)
            detected.append(None)
    return detections, tuple(detected), frozenset(v[0] for v in visible)


def _confused_label(label: str, noise: NoiseConfig, rng: np.random.Generator, item_classes: list[str]) -> str:
    """The label the detector reports for an item of class ``label`` (its row of ``noise.confusions``, else
    ``confusion_rate`` spread over the other item classes)."""
    row = noise.confusions.get(label)
    if row is not None:
        r = rng.random()
        for other, p in sorted(row.items()):
            if r < p:
                return other
            r -= p
        return label
    if rng.random() < noise.confusion_rate:
        options = [c for c in item_classes if c != label]
        if options:
            return options[int(rng.integers(len(options)))]
    return label


def _false_positive(
    depth: npt.NDArray[np.float32], rng: np.random.Generator, item_classes: list[str], lo: float, hi: float
) -> Detection | None:
    rows, cols = np.nonzero(np.isfinite(depth))
    if rows.size == 0:
        return None
    k = int(rng.integers(rows.size))
    r, c = int(rows[k]), int(cols[k])
    half = int(rng.integers(2, 6))
    mask = np.zeros(depth.shape, dtype=bool)
    mask[max(0, r - half) : r + half + 1, max(0, c - half) : c + half + 1] = True
    mask &= np.isfinite(depth)
    label = item_classes[int(rng.integers(len(item_classes)))]
    conf = lo + (hi - lo) * 0.5 * float(rng.random())
    return Detection(label=label, confidence=round(conf, 4), mask=mask)


def add_depth_noise(
    depth: npt.NDArray[np.float32], sigma_per_metre: float, rng: np.random.Generator
) -> npt.NDArray[np.float32]:
    """A copy of ``depth``, finite depths multiplied by ``1 + N(0, sigma_per_metre)`` (grows with range)."""
    if sigma_per_metre <= 0:
        return depth.copy()
    factor = rng.standard_normal(size=depth.shape, dtype=np.float32)
    factor *= np.float32(sigma_per_metre)
    factor += np.float32(1.0)
    factor *= depth  # inf stays inf
    return factor
