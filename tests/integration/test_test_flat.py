"""A flat nobody tuned the system for (``worlds/test_flat``: other layout and names, no priors): a fetch
succeeds, and of a possible and an impossible goal the possible one is achieved and the impossible one named
(its item lies in a cellar with no door)."""

from __future__ import annotations

import logging
from pathlib import Path

from knic.intake import GoalIntake, Outcome
from knic.language.vocabulary import Vocabulary
from knic.system import KnicSystem, RunConfig
from planner.trace import EventKind

logging.getLogger("knic.scheduler").setLevel(logging.ERROR)
FLAT = Path(__file__).resolve().parents[2] / "worlds" / "test_flat" / "test_flat.yaml"


def test_fetch_in_a_new_flat_achieves_the_possible_goal_and_names_the_impossible_one() -> None:
    with KnicSystem(RunConfig(world=FLAT, seed=0, max_sim_time=600.0)) as system:
        provenances = [system.kb.why(f) for f in system.kb.facts("possibly_at", "book")]
        assert all(p is not None and p.confidence == 0.0 for p in provenances)  # no priors in this flat
        intake = GoalIntake(
            system.kb, Vocabulary.from_knowledge_base(system.kb, None), say=system.context.say
        )
        for text in ("bring me the book", "bring me the lantern"):
            assert intake.submit(text, speaker="olga").outcome == Outcome.ADDED
        result = system.run()
        assert not result.success  # one goal cannot be reached
        truth = system.sim.ground_truth_facts()
        assert system.kb.holds("has", "olga", "book") and ("has", "olga", "book") in truth
        achieved = [e.goal for e in system.trace.of_kind(EventKind.GOAL_ACHIEVED)]
        dropped = [e.goal for e in system.trace.of_kind(EventKind.GOAL_DROPPED)]
        assert "(has olga book)" in achieved and dropped[-1] == "(has olga lantern)"
        assert result.reason.startswith("goal (has olga lantern) dropped")
        said = [u.text for u in system.sim.spoken()]
        assert any("(has olga lantern)" in s for s in said)  # the robot names what it gave up
        assert ("has", "olga", "lantern") not in truth
