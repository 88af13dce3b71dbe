"""The referee's running score: judged from the timeline so far, published beside the journal, read back by
whoever follows the journal; and the referee's episode of a task scenario's command."""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any, cast

from knic.bench.granny_annie.livescore import LiveScore, episode_of_task, read_score, score_path
from knic.bench.granny_annie.recording import Recorder
from knic.bench.granny_annie.referee import Sample, Timeline, judge
from tests.bench.test_granny_annie_referee import START, changed, episode, moving
from worlds.api import load_world


def test_the_score_file_is_named_after_the_journal_even_while_it_is_staged(tmp_path: Path) -> None:
    assert score_path(tmp_path / "run.sqlite") == tmp_path / "run.score.json"
    assert score_path(tmp_path / ".run.sqlite.4242.partial") == tmp_path / "run.score.json"
    assert score_path("journals/ep003_knic.sqlite") == Path("journals/ep003_knic.score.json")


def test_a_reader_gets_nothing_from_a_missing_foreign_or_oversized_file(tmp_path: Path) -> None:
    path = tmp_path / "run.score.json"
    assert read_score(path) is None
    path.write_text("{not json")
    assert read_score(path) is None
    path.write_text(json.dumps({"score": 3}))
    assert read_score(path) is None
    path.write_text(json.dumps({"score": {"achievements": 1}, "pad": "x" * 300_000}))
    assert read_score(path) is None


def test_the_running_score_follows_the_ground_truth_and_ends_with_the_verdict(tmp_path: Path) -> None:
    start = frozenset(START)
    visit = changed(set(START), (("robot_at", "r2d2", "entrance_hall"), ("robot_at", "r2d2", "bedroom")))
    timeline = Timeline(samples=moving(start, 0.0, 5.0))
    recorder = cast(Recorder, SimpleNamespace(timeline=timeline))
    took: list[tuple[str, ...] | None] = [None]
    path = tmp_path / "run.score.json"
    live = LiveScore(recorder, episode(), lambda: took[0], path)

    first = live.judge(5.0)
    assert first is not None and read_score(path) == first
    assert first["final"] is False and first["sim_time"] == 5.0
    assert first["score"]["achievements"] == 0 and first["score"]["possible"] == 7

    # the robot reaches Annie's room and the command is understood: both count at the next judgement
    timeline.samples += [Sample(5.5, visit, (3.0, 0.0, 0.0))]
    took[0] = ("(has annie glasses)",)
    second = live.judge(6.0)
    assert second is not None and read_score(path) == second
    assert second["score"]["achieved"]["entered_room"] == 1
    assert second["score"]["achieved"]["understood"] == 0  # not every goal of the command
    assert timeline.end == 0.0 and timeline.understood is None  # the recorder's timeline is not changed

    verdict = judge(episode(), Timeline(samples=timeline.samples, end=6.0, finished=True))
    final = live.finish(verdict, 6.0)
    assert read_score(path) == final and final["final"] is True
    assert final["score"] == verdict.to_dict()
    assert not list(tmp_path.glob(".*.tmp"))  # written beside, renamed into place


def test_a_task_scenarios_command_becomes_the_referees_requests() -> None:
    world = load_world("erl_home")
    ep = episode_of_task(world, "switch on the left light and bring me the remote", "bed", 3, [])
    assert [(r.kind, r.goals) for r in ep.requests] == [
        ("device", ("(light_on bedroom_left_light)",)),
        ("bring", ("(has annie remote)",)),
    ]
    assert ep.person_room == "bedroom" and ep.person_on == "bed"
    # words the benchmark cannot read back: one request per goal they mean
    meant = ["(reported tablet)", "(has annie tablet)"]
    ep = episode_of_task(world, "locate the tablet and bring it to me", "sofa", 3, meant)
    got: list[Any] = [(r.kind, r.goals, r.targets) for r in ep.requests]
    assert got == [
        ("find", ("(reported tablet)",), ("tablet",)),
        ("bring", ("(has annie tablet)",), ("tablet",)),
    ]
    assert ep.goals == tuple(meant)
