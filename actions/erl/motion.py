"""Actions that move the robot: ``move`` to a room, ``meet`` a person, ``guide`` a person to a room.

Targets come from the knowledge base's room anchors (waypoints, regions) and from perceived person poses
(:class:`~actions.erl.perception.Perception`), never from the simulator's ground truth. Failure modes:

* ``move``: the room has no anchor (activation failure); the base reports the path blocked or no path
  (execution failure); the localisation ends outside the target room (execution failure).
* ``meet``: the person was never perceived (activation failure); the person cannot be approached, or refuses
  to be escorted because they are out of reach (execution failure, after one re-approach to a fresh sighting).
* ``guide``: the person is not within escort distance at activation (activation failure); the path is blocked;
  the person was not perceived inside the target room within ``follow_timeout_s`` of arrival.
"""

from __future__ import annotations

import math

from actions.base import ActionStatus
from actions.erl.common import ErlAction, NavGoal, to_point
from actions.erl.context import (
    ErlContext,
    FurnitureMap,
    Point,
    furniture_map,
    room_map,
    standoff_points,
    wrap,
)
from core.robot import CAUSE_NOT_AT_BELIEF, CommandResult

#: metres between the robot and a person it approaches, tried in this order: inside the hand-over reach (the
#: gripper's reach plus the person's arm, about 1.25 m) with a margin for the perceived position's error; the
#: outer rings reach someone sitting in the middle of a bed, whose edge keeps the robot about 1.1 m away
PERSON_STANDOFFS = (0.7, 0.85, 1.0, 1.1, 0.6)
#: the first of them (kept for callers that need one distance)
PERSON_STANDOFF = PERSON_STANDOFFS[0]


class MoveAction(ErlAction):
    """``(move ?r ?from ?to)``: drive to the waypoint of room ``to``.

    Phases: ``nav`` (following the goal) -> done. When the base cannot reach the waypoint (someone stands on
    it, the way there is blocked), other points inside the room are tried in turn. Deactivation stops the
    base unless it succeeded.
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("move", args, ctx)
        _robot, self.origin, self.target = args
        self.nav: NavGoal | None = None

    def activation(self) -> bool:
        """Send the base to the first reachable waypoint of the target room."""
        room = room_map(self.ctx.kb, self.target)
        if room is None:
            return self.refuse(f"room {self.target} has no anchor (region, waypoints) in the knowledge base")
        self.room = room
        targets = [*room.waypoints, *room.inner_points()]
        starts = [to_point(self.ctx, p) for p in targets]
        self.nav = NavGoal(self.ctx, starts, self.target, retry_blocked=True)
        if not self.nav.start():
            return self.refuse(self.nav.reason)
        self.enter("nav")
        return True

    def step(self) -> ActionStatus:
        """Poll the navigation goal; on arrival check that the localisation is inside the room."""
        assert self.nav is not None
        waiting = self.drive(self.nav)
        if waiting is not None:
            return waiting
        pose = self.ctx.robot.robot_pose()
        if self.ctx.robot.time - pose.stamp > STALE_POSE_S:
            return ActionStatus.RUNNING  # the localisation went silent: judge the arrival on a fresh estimate
        if not self.room.contains(pose.x, pose.y):
            return self.fail(f"arrived at ({pose.x:.2f}, {pose.y:.2f}), which is outside {self.target}")
        return ActionStatus.SUCCEEDED


#: seconds after which a localisation estimate is too old to judge an arrival by (a dropped-out sensor)
STALE_POSE_S = 1.0

#: metres between a furniture's edge and the robot's centre beside someone sitting or lying on it
EDGE_CLEARANCE = 0.35


def furniture_under(ctx: ErlContext, x: float, y: float) -> FurnitureMap | None:
    """The anchored furniture whose footprint holds ``(x, y)`` (someone sitting or lying on it), or None."""
    for name in ctx.kb.instances("furniture"):
        known = furniture_map(ctx.kb, name)
        if known is None:
            continue
        c, s = math.cos(known.yaw), math.sin(known.yaw)
        dx, dy = x - known.position[0], y - known.position[1]
        lx, ly = c * dx + s * dy, -s * dx + c * dy
        if abs(lx) <= known.size[0] / 2 and abs(ly) <= known.size[1] / 2:
            return known
    return None


def beside_furniture(f: FurnitureMap, x: float, y: float) -> list[Point]:
    """Points just off both long sides of ``f``, level with ``(x, y)``.

    Someone on a bed or a sofa is closest to the robot across its long sides; the perceived position of a
    person lying there leans towards the side the camera saw them from, so choosing the side by the
    furniture's shape (not by the perceived point) keeps that bias from choosing an end, where the person is
    out of reach. A long side that is blocked (a wall, a table) fails at once; the caller then tries rings
    around the person.
    """
    c, s = math.cos(f.yaw), math.sin(f.yaw)
    dx, dy = x - f.position[0], y - f.position[1]
    lx, ly = c * dx + s * dy, -s * dx + c * dy
    hx, hy = f.size[0] / 2 + EDGE_CLEARANCE, f.size[1] / 2 + EDGE_CLEARANCE
    local = [(lx, -hy), (lx, hy)] if f.size[0] >= f.size[1] else [(-hx, ly), (hx, ly)]
    return [(f.position[0] + c * px - s * py, f.position[1] + s * px + c * py) for px, py in local]


def approach_person(ctx: ErlContext, person: str, what: str, closer: int = 0) -> NavGoal | None:
    """A started navigation goal to a free pose near the perceived person, facing them; None when the person
    was never perceived or no pose around them is reachable.

    Someone on a piece of furniture is approached from beside it (:func:`beside_furniture`) first. Then
    poses on the rings of :data:`PERSON_STANDOFFS` are tried nearest-to-the-robot first, ring by ring;
    ``closer`` > 0 (a re-approach after a refused hand-over) starts with the closest ring."""
    where = ctx.perceived.position(person)
    if where is None:
        return None
    pose = ctx.robot.robot_pose()
    target = (where[0], where[1])
    rings = sorted(PERSON_STANDOFFS) if closer > 0 else list(PERSON_STANDOFFS)
    starts = []
    seat = furniture_under(ctx, target[0], target[1])
    if seat is not None:  # sitting or lying on furniture: stand beside it, level with them
        for p in beside_furniture(seat, target[0], target[1]):
            starts.append(to_point(ctx, p, math.atan2(target[1] - p[1], target[0] - p[0])))
    for ring in rings:
        for p in standoff_points(target, ring, (pose.x, pose.y), count=16)[:10]:
            yaw = math.atan2(target[1] - p[1], target[0] - p[0])
            starts.append(to_point(ctx, p, yaw))
    nav = NavGoal(ctx, starts, what)
    return nav if nav.start() else None


class PersonApproachAction(ErlAction):
    """An action that drives up to a perceived person, ``self.person``, then does :meth:`act` with them
    (``meet``, ``give``); when that is refused, it approaches again, closer (they may have moved, or the
    perceived position was off), at most twice."""

    person: str
    nav: NavGoal | None = None
    reapproaches = 0

    def act(self) -> CommandResult:
        """What the action does once beside the person."""
        raise NotImplementedError

    def refused(self, reason: str) -> str:
        """The failure reason when :meth:`act` was refused after the re-approach."""
        raise NotImplementedError

    def step(self) -> ActionStatus:
        """Approach, then act; one re-approach when the person refuses."""
        assert self.nav is not None
        waiting = self.drive(self.nav)
        if waiting is not None:
            return waiting
        result = self.act()
        if result.ok:
            return ActionStatus.SUCCEEDED
        if self.reapproaches < 2:
            self.reapproaches += 1
            if self.reapproach():
                return ActionStatus.RUNNING
        return self.fail(self.refused(result.reason))

    def approach_or_refuse(self) -> bool:
        """Start the approach; refuse (False) when the person was never perceived or cannot be reached."""
        self.nav = approach_person(self.ctx, self.person, self.person)
        if self.nav is None:
            return self.refuse(f"cannot approach {self.person}: not perceived or no free pose around them")
        self.enter("nav")
        return True

    def reapproach(self) -> bool:
        """Approach the person again (they may have moved); False when that cannot start."""
        nav = approach_person(self.ctx, self.person, self.person, closer=self.reapproaches)
        if nav is None:
            return False
        self.nav = nav
        self.enter("nav")
        return True


class MeetAction(PersonApproachAction):
    """``(meet ?r ?p ?l)``: go to the perceived person and ask them to follow (effect: escorting).

    Phases: ``nav`` -> ``escort`` (with at most one re-approach when a fresh sighting shows they moved).
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("meet", args, ctx)
        _robot, self.person, self.room = args

    def activation(self) -> bool:
        """Start approaching where the person was last perceived."""
        return self.approach_or_refuse()

    def act(self) -> CommandResult:
        """Ask the person to follow, addressing where they are perceived."""
        return self.ctx.robot.escort(self.person, self.ctx.perceived.position(self.person))

    def refused(self, reason: str) -> str:
        return f"{self.person} will not follow: {reason}"


#: metres inside the walls a guided person must be seen for the robot to believe them in the room: their
#: body's radius and the perceived position's error (a person stopping in the doorway is not in the room)
GUIDE_DEPTH = 0.35
#: times the robot walks deeper into the room to draw in a person seen in or near the doorway
GUIDE_DRAW_INS = 2


class GuideAction(ErlAction):
    """``(guide ?r ?p ?from ?to)``: walk to room ``to`` with the person following.

    The robot addresses the person where it believes they are (the perceived position); when nobody of that
    name stands there the action fails and the belief is refuted, so the next plan looks for them.

    Phases: ``nav`` (person following) -> ``turn`` (face back to see them) -> ``wait`` (until the person is
    perceived :data:`GUIDE_DEPTH` inside ``to``). A person seen short of that (following a step behind, they
    stop in the doorway of a small room) is drawn in: the robot walks on to the room's point farthest from
    them, up to :data:`GUIDE_DRAW_INS` times. Deactivation ends the escort, so the person stays where they
    are.
    """

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("guide", args, ctx)
        _robot, self.person, self.origin, self.target = args
        self.nav: NavGoal | None = None

    def activation(self) -> bool:
        """Ask the person to follow, then head for the target room's waypoint."""
        room = room_map(self.ctx.kb, self.target)
        if room is None:
            return self.refuse(f"room {self.target} has no anchor (region, waypoints) in the knowledge base")
        self.room = room
        where = self.ctx.perceived.position(self.person)
        if where is None:
            return self.refuse(f"{self.person} was never perceived: no believed position to address")
        result = self.ctx.robot.escort(self.person, where)
        if not result.ok:
            if result.cause == CAUSE_NOT_AT_BELIEF:
                self.ctx.perceived.refute(self.person, where, self.ctx.now, result.reason)
            return self.refuse(f"{self.person} cannot be escorted: {result.reason}")
        self.nav = NavGoal(self.ctx, [to_point(self.ctx, wp) for wp in room.waypoints], self.target)
        if not self.nav.start():
            self.ctx.robot.stop_escort()
            return self.refuse(self.nav.reason)
        self.draw_ins = 0
        self.enter("nav")
        return True

    def step(self) -> ActionStatus:
        """Walk, turn round, and wait to see the person in the room."""
        assert self.nav is not None
        if self.phase in ("nav", "turn"):
            waiting = self.drive(self.nav)
            if waiting is not None:
                return waiting
            if self.phase == "nav":
                pose = self.ctx.robot.robot_pose()
                back = wrap(pose.yaw + math.pi)
                self.nav = NavGoal(self.ctx, [to_point(self.ctx, (pose.x, pose.y), back)], "turn round")
                self.nav.start()
                self.enter("turn")
                return ActionStatus.RUNNING
            self.enter("wait")
        seen = self.ctx.perceived.seen_since(self.person, self.phase_since)
        if seen is not None and self.room.depth(seen.position[0], seen.position[1]) >= GUIDE_DEPTH:
            return ActionStatus.SUCCEEDED
        if seen is not None and self.draw_ins < GUIDE_DRAW_INS:
            return self.draw_in((seen.position[0], seen.position[1]))
        if self.in_phase_for() > self.ctx.follow_timeout_s:
            return self.fail(
                f"{self.person} was not seen in {self.target} {self.ctx.follow_timeout_s:g} s after arrival"
            )
        return ActionStatus.RUNNING

    def draw_in(self, seen: Point) -> ActionStatus:
        """Walk on to the room's point farthest from where the person is seen (they keep following)."""
        self.draw_ins += 1
        pose = self.ctx.robot.robot_pose()
        here = math.dist((pose.x, pose.y), seen)
        deeper = [
            p for p in [*self.room.waypoints, *self.room.inner_points()] if math.dist(p, seen) > here + 0.3
        ]
        if not deeper:
            self.draw_ins = GUIDE_DRAW_INS  # nowhere deeper: wait for them where the robot stands
            return ActionStatus.RUNNING
        far = sorted(deeper, key=lambda p: -math.dist(p, seen))
        self.nav = NavGoal(self.ctx, [to_point(self.ctx, p) for p in far], self.target)
        if not self.nav.start():
            return self.fail(
                f"cannot walk deeper into {self.target} to draw {self.person} in: {self.nav.reason}"
            )
        self.enter("nav")
        return ActionStatus.RUNNING

    def deactivation(self) -> bool:
        """End the escort (the person stays), stop the base unless succeeded."""
        self.ctx.robot.stop_escort()
        return super().deactivation()


__all__ = ["GuideAction", "MeetAction", "MoveAction", "Point", "approach_person"]
