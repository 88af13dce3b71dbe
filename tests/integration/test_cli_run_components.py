"""``knic run`` reports each scheduled component's rate, step time and overruns (text and ``--json``)."""

from __future__ import annotations

import json

import pytest

from knic.cli import main

GOAL = ["run", "--world", "erl_home_paper", "--goal", "(robot_at r2d2 kitchen)", "--max-sim-time", "120"]


def test_json_summary_has_rate_step_time_and_overruns_per_component(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code = main([*GOAL, "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert code == 0, summary["reason"]
    components = {c["name"]: c for c in summary["components"]}
    assert {"sim", "kgm2.cognition", "kp'.robot_at", "dispatcher"} <= set(components)
    keys = {"frequency", "rate", "steps", "mean_ms", "max_ms", "slow_steps", "behind", "overruns"}
    for c in components.values():
        assert keys <= set(c), c
        assert c["overruns"] == c["slow_steps"] + c["behind"] >= 0
        assert c["max_ms"] >= c["mean_ms"] >= 0.0
    # measured rate: steps per simulated second over the run (a step at t=0 and one per period after it)
    for c in components.values():
        assert c["steps"] == pytest.approx(c["rate"] * summary["sim_time"], rel=1e-6)
    sim = components["sim"]
    assert sim["steps"] == pytest.approx(sim["frequency"] * summary["sim_time"] + 1, abs=1)
    assert sim["mean_ms"] > 0.0  # wall time was measured


def test_text_output_ends_with_the_component_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(GOAL) == 0
    out = capsys.readouterr().out
    table = out[out.index("\ncomponents: ") + 1 :].splitlines()
    assert table[0].startswith("components: ") and ", overruns " in table[0]
    header = ["component", "Hz", "rate", "steps", "mean", "ms", "max", "ms", "slow", "behind"]
    assert table[1].split() == header
    rows = [line.split() for line in table[2:] if line.startswith("  ")]
    assert len(rows) >= 5 and all(len(r) == 8 for r in rows)
    assert sum(int(r[6]) + int(r[7]) for r in rows) == int(table[0].split("overruns ")[1].split()[0])
