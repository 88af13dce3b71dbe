"""The ROS 2 adapter stays at the edge: the run, the seam and the command lines of ``knic ros`` / ``knic sim``
import without rclpy (it loads only when a ROS command runs), and a missing rclpy is one line."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from knic.ros.env import RosUnavailable, domain_id, require_ros

WITHOUT_ROS = [
    "core.robot",
    "worlds.simulation",
    "knic.system",
    "knic.pipeline",
    "knic.intake",
    "knic.cli.run",
    "knic.cli.ros",
    "knic.cli.sim",
    "knic.ros.topics",
]
ROS_MODULES = ["rclpy", "rosidl_runtime_py", "std_msgs", "geometry_msgs", "sensor_msgs", "rmw_implementation"]


def test_run_and_seam_import_without_rclpy() -> None:
    code = (
        "import importlib, json, sys\n"
        f"for name in {WITHOUT_ROS!r}: importlib.import_module(name)\n"
        f"print(json.dumps([m for m in {ROS_MODULES!r} if m in sys.modules]))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert json.loads(out) == []


def test_missing_rclpy_is_one_line(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "rclpy", None)  # import rclpy now raises ImportError
    with pytest.raises(RosUnavailable, match=r"ROS 2 is not usable here .*pip install -e '\.\[ros\]'"):
        require_ros()


def test_domain_id_is_checked(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_DOMAIN_ID", "17")
    assert domain_id() == 17
    assert domain_id(3) == 3
    monkeypatch.setenv("ROS_DOMAIN_ID", "seventeen")
    with pytest.raises(Exception, match="ROS_DOMAIN_ID 'seventeen' is not an integer"):
        domain_id()
    with pytest.raises(Exception, match=r"outside 0\.\.232"):
        domain_id(500)


def test_sim_without_ros_flag_says_so() -> None:
    from knic.cli import main

    assert main(["sim", "--world", "erl_home_paper"]) == 2
