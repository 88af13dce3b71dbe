"""What one closed-loop run is made of (:class:`RunConfig`) and how it ended (:class:`RunResult`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from collections.abc import Callable

    from core.robot import Robot
    from worlds.scenario import Scenario

#: the PDDL domain of the ERL apartment
DOMAIN = Path(__file__).resolve().parents[2] / "worlds" / "erl_home" / "domain.pddl"

#: simulated seconds each action may run before the dispatcher times it out
ACTION_TIME_LIMITS = {
    "move": 120.0,
    "search_object": 240.0,
    "search_person": 240.0,
    "search_furniture": 240.0,
    "pick_from": 90.0,
    "pick": 90.0,
    "place": 90.0,
    "give": 90.0,
    "meet": 90.0,
    "guide": 150.0,
}


@dataclass
class RunConfig:
    """What one run is made of.

    Attributes:
        world: world name (``erl_home``, ``erl_home_paper``) or world file.
        scenario: scenario name, file or :class:`~worlds.scenario.Scenario`, or None.
        seed: seed of the simulator's random draws.
        role: robot role name (``knic/roles.yaml``).
        max_sim_time: simulated seconds after which the run stops unfinished.
        settle_s: simulated seconds to wait, once the robot believes every goal achieved, for perception to
            confirm the perceivable goal facts as observed.
        journal: SQLite journal file of the knowledge base's history (replaced if it exists), or None.
        trace_stream: text stream receiving the trace as JSON lines, or None.
        gui: open the pybullet GUI.
        check_period_s: simulated seconds between checks of the stop conditions (and calls of check hooks).
        goal_retries: times the recovery policy hands a dropped goal back to the dispatcher
            (:class:`planner.recovery.GoalRetry`): when what the robot knows about the goal's subject
            changed since the drop, or ``retry_after_s`` simulated seconds after it; never cancelling a
            running action.
        retry_after_s: see ``goal_retries`` (infinite by default: only new knowledge brings a goal back).
        give_up_s: simulated seconds the robot stays idle with every open goal dropped before the run stops
            (new knowledge may bring a goal back meanwhile).
        planning_time: how planning time is charged on the simulated clock: ``model`` (a deterministic
            estimate, reproducible under the seed), ``wall`` (the wall time spent) or ``off``
            (:func:`planner.thinking.thinking_seconds`).
        replan_settle_s: simulated seconds planning waits after a knowledge change broke the plan.
        max_replans_per_goal: the recovery policy's replanning budget per goal.
        real_time_factor: the scheduler's overrun budget is period / factor (wall seconds per step).
        dispatch: plan and act (the dispatcher runs); False: perception only (benchmarks drive the robot).
        revisits: under a role with revisit data, the robot goes back to look where the role says while it
            has nothing to do (:mod:`knic.system.revisits`); False: it waits where it is.
        robot_wrapper: wraps the simulator's robot seam before KnIC sees it (fault injection in
            ``knic bench reliability``); None: KnIC talks to the simulator directly.
    """

    world: str | Path = "erl_home"
    scenario: str | Path | Scenario | None = None
    seed: int = 0
    role: str = "companion"
    max_sim_time: float = 600.0
    settle_s: float = 8.0
    journal: Path | None = None
    trace_stream: TextIO | None = None
    gui: bool = False
    check_period_s: float = 0.5
    goal_retries: int = 20
    retry_after_s: float = math.inf
    give_up_s: float = 10.0
    planning_time: str = "model"
    replan_settle_s: float = 0.6
    max_replans_per_goal: int = 12
    real_time_factor: float = 1.0
    dispatch: bool = True
    revisits: bool = True
    robot_wrapper: Callable[[Robot], Robot] | None = None


@dataclass
class RunResult:
    """How a run ended: the robot's own verdict and, when a referee watched, the referee's.

    Attributes:
        success: the referee found every goal holding in the ground truth (without a referee: the robot
            believed every goal achieved).
        reason: one line: why the run stopped and, on failure, what did not hold.
        sim_time: simulated seconds at the end.
        wall_s: wall-clock seconds the run took.
        goals: the goals, as PDDL strings.
        believed_done: the robot believed every goal achieved when the run stopped.
        unmet_in_truth: goals the referee found not holding (empty without a referee).
        unconfirmed: perceivable goal facts perception had not confirmed (status not OBSERVED) at the end.
        plans, replans: counts from the dispatcher.
        counters: the referee's penalty counters (bumps, person_hits, drops), empty without a referee.
    """

    success: bool
    reason: str
    sim_time: float
    wall_s: float
    goals: list[str] = field(default_factory=list)
    believed_done: bool = False
    unmet_in_truth: list[str] = field(default_factory=list)
    unconfirmed: list[str] = field(default_factory=list)
    plans: int = 0
    replans: int = 0
    counters: dict[str, int] = field(default_factory=dict)
