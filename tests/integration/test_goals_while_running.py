"""Goals at any time: a goal given through the intake while the robot works joins the running plan."""

from __future__ import annotations

import logging

from knic.intake import GoalIntake, Outcome
from knic.system import KnicSystem, RunConfig
from knic.system.names import run_vocabulary
from knic.system.timed import TimedGoals
from planner.trace import EventKind

logging.getLogger("knic.scheduler").setLevel(logging.ERROR)


def test_a_goal_given_while_the_robot_searches_joins_the_plan() -> None:
    with KnicSystem(RunConfig(seed=0, max_sim_time=200.0)) as system:
        intake = GoalIntake(system.kb, run_vocabulary(system), say=system.context.say)
        assert intake.submit("locate the tablet").outcome == Outcome.ADDED
        system.add_flow(TimedGoals(system, intake, [(25.0, "switch on the hallway light")]))
        result = system.run()
        assert result.success, result.reason
        later = [h for h in intake.history if h.submission.text == "switch on the hallway light"]
        assert later[0].outcome == Outcome.ADDED and later[0].time >= 25.0
        achieved = {e.goal: e.time for e in system.trace.of_kind(EventKind.GOAL_ACHIEVED)}
        assert achieved["(light_on hallway_light)"] > 25.0 and "(reported tablet)" in achieved
        # the new goal was planned together with the open one, not after restarting the task from scratch
        plans = system.trace.of_kind(EventKind.PLAN)
        joined = [p for p in plans if p.time >= 25.0 and "(switch_on r2d2 hallway_light)" in (p.plan or ())]
        assert joined and any(step.startswith("(report r2d2 tablet)") for step in joined[0].plan or ())
        assert ("light_on", "hallway_light") in system.sim.ground_truth_facts()
