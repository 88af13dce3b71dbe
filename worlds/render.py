"""Drawing a world's map as a PNG (Pillow): rooms, walls with door gaps, furniture, items, people,
devices, robot."""

from __future__ import annotations

import math
from pathlib import Path

from PIL import Image, ImageDraw, ImageFont

from worlds.model import World
from worlds.sim.navigation import wall_segments

ROOM_COLORS = [
    (255, 244, 214),
    (224, 240, 255),
    (230, 250, 225),
    (255, 228, 225),
    (240, 230, 255),
    (255, 250, 200),
    (220, 245, 245),
    (245, 235, 220),
]
DEVICE_LETTER = {"light": "L", "dimmer": "D", "blinds": "B", "bell": "ß"}


def render_map(world: World, out: Path, *, scale: float = 80.0, margin: float = 1.2) -> tuple[int, int]:
    """Draw ``world`` to the PNG file ``out`` at ``scale`` pixels per metre; returns the image size.

    The map is seen from above with +x to the right and +y up. Visitors not yet in the apartment are drawn
    hollow at their waiting place outside.
    """
    xmin, ymin, xmax, ymax = world.bounds()
    width = int((xmax - xmin + 2 * margin) * scale)
    height = int((ymax - ymin + 2 * margin) * scale) + 40
    img = Image.new("RGB", (width, height), (250, 250, 250))
    d = ImageDraw.Draw(img)
    font = _font(13)
    small = _font(11)

    def px(x: float, y: float) -> tuple[float, float]:
        return ((x - xmin + margin) * scale, (ymax - y + margin) * scale)

    for i, room in enumerate(world.rooms.values()):
        d.polygon([px(*p) for p in room.polygon], fill=ROOM_COLORS[i % len(ROOM_COLORS)])
    for room in world.rooms.values():  # room names along the bottom (else the top) of each room
        cx, _ = room.centroid
        ys = [p[1] for p in room.polygon]
        spots = [(cx, min(ys) + 0.3), (cx, max(ys) - 0.3), room.waypoint]
        spot = next(
            (q for q in spots if all(f.distance(*q) > 0.6 for f in world.furniture.values())), spots[-1]
        )
        _label(d, px(*spot), room.name.upper(), font, (110, 110, 110))
    wall_px = max(2, int(world.wall_thickness * scale))
    for a, b in wall_segments(world):
        d.line([px(*a), px(*b)], fill=(60, 60, 60), width=wall_px)
    for door in world.doors:
        x, y = px(*door.position)
        r = 4.0
        d.ellipse([x - r, y - r, x + r, y + r], fill=(40, 160, 60))
    rx, ry, ryaw = world.robot.start
    x, y = px(rx, ry)
    r = world.robot.radius * scale
    d.ellipse([x - r, y - r, x + r, y + r], fill=(200, 200, 215), outline=(0, 0, 90), width=2)
    d.line([(x, y), (x + r * 1.4 * math.cos(ryaw), y - r * 1.4 * math.sin(ryaw))], fill=(0, 0, 90), width=3)
    _label(d, (x, y + r + 9), world.robot.name, font, (0, 0, 90))
    for f in world.furniture.values():
        d.polygon(
            [px(*p) for p in f.footprint()],
            fill=tuple(int(c * 255) for c in f.color[:3]),
            outline=(50, 40, 30),
        )
        fx, fy = px(*f.position)
        xs = [px(*p)[0] for p in f.footprint()]
        text_w = d.textbbox((0, 0), f.name, font=small)[2]
        if text_w > max(xs) - min(xs):  # narrow furniture: label beside it, towards the room's middle
            side = 1.0 if world.rooms[f.room].centroid[0] > f.position[0] else -1.0
            fx += side * ((max(xs) - min(xs)) / 2 + text_w / 2 + 4)
        _label(d, (fx, fy - 8), f.name, small, (20, 20, 20), box=True)
    for it in world.items.values():
        x, y = px(it.position[0], it.position[1])
        r = 5.0
        d.ellipse(
            [x - r, y - r, x + r, y + r], fill=tuple(int(c * 255) for c in it.color[:3]), outline=(0, 0, 0)
        )
        _label(d, (x, y + 10), it.name, small, (0, 0, 120))
    for p in world.people.values():
        x, y = px(*p.position)
        r = p.radius * scale
        color = tuple(int(c * 255) for c in p.color[:3])
        if p.present:
            d.ellipse([x - r, y - r, x + r, y + r], fill=color, outline=(0, 0, 0), width=2)
        else:
            d.ellipse([x - r, y - r, x + r, y + r], outline=color, width=3)
        label_y = y + r + 9 if p.present else y - r - 9
        _label(d, (x, label_y), p.name + ("" if p.present else " (outside)"), font, (120, 0, 60))
    for dev in world.devices.values():
        x, y = px(dev.position[0], dev.position[1])
        d.rectangle([x - 7, y - 7, x + 7, y + 7], fill=(255, 220, 0), outline=(0, 0, 0))
        _label(d, (x, y), DEVICE_LETTER.get(dev.kind, "?"), small, (0, 0, 0))
    legend = [
        "rooms (filled), walls (dark), doors (green dots), furniture (boxes), items (dots), people (discs),",
        f"devices (yellow: L light, D dimmer, B blinds, ß bell), robot (heading line); 1 m = {scale:.0f} px",
    ]
    for k, line in enumerate(legend):
        d.text((8, height - 36 + 15 * k), line, fill=(40, 40, 40), font=small)
    out.parent.mkdir(parents=True, exist_ok=True)
    img.save(out)
    return img.size


def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    for name in ("DejaVuSans.ttf", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"):
        try:
            return ImageFont.truetype(name, size)
        except OSError:
            continue
    return ImageFont.load_default()


def _label(
    d: ImageDraw.ImageDraw,
    at: tuple[float, float],
    text: str,
    font: ImageFont.FreeTypeFont | ImageFont.ImageFont,
    fill: tuple[int, int, int],
    box: bool = False,
) -> None:
    left, top, right, bottom = d.textbbox((0, 0), text, font=font)
    x, y = at[0] - (right - left) / 2, at[1] - (bottom - top) / 2
    if box:
        d.rectangle([x - 2, y - 1, x + right - left + 2, y + bottom - top + 3], fill=(255, 255, 255))
    d.text((x, y - top), text, fill=fill, font=font)
