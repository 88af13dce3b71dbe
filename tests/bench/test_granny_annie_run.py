"""Granny Annie episodes run for real: a short episode end to end (score from ground truth, trace, journal and
the ERL bag read back), the static and oracle baselines, and the command line's JSON and bad input."""

from __future__ import annotations

import json
import sqlite3
from pathlib import Path

import pytest

from knic.bench.granny_annie.baselines import kp_primes, prepare
from knic.bench.granny_annie.commands import Request
from knic.bench.granny_annie.episodes import Episode
from knic.bench.granny_annie.recording import TOPICS, read_bag
from knic.bench.granny_annie.runner import Task, run_task, write_world_files
from knic.cli import main
from knic.system import KnicSystem, RunConfig


def short_episode(index: int, *requests: Request, events: tuple[dict, ...] = ()) -> Episode:
    """Annie on the sofa; the items where the world file puts them."""
    annie = {"at": 0.0, "type": "person_to", "person": "annie", "furniture": "sofa", "teleport": True}
    return Episode(
        index=index,
        seed=0,
        world="erl_home",
        lexicon=None,
        person_on="sofa",
        person_room="living_room",
        placements={"remote": "coffee_table", "tablet": "side_table", "mug": "kitchen_counter"},
        off_prior=(),
        requests=requests,
        text=" and ".join(r.text for r in requests),
        events=(annie, *events),
    )


LIGHT = Request("device", "switch on the hallway light", ("(light_on hallway_light)",), ("hallway_light",))
REMOTE = Request("bring", "bring me the remote", ("(has annie remote)",), ("remote",))


def test_a_short_episode_end_to_end(tmp_path: Path) -> None:
    episode = short_episode(0, LIGHT, REMOTE)
    write_world_files(tmp_path, [episode])
    result = run_task(Task(episode.to_dict(), "knic", "companion", str(tmp_path)))
    score = result["score"]
    assert result["understood"] == ["(light_on hallway_light)", "(has annie remote)"]
    assert (
        score["achieved"]
        == score["achievable"]
        == {
            "entered_room": 1,  # the robot brought the remote to Annie's room
            "understood": 1,
            "devices": 1,
            "found": 0,
            "brought": 1,
            "accompanied": 0,
        }
    )
    assert not score["disqualified"] and result["run"]["finished"] and result["run"]["task"] == "done"
    assert 0 < score["time_s"] == result["run"]["sim_time"] < 600
    # the trace and the journal of the run: the task flow as the rulebook has it
    trace = [json.loads(line) for line in (tmp_path / "traces" / "ep000_knic.jsonl").read_text().splitlines()]
    assert any(e["kind"] == "plan" for e in trace) and any(e["kind"] == "goal_achieved" for e in trace)
    steps = [(e["action"], e["time"]) for e in trace if e["kind"] == "task"]
    order = [a for a, _ in steps if a in ("call", "ask", "heard", "intake asked", "confirmed", "done")]
    assert order == ["call", "ask", "heard", "intake asked", "heard", "confirmed", "done"]
    asked_at = next(t for a, t in steps if a == "ask")
    entered = next(d for d in score["details"] if d.startswith("entered_room"))
    assert float(entered.split(" at ")[1].split()[0]) <= asked_at + 0.5  # it came to her room, then asked
    first_goal = min(e["time"] for e in trace if e["kind"] == "goal_achieved" and e["goal"] in episode.goals)
    assert first_goal > next(t for a, t in steps if a == "confirmed")  # work starts after her yes
    with sqlite3.connect(tmp_path / "journals" / "ep000_knic.sqlite") as db:
        assert db.execute("select count(*) from sqlite_master").fetchone()[0] > 0
    live = json.loads((tmp_path / "journals" / "ep000_knic.score.json").read_text())  # for knic serve
    assert live["final"] and live["score"] == score
    # the ERL recording, read back with a bag reader
    bag = read_bag(tmp_path / "bags" / "ep000_knic")
    assert set(bag) == set(TOPICS)
    for topic, messages in bag.items():
        assert messages, topic
        assert {m[1] for m in messages} == {TOPICS[topic]}
    poses = [t for t, _, _ in bag["/erlc/robot_pose"]]
    rate = (len(poses) - 1) / (poses[-1] - poses[0])
    assert 9.0 <= rate <= 11.0  # 10 Hz
    assert poses[-1] >= score["time_s"] - 0.2
    last = bag["/erlc/robot_pose"][-1][2]
    assert last.header.frame_id == "map" and abs(last.pose.orientation.w) <= 1.0
    paths = bag["/erlc/trajectory"]
    assert len(paths) >= 2 and any(len(m.poses) >= 2 for _, _, m in paths)  # a path per navigation (re)plan
    assert [m.data for _, _, m in bag["/erlc/command"]] == [episode.text]
    facts = [json.loads(m.data) for _, _, m in bag["/knic/facts"]]
    assert {"fact": "(has annie remote)", "op": "add"}.items() <= next(
        f for f in facts if f["fact"] == "(has annie remote)"
    ).items()
    assert all(f["op"] in ("add", "remove") for f in facts)


def test_static_and_oracle_baselines_write_no_kp_prime_facts(tmp_path: Path) -> None:
    episode = short_episode(1, LIGHT)
    write_world_files(tmp_path, [episode])
    for baseline in ("static", "oracle"):
        result = run_task(Task(episode.to_dict(), baseline, "companion", str(tmp_path), record=False))
        assert result["score"]["achieved"]["devices"] == 1, baseline
    config = RunConfig(world=tmp_path / "worlds" / "ep001.yaml", seed=0)
    with KnicSystem(config) as system:
        names = {c.name for c in kp_primes(system)}
        assert names and names <= {c.name for c in system.scheduler.components}
        prepare(system, "static")
        assert not names & {c.name for c in system.scheduler.components}
        remote = system.kb.why(next(iter(system.kb.facts("object_at", "remote"))))
        assert remote is not None and remote.source == "initial_map"
        assert system.kb.holds("found", "remote")
        # the closed world takes the likeliest prior for a fact: the glasses on the bedside table, while the
        # world has them on the kitchen table
        assert system.kb.holds("object_on", "glasses", "bedside_table")
        assert ("object_on", "glasses", "kitchen_table") in system.sim.ground_truth_facts()
        system.sim.step(5.0)
        system.scheduler.tick(5.0)
        sources = {getattr(system.kb.why(f), "source", None) for f in system.kb.facts("object_at")}
        assert sources == {"initial_map"}  # perception ran for 5 s and wrote no place
    with KnicSystem(config) as system:
        prepare(system, "oracle")
        truth = {
            f for f in system.sim.ground_truth_facts() if f[0] in ("object_at", "person_at", "light_off")
        }
        assert truth <= {(f.predicate, *f.args) for f in system.kb.facts()}
        seen = system.perceived.sighting("tablet")  # where the actions steer to: the true position
        assert seen is not None and seen.position == pytest.approx(system.sim.true_pose("tablet").position)
        # the accompany request is kept from the goals without the KP' (no plan could meet Tracy else)
        assert not system.kb.facts("to_accompany")
        system.kb.add_goal("person_at", "tracy", "bathroom")
        system.sim.step(0.5)
        system.scheduler.tick(0.5)
        assert system.kb.holds("to_accompany", "tracy")
        system.kb.remove_goal("person_at", "tracy", "bathroom")
        system.sim.step(0.5)
        system.scheduler.tick(1.0)
        assert not system.kb.facts("to_accompany")


def test_command_line_json_and_refusals(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    args = ["bench", "granny-annie", "--episodes", "1", "--seed", "5", "--out", str(tmp_path)]
    assert main([*args, "--baseline", "knic,oracle", "--max-sim-time", "20", "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert set(printed) == {"baselines", "wall_s"} and set(printed["baselines"]) == {"knic", "oracle"}
    for figures in printed["baselines"].values():
        assert figures["episodes"] == 1 and 0.0 <= figures["achievements_share"] <= 1.0
        assert set(figures["achievements"]) == {
            "entered_room",
            "understood",
            "devices",
            "found",
            "brought",
            "accompanied",
        }
        assert set(figures["penalties"]) == {"bumps", "drops", "stalls"}
        assert set(figures["disqualifications"]) == {"person_hits", "testbed_damage"}
        assert figures["time_median_s"] <= 20.0
        assert figures["cost"]["cpu_s_mean"] > 0 and figures["cost"]["wall_s_mean"] > 0
    report = json.loads((tmp_path / "report.json").read_text())
    assert len(report["results"]) == 2 and report["summary"] == printed["baselines"]
    assert sum(printed["baselines"]["knic"]["run_ends"].values()) == 1
    assert "| knic |" in (tmp_path / "report.md").read_text()
    for png in ("achievements.png", "time.png", "failures.png"):
        assert (tmp_path / png).read_bytes()[:4] == b"\x89PNG"
    assert main([*args, "--baseline", "knic,magic"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("knic: error: --baseline") and "magic" in err and "\n" not in err
    assert main([*args, "--episodes", "0"]) == 2
    capsys.readouterr()
    bad = tmp_path / "damage.yaml"
    bad.write_text("hard_contact_m_s: fast\n", encoding="utf-8")
    assert main([*args, "--damage", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert str(bad) in err and "hard_contact_m_s must be a positive number" in err and "\n" not in err


def test_worker_processes_give_the_serial_results(tmp_path: Path) -> None:
    from knic.bench.granny_annie.runner import run_tasks

    move = {"at": 5.0, "type": "move_object", "person": "tracy", "item": "mug", "to": "dining_table"}
    episodes = [short_episode(2, LIGHT), short_episode(3, REMOTE, events=(move,))]
    write_world_files(tmp_path, episodes)
    tasks = [  # one task per worker, each baseline once
        Task(e.to_dict(), b, "companion", str(tmp_path), record=False)
        for e, b in zip(episodes, ("knic", "static"), strict=True)
    ]

    def comparable(results: list[dict]) -> list[dict]:
        return sorted(
            ({k: v for k, v in r.items() if k not in ("wall_s", "cpu_s")} for r in results),
            key=lambda r: (r["episode"], r["baseline"]),
        )

    serial = comparable(list(run_tasks(tasks, workers=1)))
    parallel = comparable(list(run_tasks(tasks, workers=2)))
    assert serial == parallel
    # every run enters Annie's room (she calls it there), is understood, and does what she asked
    assert [r["score"]["achievements"] for r in serial] == [3, 3]


def test_ray_backend_gives_the_serial_result(tmp_path: Path) -> None:
    """A local Ray instance runs the same task; without the optional 'ray' extra the reason is shown."""
    from knic.bench.granny_annie.runner import ray_unavailable, run_tasks

    reason = ray_unavailable()
    if reason is not None:
        pytest.skip(reason)
    episode = short_episode(4, LIGHT)
    write_world_files(tmp_path, [episode])
    tasks = [Task(episode.to_dict(), "knic", "companion", str(tmp_path), record=False)]
    on_ray = [
        {k: v for k, v in r.items() if k not in ("wall_s", "cpu_s")} for r in run_tasks(tasks, backend="ray")
    ]
    serial = [{k: v for k, v in r.items() if k not in ("wall_s", "cpu_s")} for r in run_tasks(tasks)]
    assert on_ray == serial and serial[0]["score"]["achieved"]["devices"] == 1


def test_ray_backend_without_ray_says_why(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    from knic.bench.granny_annie import runner

    monkeypatch.setattr(runner, "ray_unavailable", lambda: "the Ray backend needs the optional 'ray' package")
    assert main(["bench", "granny-annie", "--backend", "ray", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert "--backend ray" in err and "optional 'ray' package" in err
    assert not (tmp_path / "out").exists()  # refused before anything was written
