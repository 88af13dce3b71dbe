"""Fixtures of the ROS 2 tests: one DDS domain per test, processes started and always stopped."""

from __future__ import annotations

import itertools
import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
_DOMAINS = itertools.count(100 + (os.getpid() % 50) * 2)


@pytest.fixture
def domain() -> int:
    """A ROS_DOMAIN_ID of this test only (tests never see each other's messages)."""
    return next(_DOMAINS) % 200 + 1


class Processes:
    """Child processes of one test, each with the test's domain; stopped with SIGTERM, then killed."""

    def __init__(self, domain: int, tmp: Path) -> None:
        self.domain = domain
        self.tmp = tmp
        self.children: list[subprocess.Popen[str]] = []

    def start(self, name: str, *args: str) -> subprocess.Popen[str]:
        env = dict(os.environ, ROS_DOMAIN_ID=str(self.domain))
        out = (self.tmp / f"{name}.out").open("w")
        err = (self.tmp / f"{name}.err").open("w")
        child = subprocess.Popen(
            [sys.executable, "-m", "knic", *args], cwd=ROOT, env=env, stdout=out, stderr=err, text=True
        )
        self.children.append(child)
        return child

    def output(self, name: str) -> str:
        return (self.tmp / f"{name}.out").read_text()

    def errors(self, name: str) -> str:
        return (self.tmp / f"{name}.err").read_text()

    def stop(self, child: subprocess.Popen[str], timeout: float = 20.0) -> int:
        if child.poll() is None:
            child.send_signal(signal.SIGTERM)
        try:
            return child.wait(timeout)
        except subprocess.TimeoutExpired:
            child.kill()
            return child.wait(5)


@pytest.fixture
def processes(domain: int, tmp_path: Path) -> Iterator[Processes]:
    procs = Processes(domain, tmp_path)
    yield procs
    for child in procs.children:
        procs.stop(child, timeout=10)
