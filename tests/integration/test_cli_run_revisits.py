"""``knic run`` under the companion role: while the robot has nothing to do it revisits as the role says, and
a goal given meanwhile takes the robot over at once."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from knic.cli import main

GOAL_AT = 30.0


def _task_events(path: Path) -> list[dict[str, object]]:
    events = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]
    return [e for e in events if e["kind"] == "task"]


@pytest.mark.parametrize("revisits", [True, False])
def test_an_idle_companion_revisits_until_a_goal_arrives(tmp_path: Path, revisits: bool) -> None:
    trace = tmp_path / "trace.jsonl"
    args = ["run", "--goal-at", f"{GOAL_AT:g}:switch on the hallway light", "--trace", str(trace), "--json"]
    args += ["--max-sim-time", "120"] + ([] if revisits else ["--no-revisits"])
    assert main(args) == 0
    events = _task_events(trace)
    if not revisits:
        assert events == []  # the robot waited where it was
        return
    steps = [(e["action"], e["data"]["room"]) for e in events]  # type: ignore[index]
    # the role's rooms first, a sweep of the first, then the next trip given up when the goal came
    assert steps[:4] == [
        ("revisit", "bedroom"),
        ("revisited", "bedroom"),
        ("revisit", "kitchen"),
        ("revisit interrupted", "kitchen"),
    ]
    times = [float(e["time"]) for e in events]  # type: ignore[arg-type]
    assert times[0] < GOAL_AT <= times[3] and len(events) == 4  # nothing revisited after the goal
