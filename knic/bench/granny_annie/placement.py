"""Where the served person (Annie) waits and where the items stand at the start of an episode.

Items are drawn from their priors (weighted by probability) and, with probability :data:`OFF_PRIOR_P`, put
on a surface none of their priors names. The world loader spreads the items of one piece of furniture along
its long side (:func:`worlds.loader.surface_slots`); a spot the robot cannot reach from a free floor point
(the back of a deep sofa, the middle of a bed against the walls) is replaced by a reachable option, as the ERL
referees put objects where a robot can take them.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from core.errors import KnicError
from knic.bench.granny_annie.commands import pick

if TYPE_CHECKING:
    from worlds.model import World

#: probability that an item is placed where none of its priors says
OFF_PRIOR_P = 0.1


def draw_seat(world: World, rng: np.random.Generator, person: str) -> tuple[str | None, str]:
    """(furniture ``person`` waits on or None, their room): their priors' furniture, else the bed or the sofa,
    else where the world file puts them.

    Raises:
        KnicError: the world has no such person present, or they stand outside every room.
    """
    annie = world.people.get(person)
    if annie is None or not annie.present:
        raise KnicError(f"world {world.name}: no person {person!r} in the apartment to serve")
    options = [p for p in annie.priors if p.furniture is not None]
    if options:
        on = pick(rng, [p.furniture for p in options], [p.probability for p in options])
    else:
        beds = [f for f in ("bed", "sofa") if f in world.furniture]
        on = pick(rng, beds) if beds else annie.on
    if on is not None:
        return on, world.furniture[on].room
    room = world.room_of(*annie.position)
    if room is None:
        raise KnicError(f"world {world.name}: {person} stands outside every room")
    return None, room


def draw_placements(
    world: World, rng: np.random.Generator, sitter: str | None = None, seat: str | None = None
) -> tuple[dict[str, str], list[str]]:
    """Item -> furniture (priors weighted, sometimes off-prior) and the items placed off-prior; a spot where
    ``sitter`` sits on ``seat`` (its middle) is no place for an item (it would stand inside them)."""

    def takeable(name: str) -> bool:
        return graspable(world, placements, name) and not under_sitter(world, placements, name, sitter, seat)

    surfaces = sorted(f.name for f in world.furniture.values() if f.surface)
    placements: dict[str, str] = {}
    for name in sorted(world.items):
        item = world.items[name]
        priors = [p for p in item.priors if p.furniture is not None]
        named = {p.furniture for p in priors}
        draw_off = rng.random() < OFF_PRIOR_P
        others = [f for f in surfaces if f not in named]
        if draw_off and others:
            placements[name] = pick(rng, others)
        elif priors:
            placements[name] = pick(rng, [p.furniture for p in priors], [p.probability for p in priors])
        elif item.on is not None:
            placements[name] = item.on
    for name in sorted(placements):
        if takeable(name):
            continue
        usual = [p.furniture for p in world.items[name].priors if p.furniture is not None]
        on = world.items[name].on
        original = [on] if on is not None else []
        for f in [*usual, *original, *surfaces]:
            placements[name] = f
            if takeable(name):
                break
    return placements, [n for n in sorted(placements) if _off_prior(world, n, placements[n])]


def _off_prior(world: World, name: str, furniture: str) -> bool:
    """Placed where none of the item's priors says (an item without priors: away from its file place)."""
    item = world.items[name]
    usual = {p.furniture for p in item.priors if p.furniture is not None}
    return furniture not in usual if usual else furniture != item.on


def item_spot(world: World, placements: dict[str, str], name: str) -> tuple[float, float]:
    """Where the world loader puts ``name`` given ``placements`` (spread along the furniture's long side)."""
    from worlds.loader import surface_slots

    furniture = placements[name]
    on_it = [n for n in world.items if placements.get(n) == furniture]  # world file order, as the loader
    return surface_slots(world.furniture[furniture], len(on_it))[on_it.index(name)]


def graspable(world: World, placements: dict[str, str], name: str, margin: float = 0.1) -> bool:
    """True when the item stands low enough for the gripper and a free floor point of the furniture's room
    lies within the robot's reach (less ``margin``) of its spot; free: the robot's base keeps clear of walls
    and furniture."""
    f = world.furniture[placements[name]]
    if not within_arm_height(world, f.name, name):
        return False
    x, y = item_spot(world, placements, name)
    cache = _cache(world)[1]
    key = (f.name, round(x, 3), round(y, 3), margin)
    if key not in cache:
        cache[key] = _free_point_near(world, f.room, x, y, world.robot.reach - margin)
    return bool(cache[key])


def under_sitter(
    world: World, placements: dict[str, str], name: str, sitter: str | None, seat: str | None
) -> bool:
    """True when the item's spot lies where ``sitter`` sits on ``seat`` (within their body radius plus the
    item's half length and 5 cm of the seat's middle, where the simulation seats people)."""
    if sitter is None or seat is None or placements.get(name) != seat:
        return False
    x, y = item_spot(world, placements, name)
    cx, cy = world.furniture[seat].position
    item = world.items[name]
    return math.hypot(x - cx, y - cy) < world.people[sitter].radius + max(item.size[:2]) / 2 + 0.05


def within_arm_height(world: World, furniture: str, item: str | None = None) -> bool:
    """True when an item (default: a 0.1 m one) on ``furniture`` stands low enough for the gripper."""
    from worlds.sim.hands import MAX_PICK_HEIGHT

    half = world.items[item].size[2] / 2 if item is not None else 0.05
    return world.furniture[furniture].height + half <= MAX_PICK_HEIGHT


def _free_point_near(world: World, room_name: str, x: float, y: float, reach: float) -> bool:
    monitor = _cache(world)[0]
    need = world.robot.radius + 0.03
    room = world.rooms[room_name]
    for r in np.linspace(world.robot.radius + 0.05, reach, 5):
        for a in np.linspace(0.0, 2 * math.pi, 24, endpoint=False):
            px, py = x + r * math.cos(a), y + r * math.sin(a)
            if room.contains(px, py) and monitor.clearance(px, py) >= need:
                return True
    return False


_CACHE: list[Any] = []  # [world, (ContactMonitor, {spot: graspable})] of the last world asked about


def _cache(world: World) -> tuple[Any, dict[tuple[Any, ...], bool]]:
    from worlds.sim.contacts import ContactMonitor

    if not _CACHE or _CACHE[0] is not world:
        _CACHE[:] = [world, (ContactMonitor(world), {})]
    return _CACHE[1]


def world_document(world: World, placements: dict[str, str]) -> dict[str, Any]:
    """The world file's document with every item on its episode furniture (positions left to the loader).

    Raises:
        KnicError: the world was not read from a file.
    """
    from core.inputs import read_yaml

    if world.source is None:
        raise KnicError(f"world {world.name}: no world file to derive the episode's world from")
    data = read_yaml(world.source, "world file", KnicError)
    for entry in data.get("items", []):
        name = entry.get("name")
        if name in placements:
            entry.pop("position", None)
            entry["furniture"] = placements[name]
    return dict(data)
