"""Smoke test of ``knic bench grounding``: one short companion episode, figures present and sane.

The figures themselves (targets: precision >= 0.98, recall >= 0.90, staleness <= 1 s) are measured by the
600 s benchmark; here only their presence, ranges and consistency are checked.
"""

from __future__ import annotations

import json

import pytest

from knic.cli import main


def test_short_companion_episode_prints_sane_figures(capsys: pytest.CaptureFixture[str]) -> None:
    args = ["bench", "grounding", "--sim-seconds", "60", "--roles", "companion", "--skip-octomap", "--json"]
    assert main(args) == 0
    figures = json.loads(capsys.readouterr().out)
    assert figures["duration_s"] == 60.0
    assert 0.0 <= figures["precision"] <= 1.0 and 0.0 <= figures["recall"] <= 1.0
    assert figures["samples"] >= 55  # one comparison per simulated second
    assert figures["changes_reflected"] > 0 and figures["changes_unreflected"] >= 0
    assert figures["staleness_median_s"] is not None and figures["staleness_median_s"] >= 0.0
    assert figures["cpu_s_companion"] > 0.0
    # the episode not run has null figures, and no octomap figure was asked for
    assert figures["cpu_s_all_top_rate"] is None and figures["precision_all_top_rate"] is None
    assert "octomap_throughput_ratio" not in figures
    by_predicate = figures["by_predicate_companion"]
    assert {"robot_at", "object_at", "person_at"} <= set(by_predicate)
    for name, counts in by_predicate.items():
        assert 0 <= counts["false_samples"] <= counts["believed_samples"], name
        assert 0 <= counts["missed_samples"] <= counts["perceivable_samples"], name
    assert (
        by_predicate["robot_at"]["believed_samples"] > 0 and by_predicate["object_at"]["believed_samples"] > 0
    )


def test_unknown_episode_role_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "grounding", "--roles", "companion,butler", "--json"]) == 2
    err = capsys.readouterr().err.strip()
    assert "butler" in err and "--roles" in err and "\n" not in err
