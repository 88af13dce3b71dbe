"""Assembly of the inference pipeline: KGM-1 providers, the KGM-2 cognitive layer and the KGM-3 KP'.

Usage by the closed loop::

    world = load_world("erl_home")
    sim = Simulation(world, seed=3)
    kb = KnowledgeBase.from_pddl(DOMAIN, clock=lambda: sim.time)
    seed_kb_from_world(kb, world)
    pipeline = build_pipeline(kb, sim, world, role="companion")
    scheduler = Scheduler(real_time_factor=10.0)
    for component in pipeline:
        scheduler.add(component)
    # loop: sim.step(dt); scheduler.tick(sim.time)

Components are returned in data-flow order (providers, cognition, KP'), which is also the order the scheduler
steps components due at the same instant, so a percept reaches the knowledge base within one tick.

The places of the map travel like every other percept: the locations KP publishes one location LLKU per room
and piece of furniture at the first instant, KGM-2 learns the rooms from them and republishes them as location
CKUs carrying their octomaps, and the KP' that need places learn them from those CKUs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from core.robot import Camera, DeviceSensors, Localisation, SoundDetector
from knic.bus import Bus
from knic.kgm1.camera import CameraObjectsKP, CameraPeopleKP
from knic.kgm1.locations import LocationsKP, build_location_model
from knic.kgm1.providers import DeviceKP, RobotPoseKP, SoundKP
from knic.kgm1.sources import SharedCamera
from knic.kgm2.cognition import CognitiveLayer, TrackingConfig
from knic.kgm2.roles import ROLES_FILE, Role, load_role
from knic.kgm3.fusion import Fusion
from knic.kgm3.fusion import install as install_fusion
from knic.kgm3.people import PersonPlaceKP
from knic.kgm3.places import ObjectPlaceKP, RobotAtKP
from knic.kgm3.relations import DeviceStateKP, PersonNearKP, SoundAtKP
from knic.kgm3.search import CandidatesKP, ExploredKP, priors_from_world
from knic.scheduler import Component
from knic.spatial import LocationModel
from knowledge_base import KnowledgeBase

if TYPE_CHECKING:
    from worlds.model import World


class SensorSuite(Camera, Localisation, SoundDetector, DeviceSensors, Protocol):
    """The sensor parts of the robot seam (:class:`core.robot.Robot`) the pipeline reads, plus the clock.

    Every :class:`~core.robot.Robot` satisfies it; tests pass doubles checked against it.
    """

    @property
    def time(self) -> float:
        """Seconds since the start of the episode (the robot's clock, simulated in simulation)."""
        ...


@dataclass
class PipelineOptions:
    """Tunables of the pipeline (defaults suit the ERL apartment).

    Attributes:
        camera_hz: camera KP rate; None: the role's top rate for perceived classes.
        points_per_detection: world points deprojected per detection (the density of the entity octomaps).
        object_detect_range: metres within which items are reliably detected (visibility for misses).
        person_detect_range: the same for people.
        object_min_pixels: least mask size, pixels, of an item detection that counts as a sighting.
        person_min_pixels: the same for people.
        miss_range_share: share of the detect range within which an undetected tracked entity counts as
            missed (near the range limit entities shrink under the pixel gate).
        edge_px: image border, pixels, where an undetected entity does not count as missed.
        needed: consecutive consistent observations before a place fact of an item or a person changes.
        explored_ttl_s: seconds an ``explored`` fact lives.
        fusion_half_life_s: simulated seconds over which a standing belief's weight halves in the knowledge
            base's fusion (:mod:`knic.kgm3.fusion`).
        max_candidates: candidate rooms per entity of unknown place.
        searched_ttl_s: seconds after which a ``(searched ?e ?room)`` mark lets the room be searched again
            (once per room; :class:`knic.kgm3.search.CandidatesKP`).
        tracking: association parameters.
        roles_file: the role file.
        early_role_filter: let the camera KPs skip, before deprojection, the classes the role does not process
            in this frame (CognitiveLayer.admits). Measured with ``knic bench grounding``: about 10-20 % less
            pipeline CPU under the companion role, for about 0.01 less precision and recall on non-priority
            objects (picked up at their class rate instead of at once), so it is off by default.
    """

    camera_hz: float | None = None
    points_per_detection: int = 128
    object_detect_range: float = 4.0
    person_detect_range: float = 6.0
    object_min_pixels: int = 6
    person_min_pixels: int = 30
    miss_range_share: float = 0.95
    edge_px: int = 3
    needed: int = 2
    explored_ttl_s: float = 120.0
    fusion_half_life_s: float = 60.0
    max_candidates: int = 3
    searched_ttl_s: float = 180.0
    tracking: TrackingConfig = field(default_factory=TrackingConfig)
    roles_file: Path = ROLES_FILE
    early_role_filter: bool = False


class Pipeline(list[Component]):
    """The pipeline's components in data-flow order, plus handles on its parts for the loop and benchmarks.

    ``locations`` is the map as KGM-1's locations KP reads and publishes it; KGM-2 and the KP' never receive
    it, they learn the places from the location units on the bus.
    """

    def __init__(
        self,
        components: list[Component],
        *,
        bus: Bus,
        role: Role,
        locations: LocationModel,
        cognition: CognitiveLayer,
        camera: SharedCamera,
        fusion: Fusion | None = None,
    ) -> None:
        super().__init__(components)
        self.fusion = fusion
        self.bus = bus
        self.role = role
        self.locations = locations
        self.cognition = cognition
        self.camera = camera

    def component(self, name: str) -> Component:
        """The component of that name (KeyError when absent)."""
        for c in self:
            if c.name == name:
                return c
        raise KeyError(name)


def build_pipeline(
    kb: KnowledgeBase,
    sim: SensorSuite,
    world: World,
    role: str | Role = "companion",
    *,
    robot: str | None = None,
    options: PipelineOptions | None = None,
    bus: Bus | None = None,
) -> Pipeline:
    """Build every KnIC inference component for one run (nothing is stepped yet).

    Args:
        kb: the knowledge base the KP' write (seed it first with :func:`knic.seed.seed_kb_from_world`).
        sim: the sensors and the simulated clock.
        world: the world data (room map, furniture, devices, priors).
        role: a role name from the role file or a :class:`Role`.
        robot: the robot's symbol (default: the world's robot).
        options: tunables.
        bus: the message bus (a new one by default).

    Raises:
        core.errors.InferenceError: unknown role or malformed role file.
    """
    opts = options or PipelineOptions()
    the_role = role if isinstance(role, Role) else load_role(role, opts.roles_file)
    bus = bus or Bus()
    robot_name = robot or world.robot.name
    resolution = opts.tracking.resolution
    locations = build_location_model(world, entity_resolution=resolution)
    camera = SharedCamera(sim, lambda: sim.time)
    # one belief per fact, weighed: a weak assumption never overrides a fresh observation
    fusion = install_fusion(kb, lambda: sim.time, opts.fusion_half_life_s)
    camera_hz = opts.camera_hz or the_role.max_rate(exclude=("robot", "doorbell"))
    class_symbols = _unique_classes(world)
    providers: list[Component] = [
        LocationsKP(locations, bus, kb),
        RobotPoseKP(sim, bus, robot_name, frequency=10.0),
        CameraObjectsKP(
            camera,
            bus,
            kb,
            class_symbols,
            class_colours=_class_colours(world),
            frequency=camera_hz,
            detect_range=opts.object_detect_range,
            max_points=opts.points_per_detection,
            min_pixels=opts.object_min_pixels,
            miss_range=opts.miss_range_share * opts.object_detect_range,
            edge_px=opts.edge_px,
        ),
        CameraPeopleKP(
            camera,
            bus,
            kb,
            frequency=camera_hz,
            detect_range=opts.person_detect_range,
            max_points=opts.points_per_detection,
            min_pixels=opts.person_min_pixels,
            miss_range=opts.miss_range_share * opts.person_detect_range,
            edge_px=opts.edge_px,
        ),
        SoundKP(sim, bus, kb, frequency=10.0),
        DeviceKP(
            sim,
            bus,
            {d.name: d.kind for d in world.devices.values()},
            {d.name: d.position for d in world.devices.values()},
            frequency=2.0,
        ),
    ]
    cognition = CognitiveLayer(bus, the_role, config=opts.tracking, frequency=10.0)
    for provider in providers:  # the role's filter runs before deprojection, in the camera KPs
        if opts.early_role_filter and isinstance(provider, CameraObjectsKP | CameraPeopleKP):
            provider.gate = cognition.admits
    kp_primes: list[Component] = [
        RobotAtKP(bus, kb),  # its hysteresis is a margin at the room boundary (see the class)
        ObjectPlaceKP(bus, kb, needed=opts.needed, resolution=resolution),
        PersonPlaceKP(
            bus,
            kb,
            ttl_s=the_role.person_ttl_s,
            needed=opts.needed,
            resolution=resolution,
            stale_s=opts.tracking.person_stale_s if opts.tracking.person_stale_s is not None else math.inf,
        ),
        PersonNearKP(bus, kb, needed=opts.needed),
        SoundAtKP(bus, kb),
        DeviceStateKP(bus, kb),
        ExploredKP(bus, kb, ttl_s=opts.explored_ttl_s),
        CandidatesKP(
            bus,
            kb,
            priors_from_world(world),
            list(world.rooms),
            max_candidates=opts.max_candidates,
            searched_ttl_s=opts.searched_ttl_s,
        ),
    ]
    return Pipeline(
        [*providers, cognition, *kp_primes],
        bus=bus,
        role=the_role,
        locations=locations,
        cognition=cognition,
        camera=camera,
        fusion=fusion,
    )


def _class_colours(world: World) -> dict[str, dict[str, tuple[float, float, float]]]:
    """Detector class -> {item symbol: its known colour} for the classes that name several items."""
    by_class: dict[str, dict[str, tuple[float, float, float]]] = {}
    for name, item in world.items.items():
        by_class.setdefault(item.cls, {})[name] = (item.color[0], item.color[1], item.color[2])
    return {cls: known for cls, known in by_class.items() if len(known) > 1}


def _unique_classes(world: World) -> dict[str, str]:
    """Detector class -> item symbol for the classes that name exactly one item."""
    by_class: dict[str, list[str]] = {}
    for name, item in world.items.items():
        by_class.setdefault(item.cls, []).append(name)
    return {cls: names[0] for cls, names in by_class.items() if len(names) == 1}
