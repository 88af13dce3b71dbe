"""Fixtures of the inference tests: the ERL worlds, their location models, seeded knowledge bases."""

from __future__ import annotations

import pytest

from knic.kgm1.locations import build_location_model
from knic.seed import seed_kb_from_world
from knic.spatial import LocationModel
from knowledge_base import KnowledgeBase
from tests.knic.synthetic import DOMAIN
from worlds.api import load_world
from worlds.model import World


@pytest.fixture(scope="session")
def paper_world() -> World:
    return load_world("erl_home_paper")


@pytest.fixture(scope="session")
def home_world() -> World:
    return load_world("erl_home")


@pytest.fixture(scope="session")
def paper_locations(paper_world: World) -> LocationModel:
    return build_location_model(paper_world)


@pytest.fixture()
def clock() -> list[float]:
    """A settable simulated clock: ``clock[0]`` is now."""
    return [0.0]


@pytest.fixture()
def paper_kb(paper_world: World, clock: list[float]) -> KnowledgeBase:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: clock[0])
    seed_kb_from_world(kb, paper_world)
    return kb


@pytest.fixture()
def home_kb(home_world: World, clock: list[float]) -> KnowledgeBase:
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: clock[0])
    seed_kb_from_world(kb, home_world)
    return kb
