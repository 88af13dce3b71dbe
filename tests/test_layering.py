"""The architecture, read from the import graph: lower packages never import upper ones, no cycles.

Layers, bottom first: ``core`` -> ``knowledge_base`` -> ``actions`` -> ``planner`` -> ``knic``;
``worlds`` (the simulator behind the robot seam) stands on ``core`` only. Inside ``knic`` the KGM levels
stack KGM-3 -> KGM-2 -> KGM-1 -> (spatial floor, units, bus, scheduler); the floor (``knic.spatial``: voxel
keys, volumes, octomaps, places) stands on the units alone, and language understanding needs none of them.
Every import counts: module level, inside functions and under ``TYPE_CHECKING``.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Mapping
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("core", "knowledge_base", "worlds", "actions", "planner", "knic")

#: package -> the project packages it may import (besides itself)
ALLOWED: dict[str, frozenset[str]] = {
    "core": frozenset(),
    "knowledge_base": frozenset({"core"}),
    "worlds": frozenset({"core"}),
    "actions": frozenset({"core", "knowledge_base"}),
    "planner": frozenset({"core", "knowledge_base", "actions"}),
    "knic": frozenset(PACKAGES),
}

#: module prefix inside knic -> module prefixes it must never import
KNIC_FORBIDDEN: dict[str, tuple[str, ...]] = {
    "knic.units": (
        "knic.spatial",
        "knic.kgm1",
        "knic.kgm2",
        "knic.kgm3",
        "knic.system",
        "knic.cli",
        "knic.bench",
    ),
    "knic.spatial": (
        "knic.bus",
        "knic.scheduler",
        "knic.pipeline",
        "knic.kgm1",
        "knic.kgm2",
        "knic.kgm3",
        "knic.system",
        "knic.language",
        "knic.cli",
        "knic.bench",
    ),
    "knic.bus": ("knic.kgm1", "knic.kgm2", "knic.kgm3", "knic.system", "knic.cli", "knic.bench"),
    "knic.scheduler": ("knic.kgm1", "knic.kgm2", "knic.kgm3", "knic.system", "knic.cli", "knic.bench"),
    "knic.kgm1": ("knic.kgm2", "knic.kgm3", "knic.system", "knic.language", "knic.cli", "knic.bench"),
    "knic.kgm2": ("knic.kgm3", "knic.system", "knic.language", "knic.cli", "knic.bench"),
    "knic.kgm3": ("knic.system", "knic.language", "knic.cli", "knic.bench"),
    "knic.language": ("knic.kgm1", "knic.kgm2", "knic.kgm3", "knic.system", "knic.cli", "knic.bench"),
    "knic.system": ("knic.cli", "knic.bench"),
}

MAX_MODULE_LINES = 550


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def project_modules() -> dict[str, Path]:
    return {module_name(p): p for pkg in PACKAGES for p in sorted((ROOT / pkg).rglob("*.py"))}


def imports_of(path: Path, name: str, known: Iterable[str]) -> set[str]:
    """Project modules ``name`` imports (absolute and relative imports, anywhere in the file)."""
    known = set(known)
    is_package = path.name == "__init__.py"
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        targets: list[str] = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = name.split(".")
                anchor = anchor if is_package else anchor[:-1]
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join([*anchor, base] if base else anchor)
            targets = [f"{base}.{a.name}" for a in node.names] + [base]
        for target in targets:
            while target and target not in known:
                target = target.rpartition(".")[0]
            if target and target != name:
                found.add(target)
    return found


def import_graph() -> dict[str, set[str]]:
    modules = project_modules()
    return {name: imports_of(path, name, modules) for name, path in modules.items()}


def layering_violations(graph: Mapping[str, Iterable[str]]) -> list[str]:
    out = []
    for src, targets in graph.items():
        top = src.split(".")[0]
        for dst in targets:
            other = dst.split(".")[0]
            if other != top and other not in ALLOWED[top]:
                out.append(f"{src} -> {dst}")
            for prefix, banned in KNIC_FORBIDDEN.items():
                if (src == prefix or src.startswith(prefix + ".")) and any(
                    dst == b or dst.startswith(b + ".") for b in banned
                ):
                    out.append(f"{src} -> {dst}")
    return sorted(out)


def cycles(graph: Mapping[str, Iterable[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_lower_packages_never_import_upper_ones() -> None:
    assert layering_violations(import_graph()) == []


def test_no_import_cycles() -> None:
    # a package's __init__ re-exporting its own submodules is not a cycle between parts
    graph = {
        src: {d for d in dsts if not (src + ".").startswith(d + ".")} for src, dsts in import_graph().items()
    }
    assert cycles(graph) == []


def test_actions_never_reach_the_bus_or_the_simulator() -> None:
    graph = import_graph()
    bad = [f"{s} -> {d}" for s, ds in graph.items() if s.startswith("actions") for d in ds]
    assert [b for b in bad if "knic" in b or "worlds" in b] == []


def test_modules_stay_small() -> None:
    sizes = {
        name: len(path.read_text(encoding="utf-8").splitlines()) for name, path in project_modules().items()
    }
    assert {n: s for n, s in sizes.items() if s > MAX_MODULE_LINES} == {}


@pytest.mark.parametrize(
    ("graph", "expected"),
    [
        ({"knowledge_base.kb": {"knic.bus"}}, ["knowledge_base.kb -> knic.bus"]),
        ({"actions.erl.context": {"knic.bus"}}, ["actions.erl.context -> knic.bus"]),
        ({"knic.kgm1.camera": {"knic.kgm2.spatial"}}, ["knic.kgm1.camera -> knic.kgm2.spatial"]),
        ({"knic.kgm3.places": {"knic.kgm2.tracking"}}, []),
        ({"knic.spatial.volumes": {"knic.kgm2.roles"}}, ["knic.spatial.volumes -> knic.kgm2.roles"]),
        ({"knic.kgm1.locations": {"knic.spatial.volumes"}}, []),
    ],
)
def test_the_checker_catches_upward_edges(graph: dict[str, set[str]], expected: list[str]) -> None:
    assert layering_violations(graph) == expected


def test_the_checker_catches_cycles() -> None:
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
