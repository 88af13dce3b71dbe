"""The sensor model as data: worlds/noise.yaml loads, is checked, and drives the detector."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from core.errors import WorldError
from worlds.api import NoiseConfig
from worlds.sim.noise import DEFAULT_NOISE, load_noise, noise_from_dict
from worlds.sim.perception import detect


def test_default_model_loads_with_confusion_rows() -> None:
    noise = load_noise(DEFAULT_NOISE)
    assert noise.confusions["mug"] == {"cup": 0.015, "glass": 0.015}
    assert noise.miss_rate == NoiseConfig().miss_rate and noise.sound_noise_xy > 0


@pytest.mark.parametrize(
    ("raw", "message"),
    [
        ({"detector": {"miss_rate": 1.5}}, "detector.miss_rate"),
        ({"detector": {"confusions": {"mug": {"mug": 0.1}}}}, "itself"),
        ({"detector": {"confusions": {"mug": {"cup": 0.7, "glass": 0.6}}}}, "sum to more than 1"),
        ({"radar": {}}, "unknown section"),
        ({"sound": {"sound_noise_xy": -1}}, "sound.sound_noise_xy"),
        ({"people": {"eyes": 2}}, "people.eyes"),
    ],
)
def test_bad_models_are_refused_naming_the_key(raw: dict[str, object], message: str) -> None:
    with pytest.raises(WorldError, match=message):
        noise_from_dict(raw, "test.yaml")


def test_unreadable_file_is_one_line_error(tmp_path: Path) -> None:
    bad = tmp_path / "noise.yaml"
    bad.write_text("detector: [1, 2\n")
    with pytest.raises(WorldError, match=r"noise\.yaml"):
        load_noise(bad)


def test_confusion_row_and_person_confusion_drive_the_detector() -> None:
    seg = np.full((20, 20), -1, dtype=np.int32)
    seg[2:8, 2:8] = 1  # a mug
    seg[10:19, 10:19] = 2  # annie
    depth = np.where(seg >= 0, 1.0, np.inf).astype(np.float32)
    instances = {1: ("mug", "mug", False), 2: ("annie", "person", True), 3: ("jack", "person", True)}
    noise = NoiseConfig(
        miss_rate=0.0,
        false_positive_rate=0.0,
        confusions={"mug": {"cup": 1.0}},
        person_confusion_rate=1.0,
        min_person_id_pixels=0,
        person_id_rate=1.0,
    )
    dets, detected, visible = detect(seg, depth, instances, noise, np.random.default_rng(0), ["cup", "mug"])
    assert {d.label for d in dets} == {"cup", "person"}
    assert [d.identity for d in dets if d.label == "person"] == ["jack"]  # confused with the other person
    assert detected == ("annie", "mug") and visible == frozenset({"annie", "mug"})
