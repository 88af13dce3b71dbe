"""``knic bench sim``: real-time factor of the simulated apartment and the camera's frame time.

One episode of ``--duration`` simulated seconds in the seven-room apartment with the ``busy_home`` scenario
(people walking, a visitor, an object moved): the robot tours the rooms (a navigation goal to each room in
turn) while the camera renders at ``--camera-hz`` and every frame's detections are produced. Wall-clock and
process CPU time are measured around the whole loop; the camera time around each rendered frame.
``realtime_factor`` is simulated over wall-clock seconds; ``cpu_realtime_factor`` is simulated over this
process's CPU seconds, which stays meaningful when other processes load the machine (``load_average_1min``).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import time


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--duration", type=float, default=600.0, help="simulated seconds (default 600)")
    parser.add_argument("--camera-hz", type=float, default=10.0, help="camera rate in Hz (default 10)")
    parser.add_argument("--width", type=int, default=160, help="camera width in pixels (default 160)")
    parser.add_argument("--height", type=int, default=120, help="camera height in pixels (default 120)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--world", default="erl_home", help="world name or file (default erl_home)")
    parser.add_argument("--scenario", default="busy_home", help="scenario name or file; 'none' for none")
    parser.add_argument("--floor", action="store_true", help="also render the floor (slower)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def run(args: argparse.Namespace) -> int:
    from core.errors import WorldError
    from core.robot import NavState
    from worlds.simulation import Simulation

    if args.duration <= 0 or args.camera_hz <= 0 or args.width <= 0 or args.height <= 0:
        raise WorldError("--duration, --camera-hz, --width and --height must be positive")
    scenario = None if args.scenario == "none" else args.scenario
    build_start = time.perf_counter()
    sim = Simulation(
        args.world,
        seed=args.seed,
        scenario=scenario,
        camera_hz=args.camera_hz,
        camera_size=(args.width, args.height),
        render_floor=args.floor,
    )
    build_s = time.perf_counter() - build_start
    rooms = sorted(sim.world.rooms)
    period = 1.0 / args.camera_hz
    frame_ms: list[float] = []
    detections = 0
    goals = reached = 0
    visited: set[str] = set()
    wall0, cpu0 = time.perf_counter(), time.process_time()
    try:
        while sim.time < args.duration - 1e-9:
            status = sim.nav_status()
            if status.state is not NavState.ACTIVE:
                reached += status.state is NavState.SUCCEEDED
                sim.navigate_to_room(rooms[goals % len(rooms)])
                goals += 1
            sim.step(min(period, args.duration - sim.time))
            t0 = time.perf_counter()
            frame = sim.camera_frame()
            frame_ms.append((time.perf_counter() - t0) * 1000.0)
            detections += len(frame.detections)
            pose = sim.true_robot_pose()
            room = sim.world.room_of(pose.x, pose.y)
            if room:
                visited.add(room)
        wall = time.perf_counter() - wall0
        cpu = time.process_time() - cpu0
        counters = sim.counters()
    finally:
        sim.close()
    result = {
        "world": sim.world.name,
        "scenario": scenario,
        "sim_seconds": round(sim.time, 3),
        "wall_seconds": round(wall, 3),
        "cpu_seconds": round(cpu, 3),
        "realtime_factor": round(sim.time / wall, 2),
        "cpu_realtime_factor": round(sim.time / cpu, 2) if cpu > 0 else None,
        "camera_hz": args.camera_hz,
        "camera_size": [args.width, args.height],
        "render_floor": args.floor,
        "frames": len(frame_ms),
        "camera_frame_ms": round(statistics.fmean(frame_ms), 3),
        "camera_frame_ms_p95": round(sorted(frame_ms)[int(0.95 * (len(frame_ms) - 1))], 3),
        "camera_share": round(sum(frame_ms) / 1000.0 / wall, 3),
        "detections": detections,
        "nav_goals": goals,
        "nav_goals_reached": reached,
        "rooms_visited": len(visited),
        "bumps": counters.bumps,
        "person_hits": counters.person_hits,
        "drops": counters.drops,
        "build_seconds": round(build_s, 3),
        # the machine's load while measuring: wall-clock figures shrink when other processes share the CPUs
        "load_average_1min": round(os.getloadavg()[0], 2),
        "cpu_count": os.cpu_count(),
    }
    if args.json:
        print(json.dumps(result))
    else:
        print(
            f"sim {result['sim_seconds']} s in {result['wall_seconds']} s wall: realtime factor "
            f"{result['realtime_factor']} (cpu {result['cpu_realtime_factor']}); camera "
            f"{result['camera_frame_ms']} ms/frame (p95 {result['camera_frame_ms_p95']}) over "
            f"{result['frames']} frames; {reached}/{goals} goals reached, {len(visited)} rooms visited; "
            f"bumps {counters.bumps}, person hits {counters.person_hits}, drops {counters.drops}"
        )
    return 0
