"""People in the apartment: where they are and what they do (walk, sit, carry an object, follow the robot).

Each person runs a queue of small tasks (walk to points, sit on furniture, take or put an item, wait)
filled by
scenario events, by their behaviour (``wander``) or by the robot (escorting). People walk on the same
grid map as
the robot at a fixed speed, yield to the robot (they wait rather than walk into it), and are kinematic. A
standing person the robot asks to make way (:meth:`PeopleController.make_way`) steps off the robot's path,
waits there :data:`MAKE_WAY_WAIT` seconds and then goes on with what they were doing.
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from worlds.geometry import Point, segment_distance, wrap_angle
from worlds.model import Person, World
from worlds.sim.navigation import GridMap

WALK_SPEED = 0.8  # m/s
FOLLOW_DISTANCE = 1.0  # metres behind the robot when escorted
MAKE_WAY_WAIT = 8.0  # seconds a person who made way for the robot waits aside
PUT_NEARBY_CANDIDATES = 4  # nearest pieces of furniture tried when the meant one is out of reach
HAND_REACH = 0.12  # metres in front of the body's surface where a carried item is held
HAND_HEIGHT = 0.95  # metres above the feet where a carried item is held


class PeopleHooks(Protocol):
    """What people need from the simulation (implemented by :class:`worlds.simulation.Simulation`)."""

    def person_take(self, person: str, item: str) -> bool:
        """The person takes the item if it is within their reach and free."""
        ...

    def person_put(self, person: str, furniture: str) -> bool:
        """The person puts what they carry on the furniture."""
        ...

    def approach_points(self, furniture: str, near: Point | None = None) -> list[Point]:
        """Free points from which the furniture (or ``near`` on it) is within reach."""
        ...

    def items_on(self, furniture: str) -> list[tuple[Point, float]]:
        """Centre and half length of every item standing on the furniture."""
        ...


@dataclass
class PersonState:
    """A person's true state (world frame).

    Attributes:
        name: PDDL symbol.
        x: metres.
        y: metres.
        yaw: heading, radians.
        on: furniture the person sits or lies on, or ``None``.
        present: False while outside the apartment.
        carrying: item the person holds, or ``None``.
        following: True while escorted by the robot.
    """

    name: str
    radius: float
    height: float
    x: float
    y: float
    behaviour: str
    present: bool
    on: str | None = None
    yaw: float = 0.0
    carrying: str | None = None
    following: bool = False
    tasks: deque[tuple[str, Any]] = field(default_factory=deque)
    path: list[Point] = field(default_factory=list)
    path_index: int = 0
    wait_until: float = 0.0
    replan_at: float = 0.0
    blocked_for: float = 0.0

    def z_base(self, world: World) -> float:
        """Height of the person's feet: the furniture top when sitting or lying, else 0."""
        return world.furniture[self.on].height if self.on else 0.0

    def hand_point(self, world: World) -> tuple[float, float, float]:
        """Where an item the person carries is (world frame, metres): held in front of the body at
        :data:`HAND_REACH` metres beyond its surface, at :data:`HAND_HEIGHT` above their feet. Outside the
        body, so a camera facing them sees it (from behind, the body hides it)."""
        reach = self.radius + HAND_REACH
        return (
            self.x + reach * math.cos(self.yaw),
            self.y + reach * math.sin(self.yaw),
            self.z_base(world) + HAND_HEIGHT,
        )


class PeopleController:
    """Moves every person one control period at a time (see module doc)."""

    def __init__(self, world: World, grid: GridMap, hooks: PeopleHooks, rng: np.random.Generator) -> None:
        self.world = world
        self.grid = grid
        self.hooks = hooks
        self.rng = rng
        self.people: dict[str, PersonState] = {p.name: self._initial(p) for p in world.people.values()}

    @staticmethod
    def _initial(p: Person) -> PersonState:
        return PersonState(
            name=p.name,
            radius=p.radius,
            height=p.height,
            x=p.position[0],
            y=p.position[1],
            behaviour=p.behaviour,
            present=p.present,
            on=p.on,
        )

    def discs(self) -> list[tuple[str, float, float, float]]:
        """``(name, x, y, radius)`` of the people present and standing (not on furniture)."""
        return [(p.name, p.x, p.y, p.radius) for p in self.people.values() if p.present and p.on is None]

    # ------------------------------------------------------------------------------------------ tasks

    def go_to(self, name: str, points: Sequence[Point]) -> None:
        """Queue a walk to the nearest reachable of ``points`` (after getting up if sitting)."""
        self.people[name].tasks.append(("goto", list(points)))

    def sit(self, name: str, furniture: str) -> None:
        """Queue walking to the furniture and sitting (or lying) on it; at furniture too high to sit on
        (:attr:`~worlds.model.Furniture.seat`) the person stands beside it."""
        self.go_to(name, self.hooks.approach_points(furniture))
        self.people[name].tasks.append(("sit", furniture))

    def enqueue(self, name: str, task: str, arg: Any) -> None:
        """Queue a raw task: ``appear`` (x, y), ``straight`` (x, y), ``take`` item, ``put`` furniture,
        ``wait`` s."""
        self.people[name].tasks.append((task, arg))

    def taken(self, furniture: str, person: str) -> list[tuple[Point, float]]:
        """Centre and half size of what is on the furniture that ``person`` would not sit on: the items
        there and the other people sitting there."""
        others = [
            ((q.x, q.y), q.radius) for q in self.people.values() if q.on == furniture and q.name != person
        ]
        return self.hooks.items_on(furniture) + others

    def teleport(self, name: str, x: float, y: float, on: str | None = None) -> None:
        """Put a person somewhere at once (present), dropping their queued tasks."""
        p = self.people[name]
        p.tasks.clear()
        p.path = []
        p.x, p.y, p.on, p.present = x, y, on, True

    # ------------------------------------------------------------------------------------------ update

    def update(self, dt: float, now: float, robot: tuple[float, float, float]) -> None:
        """Advance every person by ``dt`` seconds; ``robot`` is ``(x, y, radius)`` of the robot base."""
        for p in self.people.values():
            if not p.present and not p.tasks:
                continue
            if p.following:
                self._follow(p, dt, now, robot)
                continue
            if now < p.wait_until:
                continue
            if not p.tasks and p.behaviour == "wander" and p.on is None:
                room = self.world.rooms[
                    sorted(self.world.rooms)[int(self.rng.integers(len(self.world.rooms)))]
                ]
                self.go_to(p.name, [room.waypoint])
                p.tasks.append(("wait", float(self.rng.uniform(5.0, 20.0))))
            if p.tasks:
                self._run_task(p, dt, now, robot)

    def _run_task(self, p: PersonState, dt: float, now: float, robot: tuple[float, float, float]) -> None:
        kind, arg = p.tasks[0]
        if kind == "appear":
            p.x, p.y, p.present, p.on = arg[0], arg[1], True, None
            p.tasks.popleft()
        elif kind == "wait":
            p.wait_until = now + float(arg)
            p.tasks.popleft()
        elif kind == "take":
            self.hooks.person_take(p.name, arg)
            p.tasks.popleft()
        elif kind == "put":
            if not self.hooks.person_put(p.name, arg):
                self._put_nearby(p)
            p.tasks.popleft()
        elif kind == "sit":
            f = self.world.furniture[arg]
            if f.seat:  # at a table or a counter the person stays standing where they walked to
                (p.x, p.y), p.on = f.seat_spot(p.radius, self.taken(arg, p.name)), arg
            p.tasks.popleft()
        elif kind == "straight":
            if self._walk_towards(p, arg, dt, robot):
                p.tasks.popleft()
        elif kind == "goto":
            if not self._stand_up(p, robot):
                return
            if not p.path:
                path = self.grid.plan((p.x, p.y), arg)
                if path is None:  # nowhere to go: give the task up
                    p.tasks.popleft()
                    return
                p.path, p.path_index = path, 1
            elif p.blocked_for > 2.0:  # the robot is in the way: step back out of its way, then go on
                p.blocked_for = 0.0
                aside = self._aside_points(p, robot)
                if aside:
                    p.path = []
                    p.tasks.appendleft(("goto", aside))
                    return
            if p.path_index >= len(p.path):
                p.path = []
                p.tasks.popleft()
                return
            if self._walk_towards(p, p.path[p.path_index], dt, robot):
                p.path_index += 1

    def _put_nearby(self, p: PersonState) -> None:
        """The furniture meant for what ``p`` carries is out of their reach (no way to it): they put it on the
        nearest furniture they can reach instead, as a person would, rather than carrying it for good."""
        if p.carrying is None:
            return
        near = sorted(
            self.world.furniture.values(), key=lambda f: math.hypot(f.position[0] - p.x, f.position[1] - p.y)
        )
        for f in near[:PUT_NEARBY_CANDIDATES]:
            if self.hooks.person_put(p.name, f.name):
                return

    def follow(self, name: str | None) -> None:
        """``name`` follows the robot from now on (their queued tasks dropped); nobody else does. None: nobody
        follows any more (everyone's path is planned afresh)."""
        for q in self.people.values():
            q.following = False
            if name is None:
                q.path = []
        if name is not None:
            self.people[name].following = True
            self.people[name].tasks.clear()

    def make_way(
        self, name: str, now: float, robot: tuple[float, float, float], path: Sequence[Point]
    ) -> bool:
        """The robot asks ``name`` to let it pass: a person standing (present, not sitting, not escorted)
        walks to the nearest free spot off the robot's ``path`` (world points from the robot's base on), waits
        there :data:`MAKE_WAY_WAIT` seconds (or what was left of a wait, if longer) and then goes on with
        their tasks. False (and nothing changes) when they cannot: sitting, escorted, absent, or no spot."""
        p = self.people.get(name)
        if p is None or not p.present or p.on is not None or p.following:
            return False
        spots = self._off_path_points(p, robot, path)
        if not spots:
            return False
        left = max(0.0, p.wait_until - now)
        p.wait_until, p.path, p.blocked_for = now, [], 0.0
        p.tasks.appendleft(("wait", max(MAKE_WAY_WAIT, left)))
        p.tasks.appendleft(("goto", spots))
        return True

    def _off_path_points(
        self, p: PersonState, robot: tuple[float, float, float], path: Sequence[Point]
    ) -> list[Point]:
        """Free points 0.6-2.0 m from the person, clear of the robot's path and of the robot; nearest
        first."""
        rx, ry, rr = robot
        clear = rr + p.radius + 0.15
        legs = list(itertools.pairwise(path)) if len(path) > 1 else [((rx, ry), (rx, ry))]
        out = []
        for k in range(24):
            ang = 2 * math.pi * k / 24
            for dist in (0.6, 0.9, 1.2, 1.6, 2.0):
                x, y = p.x + dist * math.cos(ang), p.y + dist * math.sin(ang)
                if not self.grid.is_free(x, y) or math.hypot(x - rx, y - ry) < clear + 0.3:
                    continue
                if min(segment_distance(x, y, a, b) for a, b in legs) >= clear:
                    out.append((dist, (x, y)))
        return [pt for _, pt in sorted(out)]

    def _aside_points(self, p: PersonState, robot: tuple[float, float, float]) -> list[Point]:
        """Free points 0.8-1.6 m away from the person, away from the robot and 1.3 m or more from it."""
        rx, ry, _ = robot
        out = []
        for k in range(16):
            ang = 2 * math.pi * k / 16
            for dist in (0.8, 1.2, 1.6):
                x, y = p.x + dist * math.cos(ang), p.y + dist * math.sin(ang)
                away = (x - p.x) * (p.x - rx) + (y - p.y) * (p.y - ry) > 0
                if away and math.hypot(x - rx, y - ry) >= 1.3 and self.grid.is_free(x, y):
                    out.append((x, y))
        return out

    def _stand_up(self, p: PersonState, robot: tuple[float, float, float]) -> bool:
        """Get up from the furniture onto the nearest free floor point beside it that is clear of the robot
        and of everyone standing (``robot``: x, y, radius). False when there is none yet: the person stays
        seated and tries again next step (the robot standing close by is in the way)."""
        if p.on is None:
            return True
        rx, ry, rr = robot
        standing = [(q.x, q.y, q.radius) for q in self.people.values() if q.present and q.on is None]
        clear = [
            q
            for q in self.hooks.approach_points(p.on, (p.x, p.y))
            if math.hypot(q[0] - rx, q[1] - ry) >= rr + p.radius + 0.1
            and all(math.hypot(q[0] - x, q[1] - y) >= r + p.radius + 0.05 for x, y, r in standing)
        ]
        if not clear:
            return False
        p.x, p.y = min(clear, key=lambda q: math.hypot(q[0] - p.x, q[1] - p.y))
        p.on = None
        return True

    def _walk_towards(
        self, p: PersonState, target: Point, dt: float, robot: tuple[float, float, float]
    ) -> bool:
        """One step towards ``target``; True when reached. Waits when the robot is in the way."""
        dx, dy = target[0] - p.x, target[1] - p.y
        dist = math.hypot(dx, dy)
        if dist < 1e-6:
            return True
        step = min(WALK_SPEED * dt, dist)
        nx, ny = p.x + dx / dist * step, p.y + dy / dist * step
        rx, ry, rr = robot
        if math.hypot(nx - rx, ny - ry) < rr + p.radius + 0.05 and math.hypot(nx - rx, ny - ry) < math.hypot(
            p.x - rx, p.y - ry
        ):
            p.blocked_for += dt
            return False  # yield to the robot
        p.blocked_for = 0.0
        p.x, p.y = nx, ny
        p.yaw = wrap_angle(math.atan2(dy, dx))
        return step >= dist - 1e-9

    def _follow(self, p: PersonState, dt: float, now: float, robot: tuple[float, float, float]) -> None:
        if not self._stand_up(p, robot):
            return
        rx, ry, _ = robot
        if math.hypot(rx - p.x, ry - p.y) <= FOLLOW_DISTANCE:
            p.path = []
            return
        if not p.path or now >= p.replan_at:
            goal = self.grid.nearest_free(rx, ry, 0.5)
            path = self.grid.plan((p.x, p.y), [goal]) if goal else None
            p.path, p.path_index, p.replan_at = (path or []), 1, now + 1.0
        if p.path_index < len(p.path) and self._walk_towards(p, p.path[p.path_index], dt, robot):
            p.path_index += 1
