"""The Granny Annie task end to end in the simulated apartment (a short request and the rulebook's chain).

Each test runs one seed; the sweep over seeds is ``knic sweep`` (not a test)."""

from __future__ import annotations

import logging

from knic.intake import GoalIntake, Outcome
from knic.system import KnicSystem, RunConfig
from knic.system.granny_annie import granny_annie_system, understood_right
from knic.system.names import run_vocabulary
from planner.trace import EventKind

logging.getLogger("knic.scheduler").setLevel(logging.ERROR)


def test_call_come_spoken_request_confirmation_actions_report() -> None:
    system, flow, episode = granny_annie_system(1, max_sim_time=200.0)
    with system:
        assert episode.request.text == "switch on the bedroom lights"
        result = system.run()
        steps = [e.action for e in system.trace.of_kind(EventKind.TASK)]
        # call -> come -> ask -> her recording heard -> repeated back and asked -> her yes -> work -> report
        assert steps[0] == "call" and steps[1] == "ask" and steps[2] == "heard"
        assert "intake asked" in steps and "confirmed" in steps and steps[-1] == "done"
        assert steps.index("confirmed") > steps.index("intake asked")
        assert flow.outcome == "done" and result.success, result.reason
        assert understood_right(flow, episode.request.text)
        said = [u.text for u in system.sim.spoken()]
        assert said[0] == "Hello Annie, what can I do for you?"
        assert any(s.startswith("You asked me to switch on") and s.endswith("Is that right?") for s in said)
        assert said[-1] == "Annie, I have done what you asked."
        # the robot's beliefs and the ground truth agree: both lights on, the robot in Annie's room
        truth = system.sim.ground_truth_facts()
        for light in ("bedroom_left_light", "bedroom_right_light"):
            assert system.kb.holds("light_on", light) and ("light_on", light) in truth
        room = "bedroom" if episode.seat == "bed" else "living_room"
        assert ("robot_at", "r2d2", room) in truth
        # her goals were taken while the robot ran, after the call, from her voice
        added = [h for h in flow.intake.history if h.outcome == Outcome.ADDED]
        assert added and added[0].submission.source == "speech" and added[0].time > 2.0


def test_the_rulebook_chain_keeps_the_source_and_succeeds() -> None:
    text = "Locate Tracy, lead her to the bedroom, and bring me an apple from the kitchen cabinet"
    with KnicSystem(RunConfig(seed=0, max_sim_time=300.0)) as system:
        intake = GoalIntake(system.kb, run_vocabulary(system), say=system.context.say)
        reply = intake.submit(text)
        assert reply.outcome == Outcome.ADDED
        assert "(taken_from apple kitchen_cabinet)" in reply.goals
        result = system.run()
        assert result.success, result.reason
        assert system.kb.holds("taken_from", "apple", "kitchen_cabinet")
        assert ("apple", "kitchen_cabinet") in system.referee.taken_from
        truth = system.sim.ground_truth_facts()
        assert ("person_at", "tracy", "bedroom") in truth and ("has", "annie", "apple") in truth
        plans = [step for e in system.trace.of_kind(EventKind.PLAN) for step in e.plan or ()]
        assert any(step.startswith("(pick_from r2d2 apple kitchen_cabinet") for step in plans)
