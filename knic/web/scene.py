"""The apartment map as the robot believes it: JSON for the page's floor plan, from a knowledge-base state.

The static layout (rooms, furniture) comes from the anchors that :func:`knic.seed.seed_kb_from_world` writes,
so a journal alone draws its map; the world data adds what the knowledge base does not anchor (doors,
devices' positions) when it matches the journal's rooms. Where things are believed to be comes from facts and
anchors only, never from the simulator: an item's anchored position (KGM-3 anchors items it sees), else the
furniture it is believed on, else the room it is believed in, else the robot's hand; a person's room; the
robot's room (or its anchored pose). Search candidates (``possibly_at``, assumed) are listed apart.

Everything is in the world frame: metres, ``x`` east, ``y`` north, yaw in radians counter-clockwise
from ``+x``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knowledge_base import DomainModel, State
    from worlds.model import World

Point = tuple[float, float]
#: most search candidates placed on the map (the fact table lists them all)
MAX_CANDIDATES = 300


def static_layout(state: State, world: World | None) -> dict[str, Any]:
    """Rooms, furniture, doors and devices: from the anchors in ``state``, completed by ``world``.

    Returns:
        ``{"rooms": [...], "furniture": [...], "doors": [...], "devices": [...], "bounds": [x0, y0, x1, y1],
        "world": name or None, "note": why the world data was left out, or ""}``.
    """
    rooms: dict[str, dict[str, Any]] = {}
    furniture: dict[str, dict[str, Any]] = {}
    for symbol, (geometry, _) in state.anchors.items():
        if isinstance(geometry.get("region"), list) and len(geometry["region"]) >= 3:
            polygon = [(float(p[0]), float(p[1])) for p in geometry["region"]]
            waypoints = geometry.get("waypoints") or [_centroid(polygon)]
            rooms[symbol] = {"name": symbol, "polygon": polygon, "waypoint": tuple(waypoints[0])}
        elif isinstance(geometry.get("size"), list) and isinstance(geometry.get("pose"), dict):
            pose = geometry["pose"]
            size = [float(v) for v in geometry["size"]]
            x, y, yaw = float(pose.get("x", 0.0)), float(pose.get("y", 0.0)), float(pose.get("yaw", 0.0))
            furniture[symbol] = {
                "name": symbol,
                "room": geometry.get("room"),
                "x": x,
                "y": y,
                "yaw": yaw,
                "size": size,
                "footprint": _rectangle(x, y, yaw, size[0], size[1]),
            }
    note = ""
    doors: list[dict[str, Any]] = []
    devices: list[dict[str, Any]] = []
    if world is not None and rooms and not set(rooms) <= set(world.rooms):
        note = f"world {world.name} does not match the journal's rooms; doors and devices left out"
        world = None
    if world is not None:
        for room in world.rooms.values():
            rooms.setdefault(
                room.name, {"name": room.name, "polygon": list(room.polygon), "waypoint": room.waypoint}
            )
        for f in world.furniture.values():
            furniture.setdefault(
                f.name,
                {
                    "name": f.name,
                    "room": f.room,
                    "x": f.position[0],
                    "y": f.position[1],
                    "yaw": f.yaw,
                    "size": list(f.size),
                    "footprint": _rectangle(f.position[0], f.position[1], f.yaw, f.size[0], f.size[1]),
                },
            )
        for door in world.doors:
            a, b = _door_segment(
                door.position, door.width, [rooms[r]["polygon"] for r in door.rooms if r in rooms]
            )
            doors.append({"rooms": list(door.rooms), "position": list(door.position), "segment": [a, b]})
        devices = [
            {"name": d.name, "kind": d.kind, "room": d.room, "x": d.position[0], "y": d.position[1]}
            for d in world.devices.values()
        ]
    points = [p for r in rooms.values() for p in r["polygon"]] or [(0.0, 0.0), (1.0, 1.0)]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return {
        "rooms": sorted(rooms.values(), key=lambda r: r["name"]),
        "furniture": sorted(furniture.values(), key=lambda f: f["name"]),
        "doors": doors,
        "devices": devices,
        "bounds": [min(xs), min(ys), max(xs), max(ys)],
        "world": world.name if world is not None else None,
        "note": note,
    }


def beliefs(state: State, domain: DomainModel, layout: dict[str, Any]) -> dict[str, Any]:
    """Where the robot believes itself, the items and the people are, with the fact behind each placement.

    Args:
        state: the knowledge-base state (now or at a past time).
        domain: its domain (for the instance types).
        layout: :func:`static_layout` of the same state.

    Returns:
        ``{"robot": [...], "items": [...], "people": [...], "candidates": [...], "candidates_total": n,
        "devices": {...}}`` (at most :data:`MAX_CANDIDATES` candidates placed); each entity is
        ``{"name", "x", "y", "how", "fact", "status", "since"}``.
    """
    rooms = {r["name"]: r for r in layout["rooms"]}
    furniture = {f["name"]: f for f in layout["furniture"]}
    by_pred: dict[str, list[tuple[tuple[str, ...], Any]]] = {}
    for fact, prov in state.facts.items():
        by_pred.setdefault(fact.predicate, []).append((fact.args, prov))
    types = state.instances

    def of_type(kind: str) -> list[str]:
        allowed = domain.subtypes(kind)
        return sorted(n for n, t in types.items() if t in allowed)

    def in_room(room: str, name: str) -> Point:
        wx, wy = rooms[room]["waypoint"]
        angle = (sum(map(ord, name)) % 12) * math.pi / 6  # a fixed spot per name so markers do not stack
        return wx + 0.45 * math.cos(angle), wy + 0.45 * math.sin(angle)

    def entry(name: str, xy: Point, how: str, fact: str, prov: Any) -> dict[str, Any]:
        return {
            "name": name,
            "x": round(xy[0], 3),
            "y": round(xy[1], 3),
            "how": how,
            "fact": fact,
            "status": prov.status.value if prov is not None else "",
            "since": prov.since if prov is not None else None,
        }

    robots: list[dict[str, Any]] = []
    robot_pos: dict[str, Point] = {}
    for args, prov in by_pred.get("robot_at", []):
        name, room = args
        if room not in rooms:
            continue
        anchored = _anchored_xy(state, name)
        if anchored is not None and anchored[1].since >= prov.since and _inside(anchored[0], rooms[room]):
            xy, how = anchored[0], "anchor"
        else:
            xy, how = rooms[room]["waypoint"], "in room"
        robot_pos[name] = xy
        robots.append(entry(name, xy, how, f"(robot_at {name} {room})", prov))
    held = {args[1]: args[0] for args, _ in by_pred.get("holding", [])}
    on = {args[0]: (args[1], prov) for args, prov in by_pred.get("object_on", [])}
    at = {args[0]: (args[1], prov) for args, prov in by_pred.get("object_at", [])}
    items: list[dict[str, Any]] = []
    for name in of_type("item"):
        anchored = _anchored_xy(state, name)
        if name in held and held[name] in robot_pos:
            rx, ry = robot_pos[held[name]]
            items.append(entry(name, (rx + 0.15, ry + 0.15), "held", f"(holding {held[name]} {name})", None))
        elif name in at and at[name][0] in rooms:
            room, prov = at[name]
            if anchored is not None and _inside(anchored[0], rooms[room]):
                items.append(entry(name, anchored[0], "anchor", f"(object_at {name} {room})", prov))
            elif name in on and on[name][0] in furniture:
                f = furniture[on[name][0]]
                items.append(
                    entry(
                        name, (f["x"], f["y"]), "on furniture", f"(object_on {name} {f['name']})", on[name][1]
                    )
                )
            else:
                items.append(entry(name, in_room(room, name), "in room", f"(object_at {name} {room})", prov))
    people: list[dict[str, Any]] = []
    for args, prov in by_pred.get("person_at", []):
        name, room = args
        if room in rooms:
            anchored = _anchored_xy(state, name)
            if anchored is not None and anchored[1].since >= prov.since and _inside(anchored[0], rooms[room]):
                people.append(entry(name, anchored[0], "anchor", f"(person_at {name} {room})", prov))
            else:
                people.append(entry(name, in_room(room, name), "in room", f"(person_at {name} {room})", prov))
    placed = {e["name"] for e in items + people}
    open_candidates = [
        (args, prov)
        for args, prov in by_pred.get("possibly_at", [])
        if args[1] in rooms and args[0] not in placed
    ]
    candidates = [
        entry(args[0], in_room(args[1], args[0]), "candidate", f"(possibly_at {args[0]} {args[1]})", prov)
        for args, prov in open_candidates[:MAX_CANDIDATES]
    ]
    devices: dict[str, str] = {}
    for args, _ in by_pred.get("light_on", []):
        devices[args[0]] = "on"
    for args, _ in by_pred.get("light_off", []):
        devices[args[0]] = "off"
    for args, _ in by_pred.get("device_level", []):
        devices[args[0]] = args[1]
    return {
        "robot": robots,
        "items": items,
        "people": people,
        "candidates": candidates,
        "candidates_total": len(open_candidates),
        "devices": devices,
    }


def _anchored_xy(state: State, symbol: str) -> tuple[Point, Any] | None:
    entry = state.anchors.get(symbol)
    if entry is None:
        return None
    geometry, prov = entry
    pose = geometry.get("pose")
    if not isinstance(pose, dict):
        return None
    if "position" in pose and len(pose["position"]) >= 2:
        return (float(pose["position"][0]), float(pose["position"][1])), prov
    if "x" in pose and "y" in pose:
        return (float(pose["x"]), float(pose["y"])), prov
    return None


def _inside(xy: Point, room: dict[str, Any]) -> bool:
    """Point in polygon (even-odd rule)."""
    x, y = xy
    poly = room["polygon"]
    inside = False
    for (x1, y1), (x2, y2) in zip(poly, poly[1:] + poly[:1], strict=True):
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def _centroid(polygon: list[Point]) -> Point:
    return sum(p[0] for p in polygon) / len(polygon), sum(p[1] for p in polygon) / len(polygon)


def _rectangle(x: float, y: float, yaw: float, sx: float, sy: float) -> list[Point]:
    c, s = math.cos(yaw), math.sin(yaw)
    corners = ((sx / 2, sy / 2), (-sx / 2, sy / 2), (-sx / 2, -sy / 2), (sx / 2, -sy / 2))
    return [(round(x + c * dx - s * dy, 3), round(y + s * dx + c * dy, 3)) for dx, dy in corners]


def _door_segment(position: Point, width: float, polygons: list[list[Point]]) -> tuple[Point, Point]:
    """The door's opening drawn along the nearest wall of the rooms it joins (horizontal when none)."""
    px, py = position
    best: tuple[float, float, float] | None = None  # distance, direction x, direction y
    for poly in polygons:
        for (x1, y1), (x2, y2) in zip(poly, poly[1:] + poly[:1], strict=True):
            dx, dy = x2 - x1, y2 - y1
            length = math.hypot(dx, dy)
            if length < 1e-9:
                continue
            t = max(0.0, min(1.0, ((px - x1) * dx + (py - y1) * dy) / (length * length)))
            dist = math.hypot(px - (x1 + t * dx), py - (y1 + t * dy))
            if best is None or dist < best[0]:
                best = (dist, dx / length, dy / length)
    ux, uy = (1.0, 0.0) if best is None else (best[1], best[2])
    half = width / 2
    return (round(px - ux * half, 3), round(py - uy * half, 3)), (
        round(px + ux * half, 3),
        round(py + uy * half, 3),
    )
