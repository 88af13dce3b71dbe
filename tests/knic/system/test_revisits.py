"""The role's revisits in a run: a free companion goes back to look where the role says, from beliefs only."""

from __future__ import annotations

from typing import cast

from core.robot import NavState, NavStatus, Robot
from knic.kgm2.attention import Revisits, RoomView
from knic.kgm2.roles import Revisit
from knic.system import KnicSystem, RunConfig
from knic.system.loop import RunLoop
from knic.system.revisits import RevisitDriver, dispatcher_free
from knowledge_base import BeliefStatus, Fact
from planner.dispatch import Dispatcher
from planner.trace import EventKind, Trace, TraceEvent
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


class FakeBase:
    """A base whose goals end as told: ``outcome`` (None: the status lags, still showing the last goal)."""

    def __init__(self) -> None:
        self.goals: list[tuple[float, float]] = []
        self.outcome: NavState | None = NavState.FAILED
        self.stops = 0
        self.pans: list[float] = []

    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        self.goals.append((x, y))
        return len(self.goals)

    def nav_status(self) -> NavStatus:
        if self.outcome is None:
            return NavStatus(goal_id=len(self.goals) - 1, state=NavState.SUCCEEDED)
        return NavStatus(goal_id=len(self.goals), state=self.outcome)

    def stop(self) -> None:
        self.stops += 1

    def pan_camera(self, angle: float) -> None:
        self.pans.append(angle)


def test_a_failed_trip_sends_the_room_to_the_back_and_a_lagging_status_is_waited_for() -> None:
    kb = erl_kb(SimClock(), goals=[])
    rooms = {"bedroom": RoomView((1.0, 1.0), (2.0, 2.0)), "kitchen": RoomView((5.0, 5.0), (6.0, 6.0))}
    policy = Revisits(kb, Revisit(rooms=("bedroom", "kitchen")), rooms)
    base, trace, free = FakeBase(), Trace(), [True]
    driver = RevisitDriver(cast("Robot", base), policy, lambda: free[0], trace, idle_before_s=1.0)
    for k in range(6):  # 0.0 .. 1.0 s: free for idle_before_s, then the first trip (it fails at once)
        driver.step(0.2 * k)
    assert base.goals == [(1.0, 1.0)]
    driver.step(1.2)  # the failure is seen: event, bedroom to the back of the queue, a pause
    assert [e.action for e in trace.events] == ["revisit", "revisit failed"]
    driver.step(1.4)
    assert base.goals == [(1.0, 1.0)]  # pausing
    base.outcome = None  # the next trip is not reported yet by the robot
    for k in range(8):
        driver.step(2.4 + 0.2 * k)
    assert base.goals == [(1.0, 1.0), (5.0, 5.0)]  # the kitchen, once, while the status lags
    free[0] = False
    base.outcome = NavState.ACTIVE
    driver.step(4.2)  # a goal arrived: the trip under way is stopped
    assert base.stops == 1 and trace.events[-1].action == "revisit interrupted"
