"""Plans and planning results: the values the planner hands to the dispatcher and the command line."""

from __future__ import annotations

import enum
from collections.abc import Sequence
from dataclasses import dataclass, field

from planner.model import Atom, atom_str


@dataclass(frozen=True)
class PlanStep:
    """One ground action of a plan: PDDL action name and object arguments. ``str()`` is ``(name a b)``."""

    name: str
    args: tuple[str, ...] = ()

    def __str__(self) -> str:
        return "(" + " ".join((self.name, *self.args)) + ")"

    def as_list(self) -> list[str]:
        """``["name", "arg1", ...]`` as in ``knic plan --json``."""
        return [self.name, *self.args]

    @classmethod
    def parse(cls, text: str) -> PlanStep:
        """``"(move r2d2 a b)"`` -> ``PlanStep("move", ("r2d2", "a", "b"))``; ValueError if malformed."""
        body = text.strip()
        if not (body.startswith("(") and body.endswith(")")) or not body[1:-1].split():
            raise ValueError(f"not a plan step: {text!r}")
        name, *args = body[1:-1].split()
        return cls(name, tuple(args))


@dataclass(frozen=True)
class TimedStep:
    """One action of a temporal plan: start time and duration (seconds of plan time; None: instantaneous).

    ``str()`` is the IPC form ``0.000: (name a b) [5.000]``.
    """

    start: float
    step: PlanStep
    duration: float | None = None

    def __str__(self) -> str:
        text = f"{self.start:.3f}: {self.step}"
        return text if self.duration is None else f"{text} [{self.duration:.3f}]"

    def to_json(self) -> dict[str, object]:
        """``{"start": 0.0, "action": ["name", ...], "duration": 5.0}``."""
        return {"start": self.start, "action": self.step.as_list(), "duration": self.duration}


class PlanStatus(enum.StrEnum):
    """How planning ended.

    SOLVED: every goal is reached by the plan. PARTIAL: some goals are unreachable (named in the result) and
    the plan reaches all the others. UNSOLVABLE: no goal can be reached. TIMEOUT: the time limit passed.
    ERROR: the engine failed (message in ``PlanResult.message``).
    """

    SOLVED = "solved"
    PARTIAL = "partial"
    UNSOLVABLE = "unsolvable"
    TIMEOUT = "timeout"
    ERROR = "error"


@dataclass(frozen=True)
class PlanResult:
    """What a planner returns.

    Attributes:
        status: see :class:`PlanStatus`.
        plan: the steps (empty when the goals already hold or nothing is reachable).
        goals: the goals the planner was asked for, as atoms.
        unreachable_goals: goals proven unreachable (or not reachable together with the others), as atoms.
        planning_ms: wall-clock milliseconds spent, grounding and validation included.
        engine: the engine that produced the plan.
        message: a one-line explanation for TIMEOUT and ERROR; for PARTIAL, the conflicts in words.
        conflicts: unreachable goals that are reachable alone but provably never true together with a goal
            the plan reaches, each as ``(goal, the goal it excludes)`` (:mod:`planner.mutex`).
    """

    status: PlanStatus
    plan: tuple[PlanStep, ...] = ()
    goals: tuple[Atom, ...] = ()
    unreachable_goals: tuple[Atom, ...] = ()
    planning_ms: float = 0.0
    engine: str = ""
    message: str = ""
    stats: dict[str, float] = field(default_factory=dict)
    schedule: tuple[TimedStep, ...] = ()
    conflicts: tuple[tuple[Atom, Atom], ...] = ()

    @property
    def has_plan(self) -> bool:
        """True when the plan reaches at least one goal (SOLVED or PARTIAL)."""
        return self.status in (PlanStatus.SOLVED, PlanStatus.PARTIAL)

    @property
    def reachable_goals(self) -> tuple[Atom, ...]:
        """The goals the plan reaches."""
        dropped = set(self.unreachable_goals)
        return tuple(g for g in self.goals if g not in dropped)

    def to_json(self) -> dict[str, object]:
        """The ``knic plan --json`` object."""
        data: dict[str, object] = {
            "status": self.status.value,
            "plan": [s.as_list() for s in self.plan],
            "unreachable_goals": [atom_str(g) for g in self.unreachable_goals],
            "planning_ms": round(self.planning_ms, 3),
            "engine": self.engine,
        }
        if self.schedule:
            data["schedule"] = [t.to_json() for t in self.schedule]
        if self.message:
            data["message"] = self.message
        if self.conflicts:
            data["conflicts"] = {atom_str(g): atom_str(other) for g, other in self.conflicts}
        return data


def steps_from_lists(rows: Sequence[Sequence[str]]) -> tuple[PlanStep, ...]:
    """``[["move", "r2d2", "a", "b"], ...]`` -> plan steps."""
    return tuple(PlanStep(r[0], tuple(r[1:])) for r in rows)
