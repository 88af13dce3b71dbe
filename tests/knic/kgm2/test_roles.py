"""Roles as data: which classes and rooms KGM-2 processes, at which rate and priority."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import InferenceError
from knic.bus import Bus, Message
from knic.kgm1.sources import FrameView
from knic.kgm2.cognition import CognitiveLayer
from knic.kgm2.roles import Policy, Role, load_role, load_roles
from knic.spatial import LocationModel
from knic.units import CKU, Kind, Scan
from tests.knic.places import publish_place_percepts
from tests.knic.synthetic import frame, percept


def test_shipped_roles() -> None:
    roles = load_roles()
    assert {
        "companion",
        "service_autonomous",
        "service_semi_autonomous",
        "teleoperated",
        "all_top_rate",
    } <= set(roles)
    companion = roles["companion"]
    assert companion.policy("glasses", "entrance") == Policy(5.0, 9)
    assert companion.policy("mug", "entrance") == Policy(1.0, 1)
    assert companion.policy("mug", "kitchen") == Policy(2.0, 5)
    assert roles["all_top_rate"].policy("mug", "entrance").rate_hz == 5.0
    assert roles["service_semi_autonomous"].confirm_actions and roles["teleoperated"].operator_only


def test_bad_role_files(tmp_path: Path) -> None:
    bad = tmp_path / "roles.yaml"
    bad.write_text("roles:\n  x: {default: {rate_hz: -1}}\n")
    with pytest.raises(InferenceError, match="rate_hz"):
        load_roles(bad)
    bad.write_text("roles:\n  x: {default: {rate_hz: 1}, speed: 3}\n")
    with pytest.raises(InferenceError, match="unknown keys"):
        load_roles(bad)
    with pytest.raises(InferenceError, match="known roles"):
        load_role("pilot")


def feed(role: Role, locations: LocationModel, seconds: float = 2.0) -> dict[str, list[CKU]]:
    """Glasses and a mug seen in the entrance in every 10 Hz frame; CKUs published per symbol."""
    bus = Bus()
    layer = CognitiveLayer(bus, role)
    publish_place_percepts(bus, locations)
    out: dict[str, list[CKU]] = {}

    def collect(m: Message) -> None:
        out.setdefault(m.payload.symbol, []).append(m.payload)

    bus.subscribe("cognition.object", collect)
    view = FrameView(frame(0.0, (5.0, 2.0, 1.2, 0.0)), max_range=4.0)
    for i in range(int(seconds * 10)):
        t = i / 10
        for unit in (
            percept(Kind.OBJECT, "glasses", (7.75, 1.5, 0.92), t, identity="glasses"),
            percept(Kind.OBJECT, "mug", (7.7, 2.0, 0.92), t, identity="mug"),
        ):
            bus.publish(f"percept.vision.object.{unit.label}", unit, source="kp", stamp=t)
        bus.publish("percept.vision.scan.object", Scan(Kind.OBJECT, t, view, "cam"), source="kp", stamp=t)
        layer.step(t)
    return out


def test_roles_change_what_is_processed(paper_locations: LocationModel) -> None:
    companion = feed(load_role("companion"), paper_locations)
    top = feed(load_role("all_top_rate"), paper_locations)
    # a new track is processed in every frame until it has settled (3 hits: frames 0, 0.1, 0.2), then at the
    # role's rate: 5 Hz over 2 s for the priority glasses, 1 Hz vs 5 Hz for the mug
    assert len(companion["glasses"]) == len(top["glasses"]) == 11
    assert len(companion["mug"]) == 4 and len(top["mug"]) == 11
    assert companion["glasses"][0].role_priority == 9 and companion["mug"][0].role_priority == 1
    ignore_mugs = Role("picky", "", Policy(5.0, 1), classes={"mug": Policy(0.0, 0)})
    assert "mug" not in feed(ignore_mugs, paper_locations)


def test_cku_carries_octomap_keys_and_support(paper_locations: LocationModel) -> None:
    bus = Bus()
    layer = CognitiveLayer(bus, load_role("all_top_rate"))
    publish_place_percepts(bus, paper_locations)
    box = bus.inbox("cognition.object.glasses")
    unit = percept(Kind.OBJECT, "glasses", (7.75, 1.5, 0.92), 1.0, identity="glasses")
    bus.publish("percept.vision.object.glasses", unit, source="kp", stamp=1.0)
    layer.step(1.0)
    (message,) = box.drain()
    cku: CKU = message.payload
    assert (message.source, cku.symbol, cku.kind, cku.stamp) == (
        "kgm2.cognition",
        "glasses",
        Kind.OBJECT,
        1.0,
    )
    assert cku.support == (unit.uid,) and len(cku.keys) > 0
    assert paper_locations.rooms.best(cku.keys)[0] == "entrance"
    tree = cku.octomap
    assert tree is not None
    node = tree.search(unit.points[0])
    assert node is not None and tree.isNodeOccupied(node)


def gated_feed(
    role: Role, locations: LocationModel, seconds: float = 2.0
) -> tuple[dict[str, int], CognitiveLayer]:
    """As :func:`feed`, but the 10 Hz frames go through the layer's early filter as a camera KP would ask it:
    per class, before the units exist. Returns the units admitted per class and the layer."""
    bus = Bus()
    layer = CognitiveLayer(bus, role)
    publish_place_percepts(bus, locations)
    view = FrameView(frame(0.0, (5.0, 2.0, 1.2, 0.0)), max_range=4.0)
    admitted: dict[str, int] = {"glasses": 0, "mug": 0}
    for i in range(int(seconds * 10)):
        t = i / 10
        withheld = set()
        for unit in (
            percept(Kind.OBJECT, "glasses", (7.75, 1.5, 0.92), t, identity="glasses"),
            percept(Kind.OBJECT, "mug", (7.7, 2.0, 0.92), t, identity="mug"),
        ):
            if not layer.admits(unit.label, (5.0, 2.0, 1.2), t):
                withheld.add(unit.label)
                continue
            admitted[unit.label] += 1
            bus.publish(f"percept.vision.object.{unit.label}", unit, source="kp", stamp=t)
        scan = Scan(Kind.OBJECT, t, view, "cam", frozenset(withheld))
        bus.publish("percept.vision.scan.object", scan, source="kp", stamp=t)
        layer.step(t)
    return admitted, layer


def test_early_filter_admits_what_the_role_processes(paper_locations: LocationModel) -> None:
    companion, layer = gated_feed(load_role("companion"), paper_locations)
    top, _ = gated_feed(load_role("all_top_rate"), paper_locations)
    # as test_roles_change_what_is_processed, but the mug's units are never made when not due: 3 frames to
    # settle (0, 0.1, 0.2), then 1 Hz (1.0); the glasses and the all-top-rate role at the role's 5 Hz
    assert companion == {"glasses": 11, "mug": 4} and top == {"glasses": 11, "mug": 11}
    # a withheld frame is no miss: the mug's track stays settled, unmissed
    (mug,) = layer.trackers["mug"].tracks.values()
    assert mug.misses == 0 and mug.hits == 4
    assert layer.stats.processed == 15
