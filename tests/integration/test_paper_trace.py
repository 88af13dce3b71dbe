"""The paper's trace (seed 004, IV.B) in the four-room apartment, through the whole closed loop.

The robot starts in the bedroom; the glasses lie unseen on the entrance shelf; the goal is to have them in the
bedroom. The robot plans a search over the rooms the glasses may be in, perceives them in the entrance, its
plan breaks, it replans, carries them to the bedroom, and perception confirms them there.
"""

from __future__ import annotations

from knic.system import KnicSystem, RunConfig
from knowledge_base import BeliefStatus, Change, Fact
from planner.trace import EventKind, TraceEvent

GOAL = "(object_at glasses bedroom)"


def test_paper_trace_search_perceive_replan_carry() -> None:
    perceived: list[Change] = []
    with KnicSystem(RunConfig(world="erl_home_paper", seed=0, max_sim_time=300)) as system:
        assert system.kb.holds("robot_at", "r2d2", "bedroom")
        assert not system.kb.facts("object_at", "glasses")  # where the glasses are is unknown ...
        candidates = system.kb.facts("possibly_at", "glasses")
        assert {f.args[1] for f in candidates} == {"kitchen", "entrance", "living_room"}
        assert all(system.kb.why(f).status == BeliefStatus.ASSUMED for f in candidates)  # type: ignore[union-attr]
        system.kb.subscribe(lambda c: perceived.append(c) if c.name == "object_at" else None)
        system.add_goal(GOAL)
        result = system.run()
        truth = system.sim.ground_truth_facts()
        final = system.kb.why(Fact.parse(GOAL))
        events = list(system.trace.events)

    assert result.success, result.reason
    plans = [e for e in events if e.kind == EventKind.PLAN and e.plan]
    # 1. the robot plans a search of the candidate rooms
    assert any(step.startswith("(search_object r2d2 glasses") for step in plans[0].plan or ())
    # 2. perception (a KP', not the dispatcher) locates the glasses in the entrance, as observed
    seen = next(
        c
        for c in perceived
        if c.kind.value == "add_fact"
        and c.args == ("glasses", "entrance")
        and c.provenance.source != "dispatcher"
    )
    assert seen.provenance.status == BeliefStatus.OBSERVED
    # 3. the plan breaks and the robot replans
    assert any(e.kind == EventKind.REPLAN and e.time >= seen.time for e in events)
    # 4. a later plan carries the glasses from the entrance to the bedroom, and it is executed
    later = [p for p in plans if p.time >= seen.time]
    assert any("(pick r2d2 glasses entrance)" in (p.plan or ()) for p in later)
    successes = [e.action or "" for e in events if e.kind == EventKind.SUCCESS]
    picked = successes.index("(pick r2d2 glasses entrance)")
    assert any(a.startswith("(place r2d2 glasses") and a.endswith("bedroom)") for a in successes[picked:])
    assert _achieved(events, GOAL)
    # 5. end state: the ground truth agrees, and perception confirmed the place effect
    assert ("object_at", "glasses", "bedroom") in truth
    assert final is not None and final.status == BeliefStatus.OBSERVED
    assert final.source != "dispatcher"


def _achieved(events: list[TraceEvent], goal: str) -> bool:
    return any(e.kind == EventKind.GOAL_ACHIEVED and e.goal == goal for e in events)
