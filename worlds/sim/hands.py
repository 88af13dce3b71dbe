"""Who holds what: the robot's gripper and people's hands over the items' true state.

:class:`Hands` carries out the gripper commands of the simulated robot (pick, place, release, give) and the
people's take and put (it is the people controller's :class:`~worlds.sim.people.PeopleHooks`). It changes the
shared :class:`~worlds.sim.items.ItemState` table in place; the simulation reads it for rendering and ground
truth. Distances are horizontal, metres, from the base centre (the robot) or the person's position.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from core.errors import WorldError
from core.robot import CAUSE_HAND, CAUSE_NOT_AT_BELIEF, CAUSE_OUT_OF_REACH, CommandResult, Vec3
from worlds.geometry import Point
from worlds.model import World
from worlds.sim.goals import approach_points
from worlds.sim.items import ItemState, free_spots, items_on
from worlds.sim.navigation import GridMap
from worlds.sim.people import PersonState
from worlds.sim.robot import BaseController

PERSON_REACH = 0.8  # metres, how far people reach to take or put an item
GIVE_REACH_EXTRA = 0.35  # the robot reaches a person's hand this much farther than its gripper reach
MAX_PICK_HEIGHT = 1.6  # metres, the highest item the gripper reaches
HANDOVER_TOLERANCE = 0.5  # metres between where the arm offers an item and the person who takes it


class Hands:
    """The gripper and people's hands (see the module docstring).

    Args:
        world: the world data.
        grid: the occupancy grid (for the points people stand at to reach furniture).
        items: the items' true state, changed in place.
        base: the robot's base (its position and heading).

    Attributes:
        held: the item in the gripper, or None.
        drops: items released in mid-air so far.
        people: the people's true state; set by the simulation once the people controller exists.
    """

    def __init__(
        self, world: World, grid: GridMap, items: Mapping[str, ItemState], base: BaseController
    ) -> None:
        self.world = world
        self.grid = grid
        self.items = items
        self.base = base
        self.held: str | None = None
        self.drops = 0
        self.people: Mapping[str, PersonState] = {}

    # ------------------------------------------------------------------------------------------ gripper

    def items_on(self, furniture: str) -> list[tuple[Point, float]]:
        """Centre ``(x, y)`` and half length of every item standing on the furniture."""
        return items_on(self.items, furniture)

    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        """Attach an item within reach to the empty gripper.

        ``at``: the true world point the arm is sent to (the simulation has already turned the robot's
        believed point into it); the grasp closes on the item only when its centre lies within the robot's
        ``grasp_tolerance`` of that point (horizontally; twice that vertically).
        """
        if item not in self.items:
            raise WorldError(f"pick: unknown item {item!r}")
        it = self.items[item]
        if self.held is not None:
            return CommandResult(False, f"hand is not empty: holding {self.held}", CAUSE_HAND)
        reach = self.world.robot.reach
        if at is not None:
            d = math.hypot(at[0] - self.base.x, at[1] - self.base.y)
            if d > reach:
                return CommandResult(
                    False,
                    f"the believed position of {item} is {d:.2f} m away, reach is {reach:.2f} m",
                    CAUSE_OUT_OF_REACH,
                )
            tol = self.world.robot.grasp_tolerance
            if math.hypot(it.x - at[0], it.y - at[1]) > tol or abs(it.z - at[2]) > 2 * tol:
                return CommandResult(
                    False,
                    f"the gripper closed on nothing: {item} is not at its believed position"
                    f" ({at[0]:.2f}, {at[1]:.2f}, {at[2]:.2f})",
                    CAUSE_NOT_AT_BELIEF,
                )
        if it.holder is not None:
            return CommandResult(False, f"{item} is held by {it.holder}", CAUSE_HAND)
        d = math.hypot(it.x - self.base.x, it.y - self.base.y)
        if d > reach:
            return CommandResult(
                False, f"{item} is {d:.2f} m away, reach is {reach:.2f} m", CAUSE_OUT_OF_REACH
            )
        if it.z > MAX_PICK_HEIGHT:
            return CommandResult(False, f"{item} is too high ({it.z:.2f} m)", CAUSE_OUT_OF_REACH)
        it.holder, it.on, it.vz = self.world.robot.name, None, None
        self.held = item
        self.carry(it)
        return CommandResult(True)

    def place(self, furniture: str) -> CommandResult:
        """Put the held item on the furniture at the free spot nearest the robot, within reach."""
        if furniture not in self.world.furniture:
            raise WorldError(f"place: unknown furniture {furniture!r}")
        if self.held is None:
            return CommandResult(False, "hand is empty")
        f = self.world.furniture[furniture]
        reach = self.world.robot.reach
        if not f.surface:
            return CommandResult(False, f"{furniture} has no surface to put things on")
        d = f.distance(self.base.x, self.base.y)
        if d > reach:
            return CommandResult(False, f"{furniture} is {d:.2f} m away, reach is {reach:.2f} m")
        it = self.items[self.held]
        spot = self._nearest_spot(f.name, it, (self.base.x, self.base.y), reach)
        if spot is None:
            return CommandResult(False, f"no free spot on {furniture} within reach")
        it.x, it.y, it.z = spot[0], spot[1], f.height + it.size[2] / 2
        it.holder, it.on = None, furniture
        self.held = None
        return CommandResult(True)

    def release(self) -> CommandResult:
        """Open the gripper in mid-air: the item falls and counts as dropped."""
        if self.held is None:
            return CommandResult(False, "hand is empty")
        it = self.items[self.held]
        it.holder, it.on, it.vz = None, None, 0.0
        self.held = None
        self.drops += 1
        return CommandResult(True)

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Hand the held item to a person within reach (``at``: the true point the arm offers it at; the
        person must stand within :data:`HANDOVER_TOLERANCE` of it)."""
        if person not in self.people:
            raise WorldError(f"give: unknown person {person!r}")
        p = self.people[person]
        if self.held is None:
            return CommandResult(False, "hand is empty", CAUSE_HAND)
        if at is not None and (not p.present or math.hypot(p.x - at[0], p.y - at[1]) > HANDOVER_TOLERANCE):
            return CommandResult(
                False,
                f"nobody took the item: {person} is not at the believed position ({at[0]:.2f}, {at[1]:.2f})",
                CAUSE_NOT_AT_BELIEF,
            )
        d = math.hypot(p.x - self.base.x, p.y - self.base.y)
        reach = self.world.robot.reach + GIVE_REACH_EXTRA
        if not p.present or d > reach:
            return CommandResult(
                False, f"{person} is {d:.2f} m away, reach is {reach:.2f} m", CAUSE_OUT_OF_REACH
            )
        if p.carrying is not None:
            return CommandResult(False, f"{person} already holds {p.carrying}", CAUSE_HAND)
        it = self.items[self.held]
        it.holder = person
        p.carrying = it.name
        self.held = None
        self.carry(it)
        return CommandResult(True)

    # ------------------------------------------------------------------------------------------ PeopleHooks

    def person_take(self, person: str, item: str) -> bool:
        """A person takes an item within their reach (scenario helper)."""
        p, it = self.people[person], self.items[item]
        if it.holder is not None or p.carrying is not None:
            return False
        if math.hypot(it.x - p.x, it.y - p.y) > PERSON_REACH + 0.3:
            return False
        it.holder, it.on, it.vz = person, None, None
        p.carrying = item
        self.carry(it)
        return True

    def person_put(self, person: str, furniture: str) -> bool:
        """A person puts what they carry on the furniture (scenario helper)."""
        p = self.people[person]
        if p.carrying is None:
            return False
        it, f = self.items[p.carrying], self.world.furniture[furniture]
        spot = self._nearest_spot(furniture, it, (p.x, p.y), PERSON_REACH + 0.3)
        if spot is None:
            return False
        it.x, it.y, it.z = spot[0], spot[1], f.height + it.size[2] / 2
        it.holder, it.on = None, furniture
        p.carrying = None
        return True

    def approach_points(self, furniture: str, near: Point | None = None) -> list[Point]:
        """Free points from which a person reaches the furniture (``near`` on it when possible)."""
        return approach_points(self.world, self.grid, furniture, near, PERSON_REACH)

    # ------------------------------------------------------------------------------------------ carrying

    def carry(self, it: ItemState) -> None:
        """Move a held item with its holder (in front of the robot's base, at a person's hands)."""
        if it.holder == self.world.robot.name:
            r = self.base
            it.x, it.y, it.z = r.x + 0.3 * math.cos(r.yaw), r.y + 0.3 * math.sin(r.yaw), 0.8
        elif it.holder is not None:
            it.x, it.y, it.z = self.people[it.holder].hand_point(self.world)

    def _nearest_spot(self, furniture: str, it: ItemState, origin: Point, reach: float) -> Point | None:
        spots = free_spots(self.world.furniture[furniture], it, list(self.items.values()))
        spots = [s for s in spots if math.dist(s, origin) <= reach]
        return min(spots, key=lambda s: (math.dist(s, origin), s)) if spots else None
