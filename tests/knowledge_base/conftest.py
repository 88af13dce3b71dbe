"""Fixtures for the knowledge-base tests: the ERL domain and the delivery fixture domain, loaded once."""

from __future__ import annotations

from pathlib import Path

import pytest

from knowledge_base import KnowledgeBase
from knowledge_base.domain import DomainModel
from knowledge_base.problem import ProblemContent, load_problem

REPO = Path(__file__).resolve().parents[2]
ERL = REPO / "worlds" / "erl_home"
ERL_DOMAIN = ERL / "domain.pddl"
PAPER_PROBLEM = ERL / "paper_problem.pddl"
FIXTURES = REPO / "tests" / "fixtures" / "pddl"
DELIVERY_DOMAIN = FIXTURES / "delivery_domain.pddl"
DELIVERY_PROBLEM = FIXTURES / "delivery_problem.pddl"
BROKEN = FIXTURES / "broken"


@pytest.fixture(scope="session")
def erl_domain() -> DomainModel:
    return DomainModel.from_file(ERL_DOMAIN)


@pytest.fixture(scope="session")
def paper_problem(erl_domain: DomainModel) -> ProblemContent:
    return load_problem(erl_domain, PAPER_PROBLEM)


@pytest.fixture(scope="session")
def delivery_domain() -> DomainModel:
    return DomainModel.from_file(DELIVERY_DOMAIN)


class FakeClock:
    """A settable clock (simulated seconds)."""

    def __init__(self, t: float = 0.0) -> None:
        self.t = t

    def __call__(self) -> float:
        return self.t


@pytest.fixture
def clock() -> FakeClock:
    return FakeClock(10.0)


@pytest.fixture
def kb(erl_domain: DomainModel, paper_problem: ProblemContent, clock: FakeClock) -> KnowledgeBase:
    """The paper world (four rooms, glasses unknown) in memory, on a simulated clock starting at 10 s."""
    base = KnowledgeBase(erl_domain, clock=clock)
    base.load_problem(paper_problem)
    return base
