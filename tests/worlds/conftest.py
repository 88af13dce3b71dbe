"""Fixtures for the simulated apartment: worlds loaded from worlds/erl_home, headless simulations."""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
import yaml

from worlds.api import NoiseConfig
from worlds.loader import WORLD_NAMES, load_world
from worlds.model import World
from worlds.simulation import Simulation


@pytest.fixture(scope="session")
def erl_world() -> World:
    return load_world("erl_home")


@pytest.fixture(scope="session")
def erl_doc() -> dict[str, Any]:
    doc: dict[str, Any] = yaml.safe_load(Path(WORLD_NAMES["erl_home"]).read_text())
    return doc


@pytest.fixture
def doc(erl_doc: dict[str, Any]) -> dict[str, Any]:
    """A fresh, mutable copy of the erl_home world document."""
    return copy.deepcopy(erl_doc)


@pytest.fixture
def make_sim() -> Iterator[Callable[..., Simulation]]:
    """Build headless simulations (perfect sensors unless ``noise`` is given); all closed afterwards."""
    sims: list[Simulation] = []

    def make(world: World | str = "erl_home", **kwargs: Any) -> Simulation:
        kwargs.setdefault("noise", NoiseConfig.perfect())
        sim = Simulation(world, **kwargs)
        sims.append(sim)
        return sim

    yield make
    for sim in sims:
        sim.close()
