"""``knic world check FILE`` and ``knic world render FILE --out map.png``.

FILE is a world name (``erl_home``, ``erl_home_paper``) or a world YAML path. ``check`` validates the world
(and optionally scenarios against it) and prints a summary, with a warning for every room and piece of
furniture the robot cannot drive to from its start (a door blocked by furniture); an invalid world exits
non-zero with one line naming the entry and the problem. ``render`` draws the map as a PNG.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="world_command", metavar="ACTION", required=True)
    check = sub.add_parser("check", help="validate a world file", description="validate a world file")
    check.add_argument("file", metavar="FILE", help="world name (erl_home, erl_home_paper) or YAML path")
    check.add_argument(
        "--scenario",
        action="append",
        default=[],
        metavar="NAME_OR_FILE",
        help="also validate this scenario against the world (repeatable)",
    )
    check.add_argument("--json", action="store_true", help="print one JSON object")
    render = sub.add_parser(
        "render", help="draw a world's map as PNG", description="draw a world's map as PNG"
    )
    render.add_argument("file", metavar="FILE", help="world name or YAML path")
    render.add_argument("--out", required=True, type=Path, help="PNG file to write")
    render.add_argument("--scale", type=float, default=80.0, help="pixels per metre (default 80)")
    render.add_argument("--json", action="store_true", help="print one JSON object")


def run(args: argparse.Namespace) -> int:
    from worlds.loader import load_world

    world = load_world(args.file)
    if args.world_command == "check":
        from worlds.scenario import load_scenario
        from worlds.sim.goals import unreachable
        from worlds.sim.navigation import GridMap

        scenarios = [load_scenario(s, world).name for s in args.scenario]
        rooms_out, furniture_out = unreachable(world, GridMap.from_world(world))
        summary = {
            "world": world.name,
            "file": str(world.source) if world.source else None,
            "valid": True,
            "rooms": len(world.rooms),
            "doors": len(world.doors),
            "connected": [list(pair) for pair in world.connected()],
            "furniture": len(world.furniture),
            "items": len(world.items),
            "people": len(world.people),
            "devices": len(world.devices),
            "scenarios": scenarios,
            "unreachable_rooms": rooms_out,
            "unreachable_furniture": furniture_out,
        }
        if args.json:
            print(json.dumps(summary))
        else:
            print(
                f"{world.name}: valid: {summary['rooms']} rooms, {summary['doors']} doors, "
                f"{summary['furniture']} furniture, {summary['items']} items, {summary['people']} people, "
                f"{summary['devices']} devices"
                + (f"; scenarios ok: {', '.join(scenarios)}" if scenarios else "")
            )
            if rooms_out:
                print(
                    f"warning: the robot cannot reach {', '.join(rooms_out)} from its start (no free way in)"
                )
            if furniture_out:
                names = ", ".join(furniture_out)
                print(f"warning: the robot cannot reach {names} (no free floor within its reach)")
        return 0
    from worlds.render import render_map

    if args.scale <= 0:
        from core.errors import WorldError

        raise WorldError(f"--scale must be positive, got {args.scale}")
    size = render_map(world, args.out, scale=args.scale)
    if args.json:
        print(json.dumps({"world": world.name, "out": str(args.out), "width": size[0], "height": size[1]}))
    else:
        print(f"{world.name}: map written to {args.out} ({size[0]}x{size[1]} px)")
    return 0
