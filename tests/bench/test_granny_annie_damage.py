"""The referee's damage model: a hard collision with the testbed (ground-truth base speed at the start of a
contact) and a dropped fragile item disqualify the run; slow contacts and other drops stay penalties."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import KnicError
from knic.bench.granny_annie.damage import (
    DamageModel,
    ImpactProbe,
    damage_events,
    load_damage,
    shipped_damage,
)
from knic.bench.granny_annie.episodes import Episode
from knic.bench.granny_annie.referee import Sample, Timeline, judge
from worlds.api import load_world
from worlds.simulation import Simulation

HOLDING = frozenset({("robot_at", "r2d2", "kitchen"), ("holding", "r2d2", "mug")})
DROPPED = frozenset(
    {("robot_at", "r2d2", "kitchen"), ("hand_empty", "r2d2"), ("object_at", "mug", "kitchen")}
)


def episode() -> Episode:
    return Episode(0, 0, "erl_home", None, "bed", "bedroom", {}, (), (), "...")


def drive_into_a_wall(speed: float) -> tuple[list[tuple[float, float]], int]:
    """Turn the base towards the entrance hall's east wall, drive straight into it at ``speed``: (impacts,
    bumps)."""
    with Simulation.from_world("erl_home", seed=1) as sim:
        probe = ImpactProbe(sim, sim.world, shipped_damage().contact_window_s)
        sim.set_base_velocity(0.0, 1.0)
        while sim.time < 4.9:
            sim.step(0.1)
            probe.step(sim.time)
        assert not probe.impacts  # turning on the spot touches nothing
        sim.set_base_velocity(speed, 0.0)
        while sim.time < 30.0 and not probe.impacts:
            sim.step(0.1)
            probe.step(sim.time)
        return probe.impacts, sim.counters().bumps


def timeline_with(impacts: list[tuple[float, float]], bumps: int) -> Timeline:
    at = impacts[-1][0] if impacts else 1.0
    samples = [Sample(0.0, DROPPED, (0.0, 0.0, 0.0)), Sample(at, DROPPED, (1.0, 0.0, 0.0))]
    return Timeline(samples=samples, bumps=[at] * bumps, impacts=impacts, end=at, finished=True)


def test_a_forced_hard_collision_damages_the_testbed() -> None:
    impacts, bumps = drive_into_a_wall(0.6)
    assert bumps == 1 and len(impacts) == 1
    assert impacts[0][1] >= shipped_damage().hard_contact_m_s  # it hit the wall at full speed
    score = judge(episode(), timeline_with(impacts, bumps))
    assert score.disqualifications == {"person_hits": 0, "testbed_damage": 1} and score.disqualified
    assert score.penalties["bumps"] == 1
    assert any(d.startswith("testbed_damage: drove into furniture or a wall at 0.5") for d in score.details)


def test_a_slow_contact_is_a_bump_not_damage() -> None:
    impacts, bumps = drive_into_a_wall(0.1)
    assert bumps == 1 and impacts and impacts[0][1] < shipped_damage().hard_contact_m_s
    score = judge(episode(), timeline_with(impacts, bumps))
    assert score.penalties["bumps"] == 1 and not score.disqualified


def test_dropping_a_fragile_item_damages_the_testbed_other_drops_are_penalties() -> None:
    samples = [Sample(0.0, HOLDING, (0.0, 0.0, 0.0)), Sample(0.5, DROPPED, (0.0, 0.0, 0.0))]
    timeline = Timeline(samples=samples, drops=[0.5], end=0.5, finished=True)
    score = judge(episode(), timeline)
    assert score.disqualifications["testbed_damage"] == 1 and score.penalties["drops"] == 1
    assert "testbed_damage: dropped the fragile mug at 0.5 s" in score.details
    sturdy = DamageModel(fragile=frozenset({"glass"}))
    assert damage_events(timeline, sturdy) == []
    assert not judge(episode(), timeline, damage=sturdy).disqualified


def test_fragile_classes_name_a_world_items_and_bad_models_are_refused(tmp_path: Path) -> None:
    model = DamageModel(fragile=frozenset({"glass"})).for_world(load_world("erl_home"))
    assert "glass" in model.fragile and "remote" not in model.fragile
    assert load_damage() == shipped_damage()
    bad = tmp_path / "damage.yaml"
    for text, needle in (
        ("hard_contact_m_s: -1\n", "hard_contact_m_s must be a positive number"),
        ("fragile: mug\n", "fragile must be a list"),
        ("speed: 1\n", "unknown field 'speed'"),
        ("[1, 2]\n", "must be a mapping"),
    ):
        bad.write_text(text, encoding="utf-8")
        with pytest.raises(KnicError, match=needle) as err:
            load_damage(bad)
        assert str(bad) in str(err.value) and "\n" not in str(err.value)
