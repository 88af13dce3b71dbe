"""Planning PDDL as people write it: any problem unified-planning reads, through its engines.

The in-process planner (:mod:`planner.engines`) covers typed STRIPS with conjunctive atomic goals, which is
what the knowledge base produces. Problems brought by a user may have goal formulas (``not``, ``or``,
``imply``, ``exists``, ``forall``), conditional and quantified effects, equality, numeric fluents and
durative actions. :func:`solve_problem` plans such a problem with the engine that supports it:

* ``fast-downward`` for classical problems (conditional effects, quantifiers and equality included);
* ``tamer`` for durative actions and numeric fluents; features Tamer lacks (quantified conditions,
  conditional effects) are compiled away with unified-planning's compilers first and the plan mapped back.

Goals are the top-level conjuncts of the problem's goal. When the engine finds no plan for all of them, the
conjuncts are taken goal by goal in the order written: each is kept when a plan exists for it together with
those kept so far, and the others are named as unreachable (a partial plan). Every plan is validated with
unified-planning's validator for its kind (sequential, or time-triggered for temporal plans) against the
goals it claims; a plan that fails is never returned.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from core.errors import PlanningError
from planner.plan import PlanStatus, PlanStep, TimedStep

#: unified-planning compilers that remove a feature an engine lacks: feature -> compilation kind
_COMPILABLE = {
    "EXISTENTIAL_CONDITIONS": "QUANTIFIERS_REMOVING",
    "UNIVERSAL_CONDITIONS": "QUANTIFIERS_REMOVING",
    "CONDITIONAL_EFFECTS": "CONDITIONAL_EFFECTS_REMOVING",
    "DISJUNCTIVE_CONDITIONS": "DISJUNCTIVE_CONDITIONS_REMOVING",
}
_COMPILE_ORDER = ("QUANTIFIERS_REMOVING", "CONDITIONAL_EFFECTS_REMOVING", "DISJUNCTIVE_CONDITIONS_REMOVING")
_NUMERIC = {"NUMERIC_FLUENTS", "INT_FLUENTS", "REAL_FLUENTS"}
_TEMPORAL = {"CONTINUOUS_TIME", "DISCRETE_TIME"}


@dataclass(frozen=True)
class ProblemResult:
    """What :func:`solve_problem` returns (the ``knic plan`` output for general problems).

    Attributes:
        status: solved, partial, unsolvable, timeout or error (see :class:`PlanStatus`).
        plan: the actions in order (start order for temporal plans).
        schedule: for temporal plans, each action with its start time and duration; empty otherwise.
        goals: the top-level goal conjuncts as PDDL text.
        unreachable_goals: the conjuncts the plan does not reach, as PDDL text.
        engine: the engine that planned.
        planning_ms: wall-clock milliseconds, validation included.
        message: a one-line explanation for ERROR.
    """

    status: PlanStatus
    plan: tuple[PlanStep, ...] = ()
    schedule: tuple[TimedStep, ...] = ()
    goals: tuple[str, ...] = ()
    unreachable_goals: tuple[str, ...] = ()
    engine: str = ""
    planning_ms: float = 0.0
    message: str = ""
    stats: dict[str, float] = field(default_factory=dict)

    @property
    def has_plan(self) -> bool:
        """True for SOLVED and PARTIAL."""
        return self.status in (PlanStatus.SOLVED, PlanStatus.PARTIAL)

    def to_json(self) -> dict[str, object]:
        """The ``knic plan --json`` object; temporal plans add ``schedule``."""
        data: dict[str, object] = {
            "status": self.status.value,
            "plan": [s.as_list() for s in self.plan],
            "unreachable_goals": list(self.unreachable_goals),
            "planning_ms": round(self.planning_ms, 3),
            "engine": self.engine,
        }
        if self.schedule:
            data["schedule"] = [t.to_json() for t in self.schedule]
        if self.message:
            data["message"] = self.message
        return data


def problem_features(problem: Any) -> set[str]:
    """The unified-planning ``ProblemKind`` feature names of ``problem``."""
    return set(problem.kind.features)


def is_temporal(problem: Any) -> bool:
    """Whether the problem has durative actions (or other continuous-time features)."""
    return bool(problem_features(problem) & _TEMPORAL)


def default_engine(problem: Any) -> str:
    """``tamer`` for temporal or numeric problems, ``fast-downward`` otherwise."""
    features = problem_features(problem)
    if features & _TEMPORAL or features & _NUMERIC:
        return "tamer"
    return "fast-downward"


def goal_conjuncts(problem: Any) -> list[Any]:
    """The problem's goal as a list of top-level conjuncts (``(and A (and B C))`` -> ``[A, B, C]``)."""
    out: list[Any] = []
    stack = list(reversed(problem.goals))
    while stack:
        node = stack.pop()
        if node.is_and():
            stack.extend(reversed(node.args))
        elif not node.is_true():
            out.append(node)
    return out


def goal_text(node: Any) -> str:
    """A goal expression as PDDL text, e.g. ``(exists (?x - object) (on ?x a))``."""
    from unified_planning.environment import get_environment
    from unified_planning.io.pddl_writer import ConverterToPDDLString

    converter = ConverterToPDDLString(get_environment(), lambda item: str(item.name))
    return str(converter.convert(node))


def solve_problem(problem: Any, *, engine: str = "auto", timeout: float = 60.0) -> ProblemResult:
    """Plan ``problem`` (a unified-planning ``Problem``) for as many of its goal conjuncts as possible.

    Args:
        problem: the problem as parsed; it is not modified.
        engine: ``fast-downward``, ``tamer`` or ``auto`` (see :func:`default_engine`).
        timeout: seconds the engine may take for one call (the command bounds the whole run).

    Raises:
        PlanningError: unknown engine, or the engine cannot take a feature the problem needs (named).
    """
    start = time.perf_counter()
    chosen = default_engine(problem) if engine in ("auto", "knic") else engine
    if chosen not in ("fast-downward", "tamer"):
        raise PlanningError(f"unknown engine {engine!r} for this problem; use fast-downward or tamer")
    conjuncts = goal_conjuncts(problem)
    texts = tuple(goal_text(g) for g in conjuncts)

    def done(status: PlanStatus, plan: Any = None, unreachable: tuple[str, ...] = (), msg: str = "") -> Any:
        steps, schedule = _steps(plan)
        return ProblemResult(
            status, steps, schedule, texts, unreachable, chosen, (time.perf_counter() - start) * 1000.0, msg
        )

    if not conjuncts:
        return done(PlanStatus.SOLVED)
    _check_supported(problem, chosen)
    answer = _plan(problem, conjuncts, chosen, timeout)
    kept = list(range(len(conjuncts)))
    if answer.status == "timeout":
        return done(PlanStatus.TIMEOUT, msg="time limit reached")
    if answer.plan is None and answer.status == "unsolvable" and len(conjuncts) > 1:
        kept, answer = _greedy_subset(problem, conjuncts, chosen, timeout)
    if answer.plan is None:
        if answer.status in ("unsolvable", "empty"):
            return done(PlanStatus.UNSOLVABLE, unreachable=texts)
        if answer.status == "timeout":
            return done(PlanStatus.TIMEOUT, msg="time limit reached")
        return done(PlanStatus.ERROR, msg=f"{chosen}: {answer.status}")
    reason = validate_problem_plan(problem, [conjuncts[i] for i in kept], answer.plan)
    if reason:
        return done(PlanStatus.ERROR, msg=f"plan from {chosen} failed validation: {reason}")
    unreachable = tuple(t for i, t in enumerate(texts) if i not in kept)
    return done(PlanStatus.PARTIAL if unreachable else PlanStatus.SOLVED, answer.plan, unreachable)


@dataclass
class _Answer:
    status: str  # solved, unsolvable, timeout, error text
    plan: Any = None


def _check_supported(problem: Any, engine: str) -> None:
    from unified_planning.shortcuts import get_environment

    try:
        cls = get_environment().factory.engine(engine)
    except Exception as exc:
        raise PlanningError(f"engine {engine!r} is not installed ({exc})") from None
    supported = cls.supported_kind().features
    missing = sorted(f for f in problem_features(problem) if f not in supported and f not in _COMPILABLE)
    if missing:
        raise PlanningError(
            f"engine {engine} cannot plan problem {problem.name}: unsupported feature(s) {', '.join(missing)}"
        )


def _with_goals(problem: Any, goals: list[Any]) -> Any:
    sub = problem.clone()
    sub.clear_goals()
    for g in goals:
        sub.add_goal(g)
    return sub


def _plan(problem: Any, goals: list[Any], engine: str, timeout: float) -> _Answer:
    """One engine call for ``goals``, compiling away features the engine lacks and mapping the plan back."""
    from unified_planning.engines import CompilationKind
    from unified_planning.engines import PlanGenerationResultStatus as S
    from unified_planning.shortcuts import Compiler, OneshotPlanner, get_environment

    task = _with_goals(problem, goals)
    supported = get_environment().factory.engine(engine).supported_kind().features
    kinds = {_COMPILABLE[f] for f in task.kind.features if f not in supported and f in _COMPILABLE}
    maps = []
    for kind in _COMPILE_ORDER:
        if kind in kinds:
            with Compiler(problem_kind=task.kind, compilation_kind=getattr(CompilationKind, kind)) as comp:
                compiled = comp.compile(task, getattr(CompilationKind, kind))
            task = compiled.problem
            maps.append(compiled.map_back_action_instance)
    with OneshotPlanner(name=engine) as planner:
        answer = planner.solve(task, timeout=None if engine == "tamer" else timeout)
    if answer.status == S.TIMEOUT:
        return _Answer("timeout")
    if answer.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY):
        return _Answer("unsolvable")
    if answer.plan is None:
        return _Answer(f"no plan ({answer.status.name})")
    plan = answer.plan
    for back in reversed(maps):
        plan = plan.replace_action_instances(back)
    return _Answer("solved", plan)


def _greedy_subset(problem: Any, goals: list[Any], engine: str, timeout: float) -> tuple[list[int], _Answer]:
    kept: list[int] = []
    best = _Answer("empty")
    for i in range(len(goals)):
        trial = _plan(problem, [goals[j] for j in [*kept, i]], engine, timeout)
        if trial.status == "timeout":
            return kept, trial if not kept else best
        if trial.plan is not None:
            kept.append(i)
            best = trial
    return kept, best


def validate_problem_plan(problem: Any, goals: list[Any], plan: Any) -> str:
    """Why ``plan`` does not reach ``goals`` from ``problem``'s initial state ("" when it does).

    Sequential plans go to unified-planning's sequential validator, time-triggered (temporal) plans to its
    time-triggered validator, which checks concurrent actions against their start, over-all and end
    conditions.
    """
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.shortcuts import PlanValidator

    task = _with_goals(problem, goals)
    timed = hasattr(plan, "timed_actions")
    name = "up_time_triggered_validator" if timed else "sequential_plan_validator"
    with PlanValidator(name=name) as validator:
        result = validator.validate(task, plan)
    if result.status == ValidationResultStatus.VALID:
        return ""
    return str(result.reason or result.status.name).replace("\n", " ")


def _number(value: Any) -> float:
    return float(Fraction(str(value))) if not isinstance(value, (int, float, Fraction)) else float(value)


def _steps(plan: Any) -> tuple[tuple[PlanStep, ...], tuple[TimedStep, ...]]:
    if plan is None:
        return (), ()
    if hasattr(plan, "timed_actions"):
        schedule = tuple(
            TimedStep(
                _number(start),
                PlanStep(ai.action.name, tuple(str(p) for p in ai.actual_parameters)),
                None if dur is None else _number(dur),
            )
            for start, ai, dur in sorted(plan.timed_actions, key=lambda x: x[0])
        )
        return tuple(t.step for t in schedule), schedule
    return tuple(
        PlanStep(ai.action.name, tuple(str(p) for p in ai.actual_parameters)) for ai in plan.actions
    ), ()
