"""Actions with the gripper: ``pick`` an item, ``place`` it on a surface, ``give`` it to a person.

Where to go comes from perception (the item's or person's perceived pose, the knowledge base's item anchor as
fallback) and the furniture anchors; the gripper's own sensor (``held_item``) checks what is in the hand.
Failure modes:

* ``pick``: the item was never perceived (activation failure); the base cannot reach it; on arrival perception
  drops the item's track or the knowledge base no longer holds it in the room ("not there"); the gripper
  refuses (out of reach, held by someone), after one re-approach to a fresh sighting; the gripper, sent to
  the perceived position (the belief, never the item's true place), closes on nothing ("not where it was
  believed": the belief is refuted through :meth:`~actions.erl.perception.Perception.refute`, so the place
  fact goes and the next plan searches).
* ``place``: the gripper does not hold the item (activation failure); the furniture cannot be reached; the
  gripper refuses (no surface, out of reach, no free spot).
* ``give``: the gripper does not hold the item, or the person was never perceived (activation failure); the
  person cannot be approached; the hand-over is refused (out of reach, their hands full, nobody at the
  perceived position: then the belief is refuted), after one re-approach.
"""

from __future__ import annotations

import math

from actions.base import ActionStatus
from actions.erl.common import ErlAction, NavGoal, to_furniture, to_point
from actions.erl.context import ErlContext, FurnitureMap, bearing, furniture_map, standoff_points
from actions.erl.motion import PersonApproachAction
from core.robot import CAUSE_NOT_AT_BELIEF, CommandResult

#: metres from a loose item (on no known furniture) at which the robot stops to grasp it
GRASP_STANDOFF = 0.55
#: metres a fresh sighting must differ from the target before the robot re-approaches
MOVED_M = 0.15
#: metres from the support's footprint beyond which a perceived point is not trusted to choose the approach
OFF_SUPPORT_M = 0.4
#: metres (horizontal) within which the robot tries to grasp at once
REACH_M = 0.85
#: camera pans (radians) tried on arrival when the item is not seen straight away
LOOK_PANS = (-0.9, -0.45, 0.0, 0.45, 0.9)


def footprint_distance(f: FurnitureMap, x: float, y: float) -> float:
    """Horizontal distance in metres from ``(x, y)`` to the furniture's footprint (0 on it)."""
    c, s = math.cos(f.yaw), math.sin(f.yaw)
    dx, dy = x - f.position[0], y - f.position[1]
    lx, ly = c * dx + s * dy, -s * dx + c * dy
    return math.hypot(max(abs(lx) - f.size[0] / 2, 0.0), max(abs(ly) - f.size[1] / 2, 0.0))


class PickAction(ErlAction):
    """``(pick ?r ?o ?l)``: approach the perceived item, look at it, grasp it.

    Phases: ``nav`` -> ``look`` (camera on the item, then a little to each side, until perception
    re-confirms it) -> grasp (immediate). A fresh sighting out of reach, or a refused grasp while a fresh
    sighting shows the item elsewhere, leads to a re-approach (at most three approaches).
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("pick", args, ctx)
        _robot, self.item, self.room = args
        self.nav: NavGoal | None = None
        self.target: tuple[float, float, float] | None = None
        self.attempts = 0
        self.pans: list[float] = []
        self.looking_since = ctx.now

    def activation(self) -> bool:
        """Start driving to the item's perceived position."""
        held = self.ctx.robot.held_item()
        if held is not None:
            return self.refuse(f"the gripper already holds {held}")
        self.target = self.ctx.perceived.position(self.item)
        if self.target is None:
            return self.refuse(f"{self.item} has no perceived position to go to")
        if not self._approach():
            return self.refuse(self.nav.reason if self.nav else f"cannot approach {self.item}")
        return True

    def _approach(self) -> bool:
        """Drive within reach of the item: to its support near the perceived point, or to the whole support
        when the point is off it (a poor far-away estimate), or around the point when on no known support."""
        assert self.target is not None
        x, y, _ = self.target
        support = self._support()
        if support is not None:
            known = furniture_map(self.ctx.kb, support)
            near = (x, y) if known is None or footprint_distance(known, x, y) <= OFF_SUPPORT_M else None
            starts = [to_furniture(self.ctx, support, near)]
            if near is not None:  # someone may stand there: then any side of the support
                starts.append(to_furniture(self.ctx, support))
        else:
            pose = self.ctx.robot.robot_pose()
            starts = [
                to_point(self.ctx, p, math.atan2(y - p[1], x - p[0]))
                for p in standoff_points((x, y), GRASP_STANDOFF, (pose.x, pose.y))[:8]
            ]
        self.nav = NavGoal(self.ctx, starts, f"{self.item} ({support or 'floor'})", retry_blocked=True)
        self.attempts += 1
        if not self.nav.start():
            return False
        self.enter("nav")
        return True

    def _support(self) -> str | None:
        facts = self.ctx.kb.facts("object_on", self.item)
        return facts[0].args[1] if facts else None

    def step(self) -> ActionStatus:
        """Drive, look, grasp (see the class docstring)."""
        assert self.target is not None
        if self.phase == "nav":
            assert self.nav is not None
            waiting = self.drive(self.nav)
            if waiting is not None:
                return waiting
            pose = self.ctx.robot.robot_pose()
            self.pans = [bearing(pose, self.target[0], self.target[1]), *LOOK_PANS]
            self.ctx.robot.pan_camera(self.pans.pop(0))
            self.enter("look")
            self.looking_since = self.ctx.now
            return ActionStatus.RUNNING
        if self.ctx.perceived.lost_since(self.item, self.looking_since) or not self.ctx.kb.holds(
            "object_at", self.item, self.room
        ):
            return self.fail(f"{self.item} is not where it was believed in {self.room}")
        fresh = self.ctx.perceived.seen_since(self.item, self.looking_since)
        if fresh is None:
            if self.in_phase_for() < self.ctx.look_timeout_s / 2:
                return ActionStatus.RUNNING
            if self.pans:  # not seen yet: look a little to each side
                self.ctx.robot.pan_camera(self.pans.pop(0))
                self.enter("look")
                return ActionStatus.RUNNING
        pose = self.ctx.robot.robot_pose()
        if fresh is not None and self.attempts < 3 and pose.distance_to(*fresh.position[:2]) > REACH_M:
            self.target = fresh.position
            return ActionStatus.RUNNING if self._approach() else self.fail(self._nav_reason())
        at = fresh.position if fresh is not None else self.target  # the belief the arm acts on
        result = self.ctx.robot.pick(self.item, at)
        if result.ok and self.ctx.robot.held_item() == self.item:
            return ActionStatus.SUCCEEDED
        if (
            fresh is not None
            and self.attempts < 3
            and math.dist(fresh.position[:2], self.target[:2]) > MOVED_M
        ):
            self.target = fresh.position
            if self._approach():
                return ActionStatus.RUNNING
        if result.cause == CAUSE_NOT_AT_BELIEF:
            self.ctx.perceived.refute(self.item, at, self.ctx.now, result.reason)
            return self.fail(f"{self.item} is not where it was believed in {self.room}: {result.reason}")
        return self.fail(f"grasping {self.item} failed: {result.reason or 'the gripper is empty'}")

    def _nav_reason(self) -> str:
        return self.nav.reason if self.nav is not None else f"cannot approach {self.item}"


class PlaceAction(ErlAction):
    """``(place ?r ?o ?f ?l)``: drive within reach of the furniture and put the held item on it.

    Phases: ``nav`` -> put down (immediate).
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("place", args, ctx)
        _robot, self.item, self.furniture, self.room = args
        self.nav: NavGoal | None = None

    def activation(self) -> bool:
        """Check the gripper holds the item and drive to the furniture."""
        if not self.holds_or_refuse(self.item):
            return False
        self.nav = NavGoal(self.ctx, [to_furniture(self.ctx, self.furniture)], self.furniture)
        if not self.nav.start():
            return self.refuse(self.nav.reason)
        self.enter("nav")
        return True

    def step(self) -> ActionStatus:
        """Drive, then put the item down."""
        assert self.nav is not None
        waiting = self.drive(self.nav)
        if waiting is not None:
            return waiting
        result = self.ctx.robot.place(self.furniture)
        if not result.ok:
            return self.fail(f"placing {self.item} on {self.furniture} failed: {result.reason}")
        return ActionStatus.SUCCEEDED


class GiveAction(PersonApproachAction):
    """``(give ?r ?o ?p ?l)``: approach the perceived person and hand the item over.

    Phases: ``nav`` -> hand over (immediate; one re-approach to a fresh sighting if refused).
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("give", args, ctx)
        _robot, self.item, self.person, self.room = args
        self.at: tuple[float, float, float] | None = None
        self.result: CommandResult | None = None

    def activation(self) -> bool:
        """Check the gripper holds the item and approach the person."""
        return self.holds_or_refuse(self.item) and self.approach_or_refuse()

    def act(self) -> CommandResult:
        """Hand the item over where the person is perceived."""
        self.at = self.ctx.perceived.position(self.person)
        self.result = self.ctx.robot.give(self.person, self.at)
        return self.result

    def refused(self, reason: str) -> str:
        """The failure reason; a hand-over nobody took at the believed position refutes that belief."""
        if self.result is not None and self.result.cause == CAUSE_NOT_AT_BELIEF and self.at is not None:
            self.ctx.perceived.refute(self.person, self.at, self.ctx.now, reason)
            return f"{self.person} is not where they were believed: {reason}"
        return f"handing {self.item} to {self.person} failed: {reason}"
