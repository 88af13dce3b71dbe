"""Planning engines and the planner the dispatcher and the command line use.

Engines (:data:`ENGINES`):

``knic``
    In-process: grounding with relevance pruning (:mod:`planner.grounding`) and greedy best-first search with
    the FF heuristic (:mod:`planner.search`). Typed STRIPS with negative preconditions only. No subprocess, no
    files: a replan on the seven-room apartment takes milliseconds.
``fast-downward``
    Fast Downward through unified-planning (``lama-first``), on the object-focused task.
``tamer``
    Tamer through unified-planning, for durative (temporal) domains.
``auto`` (default)
    Chosen by what the problem needs: ``tamer`` for durative actions; ``knic`` for the STRIPS fragment with
    ``fast-downward`` as fall-back when the in-process search reaches its node limit; ``fast-downward`` for
    any other classical feature it supports. When no installed engine supports the problem,
    :class:`~core.errors.PlanningError` names the missing features.

When not all goals can be reached, the planner returns a plan for the reachable ones and names the others
(:attr:`PlanResult.unreachable_goals`): goals outside the relaxed-reachable atoms are provably unreachable;
a goal that can never hold together with an earlier goal (pairwise reachability, :mod:`planner.mutex`) is
set aside and named with the goal it excludes (:attr:`PlanResult.conflicts`), so no search has to exhaust
the state space to find out; if the rest still cannot be reached together, a greedy oversubscription keeps
the largest set found goal by goal (in-process), or unified-planning's ``oversubscription[fast-downward]``
meta-engine picks it.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import Any, Protocol

from core.errors import PlanningError
from planner.grounding import GroundedTask, GroundingCache, ground_task
from planner.model import Atom, PlanningTask, atom_str
from planner.mutex import compatible_goals, pair_reachability
from planner.plan import PlanResult, PlanStatus, PlanStep, TimedStep
from planner.problem import focus_task, task_to_up
from planner.search import SearchLimitReached, StripsSearch
from planner.validate import check_plan, check_schedule, validate_with_up

ENGINES = ("auto", "knic", "fast-downward", "tamer")
_UP_NAMES = {"fast-downward": "fast-downward", "tamer": "tamer"}
QUICK_EVALUATIONS = 20  # states the first all-goals-at-once try may evaluate


class Planner(Protocol):
    """What the dispatcher needs from a planner (the real :class:`TaskPlanner` and test stubs satisfy it)."""

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        """Plan for ``task.goals`` from ``task.facts``; never raises for unsolvable tasks (see PlanStatus)."""
        ...


def silence_up() -> None:
    """Switch off unified-planning's credits banner (printed on stdout otherwise)."""
    from unified_planning.shortcuts import get_environment

    get_environment().credits_stream = None


def unsupported_features(up_problem: Any, engine: str) -> list[str]:
    """The features of ``up_problem`` (unified-planning ``ProblemKind`` names) that ``engine`` lacks.

    Raises:
        PlanningError: the engine is not installed.
    """
    from unified_planning.shortcuts import get_environment

    try:
        cls = get_environment().factory.engine(_UP_NAMES[engine])
    except KeyError as exc:
        raise PlanningError(f"engine {engine!r} is not installed (unified-planning has no {exc})") from exc
    supported = cls.supported_kind()
    return sorted(f for f in up_problem.kind.features if f not in supported.features)


def choose_engine(task: PlanningTask, requested: str = "auto", up_problem: Any = None) -> str:
    """The engine for ``task``: ``requested`` when it can take the task, else the ``auto`` choice.

    Raises:
        PlanningError: unknown engine name, or the engine (or every engine, for ``auto``) lacks a feature the
            task needs; the message names the features.
    """
    if requested not in ENGINES:
        raise PlanningError(f"unknown engine {requested!r}; choose one of {', '.join(ENGINES)}")
    dom = task.domain
    if requested == "knic":
        if dom.unsupported or dom.temporal:
            why = dom.unsupported or "durative actions"
            raise PlanningError(f"engine knic cannot plan domain {dom.name}: unsupported feature {why}")
        return "knic"
    if requested in _UP_NAMES:
        if up_problem is not None:
            missing = unsupported_features(up_problem, requested)
            if missing:
                features = ", ".join(missing)
                raise PlanningError(
                    f"engine {requested} cannot plan domain {dom.name}: unsupported feature(s) {features}"
                )
        return requested
    if dom.temporal:
        return choose_engine(task, "tamer", up_problem)
    if dom.unsupported is None:
        return "knic"
    return choose_engine(task, "fast-downward", up_problem)


class TaskPlanner:
    """The planner: engine choice, object focus, oversubscription, validation of every plan.

    Args:
        up_domain: the unified-planning domain problem (``kb.domain.up_domain``, or a parsed PDDL problem);
            needed only for the unified-planning engines.
        engine: one of :data:`ENGINES`.
        timeout: default planning time limit in wall-clock seconds.
        focus: plan the object-focused task first (see :mod:`planner.problem`).
        node_limit: states the in-process search may expand before falling back to Fast Downward.

    Every returned plan has been checked with :func:`planner.validate.check_plan` against the *full* task;
    a plan that fails the check is never returned (status ERROR with the reason).
    """

    def __init__(
        self,
        up_domain: Any = None,
        *,
        engine: str = "auto",
        timeout: float = 30.0,
        focus: bool = True,
        node_limit: int = 50_000,
    ) -> None:
        if engine not in ENGINES:
            raise PlanningError(f"unknown engine {engine!r}; choose one of {', '.join(ENGINES)}")
        self.up_domain = up_domain
        self.engine = engine
        self.timeout = timeout
        self.focus = focus
        self.node_limit = node_limit
        self.cache = GroundingCache()

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        """Plan for ``task``; see the class docstring. Raises PlanningError only for unsupported features."""
        start = time.perf_counter()
        limit = self.timeout if timeout is None else timeout
        if not task.goals:  # nothing asked: the empty plan reaches every goal
            return PlanResult(PlanStatus.SOLVED, (), (), (), 0.0, self.engine)
        engine = choose_engine(
            task, self.engine, self._up_problem(task) if self.engine in _UP_NAMES else None
        )
        if engine == "knic":
            result = self._solve_knic(task, start + limit)
        else:
            result = self._solve_up(task, engine, limit)
        if result.has_plan:
            reason = self._invalid(task, result)
            if reason:
                result = PlanResult(
                    PlanStatus.ERROR,
                    (),
                    task.goals,
                    (),
                    0.0,
                    result.engine,
                    f"plan from {result.engine} failed validation: {reason}",
                )
        return PlanResult(
            result.status,
            result.plan,
            task.goals,
            result.unreachable_goals,
            (time.perf_counter() - start) * 1000.0,
            result.engine,
            result.message,
            result.stats,
            result.schedule,
            result.conflicts,
        )

    def _invalid(self, task: PlanningTask, result: PlanResult) -> str:
        """Why ``result.plan`` is not valid for the full task ("" when valid)."""
        if task.domain.unsupported is None:
            if result.schedule:  # a temporal plan: actions may overlap
                check = check_schedule(
                    task.domain, task.facts, result.schedule, result.reachable_goals, task.objects
                )
            else:
                check = check_plan(task.domain, task.facts, result.plan, result.reachable_goals, task.objects)
            return check.reason
        full = PlanningTask(task.domain, task.objects, task.facts, result.reachable_goals)
        valid, reason = validate_with_up(task_to_up(full, self.up_domain), result.plan, result.schedule)
        return "" if valid else reason

    def _up_problem(self, task: PlanningTask) -> Any:
        if self.up_domain is None:
            raise PlanningError("unified-planning engines need the domain: pass up_domain to TaskPlanner")
        return task_to_up(focus_task(task) if self.focus else task, self.up_domain)

    # -- in-process -------------------------------------------------------------------------------------
    def _solve_knic(self, task: PlanningTask, deadline: float) -> PlanResult:
        attempts = [focus_task(task), task] if self.focus else [task]
        result = PlanResult(PlanStatus.UNSOLVABLE, goals=task.goals, unreachable_goals=task.goals)
        for sub in attempts:
            try:
                result = self._search(sub, deadline)
            except SearchLimitReached as exc:
                if exc.timeout:
                    return PlanResult(PlanStatus.TIMEOUT, goals=task.goals, engine="knic", message=str(exc))
                if self.up_domain is None:
                    return PlanResult(PlanStatus.ERROR, goals=task.goals, engine="knic", message=str(exc))
                return self._solve_up(task, "fast-downward", max(deadline - time.perf_counter(), 1.0))
            if result.status == PlanStatus.SOLVED or sub is task:
                return result
        return result

    def _search(self, task: PlanningTask, deadline: float) -> PlanResult:
        grounded = self.cache.ground(task)
        search = StripsSearch(grounded.actions, task.facts)
        unreachable = list(grounded.unreachable_goals)
        wanted = [g for g in task.goals if g not in set(unreachable)]
        steps, wanted, conflicts = self._solve_all(search, grounded, wanted, deadline)
        unreachable = [g for g in task.goals if g in set(unreachable) or g in conflicts]
        if steps is None and wanted:
            steps, wanted = self._greedy_subset(search, wanted, deadline)
            unreachable = [g for g in task.goals if g not in set(wanted)]
        stats = {
            "ground_actions": float(grounded.generated),
            "relevant_actions": float(len(grounded.actions)),
            "objects": float(len(task.objects)),
        }
        plan = tuple(PlanStep(a.name, a.args) for a in steps or [])
        if not wanted:
            status = PlanStatus.UNSOLVABLE if task.goals else PlanStatus.SOLVED
        else:
            status = PlanStatus.PARTIAL if unreachable else PlanStatus.SOLVED
        clashes = tuple(conflicts.items())
        return PlanResult(
            status,
            plan,
            task.goals,
            tuple(unreachable),
            0.0,
            "knic",
            _clash_text(clashes),
            stats,
            (),
            clashes,
        )

    def _solve_all(
        self, search: StripsSearch, grounded: GroundedTask, goals: list[Atom], deadline: float
    ) -> tuple[list[Any] | None, list[Atom], dict[Atom, Atom]]:
        """All goals at once on a small budget; failing that, set aside the goals that can never hold together
        with an earlier one (:mod:`planner.mutex`), then goal by goal (FF's goal agenda), then all at once.

        The small first try keeps plans short where that is easy (interleaving goals) and skips the pair
        analysis; the goal agenda is what makes long navigation tasks with several goals fast. Without the
        pair analysis a search for two goals that exclude each other exhausts the whole state space.

        Returns:
            ``(steps, goals kept, conflicts)``; steps ``None`` means the kept goals are unreachable together.

        Raises:
            SearchLimitReached: the node budget ran out (the caller falls back to Fast Downward) or timeout.
        """
        conflicts: dict[Atom, Atom] = {}
        if len(goals) >= 2:
            try:
                quick = search.solve(goals, QUICK_EVALUATIONS, deadline)
                if quick is not None:
                    return quick, goals, conflicts
            except SearchLimitReached as exc:
                if exc.timeout:
                    raise
            goals, conflicts = _compatible(grounded, goals)
        if len(goals) >= 2:
            serial = search.solve_serially(goals, self.node_limit, deadline)
            if serial is not None:
                return serial, goals, conflicts
        return search.solve(goals, self.node_limit, deadline), goals, conflicts

    def _greedy_subset(
        self, search: StripsSearch, goals: list[Atom], deadline: float
    ) -> tuple[list[Any] | None, list[Atom]]:
        chosen: list[Atom] = []
        steps: list[Any] | None = None
        for goal in goals:
            trial = search.solve([*chosen, goal], self.node_limit, deadline)
            if trial is not None:
                chosen.append(goal)
                steps = trial
        return steps, chosen

    # -- unified-planning engines ----------------------------------------------------------------------
    def _solve_up(self, task: PlanningTask, engine: str, timeout: float) -> PlanResult:
        from unified_planning.engines import PlanGenerationResultStatus as S
        from unified_planning.model.metrics import Oversubscription
        from unified_planning.shortcuts import OneshotPlanner

        silence_up()
        focus = self.focus
        unreachable: list[Atom] = []
        conflicts: dict[Atom, Atom] = {}
        if not task.domain.unsupported and not task.domain.temporal:
            # what is unreachable is judged on the whole task (the focus may drop an object a goal needs)
            grounded = ground_task(task)
            unreachable = list(grounded.unreachable_goals)
            kept, conflicts = _compatible(grounded, [g for g in task.goals if g not in set(unreachable)])
            unreachable = [g for g in task.goals if g in set(unreachable) or g in conflicts]
            if focus:
                focused = ground_task(focus_task(task))
                if any(g in focused.unreachable_goals for g in kept) or _compatible(focused, kept)[1]:
                    focus = False  # the focus dropped an object some goal needs (typical of untyped domains)
        problem = task_to_up(focus_task(task) if focus else task, self.up_domain)
        wanted = [g for g in task.goals if g not in set(unreachable)]
        if not wanted:
            return PlanResult(PlanStatus.UNSOLVABLE, (), task.goals, task.goals, 0.0, engine)
        problem.clear_goals()
        for g in wanted:
            problem.add_goal(problem.fluent(g[0])(*(problem.object(a) for a in g[1:])))
        with OneshotPlanner(name=_UP_NAMES[engine]) as planner:
            answer = planner.solve(problem, timeout=None if engine == "tamer" else timeout)
        if answer.status == S.TIMEOUT:
            return PlanResult(
                PlanStatus.TIMEOUT, goals=task.goals, engine=engine, message="time limit reached"
            )
        if answer.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY) and len(wanted) > 1:
            metric_goals = {problem.fluent(g[0])(*(problem.object(a) for a in g[1:])): 1 for g in wanted}
            problem.clear_goals()
            problem.add_quality_metric(Oversubscription(metric_goals))
            with OneshotPlanner(name=f"oversubscription[{_UP_NAMES[engine]}]") as planner:
                answer = planner.solve(problem, timeout=None if engine == "tamer" else timeout)
        if answer.plan is None:
            if answer.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY):
                return PlanResult(PlanStatus.UNSOLVABLE, (), task.goals, task.goals, 0.0, engine)
            return PlanResult(
                PlanStatus.ERROR, goals=task.goals, engine=engine, message=str(answer.status.name)
            )
        steps = plan_from_up(answer.plan)
        schedule = schedule_from_up(answer.plan)
        final = None
        if not task.domain.unsupported:
            if schedule:
                final = check_schedule(task.domain, task.facts, schedule, (), None).final
            else:
                final = check_plan(task.domain, task.facts, steps, (), None).final
        if final is not None:
            unreachable += [g for g in wanted if g not in final]
        status = PlanStatus.PARTIAL if unreachable else PlanStatus.SOLVED
        clashes = tuple(conflicts.items())
        return PlanResult(
            status,
            steps,
            task.goals,
            tuple(unreachable),
            0.0,
            engine,
            _clash_text(clashes),
            schedule=schedule,
            conflicts=clashes,
        )


def _compatible(grounded: GroundedTask, goals: list[Atom]) -> tuple[list[Atom], dict[Atom, Atom]]:
    """The goals that may hold together (in order) and those excluded by an earlier one (h^2, see
    :mod:`planner.mutex`); a single goal needs no check."""
    if len(goals) < 2:
        return goals, {}
    return compatible_goals(goals, pair_reachability(grounded.actions, grounded.task.facts))


def _clash_text(clashes: tuple[tuple[Atom, Atom], ...]) -> str:
    """``"(a) can never hold together with (b)"`` for each conflict, joined by ``"; "``."""
    return "; ".join(f"{atom_str(g)} can never hold together with {atom_str(o)}" for g, o in clashes)


def plan_from_up(plan: Any) -> tuple[PlanStep, ...]:
    """A unified-planning sequential (or time-triggered) plan as plan steps."""
    timed = hasattr(plan, "timed_actions")
    actions: Sequence[Any] = [ai for _, ai, _ in plan.timed_actions] if timed else plan.actions
    return tuple(PlanStep(ai.action.name, tuple(str(p) for p in ai.actual_parameters)) for ai in actions)


def schedule_from_up(plan: Any) -> tuple[TimedStep, ...]:
    """The start times and durations of a unified-planning time-triggered plan (empty for other plans)."""
    if not hasattr(plan, "timed_actions"):
        return ()
    return tuple(
        TimedStep(
            float(start),
            PlanStep(ai.action.name, tuple(str(p) for p in ai.actual_parameters)),
            None if dur is None else float(dur),
        )
        for start, ai, dur in sorted(plan.timed_actions, key=lambda x: x[0])
    )


def goal_names(goals: Sequence[Atom]) -> list[str]:
    """Goals as PDDL text, for messages and JSON."""
    return [atom_str(g) for g in goals]
