"""Dispatch loop: trace events and the final knowledge base after failures, changes and impossible goals."""

from __future__ import annotations

from actions.base import Outcome
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from planner.dispatch import Dispatcher, DispatcherState
from planner.engines import TaskPlanner
from planner.model import PlanningTask
from planner.plan import PlanResult, PlanStatus
from planner.recovery import GoalRetry, Recovery, RecoveryPolicy, RecoveryRule
from planner.trace import EventKind, Trace
from tests.planner.doubles import PAPER_PROBLEM, SimClock, StubPlanner, World, erl_kb, scripted_registry


def dispatcher(
    kb: KnowledgeBase, world: World, planner: object | None = None, **kwargs: object
) -> Dispatcher:
    real = planner if planner is not None else TaskPlanner(engine="knic")
    return Dispatcher(kb, real, scripted_registry(kb, world), trace=Trace(), **kwargs)  # type: ignore[arg-type]


def kinds(d: Dispatcher) -> list[str]:
    return [e.kind.value for e in d.trace.events]


def test_plan_runs_and_effects_are_written_with_effect_status() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World())
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert report.state == DispatcherState.IDLE
    assert report.achieved == ["(robot_at r2d2 kitchen)"]
    assert kb.holds("robot_at", "r2d2", "kitchen") and not kb.holds("robot_at", "r2d2", "entrance_hall")
    prov = kb.why(Fact("robot_at", ("r2d2", "kitchen")))
    assert prov is not None and prov.status == BeliefStatus.EFFECT and prov.source == "dispatcher"
    assert kinds(d) == [
        "plan",
        "dispatch",
        "activation",
        "success",
        "dispatch",
        "activation",
        "success",
        "goal_achieved",
    ]
    assert d.trace.events[0].plan == ("(move r2d2 entrance_hall hallway)", "(move r2d2 hallway kitchen)")


def test_execution_failure_leads_to_replan_and_goal_is_reached() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(object_at mug bedroom)"])
    kb.add_fact("object_at", "mug", "kitchen", status=BeliefStatus.OBSERVED, source="kp_camera")
    kb.add_fact("found", "mug", status=BeliefStatus.OBSERVED, source="kp_camera")
    world = World(fail={"(pick r2d2 mug kitchen)": 1})
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.REPLAN)})
    d = dispatcher(kb, world, policy=policy)
    report = d.run(max_ticks=300, on_tick=clock.tick)
    failures = d.trace.of_kind(EventKind.FAILURE)
    assert [(f.action, f.outcome) for f in failures] == [("(pick r2d2 mug kitchen)", "execution failure")]
    replans = d.trace.of_kind(EventKind.REPLAN)
    assert len(replans) == 1 and replans[0].reason == "execution failure of (pick r2d2 mug kitchen)"
    assert world.started.count("(pick r2d2 mug kitchen)") == 2
    assert report.achieved == ["(object_at mug bedroom)"] and report.dropped == {}
    assert kb.holds("object_at", "mug", "bedroom") and kb.holds("hand_empty", "r2d2")


def test_retry_policy_retries_the_same_action_without_replanning() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    world = World(fail={"(switch_on r2d2 hallway_light)": 2})
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(2, Recovery.REPLAN)})
    d = dispatcher(kb, world, policy=policy)
    d.run(max_ticks=100, on_tick=clock.tick)
    assert len(d.trace.of_kind(EventKind.FAILURE)) == 2
    assert d.trace.of_kind(EventKind.REPLAN) == []
    assert kb.holds("light_on", "hallway_light") and not kb.holds("light_off", "hallway_light")


def test_door_closed_under_a_running_plan_leads_to_a_replan_around_it() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(steps_per_action=3))

    def close_door(tick: int) -> None:
        clock.tick()
        if tick == 2:  # first move is running: the hallway-kitchen door is found closed
            kb.remove_fact("connected", "hallway", "kitchen", source="kp_door", status=BeliefStatus.OBSERVED)

    report = d.run(max_ticks=300, on_tick=close_door)
    replans = d.trace.of_kind(EventKind.REPLAN)
    assert len(replans) == 1
    assert replans[0].reason is not None and "knowledge change breaks the plan" in replans[0].reason
    assert "(connected hallway kitchen)" in replans[0].reason
    cancelled = [e for e in d.trace.of_kind(EventKind.FAILURE) if e.outcome == "cancelled"]
    assert [e.action for e in cancelled] == ["(move r2d2 entrance_hall hallway)"]
    second = d.trace.of_kind(EventKind.PLAN)[1].plan
    assert second is not None and "(move r2d2 dining_room kitchen)" in second
    assert report.achieved == ["(robot_at r2d2 kitchen)"]
    assert kb.holds("robot_at", "r2d2", "kitchen")


def test_change_that_keeps_the_plan_valid_does_not_replan() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(steps_per_action=3))

    def perceive(tick: int) -> None:
        clock.tick()
        if tick == 2:
            kb.add_fact("person_at", "jack", "bathroom", source="kp_people", status=BeliefStatus.OBSERVED)

    d.run(max_ticks=300, on_tick=perceive)
    assert d.trace.of_kind(EventKind.REPLAN) == []
    assert kb.holds("robot_at", "r2d2", "kitchen")


def test_impossible_goal_is_dropped_by_name_and_the_others_achieved() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(has annie tissues)", "(light_on hallway_light)", "(robot_at r2d2 bathroom)"])
    d = dispatcher(kb, World())
    report = d.run(max_ticks=300, on_tick=clock.tick)
    dropped = d.trace.of_kind(EventKind.GOAL_DROPPED)
    assert [e.goal for e in dropped] == ["(has annie tissues)"]
    assert report.dropped.keys() == {"(has annie tissues)"}
    assert report.achieved == ["(light_on hallway_light)", "(robot_at r2d2 bathroom)"]
    assert kb.holds("light_on", "hallway_light") and kb.holds("robot_at", "r2d2", "bathroom")
    assert report.state == DispatcherState.IDLE


def test_unconfirmed_sensing_is_a_postcondition_failure_and_the_search_goes_on() -> None:
    clock = SimClock()
    kb = erl_kb(clock, problem=PAPER_PROBLEM)
    world = World(where={"glasses": "entrance"})
    d = dispatcher(kb, world)
    report = d.run(max_ticks=500, on_tick=clock.tick)
    post = [e for e in d.trace.of_kind(EventKind.FAILURE) if e.outcome == "postcondition failure"]
    assert post, "at least one room searched in vain"
    assert all(e.reason is not None and "not confirmed by perception" in e.reason for e in post)
    assert all(e.action is not None and "entrance" not in e.action for e in post)
    assert len(d.trace.of_kind(EventKind.REPLAN)) >= len(post)
    assert report.achieved == ["(object_at glasses bedroom)"]
    # the sensed facts come from perception, not from the dispatcher; searched is the dispatcher's effect
    found = kb.why(Fact("found", ("glasses",)))
    assert found is not None and found.source == "kp_camera" and found.status == BeliefStatus.OBSERVED
    searched = kb.why(Fact("searched", ("glasses", "entrance")))
    assert searched is not None and searched.status == BeliefStatus.EFFECT
    assert not kb.facts("explored")  # the camera's record of coverage is perception's, not the search's


def test_timeouts_are_bounded_and_the_goal_is_dropped_eventually() -> None:
    clock = SimClock(dt=1.0)
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    world = World(never_finish={"switch_on"})
    d = dispatcher(kb, world, time_limit=3.0, policy=RecoveryPolicy(max_replans_per_goal=2))
    report = d.run(max_ticks=200, on_tick=clock.tick)
    timeouts = [e for e in d.trace.of_kind(EventKind.FAILURE) if e.outcome == "timeout"]
    assert len(timeouts) == 3  # first plan + two replans
    assert report.dropped == {"(light_on hallway_light)": "gave up after 2 replans"}
    assert report.state == DispatcherState.IDLE and report.ticks < 200
    assert kb.holds("light_off", "hallway_light")


def test_a_planning_timeout_drops_the_goal_until_news_about_it() -> None:
    clock = SimClock(dt=1.0)
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    timed_out = PlanResult(PlanStatus.TIMEOUT, engine="stub", message="no answer within 30 s")
    stub = StubPlanner([timed_out] * 10)
    d = dispatcher(kb, World(), planner=stub, policy=RecoveryPolicy(max_replans_per_goal=2))
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert len(stub.tasks) == 1  # the same problem is not planned again every timeout
    assert report.dropped == {
        "(light_on hallway_light)": "no plan within the planning timeout (no answer within 30 s)"
    }
    assert report.state == DispatcherState.IDLE and not kb.holds("light_on", "hallway_light")


def test_a_planner_that_keeps_failing_charges_the_goal_until_it_is_dropped() -> None:
    clock = SimClock(dt=1.0)
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    failed = PlanResult(PlanStatus.ERROR, engine="stub", message="the engine died")
    stub = StubPlanner([failed] * 10)
    d = dispatcher(kb, World(), planner=stub, policy=RecoveryPolicy(max_replans_per_goal=2))
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert len(stub.tasks) == 3  # first call + two replans, then the goal is given up instead of looping
    assert report.dropped == {"(light_on hallway_light)": "gave up after 2 replans"}
    assert report.state == DispatcherState.IDLE and not kb.holds("light_on", "hallway_light")


def test_at_start_check_catches_a_change_the_dispatcher_did_not_hear_about() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    stub = StubPlanner(
        [
            ["(move r2d2 entrance_hall hallway)", "(move r2d2 hallway kitchen)"],
            ["(move r2d2 bathroom hallway)", "(move r2d2 hallway kitchen)"],
        ]
    )
    d = dispatcher(kb, World(steps_per_action=1), planner=stub)
    d.close()  # no change notifications: only the at-start check can notice
    d.step()  # plan, dispatch and activate the first move
    d.step()  # first move done
    kb.add_fact("robot_at", "r2d2", "bathroom", source="kp_localisation", status=BeliefStatus.OBSERVED)
    d.run(max_ticks=100, on_tick=clock.tick)
    failures = d.trace.of_kind(EventKind.FAILURE)
    assert [(e.action, e.outcome) for e in failures] == [
        ("(move r2d2 hallway kitchen)", "precondition failure")
    ]
    assert failures[0].reason == "at-start condition (robot_at r2d2 hallway) does not hold"
    assert ("robot_at", "r2d2", "bathroom") in stub.tasks[1].facts
    assert kb.holds("robot_at", "r2d2", "kitchen")


def test_invalid_stub_plan_is_rejected_before_it_runs() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    world = World()
    stub = StubPlanner(
        [
            ["(move r2d2 entrance_hall kitchen)"],
            ["(move r2d2 entrance_hall hallway)", "(move r2d2 hallway kitchen)"],
        ]
    )
    d = dispatcher(kb, world, planner=stub)
    d.run(max_ticks=100, on_tick=clock.tick)
    replans = d.trace.of_kind(EventKind.REPLAN)
    assert replans[0].reason is not None and replans[0].reason.startswith("plan rejected by validation")
    assert "(connected entrance_hall kitchen)" in replans[0].reason
    assert "(move r2d2 entrance_hall kitchen)" not in world.started
    assert kb.holds("robot_at", "r2d2", "kitchen")


def test_removed_goal_cancels_the_running_action() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(steps_per_action=5))

    def withdraw(tick: int) -> None:
        clock.tick()
        if tick == 2:
            kb.remove_goal("robot_at", "r2d2", "kitchen")

    report = d.run(max_ticks=50, on_tick=withdraw)
    assert [e.outcome for e in d.trace.of_kind(EventKind.FAILURE)] == ["cancelled"]
    assert report.state == DispatcherState.IDLE and kb.holds("robot_at", "r2d2", "entrance_hall")


def test_a_cancelled_dispatcher_resumes_and_reaches_the_goal() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(steps_per_action=5))

    def stop(tick: int) -> None:
        clock.tick()
        if tick == 3:
            d.cancel("operator stop")

    report = d.run(max_ticks=30, on_tick=stop)
    assert report.state == DispatcherState.STOPPED and [e.outcome for e in d.trace.of_kind(EventKind.FAILURE)]
    assert kb.holds("robot_at", "r2d2", "entrance_hall")
    assert d.resume() and not d.resume()  # resuming twice changes nothing
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert report.state == DispatcherState.IDLE and report.achieved == ["(robot_at r2d2 kitchen)"]
    assert kb.holds("robot_at", "r2d2", "kitchen") and len(d.trace.of_kind(EventKind.PLAN)) == 2


def test_drop_goal_policy_drops_the_goals_of_the_failed_plan() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(light_on hallway_light)", "(robot_at r2d2 hallway)"])
    world = World(fail={"(switch_on r2d2 hallway_light)": 5})
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.DROP_GOAL)})
    d = dispatcher(kb, world, policy=policy)
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert list(report.dropped) == ["(light_on hallway_light)"]
    assert "execution failure" in report.dropped["(light_on hallway_light)"]
    assert report.achieved == ["(robot_at r2d2 hallway)"]


def test_trace_jsonl_and_readable_lines() -> None:
    import io
    import json

    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 hallway)"])
    stream = io.StringIO()
    printed = io.StringIO()
    trace = Trace(jsonl=stream)
    trace.print_to(printed)
    d = Dispatcher(kb, TaskPlanner(engine="knic"), scripted_registry(kb, World()), trace=trace)
    d.run(max_ticks=50, on_tick=clock.tick)
    rows = [json.loads(line) for line in stream.getvalue().splitlines()]
    assert [r["kind"] for r in rows] == ["plan", "dispatch", "activation", "success", "goal_achieved"]
    assert rows[0]["plan"] == ["(move r2d2 entrance_hall hallway)"] and "planning_ms" in rows[0]["data"]
    assert rows[-1]["goal"] == "(robot_at r2d2 hallway)"
    lines = printed.getvalue().splitlines()
    assert "success" in lines[3] and "(move r2d2 entrance_hall hallway)" in lines[3]


def test_idle_dispatcher_wakes_up_when_a_goal_stops_holding() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 hallway)"])
    d = dispatcher(kb, World(steps_per_action=1))
    d.run(max_ticks=50, on_tick=clock.tick)
    plans = len(d.trace.of_kind(EventKind.PLAN))
    for _ in range(5):  # idle ticks do nothing
        assert d.step() == DispatcherState.IDLE
    assert len(d.trace.of_kind(EventKind.PLAN)) == plans
    kb.add_fact("robot_at", "r2d2", "kitchen", source="kp_localisation", status=BeliefStatus.OBSERVED)
    d.run(max_ticks=50, on_tick=clock.tick)
    assert len(d.trace.of_kind(EventKind.PLAN)) == plans + 1
    assert kb.holds("robot_at", "r2d2", "hallway")
    assert [e.goal for e in d.trace.of_kind(EventKind.GOAL_ACHIEVED)] == ["(robot_at r2d2 hallway)"] * 2


def test_after_dropping_a_goal_unrelated_changes_do_not_replan() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(has annie tissues)", "(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(steps_per_action=3))

    def perceive(tick: int) -> None:
        clock.tick()
        if tick == 2:
            kb.add_fact("person_at", "jack", "bathroom", source="kp_people", status=BeliefStatus.OBSERVED)

    report = d.run(max_ticks=100, on_tick=perceive)
    assert list(report.dropped) == ["(has annie tissues)"]
    assert d.trace.of_kind(EventKind.REPLAN) == []
    assert report.achieved == ["(robot_at r2d2 kitchen)"]


class _CountingPlanner:
    """The real planner, counting its calls (an idle dispatcher must not call it)."""

    def __init__(self) -> None:
        self.inner = TaskPlanner(engine="knic")
        self.calls = 0

    def solve(self, task: PlanningTask, *, timeout: float | None = None) -> PlanResult:
        self.calls += 1
        return self.inner.solve(task, timeout=timeout)


def test_idle_with_goals_holding_never_plans_while_perception_writes() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 hallway)", "(light_on hallway_light)"])
    planner = _CountingPlanner()
    d = dispatcher(kb, World(steps_per_action=1), planner=planner)
    d.run(max_ticks=100, on_tick=clock.tick)
    assert d.state == DispatcherState.IDLE and kb.goals_hold()
    plans, calls = len(d.trace.of_kind(EventKind.PLAN)), planner.calls
    events = len(d.trace.events)
    rooms = ["bathroom", "kitchen", "bedroom"]
    for tick in range(300):  # perception keeps writing, goal facts re-asserted: nothing that matters changes
        kb.add_fact("person_at", "jack", rooms[tick % 3], source="kp_people", status=BeliefStatus.OBSERVED)
        kb.add_fact("robot_at", "r2d2", "hallway", source="kp_localisation", status=BeliefStatus.OBSERVED)
        assert d.step() == DispatcherState.IDLE
        clock.tick()
    assert planner.calls == calls and len(d.trace.of_kind(EventKind.PLAN)) == plans
    assert len(d.trace.events) == events  # no event at all over the idle ticks
    # a goal stops holding: the dispatcher wakes up, plans once and achieves it again
    kb.add_fact("light_off", "hallway_light", source="kp_devices", status=BeliefStatus.OBSERVED)
    kb.remove_fact("light_on", "hallway_light", source="kp_devices", status=BeliefStatus.OBSERVED)
    d.step()
    new_plans = d.trace.of_kind(EventKind.PLAN)[plans:]
    assert [e.plan for e in new_plans] == [("(switch_on r2d2 hallway_light)",)]
    d.run(max_ticks=50, on_tick=clock.tick)
    assert kb.holds("light_on", "hallway_light") and d.state == DispatcherState.IDLE
    assert planner.calls == calls + 1


def test_goal_made_true_by_perception_after_a_failure_is_not_planned_again() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    world = World(fail={"(switch_on r2d2 hallway_light)": 1})
    planner = _CountingPlanner()
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.REPLAN)})
    d = dispatcher(kb, world, planner=planner, policy=policy)

    def someone_else_switches_it_on(tick: int) -> None:
        clock.tick()
        if d.trace.of_kind(EventKind.FAILURE) and not kb.holds("light_on", "hallway_light"):
            kb.add_fact("light_on", "hallway_light", source="kp_devices", status=BeliefStatus.OBSERVED)

    report = d.run(max_ticks=100, on_tick=someone_else_switches_it_on)
    assert [e.outcome for e in d.trace.of_kind(EventKind.FAILURE)] == ["execution failure"]
    assert planner.calls == 1 and len(d.trace.of_kind(EventKind.PLAN)) == 1  # no empty plan after the failure
    assert report.achieved == ["(light_on hallway_light)"] and report.state == DispatcherState.IDLE


def test_a_dropped_goal_handed_back_is_planned_for_again() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    world = World(fail={"(switch_on r2d2 hallway_light)": 1})
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.DROP_GOAL)})
    d = dispatcher(kb, world, policy=policy)
    report = d.run(max_ticks=100, on_tick=clock.tick)
    assert list(report.dropped) == ["(light_on hallway_light)"] and report.state == DispatcherState.IDLE
    for _ in range(10):  # dropped: idle ticks do nothing
        assert d.step() == DispatcherState.IDLE
    assert len(d.trace.of_kind(EventKind.PLAN)) == 1
    assert d.retry(("light_on", "hallway_light")) and not d.retry(("light_on", "hallway_light"))
    report = d.run(max_ticks=100, on_tick=clock.tick)
    assert len(d.trace.of_kind(EventKind.PLAN)) == 2
    assert report.dropped == {} and report.achieved == ["(light_on hallway_light)"]
    assert kb.holds("light_on", "hallway_light")


def _retrying(times: int, after_s: float) -> RecoveryPolicy:
    return RecoveryPolicy(max_replans_per_goal=5, goal_retry=GoalRetry(times, after_s))


def test_a_dropped_goal_comes_back_when_knowledge_about_it_changes() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(has annie tissues)"])
    d = dispatcher(kb, World(where={"tissues": "bathroom", "annie": "bedroom"}), policy=_retrying(3, 1e6))
    d.run(max_ticks=20, on_tick=clock.tick)
    assert list(d.dropped) == [("has", "annie", "tissues")] and d.plans == 1
    # unrelated news, or a fact re-asserted as it was: the goal stays dropped, nothing is planned
    kb.add_fact("person_at", "jack", "bathroom", source="kp_people", status=BeliefStatus.OBSERVED)
    kb.add_fact("hand_empty", "r2d2", source="kp_gripper", status=BeliefStatus.OBSERVED)
    for _ in range(5):
        assert d.step() == DispatcherState.IDLE
        clock.tick()
    assert d.trace.of_kind(EventKind.REPLAN) == [] and d.plans == 1 and d.dropped_for_good() == {}
    # someone says where the tissues may be: the recovery policy hands the goal back at once
    kb.add_fact("possibly_at", "tissues", "bathroom", source="user", status=BeliefStatus.ASSUMED)
    report = d.run(max_ticks=400, on_tick=clock.tick)
    retries = d.trace.of_kind(EventKind.REPLAN)
    assert retries[0].goal == "(has annie tissues)" and "(1/3)" in (retries[0].reason or "")
    assert report.achieved == ["(has annie tissues)"] and report.dropped == {}
    assert kb.holds("has", "annie", "tissues")


def test_a_dropped_goal_comes_back_after_its_back_off_until_its_retries_are_used_up() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(has annie tissues)"])
    d = dispatcher(kb, World(), policy=_retrying(2, 5.0))
    d.run(max_ticks=3, on_tick=clock.tick)
    assert list(d.dropped) == [("has", "annie", "tissues")]
    for _ in range(200):  # nothing new is learnt: retried after 5 s, twice, then dropped for good
        d.step()
        clock.tick()
    retries = [e for e in d.trace.of_kind(EventKind.REPLAN) if e.goal == "(has annie tissues)"]
    assert [e.reason.split(")")[1] for e in retries if e.reason] == [" (1/2", " (2/2"]
    assert retries[1].time - retries[0].time >= 5.0
    assert len(d.trace.of_kind(EventKind.GOAL_DROPPED)) == 3 and d.plans == 3
    assert list(d.dropped_for_good()) == ["(has annie tissues)"] and d.state == DispatcherState.IDLE


def test_a_goal_retry_never_cancels_an_action_running_for_another_goal() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(has annie tissues)", "(robot_at r2d2 bedroom)"])
    d = dispatcher(kb, World(steps_per_action=6), policy=_retrying(3, 1e6))
    d.step()  # plans: the tissues goal is unreachable and dropped; the first move starts
    assert list(d.dropped) == [("has", "annie", "tissues")] and d.current is not None
    running = str(d.current.step)
    kb.add_fact("possibly_at", "tissues", "bathroom", source="user", status=BeliefStatus.ASSUMED)
    while d.current is not None and str(d.current.step) == running:
        assert d.dropped  # not handed back while the move runs
        d.step()
        clock.tick()
    assert not [e for e in d.trace.of_kind(EventKind.FAILURE) if e.outcome == "cancelled"]
    assert d.trace.of_kind(EventKind.SUCCESS)[0].action == running
    d.step()  # the move has ended: the goal comes back
    assert not d.dropped and d.trace.of_kind(EventKind.REPLAN)[0].goal == "(has annie tissues)"


def test_a_repeated_identical_failure_retracts_the_belief_then_drops_the_goal() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(object_at mug bedroom)"])
    kb.add_fact("object_at", "mug", "kitchen", status=BeliefStatus.OBSERVED, source="kp_camera")
    kb.add_fact("found", "mug", status=BeliefStatus.OBSERVED, source="kp_camera")
    world = World(fail={"(pick r2d2 mug kitchen)": 99})
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(0, Recovery.REPLAN)})
    d = dispatcher(kb, world, policy=policy)

    def believe_again(tick: int) -> None:  # perception keeps seeing the mug in the kitchen
        clock.tick()
        if not kb.holds("object_at", "mug", "kitchen") and not kb.holds("holding", "r2d2", "mug"):
            kb.add_fact("object_at", "mug", "kitchen", status=BeliefStatus.OBSERVED, source="kp_camera")

    removed: list[str] = []
    kb.subscribe(
        lambda c: (
            removed.append(c.provenance.source)
            if c.kind.value == "remove_fact" and c.name == "object_at"
            else None
        )
    )
    report = d.run(max_ticks=400, on_tick=believe_again)
    reasons = [e.reason or "" for e in d.trace.of_kind(EventKind.REPLAN)]
    assert any("failed the same way 2 times: retracting (object_at mug kitchen)" in r for r in reasons)
    assert "dispatcher" in removed  # the belief the pick rested on was retracted by the recovery
    # the fourth identical failure drops the goal instead of trying the same thing again and again
    assert world.started.count("(pick r2d2 mug kitchen)") == 4
    assert "failed the same way 4 times" in report.dropped["(object_at mug bedroom)"]


def test_planning_time_passes_on_the_dispatcher_clock() -> None:
    clock = SimClock()
    kb = erl_kb(clock, goals=["(robot_at r2d2 kitchen)"])
    d = dispatcher(kb, World(), planning_time="model")
    d.run(max_ticks=300, on_tick=clock.tick)
    plan = d.trace.of_kind(EventKind.PLAN)[0]
    first = d.trace.of_kind(EventKind.DISPATCH)[0]
    assert d.thinking_s >= 0.1  # at least one tick of thought per plan, however fast the planner
    assert first.time >= plan.time + d.thinking_s - 1e-9
    # the model is deterministic: the same task costs the same simulated time
    again = dispatcher(erl_kb(SimClock(), goals=["(robot_at r2d2 kitchen)"]), World(), planning_time="model")
    again.run(max_ticks=300, on_tick=SimClock().tick)
    assert again.thinking_s == d.thinking_s


def test_a_new_goal_replaces_an_achieved_older_goal_it_can_never_hold_together_with() -> None:
    clock = SimClock(dt=1.0)
    kb = erl_kb(clock, goals=["(light_on hallway_light)"])
    d = dispatcher(kb, World())
    d.run(max_ticks=200, on_tick=clock.tick)
    assert kb.holds("light_on", "hallway_light")
    kb.add_goal("light_off", "hallway_light")  # later: "switch it off again"
    report = d.run(max_ticks=200, on_tick=clock.tick)
    assert kb.holds("light_off", "hallway_light") and not kb.holds("light_on", "hallway_light")
    assert [str(g) for g in kb.goals()] == ["(light_off hallway_light)"]
    dropped = [e for e in d.trace.of_kind(EventKind.GOAL_DROPPED)]
    assert [(e.goal, e.reason) for e in dropped] == [
        ("(light_on hallway_light)", "superseded by (light_off hallway_light)")
    ]
    assert not report.dropped
