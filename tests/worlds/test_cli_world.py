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
