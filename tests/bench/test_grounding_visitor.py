"""The grounding bench compares a met visitor's instance as the stranger it is in the ground truth."""

from __future__ import annotations

from knic.bench.grounding import _beliefs, _Recorder
from tests.planner.doubles import SimClock, erl_kb


def test_a_met_visitor_is_compared_as_the_stranger_last_in_view() -> None:
    rec = _Recorder(frozenset({"annie", "jack"}), strangers=frozenset({"jack"}))
    rec.bind("visitor_1")  # not seen yet: nobody to bind to
    assert rec.aliases == {}
    rec.seen["jack"] = [3.0, 4.0]
    rec.bind("visitor_1")
    assert rec.aliases == {"visitor_1": "jack"}
    rec.bind("visitor_2")  # the only stranger is taken: a second instance stays unnamed
    assert rec.aliases == {"visitor_1": "jack"}
    kb = erl_kb(SimClock(), goals=[])
    kb.add_instance("person", "visitor_1")
    kb.add_fact("person_at", "visitor_1", "entrance_hall")
    assert ("person_at", "jack", "entrance_hall") in _beliefs(kb, rec)
    assert not any("visitor_1" in fact for fact in _beliefs(kb, rec))
