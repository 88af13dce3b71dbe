"""Ground truth of the ERL domain's dynamic facts, computed from the simulator's true state."""

from __future__ import annotations

import math
from collections.abc import Mapping

from worlds.model import World
from worlds.sim.items import ItemState
from worlds.sim.people import PersonState

PERSON_NEAR = 1.5  # metres
LEVELS = ("l0", "l25", "l50", "l75", "l100")


def level_symbol(percent: float) -> str:
    """The level constant nearest to a percentage (0-100): 0-12.5 -> l0, ... 87.5-100 -> l100."""
    idx = math.floor(max(0.0, min(100.0, percent)) / 25.0 + 0.5)
    return LEVELS[min(idx, 4)]


def ground_truth(
    world: World,
    robot_xy: tuple[float, float],
    held: str | None,
    items: Mapping[str, ItemState],
    people: Mapping[str, PersonState],
    devices: Mapping[str, float],
    ringing: bool,
) -> set[tuple[str, ...]]:
    """The true dynamic facts (see :meth:`worlds.api.SimulationAPI.ground_truth_facts`)."""
    facts: set[tuple[str, ...]] = set()
    robot = world.robot.name
    room = world.room_of(*robot_xy)
    if room is not None:
        facts.add(("robot_at", robot, room))
    if held is None:
        facts.add(("hand_empty", robot))
    else:
        facts.add(("holding", robot, held))
    present = [p for p in people.values() if p.present]
    for p in present:
        r = world.room_of(p.x, p.y)
        if r is not None:
            facts.add(("person_at", p.name, r))
    for i, p in enumerate(present):
        for q in present[i + 1 :]:
            if math.hypot(p.x - q.x, p.y - q.y) <= PERSON_NEAR:
                facts.add(("person_near", p.name, q.name))
                facts.add(("person_near", q.name, p.name))
    for it in items.values():
        if it.holder is not None:
            if it.holder != robot:
                facts.add(("has", it.holder, it.name))
            continue
        r = world.room_of(it.x, it.y)
        if r is not None:
            facts.add(("object_at", it.name, r))
        if it.on is not None and it.vz is None:
            facts.add(("object_on", it.name, it.on))
    for d in world.devices.values():
        value = devices[d.name]
        if d.kind == "light":
            facts.add(("light_on", d.name) if value > 0.5 else ("light_off", d.name))
        elif d.kind in ("dimmer", "blinds"):
            facts.add(("device_level", d.name, level_symbol(value)))
        elif d.kind == "bell" and ringing:
            facts.add(("sound_at", "doorbell", d.room))
    return facts
