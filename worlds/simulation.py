"""The simulated apartment: :class:`Simulation` is the robot (:class:`core.robot.Robot`) and the referee's
oracle (:class:`worlds.oracle.Oracle`) at once (:class:`worlds.api.SimulationAPI`).

One simulation owns one pybullet client (DIRECT by default, a GUI window with ``gui=True``) used for rendering
the robot's camera; everything else (robot base, people, items, devices, events) is kinematic Python state
advanced by :meth:`Simulation.step` in control periods of :data:`CONTROL_DT` seconds of simulated time.
Randomness (sensor noise, people, scenario draws) comes from generators seeded by ``seed``, so a run is
reproducible call for call.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from pathlib import Path

import numpy as np

from core.errors import WorldError
from core.robot import (
    CAUSE_NOT_AT_BELIEF,
    CAUSE_OUT_OF_REACH,
    CameraFrame,
    CommandResult,
    DeviceReading,
    NavStatus,
    Pose2D,
    Pose3D,
    SoundEvent,
    Utterance,
    Vec3,
)
from worlds.api import NoiseConfig
from worlds.geometry import Point, wrap_angle
from worlds.loader import load_world
from worlds.model import Device, World
from worlds.oracle import Counters, FrameTruth, SoundTruth
from worlds.scenario import Event, Scenario, load_scenario
from worlds.sim.contacts import ContactMonitor
from worlds.sim.estimates import believed_to_true, camera_eye, heard_at
from worlds.sim.events import apply_event
from worlds.sim.goals import approach_points, person_points, room_points
from worlds.sim.hands import PERSON_REACH, Hands
from worlds.sim.items import ItemState, fall_step
from worlds.sim.navigation import GridMap
from worlds.sim.noise import load_noise
from worlds.sim.people import PeopleController, PersonState
from worlds.sim.perception import add_depth_noise, detect
from worlds.sim.robot import BaseController
from worlds.sim.scene import Scene, optical_pose
from worlds.sim.truth import ground_truth

CONTROL_DT = 0.05  # seconds per control period
RING_SECONDS = 2.0  # how long the door bell rings
PAN_LIMIT = math.pi / 2


class Simulation:
    """The simulated ERL apartment: robot, oracle and simulator controls (:class:`worlds.api.SimulationAPI`).

    Args:
        world: a :class:`World`, a world name (``erl_home``, ``erl_home_paper``) or a world file path.
        seed: seed of every random draw (noise, people, scenario).
        scenario: a :class:`Scenario`, a shipped scenario name (``visitors``) or a scenario file path.
        gui: open a pybullet GUI window (needs a display); headless DIRECT mode otherwise.
        camera_hz: camera rate; :meth:`camera_frame` renders at most once per ``1 / camera_hz`` simulated
            seconds and returns the cached frame in between.
        camera_size: ``(width, height)`` in pixels.
        noise: sensor noise: a model, or a YAML file of one (default: `worlds/noise.yaml`, see
            :mod:`worlds.sim.noise`).
        render_floor: draw the floor (costs about a third of the render time; without it floor pixels are
            background: segmentation -1, depth inf).

    Raises:
        WorldError: invalid world or scenario.
    """

    def __init__(
        self,
        world: World | str | Path,
        *,
        seed: int = 0,
        scenario: Scenario | str | Path | None = None,
        gui: bool = False,
        camera_hz: float = 10.0,
        camera_size: tuple[int, int] = (160, 120),
        noise: NoiseConfig | str | Path | None = None,
        render_floor: bool = False,
    ) -> None:
        self._world = world if isinstance(world, World) else load_world(world)
        w = self._world
        self._scenario = (
            scenario if isinstance(scenario, Scenario) or scenario is None else load_scenario(scenario, w)
        )
        if camera_hz <= 0:
            raise WorldError(f"camera_hz must be positive, got {camera_hz}")
        self.seed = seed
        self.noise = (
            noise if isinstance(noise, NoiseConfig) else load_noise(*(() if noise is None else (noise,)))
        )
        self.camera_hz = camera_hz
        self.camera_size = camera_size
        streams = np.random.SeedSequence(seed).spawn(5)
        self._rng_camera, self._rng_pose, self._rng_people, self._rng_scenario, self._rng_sound = (
            np.random.default_rng(s) for s in streams
        )
        #: the latest localisation estimate handed out (what the robot places believed points by)
        self._estimate: Pose2D | None = None
        self.grid = GridMap.from_world(w)
        self._contacts = ContactMonitor(w)
        self._base = BaseController(w.robot, self.grid)
        self._items = {name: ItemState.from_item(it) for name, it in w.items.items()}
        self._hands = Hands(w, self.grid, self._items, self._base)
        self._people = PeopleController(w, self.grid, self._hands, self._rng_people)
        self._hands.people = self._people.people
        self._base.ask_way = self._ask_way
        self._devices = {d.name: (d.initial if d.kind != "bell" else 0.0) for d in w.devices.values()}
        self._scene = Scene(w, gui=gui, render_floor=render_floor)
        self._instances = self._scene.instances()
        self._strangers = frozenset(n for n, p in w.people.items() if not p.known)
        self._item_classes = sorted({it.cls for it in w.items.values()})
        self._time = 0.0
        self._pan = 0.0
        self._ring_until = -1.0
        self._sounds: list[SoundEvent] = []
        self._sounds_made: list[SoundTruth] = []
        self._heard: list[Utterance] = []
        self._spoken: list[Utterance] = []
        self._events = list(self._scenario.events) if self._scenario else []
        self._frame: CameraFrame | None = None
        self._frame_truth: FrameTruth | None = None
        self._labels = {body: name for body, (name, _cls, _person) in self._instances.items()}
        self._closed = False
        self._apply_due_events()

    @classmethod
    def from_world(cls, world: World | str | Path, **kwargs: object) -> Simulation:
        """Same as the constructor (``Simulation.from_world("erl_home", seed=1)``)."""
        return cls(world, **kwargs)  # type: ignore[arg-type]

    # ------------------------------------------------------------------------------------------ properties

    @property
    def world(self) -> World:
        """The world data."""
        return self._world

    @property
    def scenario(self) -> Scenario | None:
        """The scenario being played, if any."""
        return self._scenario

    @property
    def time(self) -> float:
        """Simulated seconds since the start."""
        return self._time

    @property
    def robot_name(self) -> str:
        """The robot's PDDL symbol."""
        return self._world.robot.name

    # ------------------------------------------------------------------------------------------ stepping

    def step(self, dt: float = 0.1) -> None:
        """Advance simulated time by ``dt`` seconds in control periods of at most :data:`CONTROL_DT`."""
        if dt <= 0:
            raise WorldError(f"step dt must be positive, got {dt}")
        self._check_open()
        n = max(1, math.ceil(dt / CONTROL_DT - 1e-9))
        h = dt / n
        for _ in range(n):
            self._time = round(self._time + h, 9)
            self._apply_due_events()
            r = self._base
            self._people.update(h, self._time, (r.x, r.y, self._world.robot.radius))
            before = (r.x, r.y)
            r.update(
                h, self._people.discs(), lambda x, y: self._contacts.may_stand(x, y, self._people.discs())
            )
            if (r.x, r.y) != before:
                self._contacts.update(r.x, r.y, self._people.discs())
            for it in self._items.values():
                if it.vz is not None:
                    fall_step(self._world, it, h)
                elif it.holder is not None:
                    self._hands.carry(it)

    def add_events(self, events: Iterable[Event]) -> None:
        """Schedule more scenario events (validated, e.g. by :func:`worlds.scenario.scenario_from_dict`);
        events already due are carried out at the next step."""
        self._events = sorted([*self._events, *events], key=lambda e: e.at)

    def _apply_due_events(self) -> None:
        while self._events and self._events[0].at <= self._time + 1e-9:
            apply_event(self, self._people, self._items, self._rng_scenario, self._events.pop(0))

    # ------------------------------------------------------------------------------------------ sensors

    def camera_frame(self) -> CameraFrame:
        """The robot camera's latest frame, rendered now if the cached one is older than one camera period."""
        self._check_open()
        if self._frame is not None and self._time - self._frame.stamp < 1.0 / self.camera_hz - 1e-9:
            return self._frame
        self._sync_bodies()
        r, spec = self._base, self._world.robot
        eye, heading = camera_eye(r.pose(self._time), self._pan, spec.camera_height)
        width, height = self.camera_size
        rgb, depth, seg, intr, pose = self._scene.render(
            eye, heading, spec.camera_pitch, width, height, spec.camera_fov, exclude=(self.robot_name,)
        )
        # the camera's pose as the robot knows it: from its localisation estimate, not the true base pose
        est_eye, est_heading = camera_eye(self.robot_pose(), self._pan, spec.camera_height)
        pose = optical_pose(est_eye, est_heading, spec.camera_pitch, self._time)
        detections, detected, visible = detect(
            seg, depth, self._instances, self.noise, self._rng_camera, self._item_classes, self._strangers
        )
        depth = add_depth_noise(depth, self.noise.depth_noise, self._rng_camera)
        self._frame = CameraFrame(
            stamp=self._time,
            width=width,
            height=height,
            rgb=rgb,
            depth=depth,
            intrinsics=intr,
            camera_pose=pose,
            detections=detections,
        )
        self._frame_truth = FrameTruth(self._time, seg, self._labels, visible, detected)
        return self._frame

    def robot_pose(self) -> Pose2D:
        """Localisation: the true pose plus Gaussian noise (``noise.pose_noise_xy``, ``pose_noise_yaw``)."""
        r, n = self._base, self.noise
        dx, dy, dyaw = self._rng_pose.normal(0.0, 1.0, size=3)
        self._estimate = Pose2D(
            r.x + dx * n.pose_noise_xy,
            r.y + dy * n.pose_noise_xy,
            wrap_angle(r.yaw + dyaw * n.pose_noise_yaw),
            self._time,
        )
        return self._estimate

    def poll_sounds(self) -> list[SoundEvent]:
        """Sounds since the previous call."""
        out, self._sounds = self._sounds, []
        return out

    def poll_utterances(self) -> list[Utterance]:
        """Speech by people since the previous call."""
        out, self._heard = self._heard, []
        return out

    def device_states(self) -> dict[str, DeviceReading]:
        """Lights: bool; dimmer and blinds: percent; bell: ringing now (the readings are exact)."""
        out: dict[str, DeviceReading] = {}
        for d in self._world.devices.values():
            v = self._devices[d.name]
            out[d.name] = (
                v > 0.5 if d.kind == "light" else (self._time < self._ring_until if d.kind == "bell" else v)
            )
        return out

    # ------------------------------------------------------------------------------------------ navigation

    def navigate_to_point(self, x: float, y: float, yaw: float | None = None) -> int:
        """Goal to a world point (nearest free point within 0.3 m); see the protocol."""
        target = f"point ({x:.2f}, {y:.2f})"
        goal = self.grid.nearest_free(x, y, 0.3)
        if goal is None:
            return self._base.fail_now(target, f"{target} is not free")
        return self._base.start_goal(target, [goal], lambda _x, _y: yaw)

    def navigate_to_room(self, room: str) -> int:
        """Goal to the room's waypoint: the nearest free point within :data:`ROOM_GOAL_RADIUS` of it."""
        if room not in self._world.rooms:
            raise WorldError(f"navigate_to_room: unknown room {room!r}")
        goals = room_points(self._world, self.grid, room, self._people.discs())
        if not goals:
            return self._base.fail_now(f"room {room}", f"no free pose near the waypoint of {room}")
        return self._base.start_goal(f"room {room}", goals, lambda _x, _y: None)

    def navigate_to_furniture(self, furniture: str, near: tuple[float, float] | None = None) -> int:
        """Goal to a free pose within reach of the furniture (of ``near`` on it when possible), facing it."""
        if furniture not in self._world.furniture:
            raise WorldError(f"navigate_to_furniture: unknown furniture {furniture!r}")
        f = self._world.furniture[furniture]
        points = self.approach_points(furniture, near, reach=self._world.robot.reach)
        fx, fy = near if near is not None else f.position
        return self._base.start_goal(
            f"furniture {furniture}", points, lambda x, y: math.atan2(fy - y, fx - x)
        )

    def navigate_to_person(self, person: str) -> int:
        """Goal to a free pose 0.5-1.0 m from the person (1.1 m if they sit or lie), facing them."""
        p = self._person(person, "navigate_to_person")
        if not p.present:
            return self._base.fail_now(f"person {person}", f"{person} is not in the apartment")
        pts = person_points(self.grid, p.x, p.y, 1.1 if p.on else 1.0)
        return self._base.start_goal(f"person {person}", pts, lambda x, y: math.atan2(p.y - y, p.x - x))

    def nav_status(self) -> NavStatus:
        """Latest goal's status."""
        return self._base.status()

    def set_base_velocity(self, linear: float, angular: float) -> None:
        """Drive directly (clipped to limits); cancels a goal."""
        self._base.set_velocity(linear, angular)

    def stop(self) -> None:
        """Stop and cancel."""
        self._base.stop()

    def approach_points(
        self, furniture: str, near: Point | None = None, reach: float = PERSON_REACH
    ) -> list[Point]:
        """Free grid points within ``reach - 0.2`` m of the furniture (and of ``near`` when one qualifies)."""
        return approach_points(self._world, self.grid, furniture, near, reach)

    # ------------------------------------------------------------------------------------------ gripper

    def pick(self, item: str, at: Vec3 | None = None) -> CommandResult:
        """Attach an item within reach to the empty gripper; with ``at`` (the believed position), only if the
        item really is within the gripper's tolerance of where the arm goes (see :meth:`believed_to_true`)."""
        return self._hands.pick(item, self.believed_to_true(at))

    def place(self, furniture: str) -> CommandResult:
        """Put the held item on the furniture at the free spot nearest the robot, within reach."""
        return self._hands.place(furniture)

    def release(self) -> CommandResult:
        """Open the gripper in mid-air: the item falls and counts as dropped."""
        return self._hands.release()

    def give(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Hand the held item to a person within reach (at the believed position ``at`` when given)."""
        return self._hands.give(person, self.believed_to_true(at))

    def believed_to_true(self, at: Sequence[float] | None) -> Vec3 | None:
        """Where the arm really goes when sent to the believed world point ``at``: the robot places it by its
        latest localisation estimate (:meth:`robot_pose`), the arm moves from the true base
        (:func:`worlds.sim.estimates.believed_to_true`)."""
        if at is None:
            return None
        true = self._base.pose(self._time)
        return believed_to_true(at, self._estimate if self._estimate is not None else true, true)

    def held_item(self) -> str | None:
        """The item in the gripper."""
        return self._hands.held

    def pan_camera(self, angle: float) -> None:
        """Camera pan relative to the base, clipped to +-pi/2."""
        self._pan = max(-PAN_LIMIT, min(PAN_LIMIT, angle))
        self._frame = None

    @property
    def camera_pan(self) -> float:
        """Current camera pan in radians."""
        return self._pan

    # -------------------------------------------------------------------------------- devices, speech

    def set_light(self, device: str, on: bool) -> CommandResult:
        """Switch a light."""
        d = self._device(device, "set_light")
        if d.kind != "light":
            return CommandResult(False, f"{device} is a {d.kind}, not a light")
        self._devices[device] = 1.0 if on else 0.0
        return CommandResult(True)

    def set_level(self, device: str, percent: float) -> CommandResult:
        """Set a dimmer or blinds (percent, clipped to 0-100)."""
        d = self._device(device, "set_level")
        if d.kind not in ("dimmer", "blinds"):
            return CommandResult(False, f"{device} is a {d.kind}, it has no level")
        self._devices[device] = max(0.0, min(100.0, float(percent)))
        return CommandResult(True)

    def say(self, text: str) -> None:
        """Record the robot's speech."""
        r = self._base
        self._spoken.append(
            Utterance(text=text, speaker=self.robot_name, stamp=self._time, position=(r.x, r.y, 1.0))
        )

    def _ask_way(self, person: str, path: list[Point]) -> None:
        """The navigation stack asks a person who blocks the robot's way to step aside (said aloud)."""
        self.say("Excuse me, may I pass?")
        r = self._base
        self._people.make_way(person, self._time, (r.x, r.y, self._world.robot.radius), path)

    def spoken(self) -> list[Utterance]:
        """Everything the robot said."""
        return list(self._spoken)

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        """A person says ``text`` now."""
        p = self._person(speaker, "hear")
        words = " ".join("".join(ch for ch in text.lower() if ch.isalnum() or ch in " '_").split())
        self._heard.append(
            Utterance(
                text=words,
                speaker=speaker,
                stamp=self._time,
                audio_path=audio_path,
                position=(p.x, p.y, p.z_base(self._world) + p.height * 0.9),
            )
        )

    def escort(self, person: str, at: Vec3 | None = None) -> CommandResult:
        """Ask a person within 2 m to follow (and within 1 m of the believed position ``at`` if given)."""
        p = self._person(person, "escort")
        spot = self.believed_to_true(at)
        if spot is not None and (not p.present or math.hypot(p.x - spot[0], p.y - spot[1]) > 1.0):
            return CommandResult(
                False,
                f"nobody answered: {person} is not at the believed position ({spot[0]:.2f}, {spot[1]:.2f})",
                CAUSE_NOT_AT_BELIEF,
            )
        d = math.hypot(p.x - self._base.x, p.y - self._base.y)
        if not p.present or d > 2.0:
            return CommandResult(
                False, f"{person} is {d:.2f} m away, must be within 2.00 m", CAUSE_OUT_OF_REACH
            )
        self._people.follow(person)
        return CommandResult(True)

    def stop_escort(self) -> None:
        """Nobody follows the robot any more."""
        self._people.follow(None)

    # ------------------------------------------------------------------------------------------ ground truth

    def true_robot_pose(self) -> Pose2D:
        """The robot's true pose."""
        return self._base.pose(self._time)

    def true_pose(self, name: str) -> Pose3D:
        """True pose of any instance."""
        w, t = self._world, self._time
        if name == self.robot_name:
            r = self._base
            return Pose3D((r.x, r.y, 0.0), _yaw_quat(r.yaw), t)
        if name in self._items:
            it = self._items[name]
            return Pose3D((it.x, it.y, it.z), (0.0, 0.0, 0.0, 1.0), t)
        if name in self._people.people:
            p = self._people.people[name]
            return Pose3D((p.x, p.y, p.z_base(w)), _yaw_quat(p.yaw), t)
        if name in w.furniture:
            f = w.furniture[name]
            return Pose3D((f.position[0], f.position[1], 0.0), _yaw_quat(f.yaw), t)
        raise WorldError(f"true_pose: unknown instance {name!r}")

    def person_present(self, name: str) -> bool:
        """True when the person is inside the apartment."""
        return self._person(name, "person_present").present

    def ground_truth_facts(self, include_static: bool = False) -> set[tuple[str, ...]]:
        """True facts now (see the protocol)."""
        facts = ground_truth(
            self._world,
            (self._base.x, self._base.y),
            self._hands.held,
            self._items,
            self._people.people,
            self._devices,
            self._time < self._ring_until,
        )
        if include_static:
            facts |= self._world.static_facts()
        return facts

    def frame_truth(self) -> FrameTruth | None:
        """The truth behind the latest rendered camera frame."""
        return self._frame_truth

    def sounds_made(self) -> list[SoundTruth]:
        """Every sound made so far."""
        return list(self._sounds_made)

    def true_device_states(self) -> dict[str, DeviceReading]:
        """The devices' true states (the simulated readings are exact: the same as :meth:`device_states`)."""
        return self.device_states()

    def counters(self) -> Counters:
        """Penalty counters."""
        c = self._contacts
        return Counters(bumps=c.bumps, person_hits=c.hits, drops=self._hands.drops)

    def close(self) -> None:
        """Disconnect pybullet (idempotent)."""
        if not self._closed:
            self._scene.close()
            self._closed = True

    def __enter__(self) -> Simulation:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------------------------------ internals

    def _sync_bodies(self) -> None:
        s, w = self._scene, self._world
        r = self._base
        s.move(self.robot_name, (r.x, r.y, w.robot.height / 2), r.yaw)
        for p in self._people.people.values():
            z = p.z_base(w) + p.height / 2 if p.present else -50.0
            s.move(p.name, (p.x, p.y, z), p.yaw)
        for it in self._items.values():
            s.move(it.name, (it.x, it.y, it.z))

    def ring_bell(self) -> None:
        """The door bell rings now: a sound heard at the bell, the bell's state on for :data:`RING_SECONDS`
        (scenario hook)."""
        bell = next(d for d in self._world.devices.values() if d.kind == "bell")
        self._ring_until = self._time + RING_SECONDS
        self._sounds.append(
            SoundEvent(
                kind="doorbell",
                position=heard_at(bell.position, (self._base.x, self._base.y), self.noise, self._rng_sound),
                stamp=self._time,
            )
        )
        self._sounds_made.append(SoundTruth("doorbell", bell.name, bell.position, self._time))

    def _check_open(self) -> None:
        if self._closed:
            raise WorldError("the simulation is closed")

    def _person(self, name: str, what: str) -> PersonState:
        if name not in self._people.people:
            raise WorldError(f"{what}: unknown person {name!r}")
        return self._people.people[name]

    def _device(self, name: str, what: str) -> Device:
        if name not in self._world.devices:
            raise WorldError(f"{what}: unknown device {name!r}")
        return self._world.devices[name]


def _yaw_quat(yaw: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
