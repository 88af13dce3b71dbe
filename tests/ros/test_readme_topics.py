"""The README's ROS 2 section names every topic of :mod:`knic.ros.topics` (the table stays accurate)."""

from __future__ import annotations

from pathlib import Path

from knic.ros import topics as tp

ROOT = Path(__file__).resolve().parents[2]


def test_readme_ros_section_lists_every_topic() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## KnIC beside a ROS 2 robot", 1)[1].split("\n## ", 1)[0]
    names = {
        value: key
        for key, value in vars(tp).items()
        if key.isupper() and isinstance(value, str) and value.startswith("/")
    }
    names.pop(tp.OCTOMAP_PREFIX)
    assert "/knic/octomap/<kind>_<name>" in section
    missing = sorted(f"{key} {topic}" for topic, key in names.items() if f"`{topic}`" not in section)
    assert missing == []
