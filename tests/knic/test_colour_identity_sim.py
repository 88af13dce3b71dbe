"""Two known items of one detector class (a red cup and a blue cup) are told apart by the colour the camera
sees; two of one colour are not guessed at."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

from knic.kgm1.camera import colour_match
from knic.pipeline import build_pipeline
from knic.scheduler import Scheduler
from knic.seed import seed_kb_from_world
from knowledge_base import KnowledgeBase
from tests.knic.synthetic import DOMAIN
from tests.knic.test_pipeline_sim import drive_to
from worlds.api import NoiseConfig
from worlds.loader import WORLD_NAMES, world_from_dict
from worlds.simulation import Simulation

RED, BLUE = [0.8, 0.1, 0.1, 1], [0.1, 0.2, 0.8, 1]


def test_colour_match_needs_a_clear_nearest_colour() -> None:
    known = {"red_cup": (0.8, 0.1, 0.1), "blue_cup": (0.1, 0.2, 0.8)}
    assert colour_match(np.array([0.5, 0.07, 0.06]), known) == "red_cup"  # darker under shading: same hue
    assert colour_match(np.array([0.06, 0.13, 0.55]), known) == "blue_cup"
    assert colour_match(np.array([0.4, 0.4, 0.4]), known) is None  # grey: neither
    assert colour_match(np.array([0.5, 0.1, 0.5]), known) is None  # halfway: no clear winner
    assert colour_match(np.array([0.5, 0.1, 0.1]), {"a": (0.8, 0.1, 0.1), "b": (0.8, 0.1, 0.1)}) is None


def _run_entrance(colours: tuple[list[float], list[float]]) -> KnowledgeBase:
    doc: dict[str, Any] = yaml.safe_load(Path(WORLD_NAMES["erl_home_paper"]).read_text())
    for name, colour in zip(("red_cup", "blue_cup"), colours, strict=True):
        item = {"name": name, "class": "cup", "furniture": "entrance_shelf", "size": [0.08, 0.08, 0.1]}
        doc["items"].append({**item, "color": colour})
    world = world_from_dict(doc)
    sim = Simulation(world, seed=3, noise=NoiseConfig())
    try:
        kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: sim.time)
        seed_kb_from_world(kb, world)
        scheduler = Scheduler(real_time_factor=1.0)
        for component in build_pipeline(kb, sim, world, role="companion"):
            scheduler.add(component)
        drive_to(sim, scheduler, "entrance")
        for _ in range(40):  # four seconds looking around the entrance
            sim.step(0.1)
            scheduler.tick(sim.time)
        assert kb.holds("object_at", "glasses", "entrance")  # the shelf was in view
        return kb
    finally:
        sim.close()


@pytest.mark.parametrize("same", [False, True], ids=["red_and_blue", "both_red"])
def test_cups_of_one_class_are_named_by_colour(same: bool) -> None:
    kb = _run_entrance((RED, RED) if same else (RED, BLUE))
    named = kb.holds("object_at", "red_cup", "entrance") and kb.holds("object_at", "blue_cup", "entrance")
    assert named is not same
    if same:  # neither was guessed
        assert not kb.holds("object_at", "red_cup", "entrance")
        assert not kb.holds("object_at", "blue_cup", "entrance")
