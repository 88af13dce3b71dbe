"""Test doubles for dispatch tests: a simulated clock, scripted actions with fake perception, a stub planner.

Every double satisfies the same type as the real thing (``Action``, ``Planner``) so mypy checks them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

from actions.base import Action, ActionRegistry, ActionStatus
from knowledge_base import BeliefStatus, KnowledgeBase
from planner.engines import Planner
from planner.model import Atom, PlanningTask
from planner.plan import PlanResult, PlanStatus, PlanStep

ROOT = Path(__file__).resolve().parents[2]
ERL_DOMAIN = ROOT / "worlds" / "erl_home" / "domain.pddl"
ERL_PROBLEM = ROOT / "worlds" / "erl_home" / "erl_home_problem.pddl"
PAPER_PROBLEM = ROOT / "worlds" / "erl_home" / "paper_problem.pddl"


class SimClock:
    """Simulated seconds; the test advances it (``tick``) after each dispatcher step."""

    def __init__(self, dt: float = 0.1) -> None:
        self.t = 0.0
        self.dt = dt

    def __call__(self) -> float:
        return self.t

    def tick(self, _: int = 0) -> None:
        self.t += self.dt


def erl_kb(clock: SimClock, problem: Path = ERL_PROBLEM, goals: Iterable[str] | None = None) -> KnowledgeBase:
    """The ERL apartment knowledge base on the simulated clock; ``goals`` replace the problem's goals."""
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, problem, clock=clock)
    if goals is not None:
        kb.clear_goals()
        for text in goals:
            pred, *args = text.strip("()").split()
            kb.add_goal(pred, *args)
    return kb


@dataclass
class World:
    """Ground truth for fake perception and a log of what ran.

    Attributes:
        where: entity -> room where it really is (search actions confirm only these).
        fail: plan steps (as ``(name ...)``) that fail; each listed count is used up one failure at a time.
        never_finish: action names whose step() keeps RUNNING (for timeouts).
        steps_per_action: ticks each action runs before it finishes.
        started: every action started, in order.
    """

    where: dict[str, str] = field(default_factory=dict)
    fail: dict[str, int] = field(default_factory=dict)
    never_finish: set[str] = field(default_factory=set)
    steps_per_action: int = 2
    started: list[str] = field(default_factory=list)


class ScriptedAction(Action):
    """Finishes after ``world.steps_per_action`` steps, or fails when the world says so.

    Search actions play perception (a KP'): on finishing they assert ``found``/``*_at`` when the world puts
    the entity in that room (belief status "observed"), else they retract the candidate ``possibly_at``.
    """

    def __init__(self, name: str, args: tuple[str, ...], kb: KnowledgeBase, world: World) -> None:
        super().__init__(name, args)
        self.kb = kb
        self.world = world
        self.ticks = 0

    def activation(self) -> bool:
        self.world.started.append(str(self))
        return True

    def step(self) -> ActionStatus:
        self.ticks += 1
        if self.name in self.world.never_finish:
            return ActionStatus.RUNNING
        if self.ticks < self.world.steps_per_action:
            return ActionStatus.RUNNING
        key = str(self)
        if self.world.fail.get(key, 0) > 0:
            self.world.fail[key] -= 1
            self.failure_reason = "gripper slipped"
            return ActionStatus.FAILED
        if self.name in ("search_object", "search_person"):
            self._perceive()
        return ActionStatus.SUCCEEDED

    def _perceive(self) -> None:
        _, entity, room = self.args
        pred = "object_at" if self.name == "search_object" else "person_at"
        if self.world.where.get(entity) == room:
            with self.kb.batch():
                self.kb.add_fact("found", entity, source="kp_camera", status=BeliefStatus.OBSERVED)
                self.kb.add_fact(pred, entity, room, source="kp_camera", status=BeliefStatus.OBSERVED)
        else:
            self.kb.remove_fact("possibly_at", entity, room, source="kp_camera", status=BeliefStatus.OBSERVED)


def scripted_registry(kb: KnowledgeBase, world: World) -> ActionRegistry:
    """One :class:`ScriptedAction` factory per action of the knowledge base's domain."""

    def factory_for(name: str) -> Callable[[tuple[str, ...]], Action]:
        return lambda args: ScriptedAction(name, args, kb, world)

    return ActionRegistry({name: factory_for(name) for name in kb.domain.actions})


class StubPlanner:
    """Hands out scripted plans in order (never starts a subprocess); records each task it was given.

    Args:
        plans: one entry per call: a list of ``"(name args)"`` strings, or a ready ``PlanResult``.
        unreachable: goals to report unreachable in every answer.
    """

    def __init__(self, plans: list[list[str] | PlanResult], unreachable: Iterable[Atom] = ()) -> None:
        self.plans = list(plans)
        self.unreachable = tuple(unreachable)
        self.tasks: list[PlanningTask] = []

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        self.tasks.append(task)
        if not self.plans:
            return PlanResult(PlanStatus.UNSOLVABLE, (), task.goals, task.goals, 0.0, "stub")
        entry = self.plans.pop(0)
        if isinstance(entry, PlanResult):
            return entry
        steps = tuple(PlanStep.parse(s) for s in entry)
        unreachable = tuple(g for g in self.unreachable if g in task.goals)
        status = PlanStatus.PARTIAL if unreachable else PlanStatus.SOLVED
        return PlanResult(status, steps, task.goals, unreachable, 0.0, "stub")


def _typed(planner: StubPlanner) -> Planner:
    """mypy checks here that the stub satisfies the planner protocol."""
    return planner
