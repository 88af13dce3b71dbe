"""The registry of example planning problems (tests/fixtures/planning/examples.yaml), loaded once."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import yaml

from planner.engines import silence_up
from planner.model import Atom, PlanningTask, atom_from_str
from planner.plan import PlanStep
from planner.problem import load_pddl

ROOT = Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "tests" / "fixtures" / "planning"


@dataclass(frozen=True)
class Example:
    """One named example: files, expected solvability, known valid and invalid plans."""

    name: str
    domain: Path
    problem: Path
    solvable: str
    unreachable: tuple[Atom, ...]
    valid: tuple[tuple[PlanStep, ...], ...]
    invalid: tuple[tuple[tuple[PlanStep, ...], int], ...]

    def load(self) -> tuple[Any, Any, PlanningTask]:
        """``(up_domain, up_problem, task)``, parsed once per example."""
        return _load(str(self.domain), str(self.problem))


@cache
def _load(domain: str, problem: str) -> tuple[Any, Any, PlanningTask]:
    silence_up()
    return load_pddl(domain, problem)


def _steps(rows: list[str]) -> tuple[PlanStep, ...]:
    return tuple(PlanStep.parse(s) for s in rows)


@cache
def examples() -> tuple[Example, ...]:
    data = yaml.safe_load((FIXTURES / "examples.yaml").read_text(encoding="utf-8"))["examples"]
    return tuple(
        Example(
            name,
            ROOT / spec["domain"],
            ROOT / spec["problem"],
            spec["solvable"],
            tuple(atom_from_str(g) for g in spec.get("unreachable", [])),
            tuple(_steps(p) for p in spec["valid"]),
            tuple((_steps(i["plan"]), int(i["breaks_at"])) for i in spec["invalid"]),
        )
        for name, spec in data.items()
    )


def example(name: str) -> Example:
    return next(e for e in examples() if e.name == name)
