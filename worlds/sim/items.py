"""Movable items: their true state, surfaces to put them on, falling after a release."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from worlds.geometry import Point
from worlds.model import Furniture, Item, World

GRAVITY = 9.81  # m/s^2


@dataclass
class ItemState:
    """An item's true state (world frame, metres).

    Attributes:
        name: PDDL symbol.
        cls: class label.
        size: box size.
        x: centre x.
        y: centre y.
        z: centre z.
        holder: ``None``, the robot's name or a person's name.
        on: furniture the item rests on (``None`` on the floor, while held or falling).
        vz: vertical speed while falling (m/s, negative down); ``None`` when not falling.
    """

    name: str
    cls: str
    size: tuple[float, float, float]
    x: float
    y: float
    z: float
    holder: str | None = None
    on: str | None = None
    vz: float | None = None

    @classmethod
    def from_item(cls, item: Item) -> ItemState:
        """Initial state from world data."""
        x, y, z = item.position
        return cls(name=item.name, cls=item.cls, size=item.size, x=x, y=y, z=z, on=item.on)


def items_on(items: Mapping[str, ItemState], furniture: str) -> list[tuple[Point, float]]:
    """Centre ``(x, y)`` and half length of every item standing on the furniture."""
    return [
        ((it.x, it.y), max(it.size[0], it.size[1]) / 2)
        for it in items.values()
        if it.on == furniture and it.holder is None
    ]


def support_below(world: World, x: float, y: float, z_bottom: float) -> tuple[float, str | None]:
    """Height and name of the highest surface under ``(x, y)`` at or below ``z_bottom`` (floor: 0, None)."""
    best: tuple[float, str | None] = (0.0, None)
    for f in world.furniture.values():
        if f.height <= z_bottom + 1e-6 and f.distance(x, y) <= 0.0 and f.height > best[0]:
            best = (f.height, f.name)
    return best


def fall_step(world: World, it: ItemState, dt: float) -> bool:
    """Advance a falling item by ``dt`` seconds; True when it has landed (then ``on`` is set)."""
    assert it.vz is not None
    support, name = support_below(world, it.x, it.y, it.z - it.size[2] / 2)
    it.vz -= GRAVITY * dt
    it.z += it.vz * dt
    if it.z - it.size[2] / 2 <= support:
        it.z = support + it.size[2] / 2
        it.vz = None
        it.on = name
        return True
    return False


def free_spots(f: Furniture, item: ItemState, others: list[ItemState], step: float = 0.05) -> list[Point]:
    """Points on the furniture top where ``item`` fits without touching the items already there."""
    hx = f.size[0] / 2 - max(item.size[0], item.size[1]) / 2 - 0.03
    hy = f.size[1] / 2 - max(item.size[0], item.size[1]) / 2 - 0.03
    if hx < 0 or hy < 0:
        return []
    r_item = math.hypot(item.size[0], item.size[1]) / 2
    nx, ny = int(hx / step), int(hy / step)
    out = []
    for i in range(-nx, nx + 1):
        for j in range(-ny, ny + 1):
            px, py = f.to_world(i * step, j * step)
            ok = all(
                math.hypot(px - o.x, py - o.y) >= r_item + math.hypot(o.size[0], o.size[1]) / 2 + 0.01
                for o in others
                if o.name != item.name and o.on == f.name and o.holder is None
            )
            if ok:
                out.append((px, py))
    return out
