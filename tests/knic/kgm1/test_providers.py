"""KGM-1 providers: camera objects and people, pose, sounds, devices, locations; first-meeting instances."""

from __future__ import annotations

import math

import numpy as np

from knic.bus import Bus, Message
from knic.kgm1.camera import CameraObjectsKP, CameraPeopleKP
from knic.kgm1.locations import LocationsKP
from knic.kgm1.providers import DeviceKP, RobotPoseKP, SoundKP
from knic.kgm1.sources import CameraSource, FrameView, SharedCamera
from knic.spatial import FURNITURE, ROOM, LocationModel
from knic.units import LLKU, Kind, Scan
from knowledge_base import BeliefStatus, KnowledgeBase
from tests.knic.synthetic import FakeSensors, frame
from worlds.api import Pose2D, SoundEvent

# camera at (5.0, 2.0), 1.2 m high, looking along +x; a box of pixels around the image centre at 2 m depth
CAMERA = (5.0, 2.0, 1.2, 0.0)
CENTRE_BOX = (36, 26, 44, 34)


def collect(bus: Bus, pattern: str) -> list[Message]:
    got: list[Message] = []
    bus.subscribe(pattern, got.append)
    return got


def test_camera_objects_kp_publishes_world_frame_units_then_the_scan(paper_kb: KnowledgeBase) -> None:
    sensors = FakeSensors()
    sensors.next_frame = frame(
        3.0, CAMERA, boxes=[("glasses", CENTRE_BOX, 2.0, None), ("person", (0, 0, 4, 4), 3.0, "annie")]
    )
    camera: CameraSource = sensors
    bus = Bus()
    got = collect(bus, "percept.vision")
    kp = CameraObjectsKP(camera, bus, paper_kb, {"glasses": "glasses"})
    kp.step(3.0)
    kp.step(3.1)  # the same frame again: nothing new
    assert [m.topic for m in got] == ["percept.vision.object.glasses", "percept.vision.scan.object"]
    unit: LLKU = got[0].payload
    assert (unit.kind, unit.identity, unit.stamp, got[0].source) == (
        Kind.OBJECT,
        "glasses",
        3.0,
        "kp.camera_objects",
    )
    assert np.allclose(unit.position, (7.0, 2.0, 1.2), atol=0.1)  # 2 m in front of the camera
    assert np.allclose(unit.points.mean(axis=0), unit.position, atol=0.1)
    assert unit.sensor_origin == (5.0, 2.0, 1.2)
    scan: Scan = got[1].payload
    assert scan.kind is Kind.OBJECT and scan.stamp == 3.0


def test_camera_people_kp_meets_a_new_person_once(paper_kb: KnowledgeBase) -> None:
    sensors = FakeSensors()
    sensors.next_frame = frame(
        1.0, CAMERA, boxes=[("person", CENTRE_BOX, 3.0, "nick"), ("cup", (0, 0, 4, 4), 2, None)]
    )
    bus = Bus()
    got = collect(bus, "percept.vision.person")
    kp = CameraPeopleKP(sensors, bus, paper_kb)
    kp.step(1.0)
    assert [m.payload.identity for m in got] == ["nick"]
    assert paper_kb.type_of("nick") == "person"
    changes = [c for c in paper_kb.changes() if "nick" in c.args]
    assert len(changes) == 1 and changes[0].provenance.source == "kp.camera_people"
    assert changes[0].provenance.status is BeliefStatus.OBSERVED


def test_frame_view_sees_what_is_in_front_and_not_hidden() -> None:
    open_view = FrameView(frame(0.0, CAMERA), max_range=4.0)
    pts = np.array([[7.0, 2.0, 1.2], [4.0, 2.0, 1.2], [12.0, 2.0, 1.2], [7.0, 6.0, 1.2]])
    assert open_view.visible(pts).tolist() == [True, False, False, False]  # ahead; behind; too far; aside
    walled = FrameView(frame(0.0, CAMERA, depth=1.0), max_range=4.0)
    assert walled.visible(pts[:1]).tolist() == [False]
    assert np.allclose(open_view.optical_axis(), [1.0, 0.0, 0.0])


def test_shared_camera_renders_once_per_instant() -> None:
    sensors = FakeSensors()
    shared = SharedCamera(sensors, lambda: sensors.time)
    shared.camera_frame()
    shared.camera_frame()
    sensors.time = 0.2
    shared.camera_frame()
    assert sensors.frames_rendered == 2 == shared.renders


def test_pose_sound_and_device_providers(paper_kb: KnowledgeBase) -> None:
    sensors = FakeSensors()
    sensors.time = 2.0
    sensors.pose = Pose2D(1.0, 2.0, math.pi / 2)
    sensors.sounds = [SoundEvent("doorbell", (6.0, 0.2, 1.5), 1.9)]
    sensors.devices = {"hallway_light": True}
    bus = Bus()
    got = collect(bus, "percept")
    RobotPoseKP(sensors, bus, "r2d2").step(2.0)
    sound = SoundKP(sensors, bus, paper_kb)
    sound.step(2.0)
    sound.step(2.1)  # each event once
    DeviceKP(sensors, bus, {"hallway_light": "light"}).step(2.0)
    topics = [m.topic for m in got]
    assert topics == [
        "percept.pose.robot.robot",
        "percept.audio.sound.doorbell",
        "percept.device.device.light",
    ]
    pose: LLKU = got[0].payload
    assert (
        pose.identity == "r2d2" and pose.position == (1.0, 2.0, 0.0) and pose.attributes["yaw"] == math.pi / 2
    )
    assert got[2].payload.attributes["state"] is True
    assert paper_kb.type_of("doorbell") == "sound"  # met for the first time


def test_locations_kp_publishes_every_place_once(paper_locations: LocationModel) -> None:
    bus = Bus()
    got = collect(bus, "percept.map.location")
    kp = LocationsKP(paper_locations, bus)
    kp.step(0.0)
    kp.step(10.0)
    places = [m.payload.attributes["location"] for m in got]
    rooms = [p.name for p in places if p.cls == ROOM]
    furniture = [p.name for p in places if p.cls == FURNITURE]
    assert rooms == ["bedroom", "kitchen", "entrance", "living_room"]
    assert furniture == list(paper_locations.footprints) and "entrance_shelf" in furniture
    assert [m.payload.identity for m in got] == rooms + furniture
    assert got[0].topic == "percept.map.location.bedroom"
    # each room's octomap is built before it is published; a surface carries its support volume's
    bedroom = places[0].volume
    assert bedroom is not None and bedroom.octree().getNumLeafNodes() > 0
    assert got[0].payload.attributes["voxels"] == bedroom.voxel_count
    shelf = places[len(rooms) + furniture.index("entrance_shelf")]
    assert shelf.volume is not None and shelf.room == "entrance"


def test_camera_gate_withholds_classes_before_deprojection(paper_kb: KnowledgeBase) -> None:
    sensors = FakeSensors()
    sensors.next_frame = frame(
        3.0,
        CAMERA,
        boxes=[
            ("glasses", CENTRE_BOX, 2.0, None),
            ("mug", (10, 10, 14, 14), 2.0, None),
            ("mug", (50, 10, 54, 14), 2.0, None),
        ],
    )
    bus = Bus()
    got = collect(bus, "percept.vision")
    asked: list[tuple[str, float]] = []

    def gate(cls: str, position: tuple[float, float, float], stamp: float) -> bool:
        assert position == (5.0, 2.0, 1.2)
        asked.append((cls, stamp))
        return cls != "mug"

    kp = CameraObjectsKP(sensors, bus, paper_kb, {"glasses": "glasses"})
    kp.gate = gate
    kp.step(3.0)
    assert [m.topic for m in got] == ["percept.vision.object.glasses", "percept.vision.scan.object"]
    assert sorted(asked) == [("glasses", 3.0), ("mug", 3.0)]  # one question per class and frame
    assert got[1].payload.withheld == frozenset({"mug"}) and kp.withheld == 2


def test_frame_view_with_a_footprint_does_not_see_a_partly_hidden_entity() -> None:
    from tests.knic.synthetic import INTRINSICS

    # a bottle 1 m in front covers the image right of the pixel where a glass 2 m ahead projects
    cu = int(INTRINSICS.cx)
    bottle = ("water", (cu + 1, 0, INTRINSICS.width, INTRINSICS.height), 1.0, None)
    beside = frame(0.0, CAMERA, boxes=[bottle])
    glass = np.array([[7.0, 2.0, 1.2]])
    assert FrameView(beside, max_range=4.0).visible(glass).tolist() == [True]
    # the glass's own pixel is clear, its right side is hidden: not seeing it there proves nothing
    assert FrameView(beside, max_range=4.0, footprint_m=0.1).visible(glass).tolist() == [False]
    # in the open the footprint changes nothing
    assert FrameView(frame(0.0, CAMERA), max_range=4.0, footprint_m=0.1).visible(glass).tolist() == [True]
