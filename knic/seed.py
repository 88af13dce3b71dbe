"""What the robot knows before a run, written into the knowledge base from the world data.

:func:`seed_kb_from_world` adds the map and the task's prior knowledge, never where movable things really are:
rooms, furniture, items, people, devices, the robot and the sounds it can hear as instances; ``connected``
(both orders), ``furniture_in``, ``surface`` (furniture items can be put on), ``hand_empty``, the robot's
start room, the devices' initial states; the anchors (room polygon and waypoint, furniture pose and size, the
robot's start pose); and the search candidates ``(possibly_at ?e ?room)`` from the priors, ASSUMED. Items and
people get no place: perception (KGM-3) finds them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from knic.kgm3.relations import level_of
from knowledge_base import BeliefStatus, KnowledgeBase

if TYPE_CHECKING:
    from worlds.model import World

#: sound symbol heard when a device of kind ``bell`` rings
BELL_SOUND = "doorbell"


def seed_kb_from_world(
    kb: KnowledgeBase,
    world: World,
    *,
    at: float = 0.0,
    source: str = "world",
    max_candidates: int = 3,
) -> int:
    """Write the robot's prior knowledge of ``world`` into ``kb`` in one batch; return the number of writes.

    Facts that already hold (for instance from a PDDL problem file) are left as they are. All-or-nothing: a
    refused write raises :class:`core.errors.KnowledgeBaseError` and nothing is written.
    """
    writes = 0
    given = BeliefStatus.GIVEN

    def instance(pddl_type: str, name: str) -> None:
        nonlocal writes
        if kb.type_of(name) is None:
            writes += kb.add_instance(pddl_type, name, source=source, at=at, status=given)

    def fact(
        predicate: str,
        *args: str,
        status: BeliefStatus = given,
        confidence: float = 1.0,
        support: tuple[str, ...] = (),
    ) -> None:
        nonlocal writes
        if not kb.holds(predicate, *args):
            writes += kb.add_fact(
                predicate, *args, source=source, at=at, status=status, confidence=confidence, support=support
            )

    def anchor(symbol: str, geometry: dict[str, Any]) -> None:
        nonlocal writes
        kb.set_anchor(symbol, geometry, source=source, at=at, status=given)
        writes += 1

    with kb.batch():
        strangers = {name for name, person in world.people.items() if not person.known}
        for name, pddl_type in world.symbols().items():
            if name not in strangers:  # met, not preloaded
                instance(pddl_type, name)
        if any(d.kind == "bell" for d in world.devices.values()):
            instance("sound", BELL_SOUND)
        for pred, *args in sorted(world.static_facts()):
            fact(pred, *args)
        for furniture in world.furniture.values():
            if furniture.surface:
                fact("surface", furniture.name)
        robot = world.robot
        fact("hand_empty", robot.name)
        start_room = world.room_of(robot.start[0], robot.start[1])
        if start_room is not None and not kb.facts("robot_at", robot.name):
            fact("robot_at", robot.name, start_room)
        for device in world.devices.values():
            if device.kind == "light":
                on = bool(device.initial)
                if not kb.holds("light_on", device.name) and not kb.holds("light_off", device.name):
                    fact("light_on" if on else "light_off", device.name)
            elif device.kind in ("dimmer", "blinds") and not kb.facts("device_level", device.name):
                fact("device_level", device.name, level_of(device.initial))
        for room in world.rooms.values():
            anchor(
                room.name,
                {
                    "region": [list(p) for p in room.polygon],
                    "waypoints": [list(room.waypoint)],
                    # the openings in its walls: centre, clear width and the room beyond (None: outside)
                    "doors": [
                        {
                            "position": list(door.position),
                            "width": door.width,
                            "to": next((r for r in door.rooms if r != room.name), None),
                        }
                        for door in world.doors
                        if room.name in door.rooms
                    ],
                    "frame": "world",
                },
            )
        for furniture in world.furniture.values():
            anchor(
                furniture.name,
                {
                    "pose": {"x": furniture.position[0], "y": furniture.position[1], "yaw": furniture.yaw},
                    "size": list(furniture.size),
                    "room": furniture.room,
                    "frame": "world",
                },
            )
        anchor(
            robot.name,
            {"pose": {"x": robot.start[0], "y": robot.start[1], "yaw": robot.start[2]}, "frame": "world"},
        )
        for group in (world.items, world.people):
            for name, thing in group.items():
                if name in strangers:
                    continue
                ranked = sorted(thing.priors, key=lambda p: -p.probability)
                rooms: list[str] = []
                for prior in ranked:
                    if prior.room not in rooms:
                        rooms.append(prior.room)
                for room_name in rooms[:max_candidates]:
                    prob = max(p.probability for p in ranked if p.room == room_name)
                    fact(
                        "possibly_at",
                        name,
                        room_name,
                        status=BeliefStatus.ASSUMED,
                        confidence=float(prob),
                        support=(f"prior:{name}",),
                    )
    return writes
