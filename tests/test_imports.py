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


def test_the_command_side_starts_without_the_journal_or_the_planning_library() -> None:
    """``knic goal`` and ``knic say`` need only the knowledge base's value types (start-up time)."""
    code = (
        "import json, sys\n"
        "import knic.language.lmspeech, knic.language.understanding\n"
        "from knowledge_base import Fact\n"
        "heavy = ('sqlite3', 'unified_planning', 'knowledge_base.kb')\n"
        "print(json.dumps([m for m in heavy if m in sys.modules]))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert json.loads(out) == []
    code = "from knowledge_base import KnowledgeBase as K, DomainModel as D; print(K.__name__, D.__name__)"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert out.split() == ["KnowledgeBase", "DomainModel"]
