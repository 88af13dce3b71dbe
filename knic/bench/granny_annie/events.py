"""Dynamic events of an episode, as scenario events (:mod:`worlds.scenario` carries them out).

Annie's place is set at t=0. Every other event is timed from the moment the robot takes Annie's command
(the task flow hears it some 20 s into the run, after her call and the robot's trip to her room), so the
events happen while the robot works on her request, whatever the trip took; :class:`~.flow.EventsAfterCommand`
schedules them in the run. The windows are simulated seconds after the command.

* Annie's place (the served person's): ``person_to`` onto her furniture at t=0 (teleport).
* The door bell (probability :data:`VISITOR_P`, when the world has a bell and a person outside): a
  ``doorbell`` event with the visitor walking in to one of their prior rooms.
* A person moving an object mid-run (probability :data:`MOVE_P`): ``move_object`` by someone other than Annie
  and the person to accompany; the object is one Annie asked for with probability :data:`MOVE_REQUESTED_P`.
* People walking: every other present person walks to 1-3 rooms at random times (probability
  :data:`WALK_P` each).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from knic.bench.granny_annie.commands import Request, pick
from knic.bench.granny_annie.placement import within_arm_height

if TYPE_CHECKING:
    from worlds.model import World

VISITOR_P = 0.5
MOVE_P = 0.4
MOVE_REQUESTED_P = 0.6
WALK_P = 0.5
#: windows of the events, simulated seconds after the robot took the command (the robot's work then takes
#: some 10-60 s: a moved object is moved while the robot heads for it, the visitor rings while it works)
VISITOR_AT = (2.0, 45.0)
MOVE_AT = (1.0, 20.0)
WALK_AT = (1.0, 120.0)
#: when the events start if the robot has taken no command by then (simulated seconds into the run)
NO_COMMAND_BY_S = 90.0


def draw_events(
    world: World,
    rng: np.random.Generator,
    requests: list[Request],
    placements: dict[str, str],
    seat: str | None,
    person: str,
) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """The episode's scenario events (see the module docstring): ``(at the start, after the command)``, each
    sorted by time; the ``at`` of the second list is seconds after the robot took the command. ``person`` is
    the served person (seated on ``seat``; never moved by the other events)."""
    start: list[dict[str, Any]] = []
    if seat is not None:
        start.append({"at": 0.0, "type": "person_to", "person": person, "furniture": seat, "teleport": True})
    events: list[dict[str, Any]] = []
    escorted = {t for r in requests if r.kind == "accompany" for t in r.targets}
    bells = [d for d in world.devices.values() if d.kind == "bell"]
    outside = sorted(p.name for p in world.people.values() if not p.present)
    visit = rng.random() < VISITOR_P
    if bells and outside and visit:
        visitor = pick(rng, outside)
        rooms = [p.room for p in world.people[visitor].priors] or [bells[0].room]
        events.append(
            {"at": _time(rng, VISITOR_AT), "type": "doorbell", "visitor": visitor, "to": pick(rng, rooms)}
        )
    present = sorted(
        p.name for p in world.people.values() if p.present and p.name != person and p.name not in escorted
    )
    mover = None
    move = rng.random() < MOVE_P
    if present and placements and move:
        mover = pick(rng, present)
        asked = [t for r in requests if r.kind in ("find", "bring") for t in r.targets]
        choose_asked = rng.random() < MOVE_REQUESTED_P
        item = pick(rng, asked) if asked and choose_asked else pick(rng, sorted(placements))
        destinations = _destinations(world, placements, item)
        if destinations:
            to = pick(rng, destinations)
            events.append(
                {"at": _time(rng, MOVE_AT), "type": "move_object", "person": mover, "item": item, "to": to}
            )
    for person in present:
        walk = rng.random() < WALK_P
        if person == mover or not walk:
            continue
        count = int(rng.integers(1, 4))
        times = sorted(_time(rng, WALK_AT) for _ in range(count))
        rooms = sorted(world.rooms)
        for at in times:
            events.append({"at": at, "type": "person_to", "person": person, "room": pick(rng, rooms)})
    events.sort(key=lambda e: e["at"])
    return start, events


def _time(rng: np.random.Generator, window: tuple[float, float]) -> float:
    return round(float(rng.uniform(*window)), 1)


def _destinations(world: World, placements: dict[str, str], item: str) -> list[str]:
    """Surfaces other than the item's own, preferring those any item's priors name (places things go)."""
    usual = {p.furniture for it in world.items.values() for p in it.priors if p.furniture}
    surfaces = sorted(
        f.name
        for f in world.furniture.values()
        if f.surface and f.name != placements[item] and within_arm_height(world, f.name, item)
    )
    preferred = [f for f in surfaces if f in usual]
    return preferred or surfaces
