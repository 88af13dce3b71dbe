"""Reading and validating world files (YAML).

A world file has the top-level keys ``name``, ``rooms``, ``doors``, ``furniture``, ``items``, ``people``,
``devices`` and ``robot`` (see ``worlds/erl_home/erl_home.yaml`` for a documented example). Validation runs
in full before anything is built; the first problem found raises :class:`core.errors.WorldError` with a
message ``<file>: <entry>: <problem>``, e.g. ``erl_home.yaml: doors[3]: unknown room 'kitchn'``.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from core.errors import WorldError
from core.geometry import distance_to_outline
from core.inputs import MAX_YAML_BYTES, read_text_limited, safe_yaml
from worlds.geometry import (
    Point,
    point_on_boundary,
    polygon_area,
    polygons_overlap,
    self_intersection,
)
from worlds.model import (
    DEVICE_KINDS,
    Device,
    Door,
    Furniture,
    Item,
    Person,
    Prior,
    RobotSpec,
    Room,
    World,
)

WORLDS_DIR = Path(__file__).resolve().parent
#: world names accepted wherever a world file path is
WORLD_NAMES: dict[str, Path] = {
    "erl_home": WORLDS_DIR / "erl_home" / "erl_home.yaml",
    "erl_home_paper": WORLDS_DIR / "erl_home" / "erl_home_paper.yaml",
    "test_flat": WORLDS_DIR / "test_flat" / "test_flat.yaml",
    "test_bungalow": WORLDS_DIR / "test_bungalow" / "test_bungalow.yaml",
}

_TOP = {
    "name",
    "rooms",
    "doors",
    "furniture",
    "items",
    "people",
    "devices",
    "robot",
    "wall_height",
    "wall_thickness",
}
_ITEM_COLORS: dict[str, tuple[float, float, float, float]] = {
    "glasses": (0.1, 0.1, 0.1, 1.0),
    "apple": (0.8, 0.1, 0.1, 1.0),
    "lemon": (0.95, 0.9, 0.1, 1.0),
    "coke_can": (0.7, 0.0, 0.0, 1.0),
    "water": (0.6, 0.8, 1.0, 1.0),
    "juice": (1.0, 0.6, 0.1, 1.0),
    "mug": (0.9, 0.9, 0.85, 1.0),
    "cup": (0.3, 0.6, 0.9, 1.0),
    "glass": (0.75, 0.9, 0.95, 1.0),
    "candle": (0.95, 0.95, 0.8, 1.0),
    "cardboard_box": (0.65, 0.5, 0.3, 1.0),
    "remote": (0.15, 0.15, 0.2, 1.0),
    "tablet": (0.2, 0.2, 0.25, 1.0),
    "sponge": (0.9, 0.85, 0.2, 1.0),
    "soap": (0.9, 0.6, 0.8, 1.0),
    "tissues": (0.95, 0.95, 0.95, 1.0),
}


class _Ctx:
    """Where the validator is, for error messages."""

    def __init__(self, file: str) -> None:
        self.file = file

    def fail(self, entry: str, problem: str) -> WorldError:
        return WorldError(f"{self.file}: {entry}: {problem}")


def resolve_world_path(name_or_path: str | Path) -> Path:
    """The file of a world name (``erl_home``, ``erl_home_paper``, ``test_flat``, ``test_bungalow``) or an
    existing path.

    Raises:
        WorldError: neither a known name nor an existing file.
    """
    if isinstance(name_or_path, str) and name_or_path in WORLD_NAMES:
        return WORLD_NAMES[name_or_path]
    path = Path(name_or_path)
    if not path.is_file():
        raise WorldError(f"unknown world {str(name_or_path)!r}: not one of {sorted(WORLD_NAMES)} nor a file")
    return path


def load_world(name_or_path: str | Path) -> World:
    """Read and validate a world by name or path (see :func:`worlds.api.load_world`)."""
    path = resolve_world_path(name_or_path)
    text = read_text_limited(path, MAX_YAML_BYTES, "world file", WorldError)
    data = safe_yaml(text, path.name, WorldError)  # no aliases, bounded depth: a tiny file stays tiny
    return world_from_dict(data, file=path.name, source=path)


def world_from_dict(data: Any, *, file: str = "<world>", source: Path | None = None) -> World:
    """Validate a parsed world document and build the :class:`World`.

    Raises:
        WorldError: the first problem, naming the entry.
    """
    ctx = _Ctx(file)
    if not isinstance(data, dict):
        raise ctx.fail("document", "must be a mapping with rooms, doors, furniture, items, people, robot")
    _no_unknown(ctx, "document", data, _TOP)
    name = _str(ctx, "name", _req(ctx, "document", data, "name"))
    rooms = _rooms(ctx, _list(ctx, "rooms", _req(ctx, "document", data, "rooms")))
    doors = _doors(ctx, _list(ctx, "doors", data.get("doors", [])), rooms)
    furniture = _furniture(ctx, _list(ctx, "furniture", data.get("furniture", [])), rooms)
    items = _items(ctx, _list(ctx, "items", data.get("items", [])), rooms, furniture)
    people = _people(ctx, _list(ctx, "people", data.get("people", [])), rooms, furniture, items)
    devices = _devices(ctx, _list(ctx, "devices", data.get("devices", [])), rooms)
    robot = _robot(ctx, _req(ctx, "document", data, "robot"), rooms)
    names: dict[str, str] = {}
    for kind, group in (
        ("rooms", rooms),
        ("furniture", furniture),
        ("items", items),
        ("people", people),
        ("devices", devices),
    ):
        for n in group:
            if n in names:
                raise ctx.fail(f"{kind} {n!r}", f"name already used by {names[n]}")
            names[n] = kind
    if robot.name in names:
        raise ctx.fail("robot", f"name {robot.name!r} already used by {names[robot.name]}")
    return World(
        name=name,
        rooms=rooms,
        doors=tuple(doors),
        furniture=furniture,
        items=items,
        people=people,
        devices=devices,
        robot=robot,
        wall_height=_num(ctx, "wall_height", data.get("wall_height", 2.5), positive=True),
        wall_thickness=_num(ctx, "wall_thickness", data.get("wall_thickness", 0.1), positive=True),
        source=source,
    )


# ----------------------------------------------------------------------------------- primitive checks


def _req(ctx: _Ctx, entry: str, d: dict[str, Any], key: str) -> Any:
    if key not in d:
        raise ctx.fail(entry, f"missing field {key!r}")
    return d[key]


def _no_unknown(ctx: _Ctx, entry: str, d: dict[str, Any], allowed: set[str]) -> None:
    extra = sorted(str(k) for k in set(d) - allowed)
    if extra:
        raise ctx.fail(entry, f"unknown field {extra[0]!r} (allowed: {', '.join(sorted(allowed))})")


def _list(ctx: _Ctx, entry: str, v: Any) -> list[Any]:
    if not isinstance(v, list):
        raise ctx.fail(entry, "must be a list")
    return v


def _map(ctx: _Ctx, entry: str, v: Any) -> dict[str, Any]:
    if not isinstance(v, dict):
        raise ctx.fail(entry, "must be a mapping")
    return v


def _str(ctx: _Ctx, entry: str, v: Any) -> str:
    if not isinstance(v, str) or not v or not v.replace("_", "").isalnum() or not v[0].isalpha():
        raise ctx.fail(entry, f"must be a symbol (letters, digits, '_'), got {v!r}")
    return v


def _num(ctx: _Ctx, entry: str, v: Any, *, positive: bool = False) -> float:
    if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
        raise ctx.fail(entry, f"must be a number, got {v!r}")
    if positive and v <= 0:
        raise ctx.fail(entry, f"must be positive, got {v!r}")
    return float(v)


def _vec(ctx: _Ctx, entry: str, v: Any, n: int, *, positive: bool = False) -> tuple[float, ...]:
    if not isinstance(v, list | tuple) or len(v) != n:
        raise ctx.fail(entry, f"must be a list of {n} numbers, got {v!r}")
    return tuple(_num(ctx, entry, x, positive=positive) for x in v)


def _color(ctx: _Ctx, entry: str, v: Any) -> tuple[float, float, float, float]:
    c = _vec(ctx, entry, v, 4)
    return (c[0], c[1], c[2], c[3])


# ----------------------------------------------------------------------------------- sections


def _entries(ctx: _Ctx, section: str, raw: list[Any]) -> list[tuple[str, dict[str, Any]]]:
    out = []
    for i, e in enumerate(raw):
        entry = f"{section}[{i}]"
        d = _map(ctx, entry, e)
        if "name" in d and isinstance(d["name"], str):
            entry = f"{section}[{i}] {d['name']!r}"
        out.append((entry, d))
    return out


def _rooms(ctx: _Ctx, raw: list[Any]) -> dict[str, Room]:
    rooms: dict[str, Room] = {}
    if not raw:
        raise ctx.fail("rooms", "at least one room is needed")
    for entry, d in _entries(ctx, "rooms", raw):
        _no_unknown(ctx, entry, d, {"name", "polygon", "waypoint"})
        name = _str(ctx, entry + ".name", _req(ctx, entry, d, "name"))
        if name in rooms:
            raise ctx.fail(entry, f"duplicate room {name!r}")
        poly_raw = _list(ctx, entry + ".polygon", _req(ctx, entry, d, "polygon"))
        if len(poly_raw) < 3:
            raise ctx.fail(entry, "polygon needs at least 3 vertices")
        poly = tuple((p[0], p[1]) for p in (_vec(ctx, entry + ".polygon", v, 2) for v in poly_raw))
        bad = self_intersection(poly)
        if bad is not None:
            raise ctx.fail(entry, f"polygon is self-intersecting (edges {bad[0]} and {bad[1]} cross)")
        if abs(polygon_area(poly)) < 1e-6:
            raise ctx.fail(entry, "polygon has no area")
        room = Room(name=name, polygon=poly, waypoint=(0.0, 0.0))
        wp = _vec(ctx, entry + ".waypoint", d["waypoint"], 2) if "waypoint" in d else room.centroid
        if not room.contains(wp[0], wp[1]):
            raise ctx.fail(entry, f"waypoint {wp} is outside the room")
        rooms[name] = Room(name=name, polygon=poly, waypoint=(wp[0], wp[1]))
    names = list(rooms)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            if polygons_overlap(rooms[a].polygon, rooms[b].polygon):
                raise ctx.fail(f"rooms {a!r} and {b!r}", "floor polygons overlap")
    return rooms


def _doors(ctx: _Ctx, raw: list[Any], rooms: dict[str, Room]) -> list[Door]:
    doors = []
    seen: set[frozenset[str]] = set()
    for i, d in enumerate(raw):
        entry = f"doors[{i}]"
        d = _map(ctx, entry, d)
        _no_unknown(ctx, entry, d, {"rooms", "position", "width"})
        rs = _list(ctx, entry + ".rooms", _req(ctx, entry, d, "rooms"))
        if len(rs) not in (1, 2):
            raise ctx.fail(entry, "rooms must list two rooms (or one for a front door)")
        for r in rs:
            if r not in rooms:
                raise ctx.fail(entry, f"unknown room {r!r}")
        if len(rs) == 2 and rs[0] == rs[1]:
            raise ctx.fail(entry, f"connects room {rs[0]!r} to itself")
        pos = _vec(ctx, entry + ".position", _req(ctx, entry, d, "position"), 2)
        width = _num(ctx, entry + ".width", d.get("width", 0.9), positive=True)
        for r in rs:
            if not point_on_boundary(pos[0], pos[1], rooms[r].polygon, tol=0.05):
                raise ctx.fail(entry, f"position {pos} is not on a wall of room {r!r}")
        key = frozenset(rs)
        if len(rs) == 2 and key in seen:
            raise ctx.fail(entry, f"second door between {rs[0]!r} and {rs[1]!r}")
        seen.add(key)
        doors.append(Door(rooms=tuple(rs), position=(pos[0], pos[1]), width=width))
    return doors


def _furniture(ctx: _Ctx, raw: list[Any], rooms: dict[str, Room]) -> dict[str, Furniture]:
    out: dict[str, Furniture] = {}
    for entry, d in _entries(ctx, "furniture", raw):
        _no_unknown(ctx, entry, d, {"name", "room", "position", "size", "yaw", "surface", "color"})
        name = _str(ctx, entry + ".name", _req(ctx, entry, d, "name"))
        room = _req(ctx, entry, d, "room")
        if room not in rooms:
            raise ctx.fail(entry, f"unknown room {room!r}")
        pos = _vec(ctx, entry + ".position", _req(ctx, entry, d, "position"), 2)
        size = _vec(ctx, entry + ".size", _req(ctx, entry, d, "size"), 3, positive=True)
        f = Furniture(
            name=name,
            room=room,
            position=(pos[0], pos[1]),
            size=(size[0], size[1], size[2]),
            yaw=math.radians(_num(ctx, entry + ".yaw", d.get("yaw", 0.0))),
            surface=bool(d.get("surface", True)),
            color=_color(ctx, entry + ".color", d["color"]) if "color" in d else (0.6, 0.45, 0.3, 1.0),
        )
        for cx, cy in f.footprint():
            if not rooms[room].contains(cx, cy):
                raise ctx.fail(entry, f"footprint corner ({cx:.2f}, {cy:.2f}) is outside room {room!r}")
        if name in out:
            raise ctx.fail(entry, f"duplicate furniture {name!r}")
        out[name] = f
    return out


def _priors(
    ctx: _Ctx, entry: str, raw: Any, rooms: dict[str, Room], furniture: dict[str, Furniture]
) -> tuple[Prior, ...]:
    out = []
    lst = _list(ctx, entry + ".priors", raw)
    if len(lst) > 3:
        raise ctx.fail(entry, f"at most three priors, got {len(lst)}")
    for j, p in enumerate(lst):
        pe = f"{entry}.priors[{j}]"
        p = _map(ctx, pe, p)
        _no_unknown(ctx, pe, p, {"room", "furniture", "p"})
        fur = p.get("furniture")
        room = p.get("room")
        if fur is not None:
            if fur not in furniture:
                raise ctx.fail(pe, f"unknown furniture {fur!r}")
            if room is None:
                room = furniture[fur].room
            elif furniture[fur].room != room:
                raise ctx.fail(pe, f"furniture {fur!r} is in {furniture[fur].room!r}, not {room!r}")
        if room is None:
            raise ctx.fail(pe, "missing field 'room'")
        if room not in rooms:
            raise ctx.fail(pe, f"unknown room {room!r}")
        prob = _num(ctx, pe + ".p", _req(ctx, pe, p, "p"))
        if not 0.0 < prob <= 1.0:
            raise ctx.fail(pe, f"probability must be in (0, 1], got {prob}")
        out.append(Prior(room=room, probability=prob, furniture=fur))
    if sum(p.probability for p in out) > 1.0 + 1e-6:
        raise ctx.fail(entry, "prior probabilities sum to more than 1")
    return tuple(out)


def surface_slots(f: Furniture, count: int) -> list[tuple[float, float]]:
    """``count`` evenly spread world points on a furniture top, along its longer side."""
    long_x = f.size[0] >= f.size[1]
    length = f.size[0] if long_x else f.size[1]
    pts = []
    for k in range(count):
        t = (k + 0.5) / count - 0.5
        off = t * (length - 0.1)
        pts.append(f.to_world(off, 0.0) if long_x else f.to_world(0.0, off))
    return pts


def _items(
    ctx: _Ctx, raw: list[Any], rooms: dict[str, Room], furniture: dict[str, Furniture]
) -> dict[str, Item]:
    entries = _entries(ctx, "items", raw)
    counts: dict[str, int] = {}
    for entry, d in entries:
        on = d.get("furniture")
        if on is not None:
            if on not in furniture:
                raise ctx.fail(entry, f"on unknown furniture {on!r}")
            if not furniture[on].surface:
                raise ctx.fail(entry, f"furniture {on!r} has no surface to put things on")
            counts[on] = counts.get(on, 0) + 1
    used: dict[str, int] = {}
    out: dict[str, Item] = {}
    for entry, d in entries:
        _no_unknown(ctx, entry, d, {"name", "class", "furniture", "position", "size", "color", "priors"})
        name = _str(ctx, entry + ".name", _req(ctx, entry, d, "name"))
        cls = _str(ctx, entry + ".class", d.get("class", name))
        size_v = _vec(ctx, entry + ".size", d["size"], 3, positive=True) if "size" in d else (0.08, 0.08, 0.1)
        size = (size_v[0], size_v[1], size_v[2])
        on = d.get("furniture")
        if on is not None:
            f = furniture[on]
            k = used.get(on, 0)
            used[on] = k + 1
            xy = surface_slots(f, counts[on])[k]
            pos = (xy[0], xy[1], f.height + size[2] / 2)
        elif "position" in d:
            p = _vec(ctx, entry + ".position", d["position"], 3)
            pos = (p[0], p[1], p[2])
            if not any(r.contains(pos[0], pos[1]) for r in rooms.values()):
                raise ctx.fail(entry, f"position {pos} is outside every room")
        else:
            raise ctx.fail(entry, "missing field 'furniture' or 'position'")
        default_color = _ITEM_COLORS.get(cls, (0.2, 0.4, 0.9, 1.0))
        if name in out:
            raise ctx.fail(entry, f"duplicate item {name!r}")
        out[name] = Item(
            name=name,
            cls=cls,
            position=pos,
            on=on,
            size=size,
            color=_color(ctx, entry + ".color", d["color"]) if "color" in d else default_color,
            priors=_priors(ctx, entry, d.get("priors", []), rooms, furniture),
        )
    return out


def _people(
    ctx: _Ctx,
    raw: list[Any],
    rooms: dict[str, Room],
    furniture: dict[str, Furniture],
    items: dict[str, Item],
) -> dict[str, Person]:
    out: dict[str, Person] = {}
    allowed = {"name", "furniture", "position", "behaviour", "present", "known", "radius", "height", "color"}
    allowed.add("priors")
    for entry, d in _entries(ctx, "people", raw):
        _no_unknown(ctx, entry, d, allowed)
        name = _str(ctx, entry + ".name", _req(ctx, entry, d, "name"))
        on = d.get("furniture")
        radius = _num(ctx, entry + ".radius", d.get("radius", 0.22), positive=True)
        if on is not None:
            if on not in furniture:
                raise ctx.fail(entry, f"on unknown furniture {on!r}")
            if furniture[on].seat:  # in the middle, or beside the items and people already there
                taken = [
                    ((i.position[0], i.position[1]), max(i.size[:2]) / 2)
                    for i in items.values()
                    if i.on == on
                ]
                taken += [(q.position, q.radius) for q in out.values() if q.on == on]
                pos = furniture[on].seat_spot(radius, taken)
            else:  # a table, a counter: the person stands beside it
                pos = _beside(ctx, entry, furniture[on], furniture, rooms[furniture[on].room], radius)
                on = None
        elif "position" in d:
            p = _vec(ctx, entry + ".position", d["position"], 2)
            pos = (p[0], p[1])
        else:
            raise ctx.fail(entry, "missing field 'furniture' or 'position'")
        present = bool(d.get("present", True))
        if present and not any(r.contains(pos[0], pos[1]) for r in rooms.values()):
            raise ctx.fail(entry, f"position {pos} is outside every room (set present: false for a visitor)")
        behaviour = d.get("behaviour", "static")
        if behaviour not in ("static", "wander"):
            raise ctx.fail(entry, f"unknown behaviour {behaviour!r} (static, wander)")
        if name in out:
            raise ctx.fail(entry, f"duplicate person {name!r}")
        out[name] = Person(
            name=name,
            position=pos,
            on=on,
            behaviour=behaviour,
            present=present,
            known=_known(ctx, entry, d.get("known", True)),
            radius=radius,
            height=_num(ctx, entry + ".height", d.get("height", 1.65), positive=True),
            color=_color(ctx, entry + ".color", d["color"]) if "color" in d else (0.9, 0.7, 0.55, 1.0),
            priors=_priors(ctx, entry, d.get("priors", []), rooms, furniture),
        )
    return out


def _beside(
    ctx: _Ctx, entry: str, at: Furniture, furniture: dict[str, Furniture], room: Room, radius: float
) -> Point:
    """The first free place beside ``at`` for a person of body ``radius`` (see :meth:`Furniture.beside`):
    inside its room, clear of the walls and of every piece of furniture."""
    for x, y in at.beside(radius):
        if not room.contains(x, y) or distance_to_outline(x, y, room.polygon) < radius:
            continue
        if all(f.distance(x, y) >= radius for f in furniture.values()):
            return (x, y)
    raise ctx.fail(entry, f"no free place beside {at.name!r} to stand at (it is too high to sit on)")


def _known(ctx: _Ctx, entry: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise ctx.fail(entry, f"known must be true or false, got {value!r}")
    return value


def _devices(ctx: _Ctx, raw: list[Any], rooms: dict[str, Room]) -> dict[str, Device]:
    out: dict[str, Device] = {}
    for entry, d in _entries(ctx, "devices", raw):
        _no_unknown(ctx, entry, d, {"name", "type", "room", "position", "initial"})
        name = _str(ctx, entry + ".name", _req(ctx, entry, d, "name"))
        kind = _req(ctx, entry, d, "type")
        if kind not in DEVICE_KINDS:
            raise ctx.fail(entry, f"unknown device type {kind!r} ({', '.join(DEVICE_KINDS)})")
        room = _req(ctx, entry, d, "room")
        if room not in rooms:
            raise ctx.fail(entry, f"unknown room {room!r}")
        p = _vec(ctx, entry + ".position", _req(ctx, entry, d, "position"), 3)
        init = d.get("initial", 0)
        initial = (1.0 if init else 0.0) if isinstance(init, bool) else _num(ctx, entry + ".initial", init)
        if not 0.0 <= initial <= 100.0:
            raise ctx.fail(entry, f"initial must be 0-100, got {initial}")
        if name in out:
            raise ctx.fail(entry, f"duplicate device {name!r}")
        out[name] = Device(name=name, kind=kind, room=room, position=(p[0], p[1], p[2]), initial=initial)
    return out


def _robot(ctx: _Ctx, raw: Any, rooms: dict[str, Room]) -> RobotSpec:
    d = _map(ctx, "robot", raw)
    fields = {
        "name",
        "start",
        "radius",
        "height",
        "max_linear",
        "max_angular",
        "reach",
        "camera_height",
        "camera_pitch",
        "camera_fov",
        "grasp_tolerance",
    }
    _no_unknown(ctx, "robot", d, fields)
    name = _str(ctx, "robot.name", _req(ctx, "robot", d, "name"))
    s = _vec(ctx, "robot.start", _req(ctx, "robot", d, "start"), 3)
    if not any(r.contains(s[0], s[1]) for r in rooms.values()):
        raise ctx.fail("robot.start", f"({s[0]}, {s[1]}) is outside every room")
    kw: dict[str, float] = {}
    for k in sorted(fields - {"name", "start"}):
        if k in d:
            kw[k] = _num(ctx, f"robot.{k}", d[k], positive=k != "camera_pitch")
    if "camera_pitch" in kw:  # degrees in the file, radians in the model
        kw["camera_pitch"] = math.radians(kw["camera_pitch"])
    kw_start = (s[0], s[1], math.radians(s[2]))
    return RobotSpec(name=name, start=kw_start, **kw)
