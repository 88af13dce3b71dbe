"""The core packages import in a fresh interpreter without any adapter library (ROS, DDS, web, GUI)."""

import json
import subprocess
import sys

CORE = ["core", "core.errors", "knic", "knic.cli", "knowledge_base", "planner", "actions", "worlds"]
ADAPTERS = ["rclpy", "cyclonedds", "http.server", "PySide6", "tkinter", "fastapi", "starlette", "uvicorn"]


def test_core_imports_without_adapters() -> None:
    code = (
        "import importlib, json, sys\n"
        f"for name in {CORE!r}: importlib.import_module(name)\n"
        f"print(json.dumps([m for m in {ADAPTERS!r} if m in sys.modules]))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert json.loads(out) == []


def test_cli_help_lists_every_command() -> None:
    from knic.cli import COMMANDS

    out = subprocess.run(
        [sys.executable, "-m", "knic", "--help"], check=True, capture_output=True, text=True
    ).stdout
    for name in COMMANDS:
        assert name in out
