"""The octomap throughput benchmark runs on a small scene and accounts for every point (no timing)."""

from __future__ import annotations

from knic.bench.octomap import measure_octomap_throughput


def test_measure_octomap_throughput_reports_its_figures() -> None:
    figures = measure_octomap_throughput(objects=2, frames=3, points=16, repeats=1)
    assert figures["clouds"] == 6 and figures["points_per_cloud"] == 16
    assert set(figures) >= {
        "octomap_throughput_ratio",
        "octomap_overhead_ratio_same_mode",
        "octomap_ratio_with_key_reads",
        "kgm2_points_per_s",
    }
    assert figures["octomap_throughput_ratio"] > 0 and figures["raw_points_per_s"] > 0
