"""The planning system: problems from the knowledge base, planning, validation, dispatch, replanning, trace.

Modules (the architecture):

* :mod:`planner.model` -- the planner's view of PDDL (STRIPS schemas, ground atoms); the one conversion
  boundary to and from unified-planning (``domain_from_up``, ``task_from_up``; ``problem.task_to_up``).
* :mod:`planner.problem` -- ``task_from_kb`` (knowledge base -> :class:`PlanningTask`), object focusing
  (relevance pruning), ``task_to_up``, ``load_pddl``.
* :mod:`planner.grounding` / :mod:`planner.search` -- in-process grounding with relevance analysis and a
  grounding cache, and lazy greedy best-first search with the FF heuristic.
* :mod:`planner.mutex` -- pairwise reachability (h^2): goals that can never hold together, named before any
  search.
* :mod:`planner.engines` -- :class:`Planner` (the protocol), :class:`TaskPlanner` (engine choice: in-process,
  Fast Downward, Tamer; oversubscription; validation), ``choose_engine``.
* :mod:`planner.validate` -- ``check_plan`` (fast, independent) and ``validate_with_up``.
* :mod:`planner.dispatch` -- :class:`Dispatcher`, the steppable dispatch loop (seed 004, Algorithm 1): a
  state machine over :mod:`planner.executor` (one action, its PDDL checks and time limit),
  :mod:`planner.monitor` (the plan against the knowledge base) and :mod:`planner.goals` (active, achieved
  and dropped goals, goal retries).
* :mod:`planner.recovery` -- :class:`RecoveryPolicy`, what to do after each outcome and when a dropped goal
  comes back, as data.
* :mod:`planner.trace` -- :class:`Trace` and :class:`TraceEvent`.

Using the dispatcher in a closed loop (one thread, simulated time)::

    from actions import ActionRegistry
    from knowledge_base import KnowledgeBase
    from planner import Dispatcher, TaskPlanner, Trace

    kb = KnowledgeBase.from_pddl("worlds/erl_home/domain.pddl", "worlds/erl_home/erl_home_problem.pddl")
    kb.set_clock(sim.time)                                   # the dispatcher's time base is kb.now()
    registry = ActionRegistry({"move": lambda args: Move(robot, *args), ...})   # factory(args) -> Action
    trace = Trace(jsonl=open("run.jsonl", "w"))               # optional JSON lines
    trace.print_to(sys.stdout)                                # optional readable lines
    dispatcher = Dispatcher(kb, TaskPlanner(kb.domain.up_domain), registry, trace=trace,
                            time_limit=120.0, time_limits={"move": 300.0})
    scheduler.add(dispatcher.step, hz=10)                    # or: while ...: dispatcher.step(); sim.step()

Dispatcher API:

* ``step() -> DispatcherState`` -- one bounded unit of work per call: notice knowledge-base changes (replan
  only when the goals changed or the rest of the plan no longer reaches them), plan if needed (validated),
  then start the next action (at-start check, ``activation()``) or advance the running one (time limit,
  over-all check, ``step()``; at the end ``deactivation()``, at-end check, effects written with belief
  status "effect" and source "dispatcher", sensed effects checked). Returns ``EXECUTING`` while goals are
  pending, ``IDLE`` when every goal is achieved or dropped (new goals wake it up), ``STOPPED`` after
  :meth:`Dispatcher.cancel`. ``tick(now)`` is an alias.
* ``run(max_ticks=10_000, on_tick=None) -> DispatchReport`` -- blocking convenience for tests and scripts.
* ``cancel(reason)``, ``close()`` (unsubscribe from the knowledge base), ``report()``.
* State to read: ``plan`` (tuple of :class:`PlanStep`), ``index`` (next step), ``current`` (running action
  or None), ``achieved`` and ``dropped`` (goal -> reason), ``last_result`` (the last :class:`PlanResult`).
* Every action ending has an :class:`actions.Outcome`: succeeded, precondition failure, activation failure,
  execution failure, timeout, deactivation failure, postcondition failure, cancelled. The
  :class:`RecoveryPolicy` maps each failure outcome to retry N times, then replan or drop the goal; each goal
  may cause at most ``max_replans_per_goal`` replans before it is dropped, so the loop never spins forever.
* Trace events (``EventKind``): plan, dispatch, activation, success, failure (with outcome and reason),
  replan (with reason), goal_achieved, goal_dropped (with reason); each with the clock time.

Planner API: ``Planner.solve(task, *, timeout=None) -> PlanResult`` where :class:`PlanResult` has ``status``
(solved, partial, unsolvable, timeout, error), ``plan``, ``unreachable_goals`` (named), ``planning_ms``,
``engine``. Test doubles implement the same :class:`Planner` protocol.
"""

from planner.dispatch import Dispatcher, DispatcherState, DispatchReport
from planner.engines import ENGINES, Planner, TaskPlanner, choose_engine
from planner.model import PlanningTask
from planner.plan import PlanResult, PlanStatus, PlanStep
from planner.problem import task_from_kb
from planner.recovery import Recovery, RecoveryPolicy, RecoveryRule
from planner.trace import EventKind, Trace, TraceEvent
from planner.validate import check_plan, validate_with_up

__all__ = [
    "ENGINES",
    "DispatchReport",
    "Dispatcher",
    "DispatcherState",
    "EventKind",
    "PlanResult",
    "PlanStatus",
    "PlanStep",
    "Planner",
    "PlanningTask",
    "Recovery",
    "RecoveryPolicy",
    "RecoveryRule",
    "TaskPlanner",
    "Trace",
    "TraceEvent",
    "check_plan",
    "choose_engine",
    "task_from_kb",
    "validate_with_up",
]
