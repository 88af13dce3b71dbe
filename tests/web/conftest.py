"""Fixtures of the web view's tests: a journal written by a real knowledge base (the ERL domain seeded from
the erl_home world), the app over it, and Debian's chromium for the browser tests."""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from knic.seed import seed_kb_from_world
from knic.system.config import DOMAIN
from knowledge_base import KnowledgeBase
from worlds.api import load_world
from worlds.model import World

CHROMIUM = "/usr/bin/chromium"


@dataclass
class Writer:
    """A knowledge base writing a journal file, on a clock the test sets (simulated seconds)."""

    kb: KnowledgeBase
    journal: Path
    trace: Path
    clock: list[float] = field(default_factory=lambda: [0.0])

    def at(self, t: float) -> KnowledgeBase:
        self.clock[0] = t
        return self.kb


@pytest.fixture(scope="session")
def world() -> World:
    return load_world("erl_home")


@pytest.fixture
def writer(tmp_path: Path, world: World) -> Iterator[Writer]:
    journal = tmp_path / "run.sqlite"
    kb = KnowledgeBase.from_pddl(DOMAIN, journal=journal)
    w = Writer(kb, journal, tmp_path / "run.jsonl")
    kb.set_clock(lambda: w.clock[0])
    seed_kb_from_world(kb, world)
    yield w
    kb.close()


@pytest.fixture(scope="session")
def chromium() -> str:
    """Debian's chromium (``make test`` installs it); missing outside CI skips the browser tests."""
    if not Path(CHROMIUM).exists() and shutil.which("chromium") is None:
        if os.environ.get("CI"):
            pytest.fail(f"{CHROMIUM} is missing: make test installs it (apt-get install chromium)")
        pytest.skip(f"{CHROMIUM} is missing (apt-get install chromium)")
    return CHROMIUM
