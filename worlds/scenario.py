"""Scenarios as data: timed events that happen in the apartment while the robot works.

A scenario file (``worlds/erl_home/scenarios/*.yaml``) has a ``name``, an optional ``world`` it was written
for, a ``description`` and a list of ``events``, each with ``at`` (simulated seconds) and a ``type``:

* ``doorbell``: the door bell rings (a sound event at the bell); with ``visitor`` that person appears outside
  the front door ``enter_after`` seconds later (default 5) and walks to room ``to`` (default: the bell's
  room); with ``enter: false`` they wait at the door, just inside it, instead of walking in.
* ``say``: ``person`` says ``text`` (optional ``audio``: a WAV path relative to the scenario file).
* ``move_object``: ``person`` walks to ``item``, takes it, carries it to furniture ``to`` and puts it there.
* ``person_to``: ``person`` walks to ``room`` or onto ``furniture`` (``teleport: true``: is there at once).
* ``set_device``: ``device`` is set to ``value`` (lights: true/false; dimmer, blinds: percent).
* ``place_items``: each of ``items`` (default: all) is put on furniture drawn at random (seeded) from its
  priors, weighted by their probabilities.
* ``call``: ``person`` calls the robot from the tablet (as the ERL referee box sends it): the robot's speech
  channel receives the call, :data:`CALL_TEXT`, localised at the person (the position they tap).

A scenario may also describe a task flow (``task:``, the Granny Annie task; see
:mod:`worlds.granny_annie`): the person who calls, where they may wait, the requests they may make (voice
bank texts) and their answer. The flow's events are drawn per seed by :func:`worlds.granny_annie.episode`.

Scenario names resolve to ``worlds/erl_home/scenarios/<name>.yaml``; a path works too.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from core.errors import WorldError
from core.inputs import read_yaml
from worlds.model import World

SCENARIO_DIR = Path(__file__).resolve().parent / "erl_home" / "scenarios"

EVENT_FIELDS: dict[str, tuple[set[str], set[str]]] = {
    # type: (required fields, optional fields)
    "doorbell": (set(), {"visitor", "enter_after", "to", "enter"}),
    "say": ({"person", "text"}, {"audio"}),
    "move_object": ({"person", "item", "to"}, set()),
    "person_to": ({"person"}, {"room", "furniture", "teleport"}),
    "set_device": ({"device", "value"}, set()),
    "place_items": (set(), {"items"}),
    "call": ({"person"}, set()),
}
#: the fields of a scenario's task section (see :mod:`worlds.granny_annie`)
TASK_FIELDS = {"person", "seats", "call_at", "requests", "answer", "bank"}
#: what the robot's speech channel receives when a person calls from the tablet
CALL_TEXT = "tablet call"


@dataclass(frozen=True, slots=True)
class Event:
    """One scenario event.

    Attributes:
        at: simulated time in seconds when it happens.
        type: one of :data:`EVENT_FIELDS`.
        args: the event's other fields, validated against the world.
    """

    at: float
    type: str
    args: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: events sorted by time (file order among equal times)."""

    name: str
    description: str
    events: tuple[Event, ...]
    source: Path | None = None
    task: dict[str, Any] | None = None


def resolve_scenario_path(name_or_path: str | Path) -> Path:
    """The file of a scenario name or path.

    Raises:
        WorldError: neither a shipped scenario nor an existing file.
    """
    if isinstance(name_or_path, str) and "/" not in name_or_path and not name_or_path.endswith(".yaml"):
        path = SCENARIO_DIR / f"{name_or_path}.yaml"
        if path.is_file():
            return path
        known = sorted(p.stem for p in SCENARIO_DIR.glob("*.yaml"))
        raise WorldError(f"unknown scenario {name_or_path!r}: shipped scenarios are {known}")
    path = Path(name_or_path)
    if not path.is_file():
        raise WorldError(f"scenario file {str(path)!r} does not exist")
    return path


def load_scenario(name_or_path: str | Path, world: World) -> Scenario:
    """Read and validate a scenario against ``world``.

    Raises:
        WorldError: ``<file>: events[i]: <problem>`` for the first problem.
    """
    path = resolve_scenario_path(name_or_path)
    data = read_yaml(path, "scenario", WorldError)
    return scenario_from_dict(data, world, file=path.name, source=path)


def scenario_from_dict(
    data: Any, world: World, *, file: str = "<scenario>", source: Path | None = None
) -> Scenario:
    """Validate a parsed scenario document against ``world``."""

    def fail(entry: str, problem: str) -> WorldError:
        return WorldError(f"{file}: {entry}: {problem}")

    if not isinstance(data, dict):
        raise fail("document", "must be a mapping with name and events")
    extra = sorted(str(k) for k in set(data) - {"name", "world", "description", "events", "task"})
    if extra:
        raise fail("document", f"unknown field {extra[0]!r}")
    if "name" not in data:
        raise fail("document", "missing field 'name'")
    events_raw = data.get("events")
    if not isinstance(events_raw, list):
        raise fail("document", "missing field 'events' (a list)")
    events: list[Event] = []
    for i, raw in enumerate(events_raw):
        entry = f"events[{i}]"
        if not isinstance(raw, dict):
            raise fail(entry, "must be a mapping")
        if "at" not in raw or "type" not in raw:
            raise fail(entry, f"missing field {'at' if 'at' not in raw else 'type'!r}")
        at, kind = raw["at"], raw["type"]
        if isinstance(at, bool) or not isinstance(at, int | float) or at < 0:
            raise fail(entry, f"'at' must be a time in seconds >= 0, got {at!r}")
        if kind not in EVENT_FIELDS:
            raise fail(entry, f"unknown event type {kind!r} ({', '.join(EVENT_FIELDS)})")
        required, optional = EVENT_FIELDS[kind]
        args = {k: v for k, v in raw.items() if k not in ("at", "type")}
        for k in sorted(required - set(args)):
            raise fail(entry, f"missing field {k!r} for a {kind} event")
        for k in sorted(set(args) - required - optional):
            raise fail(entry, f"unknown field {k!r} for a {kind} event")
        _check_names(fail, entry, kind, args, world, source)
        events.append(Event(at=float(at), type=kind, args=args))
    events.sort(key=lambda e: e.at)
    task = data.get("task")
    if task is not None:
        try:
            check_task(task, world)
        except WorldError as exc:
            raise fail("task", str(exc)) from None
    return Scenario(
        name=str(data["name"]),
        description=str(data.get("description", "")),
        events=tuple(events),
        source=source,
        task=dict(task) if task is not None else None,
    )


def check_task(task: Any, world: World) -> None:
    """Validate a scenario's ``task:`` section against the world (see :mod:`worlds.granny_annie`).

    Raises:
        WorldError: the first problem, one line.
    """
    if not isinstance(task, dict):
        raise WorldError("must be a mapping with person, seats, requests")
    extra = sorted(set(task) - TASK_FIELDS)
    if extra:
        raise WorldError(f"unknown field {extra[0]!r} ({', '.join(sorted(TASK_FIELDS))})")
    person = task.get("person")
    if person not in world.people:
        raise WorldError(f"unknown person {person!r}")
    seats = task.get("seats", [])
    if not isinstance(seats, list) or any(s not in world.furniture for s in seats):
        raise WorldError(f"seats must be furniture of the world, got {seats!r}")
    call_at = task.get("call_at", 2.0)
    if isinstance(call_at, bool) or not isinstance(call_at, int | float) or call_at < 0:
        raise WorldError(f"call_at must be a time in seconds >= 0, got {call_at!r}")
    if str(task.get("answer", "yes")) not in ("yes", "no"):
        raise WorldError(f"answer must be yes or no, got {task.get('answer')!r}")
    requests = task.get("requests", [])
    if not isinstance(requests, list) or not all(isinstance(r, str) for r in requests):
        raise WorldError("requests must be a list of request texts of the voice bank")


def _check_names(
    fail: Any, entry: str, kind: str, args: dict[str, Any], world: World, source: Path | None
) -> None:
    def need(key: str, group: dict[str, Any], what: str) -> None:
        if key in args and args[key] not in group:
            raise fail(entry, f"unknown {what} {args[key]!r}")

    need("person", world.people, "person")
    need("visitor", world.people, "person")
    need("item", world.items, "item")
    need("room", world.rooms, "room")
    need("furniture", world.furniture, "furniture")
    need("device", world.devices, "device")
    if kind == "doorbell":
        if not any(d.kind == "bell" for d in world.devices.values()):
            raise fail(entry, "the world has no door bell")
        need("to", world.rooms, "room")
    if kind == "move_object":
        need("to", world.furniture, "furniture")
        if not world.furniture[args["to"]].surface:
            raise fail(entry, f"furniture {args['to']!r} has no surface")
    if kind == "person_to" and ("room" in args) == ("furniture" in args):
        raise fail(entry, "person_to needs exactly one of 'room' or 'furniture'")
    if kind == "place_items":
        for it in args.get("items", []):
            if it not in world.items:
                raise fail(entry, f"unknown item {it!r}")
            if not any(p.furniture for p in world.items[it].priors):
                raise fail(entry, f"item {it!r} has no prior naming furniture to draw from")
    if kind == "say" and not isinstance(args["text"], str):
        raise fail(entry, "'text' must be a string")
    if kind == "say" and "audio" in args and source is not None:
        audio = source.parent / str(args["audio"])
        if not audio.is_file():
            raise fail(entry, f"audio file {str(audio)!r} does not exist")
        args["audio"] = str(audio)
