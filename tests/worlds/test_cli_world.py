"""``knic world check`` and ``knic world render`` from the command line."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
import yaml
from PIL import Image

from knic.cli import main


def test_check_prints_a_summary(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["world", "check", "erl_home", "--json", "--scenario", "visitors"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["valid"] and out["rooms"] == 7 and out["doors"] == 8 and out["scenarios"] == ["visitors"]


def test_check_rejects_an_invalid_file(
    tmp_path: Path, doc: dict[str, Any], capsys: pytest.CaptureFixture[str]
) -> None:
    doc["items"][0]["furniture"] = "fridge"
    bad = tmp_path / "bad_world.yaml"
    bad.write_text(yaml.safe_dump(doc))
    assert main(["world", "check", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert err == "knic: error: bad_world.yaml: items[0] 'glasses': on unknown furniture 'fridge'"


def test_render_writes_a_png(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "map.png"
    assert main(["world", "render", "erl_home_paper", "--out", str(out), "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    with Image.open(out) as img:
        assert img.format == "PNG" and img.size == (info["width"], info["height"])
        colours = img.convert("RGB").getcolors(maxcolors=100000)
        assert colours is not None and len(colours) > 20


def test_check_warns_of_rooms_and_furniture_the_robot_cannot_reach(
    tmp_path: Path, doc: dict[str, Any], capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["world", "check", "erl_home", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["unreachable_rooms"] == [] and out["unreachable_furniture"] == []
    # a wardrobe pushed in front of the bedroom's only door; a box in the bathroom's corner behind a bathtub
    # and a basin, with no gap wide enough for the robot
    furniture = doc["furniture"]
    furniture.append({"name": "wardrobe", "room": "bedroom", "position": [3.6, 7.0], "size": [0.6, 1.4, 2]})
    furniture.append({"name": "box", "room": "bathroom", "position": [0.3, 4.0], "size": [0.4, 0.4, 0.3]})
    furniture.append({"name": "bathtub", "room": "bathroom", "position": [1.2, 4.0], "size": [1.4, 1.9, 0.5]})
    furniture.append({"name": "basin", "room": "bathroom", "position": [0.3, 3.3], "size": [0.5, 0.6, 0.8]})
    world_file = tmp_path / "blocked.yaml"
    world_file.write_text(yaml.safe_dump(doc))
    assert main(["world", "check", str(world_file), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["unreachable_rooms"] == ["bedroom"]
    assert out["unreachable_furniture"] == ["box"]
    assert main(["world", "check", str(world_file)]) == 0
    assert "warning: the robot cannot reach bedroom from its start" in capsys.readouterr().out
