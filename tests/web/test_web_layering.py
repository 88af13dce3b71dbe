"""The web view stays at the edge: only knic.web imports the web framework; only the CLI imports knic.web."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("core", "knowledge_base", "planner", "actions", "worlds", "knic")
WEB = ("fastapi", "starlette", "uvicorn", "httpx", "httpx2", "playwright", "pydantic", "fastapi_offline")


def imported(path: Path) -> set[str]:
    """Every module a file imports, anywhere in it (module level, functions, TYPE_CHECKING)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module)
    return found


def test_only_the_web_view_imports_the_web_framework() -> None:
    offenders = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if path.is_relative_to(ROOT / "knic" / "web"):
                continue
            for name in imported(path):
                if name.split(".")[0] in WEB:
                    offenders.append(f"{path.relative_to(ROOT)} imports {name}")
    assert offenders == []


def test_only_the_command_line_imports_the_web_view() -> None:
    offenders = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            rel = path.relative_to(ROOT)
            if rel.parts[:2] in (("knic", "web"), ("knic", "cli")):
                continue
            offenders += [
                f"{rel} imports {n}" for n in imported(path) if n == "knic.web" or n.startswith("knic.web.")
            ]
    assert offenders == []


def test_the_web_package_itself_imports_no_framework() -> None:
    """``import knic.web`` is free: the package's __init__ and the view's data modules need no framework."""
    for module in ("__init__.py", "scene.py", "view.py", "live.py"):
        assert not {n.split(".")[0] for n in imported(ROOT / "knic" / "web" / module)} & set(WEB), module
