"""Carrying out scenario events (:mod:`worlds.scenario`) in a running simulation.

The simulation hands itself in as an :class:`EventHost` (the few hooks the events need) together with the
state the events change directly (people, items, the scenario's random generator); this module knows
nothing else of the simulator.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Protocol

import numpy as np

from core.robot import CommandResult
from worlds.geometry import Point
from worlds.model import World
from worlds.scenario import CALL_TEXT, Event
from worlds.sim.items import ItemState, free_spots
from worlds.sim.navigation import GridMap
from worlds.sim.people import PeopleController


class EventHost(Protocol):
    """What scenario events use of the simulation (:class:`worlds.simulation.Simulation` satisfies it)."""

    grid: GridMap

    @property
    def world(self) -> World:
        """The world data."""
        ...

    def ring_bell(self) -> None:
        """The door bell rings now (a sound event, the bell's state)."""
        ...

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        """A person says ``text`` now."""
        ...

    def set_light(self, device: str, on: bool) -> CommandResult:
        """Switch a light."""
        ...

    def set_level(self, device: str, percent: float) -> CommandResult:
        """Set a dimmer or blinds."""
        ...

    def approach_points(self, furniture: str, near: Point | None = None, reach: float = ...) -> list[Point]:
        """Free points from which ``furniture`` (``near`` on it) is within ``reach``."""
        ...


def apply_event(
    sim: EventHost,
    people: PeopleController,
    items: Mapping[str, ItemState],
    rng: np.random.Generator,
    ev: Event,
) -> None:
    """Carry out one due event; people's parts are queued as tasks and run over the following steps.

    Args:
        sim: the simulation's hooks.
        people: the people controller (tasks are queued on it).
        items: the items' true state (``place_items`` moves them).
        rng: the scenario's random generator (``place_items`` draws from it).
        ev: the event.
    """
    a = ev.args
    w = sim.world
    if ev.type == "doorbell":
        sim.ring_bell()
        visitor = a.get("visitor")
        if visitor is not None:
            outside, inside = _front_door(sim)
            room = a.get("to") or next(d.room for d in w.devices.values() if d.kind == "bell")
            people.enqueue(visitor, "wait", float(a.get("enter_after", 5.0)))
            people.enqueue(visitor, "appear", outside)
            people.enqueue(visitor, "straight", inside)
            if a.get("enter", True):
                goal = sim.grid.nearest_free(*w.rooms[room].waypoint, 1.5)
                people.go_to(visitor, [goal] if goal else [])
    elif ev.type == "call":
        sim.hear(CALL_TEXT, speaker=a["person"])
    elif ev.type == "say":
        sim.hear(str(a["text"]), speaker=a["person"], audio_path=a.get("audio"))
    elif ev.type == "move_object":
        person, item, to = a["person"], a["item"], a["to"]
        it = items[item]
        source = it.on or w.room_of(it.x, it.y)
        if it.on is not None:
            people.go_to(person, sim.approach_points(it.on, (it.x, it.y)))
        elif source is not None:
            goal = sim.grid.nearest_free(it.x, it.y, 1.0)
            people.go_to(person, [goal] if goal else [])
        people.enqueue(person, "take", item)
        people.go_to(person, sim.approach_points(to))
        people.enqueue(person, "put", to)
    elif ev.type == "person_to":
        person = a["person"]
        if "furniture" in a:
            f = w.furniture[a["furniture"]]
            if a.get("teleport") and f.seat:  # in the middle, or beside the items standing there
                spot = f.seat_spot(people.people[person].radius, people.taken(f.name, person))
                people.teleport(person, spot[0], spot[1], on=f.name)
            elif a.get("teleport"):  # a table, a counter: the free place beside it nearest its middle
                spots = sorted(sim.approach_points(f.name), key=lambda q: f.distance(*q))
                if spots:
                    people.teleport(person, *spots[0])
            else:
                people.sit(person, f.name)
        else:
            goal = sim.grid.nearest_free(*w.rooms[a["room"]].waypoint, 1.5)
            if goal is None:
                return
            if a.get("teleport"):
                people.teleport(person, goal[0], goal[1])
            else:
                people.go_to(person, [goal])
    elif ev.type == "set_device":
        d = w.devices[a["device"]]
        v = a["value"]
        if d.kind == "light":
            sim.set_light(d.name, bool(v))
        elif d.kind in ("dimmer", "blinds"):
            sim.set_level(d.name, float(v))
    elif ev.type == "place_items":
        _place_items(sim, items, rng, list(a.get("items") or sorted(w.items)))


def _front_door(sim: EventHost) -> tuple[Point, Point]:
    """A point 1 m outside and one 0.6 m inside the front door (a door with one room)."""
    w = sim.world
    door = next((d for d in w.doors if len(d.rooms) == 1), None)
    if door is None:  # no front door: visitors appear at the bell
        bell = next(d for d in w.devices.values() if d.kind == "bell")
        p = sim.grid.nearest_free(bell.position[0], bell.position[1], 1.5) or (
            bell.position[0],
            bell.position[1],
        )
        return p, p
    room = w.rooms[door.rooms[0]]
    cx, cy = room.centroid
    dx, dy = cx - door.position[0], cy - door.position[1]
    # the wall normal pointing into the room: the axis along which the centroid lies farther
    nx, ny = (math.copysign(1.0, dx), 0.0) if abs(dx) > abs(dy) else (0.0, math.copysign(1.0, dy))
    outside = (door.position[0] - nx, door.position[1] - ny)
    inside = (door.position[0] + 0.6 * nx, door.position[1] + 0.6 * ny)
    return outside, inside


#: how far inside the robot's reach a placed item must lie from some free spot beside its furniture (m)
REACH_MARGIN = 0.1


def reachable(sim: EventHost, furniture: str, spots: list[Point]) -> list[Point]:
    """The spots on ``furniture`` the robot can grasp from a free point beside it (ERL places objects where a
    robot can take them; the middle of a deep sofa against a wall may be out of an arm's reach)."""
    reach = sim.world.robot.reach
    stands = sim.approach_points(furniture, reach=reach)
    if not stands or not spots:
        return []
    xs, ys = zip(*stands, strict=True)
    sx, sy = np.asarray(xs), np.asarray(ys)
    return [p for p in spots if float(np.min(np.hypot(sx - p[0], sy - p[1]))) <= reach - REACH_MARGIN]


def _place_items(
    sim: EventHost, items: Mapping[str, ItemState], rng: np.random.Generator, names: list[str]
) -> None:
    """Put each item on furniture drawn from its priors (weighted), at a random free spot within the robot's
    reach (seeded)."""
    for name in names:
        item = sim.world.items[name]
        options = [p for p in item.priors if p.furniture is not None]
        if not options:
            continue
        weights = [p.probability for p in options]
        total = sum(weights)
        k = int(rng.choice(len(options), p=[x / total for x in weights]))
        furniture = options[k].furniture
        assert furniture is not None
        f = sim.world.furniture[furniture]
        it = items[name]
        if it.holder is not None:
            continue
        it.on = None  # do not count the item as an obstacle to itself
        spots = reachable(sim, furniture, free_spots(f, it, list(items.values())))
        if not spots:
            it.on = item.on
            continue
        x, y = spots[int(rng.integers(len(spots)))]
        it.x, it.y, it.z, it.on = x, y, f.height + it.size[2] / 2, furniture
