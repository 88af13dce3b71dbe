"""The role's revisits in a run: a free companion goes back to look where the role says, from beliefs only."""

from __future__ import annotations

from knic.system import KnicSystem, RunConfig
from knic.system.loop import RunLoop
from knic.system.revisits import dispatcher_free
from knowledge_base import BeliefStatus, Fact
from planner.dispatch import Dispatcher
from planner.trace import EventKind, TraceEvent
from tests.planner.doubles import SimClock, StubPlanner, World, erl_kb, scripted_registry


def test_an_idle_companion_revisits_its_rooms_and_refreshes_an_aged_person_belief() -> None:
    with KnicSystem(RunConfig(seed=0, role="companion")) as system:
        assert system.parts.revisits is not None
        events: list[TraceEvent] = []
        system.trace.subscribe(lambda e: events.append(e) if e.kind is EventKind.TASK else None)
        loop: RunLoop[bool] = RunLoop(system.scheduler)
        loop.add_stop(
            lambda now: (
                True
                if any(e.action == "revisited" and e.data.get("why") == "person" for e in events)
                else None
            )
        )
        end = loop.run(150.0)

        assert end.stop, [(e.time, e.action, e.reason) for e in events]
        trips = [e for e in events if e.action == "revisit"]
        # nothing looked at yet: the role's rooms first (bedroom, kitchen, living room weigh twice the others)
        assert trips[0].data == {"room": "bedroom", "why": "room"}
        # Annie, seen on the bed, aged after the role's time to live unseen: the robot went back for her
        back = next(e for e in trips if e.data.get("why") == "person")
        assert back.data == {"room": "bedroom", "why": "person", "person": "annie"}
        looked = next(e for e in events if e.action == "revisited" and e.time > back.time)
        prov = system.kb.why(Fact("person_at", ("annie", "bedroom")))
        assert prov is not None and prov.status is BeliefStatus.OBSERVED and prov.since > back.time
        assert ("robot_at", "r2d2", "bedroom") in system.sim.ground_truth_facts()
        assert looked.data["room"] == "bedroom"


def test_a_role_without_revisit_data_does_not_revisit() -> None:
    with KnicSystem(RunConfig(seed=0, role="service_autonomous")) as system:
        assert system.parts.revisits is None


def test_the_robot_is_free_only_with_nothing_to_work_on() -> None:
    clock = SimClock(dt=0.1)
    kb = erl_kb(clock, goals=[])
    dispatcher = Dispatcher(kb, StubPlanner([]), scripted_registry(kb, World()))
    free = dispatcher_free(kb, dispatcher)
    assert free()  # no goal at all
    kb.add_goal("light_on", "hallway_light")
    assert not free()  # a goal not worked on yet
    for _ in range(5):
        dispatcher.step()
    assert dispatcher.dropped and free()  # dropped (the stub plans nothing): waiting for news
    kb.remove_goal("light_on", "hallway_light")
    kb.add_goal("light_off", "hallway_light")
    assert kb.holds("light_off", "hallway_light") and not free()  # every goal holds: the robot stays
