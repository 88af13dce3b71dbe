"""World files: the shipped worlds hold the shared symbols; invalid worlds are rejected with a clear
message."""

from __future__ import annotations

import re
from typing import Any

import pytest

from core.errors import WorldError
from worlds.api import load_world
from worlds.loader import world_from_dict
from worlds.model import World

ROOMS = {"entrance_hall", "hallway", "living_room", "dining_room", "kitchen", "bedroom", "bathroom"}
FURNITURE = {
    "kitchen_counter",
    "kitchen_table",
    "kitchen_cabinet",
    "bin",
    "dining_table",
    "coffee_table",
    "side_table",
    "tv_table",
    "bookshelf",
    "sofa",
    "armchair",
    "bed",
    "bedside_table",
    "closet",
    "bathroom_drawer",
    "plant",
    "entrance_shelf",
}
ITEMS = {
    "glasses",
    "mug",
    "cup",
    "glass",
    "coke_can",
    "water",
    "juice",
    "apple",
    "lemon",
    "candle",
    "cardboard_box",
    "remote",
    "tablet",
    "sponge",
    "soap",
    "tissues",
}
CONNECTED = {
    frozenset(p)
    for p in [
        ("entrance_hall", "hallway"),
        ("hallway", "living_room"),
        ("hallway", "kitchen"),
        ("hallway", "bedroom"),
        ("hallway", "bathroom"),
        ("living_room", "dining_room"),
        ("dining_room", "kitchen"),
    ]
}


def test_erl_home_has_the_shared_symbols(erl_world: World) -> None:
    w = erl_world
    assert set(w.rooms) == ROOMS
    assert set(w.furniture) == FURNITURE
    assert set(w.items) == ITEMS
    assert set(w.people) == {"annie", "tracy", "jack"}
    assert w.robot.name == "r2d2"
    kinds = {d.name: d.kind for d in w.devices.values()}
    assert kinds == {
        "bedroom_left_light": "light",
        "bedroom_right_light": "light",
        "hallway_light": "light",
        "living_room_dimmer": "dimmer",
        "bedroom_blinds": "blinds",
        "door_bell": "bell",
    }
    assert {frozenset(p) for p in w.connected()} == CONNECTED
    assert w.people["annie"].on in ("bed", "sofa")
    assert w.room_of(*w.robot.start[:2]) == "entrance_hall"
    for item in w.items.values():
        assert 1 <= len(item.priors) <= 3
        assert sum(p.probability for p in item.priors) == pytest.approx(1.0)


def test_paper_world(erl_world: World) -> None:
    w = load_world("erl_home_paper")
    assert set(w.rooms) == {"kitchen", "bedroom", "entrance", "living_room"}
    assert {frozenset(p) for p in w.connected()} == {
        frozenset(p)
        for p in [
            ("bedroom", "kitchen"),
            ("kitchen", "entrance"),
            ("entrance", "living_room"),
            ("living_room", "bedroom"),
        ]
    }
    assert w.room_of(*w.robot.start[:2]) == "bedroom"
    assert w.room_of(*w.people["annie"].position) == "bedroom"
    assert w.items["glasses"].on == "entrance_shelf"
    assert [p.room for p in w.items["glasses"].priors] == ["kitchen", "entrance", "living_room"]


def test_a_path_works_like_a_name(erl_world: World) -> None:
    assert erl_world.source is not None
    assert load_world(str(erl_world.source)).rooms == erl_world.rooms


def _reject(doc: dict[str, Any], pattern: str) -> None:
    with pytest.raises(WorldError, match=pattern) as info:
        world_from_dict(doc, file="bad.yaml")
    assert "\n" not in str(info.value)
    assert str(info.value).startswith("bad.yaml: ")


def test_door_to_unknown_room(doc: dict[str, Any]) -> None:
    doc["doors"][2]["rooms"] = ["hallway", "kitchn"]
    _reject(doc, re.escape("doors[2]: unknown room 'kitchn'"))


def test_object_on_missing_furniture(doc: dict[str, Any]) -> None:
    doc["items"][1]["furniture"] = "fridge"
    _reject(doc, re.escape("items[1] 'mug': on unknown furniture 'fridge'"))


def test_overlapping_rooms(doc: dict[str, Any]) -> None:
    doc["rooms"][5]["polygon"] = [[0, 4.5], [4, 4.5], [4, 9], [0, 9]]  # bedroom reaches into the bathroom
    _reject(doc, "rooms 'bedroom' and 'bathroom': floor polygons overlap")


def test_self_intersecting_polygon(doc: dict[str, Any]) -> None:
    doc["rooms"][6]["polygon"] = [[0, 2], [4, 5], [4, 2], [0, 5]]  # a bow tie
    _reject(doc, re.escape("rooms[6] 'bathroom': polygon is self-intersecting"))


@pytest.mark.parametrize(
    ("section", "index", "field", "pattern"),
    [
        ("rooms", 0, "polygon", "rooms[0] 'entrance_hall': missing field 'polygon'"),
        ("furniture", 3, "size", "furniture[3] 'bin': missing field 'size'"),
        ("devices", 0, "type", "devices[0] 'bedroom_left_light': missing field 'type'"),
        ("doors", 1, "position", "doors[1]: missing field 'position'"),
    ],
)
def test_missing_field(doc: dict[str, Any], section: str, index: int, field: str, pattern: str) -> None:
    del doc[section][index][field]
    _reject(doc, re.escape(pattern))


def test_missing_robot(doc: dict[str, Any]) -> None:
    del doc["robot"]
    _reject(doc, re.escape("document: missing field 'robot'"))


def test_other_mistakes_are_named(doc: dict[str, Any]) -> None:
    bad = dict(doc, doors=[*doc["doors"], {"rooms": ["bedroom", "kitchen"], "position": [4.0, 7.0]}])
    _reject(bad, re.escape("doors[8]: position (4.0, 7.0) is not on a wall of room 'kitchen'"))
    doc["furniture"][0]["colour"] = [1, 1, 1, 1]
    _reject(doc, re.escape("furniture[0] 'kitchen_counter': unknown field 'colour'"))


def test_unknown_world_name() -> None:
    with pytest.raises(WorldError, match="unknown world 'nowhere'"):
        load_world("nowhere")
