"""Carrying out scenario events (:mod:`worlds.scenario`) in a running simulation."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from worlds.geometry import Point
from worlds.scenario import Event
from worlds.sim.people import PeopleController

if TYPE_CHECKING:
    from worlds.simulation import Simulation


def apply_event(sim: Simulation, people: PeopleController, ev: Event) -> None:
    """Carry out one due event; people's parts are queued as tasks and run over the following steps."""
    a = ev.args
    w = sim.world
    if ev.type == "doorbell":
        sim._ring()
        visitor = a.get("visitor")
        if visitor is not None:
            outside, inside = _front_door(sim)
            room = a.get("to") or next(d.room for d in w.devices.values() if d.kind == "bell")
            people.enqueue(visitor, "wait", float(a.get("enter_after", 5.0)))
            people.enqueue(visitor, "appear", outside)
            people.enqueue(visitor, "straight", inside)
            goal = sim.grid.nearest_free(*w.rooms[room].waypoint, 1.5)
            people.go_to(visitor, [goal] if goal else [])
    elif ev.type == "say":
        sim.hear(str(a["text"]), speaker=a["person"], audio_path=a.get("audio"))
    elif ev.type == "move_object":
        person, item, to = a["person"], a["item"], a["to"]
        it = sim._items[item]
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
            if a.get("teleport"):
                people.teleport(person, f.position[0], f.position[1], on=f.name)
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
        _place_items(sim, list(a.get("items") or sorted(w.items)))


def _front_door(sim: Simulation) -> tuple[Point, Point]:
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


def reachable(sim: Simulation, furniture: str, spots: list[Point]) -> list[Point]:
    """The spots on ``furniture`` the robot can grasp from a free point beside it (ERL places objects where a
    robot can take them; the middle of a deep sofa against a wall may be out of an arm's reach)."""
    reach = sim.world.robot.reach
    stands = sim.approach_points(furniture, reach=reach)
    if not stands or not spots:
        return []
    xs, ys = zip(*stands, strict=True)
    sx, sy = np.asarray(xs), np.asarray(ys)
    return [p for p in spots if float(np.min(np.hypot(sx - p[0], sy - p[1]))) <= reach - REACH_MARGIN]


def _place_items(sim: Simulation, names: list[str]) -> None:
    """Put each item on furniture drawn from its priors (weighted), at a random free spot within the robot's
    reach (seeded)."""
    rng = sim._rng_scenario
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
        it = sim._items[name]
        if it.holder is not None:
            continue
        it.on = None  # do not count the item as an obstacle to itself
        from worlds.sim.items import free_spots

        spots = reachable(sim, furniture, free_spots(f, it, list(sim._items.values())))
        if not spots:
            it.on = item.on
            continue
        x, y = spots[int(rng.integers(len(spots)))]
        it.x, it.y, it.z, it.on = x, y, f.height + it.size[2] / 2, furniture
