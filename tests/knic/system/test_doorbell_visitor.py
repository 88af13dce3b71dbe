"""The door-bell visitor of the ERL apartment is a stranger: met after the bell, a new instance."""

from __future__ import annotations

import math

from knic.system import KnicSystem, RunConfig
from knic.system.granny_annie import GrannyAnnieFlow
from knic.system.loop import RunLoop
from knowledge_base import BeliefStatus, Change, ChangeKind
from planner.trace import EventKind, TraceEvent
from worlds.api import load_world
from worlds.scenario import scenario_from_dict

BELL_AT = 10.0


def test_the_visitor_is_unknown_until_seen_after_the_bell_then_becomes_visitor_1() -> None:
    world = load_world("erl_home")
    assert not world.people["jack"].known and world.people["tracy"].known and world.people["annie"].known
    scenario = scenario_from_dict(
        {
            "name": "bell",
            "description": "the visitor rings and waits just inside the front door",
            "events": [
                {"at": BELL_AT, "type": "doorbell", "visitor": "jack", "enter_after": 3, "enter": False}
            ],
        },
        world,
    )
    role = "service_semi_autonomous"  # door bell reaction: tell Annie; no revisits (the robot stays put)
    with KnicSystem(RunConfig(seed=0, role=role, scenario=scenario)) as system:
        kb = system.kb
        # no preloaded symbol for the visitor: neither his simulator name nor a visitor instance
        assert kb.type_of("jack") is None
        assert sorted(kb.instances("person")) == ["annie", "tracy"]
        events: list[TraceEvent] = []
        system.trace.subscribe(lambda e: events.append(e) if e.kind is EventKind.TASK else None)
        added: list[Change] = []
        kb.subscribe(lambda c: added.append(c) if c.kind is ChangeKind.ADD_INSTANCE else None)
        system.add_flow(GrannyAnnieFlow(system, role=role))
        system.sim.navigate_to_point(5.1, 1.3, -math.pi / 2)  # in the entrance hall, facing the front door
        loop: RunLoop[bool] = RunLoop(system.scheduler)
        loop.add_stop(lambda now: True if kb.facts("person_at", "visitor_1") else None)
        end = loop.run(60.0)

        assert end.stop, "the robot never met the visitor"
        # one instance made during the run: the visitor, after the bell
        assert [(c.name, c.args) for c in added] == [("person", ("visitor_1",))] and added[0].time > BELL_AT
        assert kb.type_of("visitor_1") == "person" and kb.type_of("jack") is None
        assert kb.holds("person_at", "visitor_1", "entrance_hall")
        prov = kb.why(kb.facts("person_at", "visitor_1")[0])
        assert prov is not None and prov.status is BeliefStatus.OBSERVED and prov.since > BELL_AT
        assert ("person_at", "jack", "entrance_hall") in system.sim.ground_truth_facts()  # it is him
        # the flow heard the bell, reacted as the role says, and noted the visitor by the new instance
        steps = [(e.action, e.data.get("person")) for e in events]
        assert steps[:2] == [("doorbell", None), ("visitor", "visitor_1")]
        said = [u.text for u in system.sim.spoken()]
        assert said == ["Annie, someone rang the door bell.", "Annie, a visitor is in the entrance hall."]
