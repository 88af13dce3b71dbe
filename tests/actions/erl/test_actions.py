"""The ERL actions against a scripted robot: where they go, what they command, how they fail."""

from __future__ import annotations

import math

import pytest

from actions.base import Action, ActionStatus
from actions.erl import build_erl_registry
from actions.erl.context import ErlContext
from actions.erl.perception import AnchorPerception, Sighting, SightingBook
from core.errors import ActionError
from knowledge_base import BeliefStatus, KnowledgeBase
from tests.actions.erl.doubles import DOMAIN, FakeRobot, paper_kb


def record(ctx: ErlContext, symbol: str, sighting: Sighting) -> None:
    """Make the test's perception report ``sighting`` of ``symbol``."""
    assert isinstance(ctx.perceived, SightingBook)
    ctx.perceived.record(symbol, sighting)


def drive(action: Action, robot: FakeRobot, max_ticks: int = 400) -> tuple[bool, ActionStatus | None]:
    """Run the lifecycle like the dispatcher: activation, step per tick, deactivation."""
    if not action.activation():
        return False, None
    status = ActionStatus.RUNNING
    for _ in range(max_ticks):
        robot.tick()
        status = action.step()
        if status is not ActionStatus.RUNNING:
            break
    action.ending = "succeeded" if status is ActionStatus.SUCCEEDED else "failed"
    action.deactivation()
    return True, status


Setup = tuple[FakeRobot, KnowledgeBase, ErlContext]


@pytest.fixture
def setup() -> Setup:
    robot = FakeRobot()
    kb = paper_kb()
    kb.set_clock(lambda: robot.time)
    ctx = ErlContext(robot, kb, AnchorPerception(kb), dwell_s=0.2, look_timeout_s=0.5)
    return robot, kb, ctx


def create(ctx: ErlContext, text: str) -> Action:
    name, *args = text.strip("()").split()
    return build_erl_registry(ctx.robot, ctx.kb, context=ctx).create(name, tuple(args))


def test_registry_covers_every_domain_action(setup: Setup) -> None:
    _robot, kb, ctx = setup
    reg = build_erl_registry(ctx.robot, kb, context=ctx)
    assert reg.missing(kb.domain.actions) == []
    assert "speak" in reg
    with pytest.raises(ActionError, match="takes 3 arguments"):
        reg.create("move", ("r2d2", "bedroom"))


def test_move_goes_to_the_anchored_waypoint(setup: Setup) -> None:
    robot, kb, ctx = setup
    started, status = drive(create(ctx, "(move r2d2 bedroom kitchen)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    waypoint = kb.anchor("kitchen")["waypoints"][0]  # type: ignore[index]
    assert (robot.x, robot.y) == pytest.approx(tuple(waypoint))


def test_move_fails_when_the_path_is_blocked(setup: Setup) -> None:
    robot, _kb, ctx = setup
    robot.nav_failure = "path blocked by tracy"
    action = create(ctx, "(move r2d2 bedroom kitchen)")
    assert not action.activation()
    assert "path blocked by tracy" in action.failure_reason


def test_move_without_room_anchor_is_refused() -> None:
    robot = FakeRobot()
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: 0.0)
    kb.add_instance("room", "kitchen")
    ctx = ErlContext(robot, kb, AnchorPerception(kb))
    action = create(ctx, "(move r2d2 kitchen kitchen)")
    assert not action.activation()
    assert "no anchor" in action.failure_reason


def test_search_visits_viewpoints_and_pans_the_camera(
    setup: Setup,
) -> None:
    robot, _kb, ctx = setup
    started, status = drive(create(ctx, "(search_object r2d2 glasses kitchen)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.goals[0].startswith("point")  # the room's waypoint first
    assert "furniture kitchen_table" in robot.goals  # then the furniture of the room
    assert set(ctx.search_pans) <= set(robot.pans)
    assert robot.pan == 0.0


def test_search_stops_once_perception_found_the_entity(
    setup: Setup,
) -> None:
    robot, kb, ctx = setup
    action = create(ctx, "(search_object r2d2 glasses entrance)")
    assert action.activation()
    for _ in range(5):
        robot.tick()
        assert action.step() is ActionStatus.RUNNING
    with kb.batch():  # what the object KP' writes when the camera sees the glasses
        kb.add_fact("object_at", "glasses", "entrance", source="kp'.object_at", status=BeliefStatus.OBSERVED)
        kb.add_fact("found", "glasses", source="kp'.object_at", status=BeliefStatus.OBSERVED)
    robot.tick()
    assert action.step() is ActionStatus.SUCCEEDED
    assert len(robot.goals) == 1


def _perceive_glasses(kb: KnowledgeBase, ctx: ErlContext, at: tuple[float, float, float]) -> None:
    with kb.batch():
        kb.add_fact("object_at", "glasses", "entrance", status=BeliefStatus.OBSERVED)
        kb.add_fact("object_on", "glasses", "entrance_shelf", status=BeliefStatus.OBSERVED)
        kb.add_fact("found", "glasses", status=BeliefStatus.OBSERVED)
    record(ctx, "glasses", Sighting(at, 0.0))


def test_pick_approaches_the_perceived_item_and_grasps_it(
    setup: Setup,
) -> None:
    robot, kb, ctx = setup
    _perceive_glasses(kb, ctx, (7.7, 1.5, 0.92))
    robot.items["glasses"] = (7.7, 1.5)
    started, status = drive(create(ctx, "(pick r2d2 glasses entrance)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.held == "glasses"
    assert robot.goals == ["furniture entrance_shelf"]


def test_pick_fails_when_the_item_is_not_there(setup: Setup) -> None:
    robot, kb, ctx = setup
    _perceive_glasses(kb, ctx, (7.7, 1.5, 0.92))  # believed there, but someone took it
    started, status = drive(create(ctx, "(pick r2d2 glasses entrance)"), robot)
    assert started and status is ActionStatus.FAILED
    assert robot.held is None


def test_pick_on_a_wrong_belief_fails_with_its_cause_and_refutes_it(setup: Setup) -> None:
    robot, kb, ctx = setup
    _perceive_glasses(kb, ctx, (7.7, 1.5, 0.92))  # believed here ...
    robot.items["glasses"] = (7.7, 1.95)  # ... really 0.45 m along the shelf, within the arm's reach
    action = create(ctx, "(pick r2d2 glasses entrance)")
    started, status = drive(action, robot)
    assert started and status is ActionStatus.FAILED
    assert robot.held is None and robot.items["glasses"] == (7.7, 1.95)
    assert (
        "not where it was believed" in action.failure_reason and "closed on nothing" in action.failure_reason
    )
    assert isinstance(ctx.perceived, SightingBook)
    assert [(s, p) for s, p, _t, _r in ctx.perceived.refuted] == [("glasses", (7.7, 1.5, 0.92))]
    assert ctx.perceived.lost_since("glasses", 0.0)


def test_pick_fails_when_perception_retracts_the_item(
    setup: Setup,
) -> None:
    robot, kb, ctx = setup
    _perceive_glasses(kb, ctx, (7.7, 1.5, 0.92))
    action = create(ctx, "(pick r2d2 glasses entrance)")
    assert action.activation()
    kb.remove_fact("object_at", "glasses", "entrance", source="kp'.object_at", status=BeliefStatus.OBSERVED)
    status = ActionStatus.RUNNING
    for _ in range(20):
        robot.tick()
        status = action.step()
        if status is not ActionStatus.RUNNING:
            break
    assert status is ActionStatus.FAILED
    assert "not where it was believed" in action.failure_reason


def test_pick_without_perceived_position_is_refused(
    setup: Setup,
) -> None:
    _robot, _kb, ctx = setup
    action = create(ctx, "(pick r2d2 glasses entrance)")
    assert not action.activation()
    assert "no perceived position" in action.failure_reason


def test_place_puts_the_held_item_on_the_furniture(
    setup: Setup,
) -> None:
    robot, _kb, ctx = setup
    robot.held = "glasses"
    started, status = drive(create(ctx, "(place r2d2 glasses bed bedroom)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.placed == {"glasses": "bed"}
    robot.held = None
    action = create(ctx, "(place r2d2 glasses bed bedroom)")
    assert not action.activation()
    assert "holds nothing" in action.failure_reason


def test_give_hands_over_to_the_perceived_person(setup: Setup) -> None:
    robot, _kb, ctx = setup
    robot.held = "glasses"
    robot.people["annie"] = (1.0, 6.6)
    record(ctx, "annie", Sighting((1.0, 6.6, 0.9), 0.0))
    started, status = drive(create(ctx, "(give r2d2 glasses annie bedroom)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.held is None


def test_guide_walks_with_the_person_and_ends_the_escort(
    setup: Setup,
) -> None:
    robot, _kb, ctx = setup
    robot.people["annie"] = (3.2, 5.0)
    record(ctx, "annie", Sighting((3.3, 5.1, 0.9), 0.0))
    action = create(ctx, "(guide r2d2 annie bedroom kitchen)")
    assert action.activation() and robot.escorting == "annie"
    status = ActionStatus.RUNNING
    for i in range(200):
        robot.tick()
        if i == 20:  # the camera sees annie in the kitchen behind the robot
            record(ctx, "annie", Sighting((5.0, 5.5, 0.9), robot.time))
        status = action.step()
        if status is not ActionStatus.RUNNING:
            break
    action.ending = "succeeded"
    action.deactivation()
    assert status is ActionStatus.SUCCEEDED
    assert robot.escorting is None


def test_guide_draws_in_a_person_seen_in_the_doorway(setup: Setup) -> None:
    robot, _kb, ctx = setup
    robot.people["annie"] = (3.2, 5.0)
    record(ctx, "annie", Sighting((3.3, 5.1, 0.9), 0.0))
    action = create(ctx, "(guide r2d2 annie bedroom kitchen)")
    assert action.activation()
    status, goals_at_doorway = ActionStatus.RUNNING, 0
    for i in range(300):
        robot.tick()
        if i == 20:  # seen 10 cm past the kitchen's wall: in the doorway, not in the kitchen
            record(ctx, "annie", Sighting((4.1, 6.0, 0.9), robot.time))
            goals_at_doorway = len(robot.goals)
        if i == 60:  # the robot walked on; she followed it in
            assert len(robot.goals) > goals_at_doorway
            assert math.dist((robot.x, robot.y), (4.1, 6.0)) > math.dist((5.5, 5.3), (4.1, 6.0))
            record(ctx, "annie", Sighting((5.6, 6.2, 0.9), robot.time))
        status = action.step()
        if status is not ActionStatus.RUNNING:
            break
    assert status is ActionStatus.SUCCEEDED and i >= 60  # not before she was seen inside


def test_guide_addresses_the_believed_position_and_refutes_a_wrong_belief(setup: Setup) -> None:
    robot, _kb, ctx = setup
    robot.people["annie"] = (3.2, 5.0)
    record(ctx, "annie", Sighting((1.8, 5.0, 0.9), 0.0))  # believed 1.4 m from where she stands
    action = create(ctx, "(guide r2d2 annie bedroom kitchen)")
    assert not action.activation() and robot.escorting is None
    assert "not at the believed position" in action.failure_reason
    assert isinstance(ctx.perceived, SightingBook)
    assert [(s, p) for s, p, _t, _r in ctx.perceived.refuted] == [("annie", (1.8, 5.0, 0.9))]
    assert ctx.perceived.lost_since("annie", 0.0)


def test_guide_without_a_believed_position_is_refused() -> None:
    robot = FakeRobot()
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: robot.time)
    for room in ("bedroom", "kitchen"):
        kb.add_instance("room", room)
    kb.set_anchor("kitchen", {"region": [[4, 4], [6, 4], [6, 6], [4, 6]], "waypoints": [[5, 5]]})
    kb.add_instance("person", "annie")
    robot.people["annie"] = (1.0, 1.0)
    ctx = ErlContext(robot, kb, AnchorPerception(kb))
    action = create(ctx, "(guide r2d2 annie bedroom kitchen)")
    assert not action.activation() and robot.escorting is None
    assert "never perceived" in action.failure_reason


def test_switch_on_waits_for_the_device_reading(setup: Setup) -> None:
    robot = FakeRobot()
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: robot.time)
    kb.add_instance("light", "bedroom_left_light")
    kb.add_fact("light_off", "bedroom_left_light")
    ctx = ErlContext(robot, kb, AnchorPerception(kb))
    reg = build_erl_registry(robot, kb, context=ctx, confirm_devices=True)
    action = reg.create("switch_on", ("r2d2", "bedroom_left_light"))
    assert action.activation() and robot.lights == {"bedroom_left_light": True}
    robot.tick()
    assert action.step() is ActionStatus.RUNNING
    with kb.batch():  # what the device KP' writes from the reading
        kb.add_fact("light_on", "bedroom_left_light", source="kp'.devices", status=BeliefStatus.OBSERVED)
        kb.remove_fact("light_off", "bedroom_left_light", source="kp'.devices", status=BeliefStatus.OBSERVED)
    assert action.step() is ActionStatus.SUCCEEDED
    silent = reg.create("switch_off", ("r2d2", "bedroom_left_light"))
    started, status = drive(silent, robot)
    assert started and status is ActionStatus.FAILED
    assert "did not report (light_off bedroom_left_light)" in silent.failure_reason


def test_set_level_sends_the_percentage(setup: Setup) -> None:
    robot, kb, ctx = setup
    reg = build_erl_registry(robot, kb, context=ctx, confirm_devices=False)
    started, status = drive(reg.create("set_level", ("r2d2", "bedroom_blinds", "l0", "l50")), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.levels == {"bedroom_blinds": 50.0}
    with pytest.raises(ActionError, match="unknown level"):
        reg.create("set_level", ("r2d2", "bedroom_blinds", "l0", "l60"))


def test_report_says_where_the_entity_was_found(setup: Setup) -> None:
    robot, kb, ctx = setup
    _perceive_glasses(kb, ctx, (7.7, 1.5, 0.92))
    started, status = drive(create(ctx, "(report r2d2 glasses)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.said == ["I found the glasses on the entrance shelf in the entrance."]


def test_report_after_the_hand_over_says_who_has_it_and_where(setup: Setup) -> None:
    robot, kb, ctx = setup
    with kb.batch():
        kb.add_fact("has", "annie", "glasses", source="test", status=BeliefStatus.OBSERVED)
        kb.add_fact("person_at", "annie", "bedroom", source="test", status=BeliefStatus.OBSERVED)
    started, status = drive(create(ctx, "(report r2d2 glasses)"), robot)
    assert started and status is ActionStatus.SUCCEEDED
    assert robot.said == ["I found the glasses with annie in the bedroom."]
