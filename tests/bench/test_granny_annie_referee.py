"""The Granny Annie referee on hand-made ground-truth timelines: each achievement, penalty and
disqualification is counted, none passes vacuously, and runs rank as the ERL sheet says."""

from __future__ import annotations

from knic.bench.granny_annie.commands import Request
from knic.bench.granny_annie.episodes import Episode
from knic.bench.granny_annie.referee import Sample, Score, Timeline, judge, rank_key, stalls, summarise

START = {
    ("robot_at", "r2d2", "entrance_hall"),
    ("person_at", "annie", "bedroom"),
    ("person_at", "tracy", "kitchen"),
    ("object_at", "remote", "living_room"),
    ("object_at", "glasses", "kitchen"),
    ("light_off", "hallway_light"),
    ("device_level", "bedroom_blinds", "l0"),
    ("hand_empty", "r2d2"),
}
REQUESTS = (
    Request("device", "switch on the hallway light", ("(light_on hallway_light)",), ("hallway_light",)),
    Request("device", "open the blinds", ("(device_level bedroom_blinds l100)",), ("bedroom_blinds",)),
    Request("find", "find the remote", ("(reported remote)",), ("remote",)),
    Request("bring", "bring me my glasses", ("(has annie glasses)",), ("glasses",)),
    Request("accompany", "lead tracy to the bedroom", ("(person_at tracy bedroom)",), ("tracy",), "bedroom"),
)
GOALS = tuple(g for r in REQUESTS for g in r.goals)


def episode(requests: tuple[Request, ...] = REQUESTS) -> Episode:
    return Episode(0, 0, "erl_home", None, "bed", "bedroom", {}, (), requests, "...")


def changed(
    facts: set[tuple[str, ...]], *changes: tuple[tuple[str, ...], tuple[str, ...] | None]
) -> frozenset:
    out = set(facts)
    for old, new in changes:
        out.discard(old)
        if new is not None:
            out.add(new)
    return frozenset(out)


def moving(facts: frozenset, t0: float, t1: float, step: float = 0.5) -> list[Sample]:
    """Samples of a robot driving along x at 0.5 m/s."""
    n = round((t1 - t0) / step)
    return [Sample(t0 + k * step, facts, (t0 + k * step * 0.5, 0.0, 0.0)) for k in range(n + 1)]


def full_run() -> Timeline:
    """A run in which the robot does everything right."""
    start = frozenset(START)
    visit = changed(START, (("robot_at", "r2d2", "entrance_hall"), ("robot_at", "r2d2", "living_room")))
    done = changed(
        set(visit),
        (("robot_at", "r2d2", "living_room"), ("robot_at", "r2d2", "bedroom")),
        (("light_off", "hallway_light"), ("light_on", "hallway_light")),
        (("device_level", "bedroom_blinds", "l0"), ("device_level", "bedroom_blinds", "l100")),
        (("object_at", "glasses", "kitchen"), ("has", "annie", "glasses")),
        (("person_at", "tracy", "kitchen"), ("person_at", "tracy", "bedroom")),
    )
    samples = moving(start, 0.0, 10.0) + moving(visit, 10.5, 20.0) + moving(done, 20.5, 40.0)
    return Timeline(
        samples=samples,
        said=[(15.0, "I found the remote in the living room.")],
        understood=GOALS,
        end=40.0,
        finished=True,
    )


def test_a_perfect_run_gets_every_achievement() -> None:
    score = judge(episode(), full_run())
    assert score.achieved == score.achievable
    assert score.achievable == {
        "entered_room": 1,
        "understood": 1,
        "devices": 2,
        "found": 1,
        "brought": 1,
        "accompanied": 1,
    }
    assert score.total == 7 and not score.disqualified and score.time_s == 40.0
    assert score.penalties == {"bumps": 0, "drops": 0, "stalls": 0}


def test_an_idle_robot_gets_nothing() -> None:
    still = [Sample(t * 0.5, frozenset(START), (5.0, 1.0, 0.0)) for t in range(1201)]
    timeline = Timeline(samples=still, understood=None, end=600.0)
    score = judge(episode(), timeline)
    assert score.total == 0 and score.possible == 7
    assert score.penalties["stalls"] == 1  # one stretch of stopping working, however long


def test_no_achievement_passes_vacuously() -> None:
    # the light was already on and Tracy already in the bedroom: nothing was done
    start = changed(
        START,
        (("light_off", "hallway_light"), ("light_on", "hallway_light")),
        (("person_at", "tracy", "kitchen"), ("person_at", "tracy", "bedroom")),
    )
    timeline = Timeline(
        samples=moving(start, 0.0, 30.0),
        # reports of the wrong place, of another entity, and a claim that is no report
        said=[
            (5.0, "I found the remote in the kitchen."),
            (6.0, "I found the glasses in the kitchen."),
            (7.0, "remote"),
        ],
        understood=GOALS[:-1],  # one goal missing: not understood
        end=30.0,
    )
    score = judge(episode(), timeline)
    assert score.achieved == dict.fromkeys(score.achieved, 0)
    # Annie's room entered only after she left it does not count
    left = changed(set(start), (("person_at", "annie", "bedroom"), ("person_at", "annie", "kitchen")))
    inside = changed(set(left), (("robot_at", "r2d2", "entrance_hall"), ("robot_at", "r2d2", "bedroom")))
    late = Timeline(samples=moving(left, 0.0, 5.0) + moving(inside, 5.5, 10.0), end=10.0)
    assert judge(episode(), late).achieved["entered_room"] == 0


def test_a_report_counts_when_it_was_true_when_made() -> None:
    before = frozenset(START)
    moved = changed(START, (("object_at", "remote", "living_room"), ("object_at", "remote", "kitchen")))
    samples = moving(before, 0.0, 10.0) + moving(moved, 10.5, 20.0)
    ep = episode((REQUESTS[2],))
    true_then = Timeline(samples=samples, said=[(9.0, "I found the remote in the living room.")], end=20.0)
    stale = Timeline(samples=samples, said=[(15.0, "I found the remote in the living room.")], end=20.0)
    held = changed(set(moved), (("object_at", "remote", "kitchen"), ("holding", "r2d2", "remote")))
    gripper = Timeline(
        samples=moving(before, 0.0, 10.0) + moving(held, 10.5, 20.0),
        said=[(12.0, "I found the remote in my gripper.")],
        end=20.0,
    )
    assert judge(ep, true_then).achieved["found"] == 1
    assert judge(ep, stale).achieved["found"] == 0
    assert judge(ep, gripper).achieved["found"] == 1
    # already handed to Annie: the remote is where she is (and nowhere else)
    handed = changed(set(before), (("object_at", "remote", "living_room"), ("has", "annie", "remote")))
    annie_room = next(f[2] for f in handed if f[0] == "person_at" and f[1] == "annie")
    samples = moving(before, 0.0, 10.0) + moving(handed, 10.5, 20.0)
    report = f"I found the remote in the {annie_room.replace('_', ' ')}."
    with_her = Timeline(samples=samples, said=[(15.0, report)], end=20.0)
    wrong_room = "kitchen" if annie_room != "kitchen" else "bathroom"
    elsewhere = Timeline(samples=samples, said=[(15.0, f"I found the remote in the {wrong_room}.")], end=20.0)
    assert judge(ep, with_her).achieved["found"] == 1
    assert judge(ep, elsewhere).achieved["found"] == 0


def test_penalties_and_disqualifications_are_counted() -> None:
    timeline = full_run()
    timeline.bumps = [3.0, 7.5]
    timeline.drops = [12.0]
    score = judge(episode(), timeline)
    assert score.penalties["bumps"] == 2 and score.penalties["drops"] == 1
    assert not score.disqualified
    timeline.person_hits = [20.0]
    hit = judge(episode(), timeline)
    assert hit.disqualified and hit.disqualifications == {"person_hits": 1, "testbed_damage": 0}
    timeline.person_hits = []
    timeline.testbed_damage = [5.0]
    assert judge(episode(), timeline).disqualified


def test_stopping_working_is_a_stretch_of_30_s_without_progress() -> None:
    facts = frozenset(START)
    pose = (1.0, 1.0, 0.0)
    still = [Sample(t * 0.5, facts, pose) for t in range(0, 61)]  # 0-30 s still
    driving = [Sample(30.5 + k * 0.5, facts, (1.0 + 0.5 * (k + 1), 1.0, 0.0)) for k in range(20)]  # moves
    still_again = [Sample(40.5 + k * 0.5, facts, driving[-1].pose) for k in range(80)]  # 40.5-80 s still
    samples = still + driving + still_again
    assert len(stalls(Timeline(samples=samples, end=80.0))) == 2
    # stillness after the run ended does not count; 29 s of stillness is no stall
    assert len(stalls(Timeline(samples=samples, end=55.0))) == 1
    assert stalls(Timeline(samples=still[:59], end=29.0)) == []
    # speaking, turning and operating a device are progress
    assert stalls(Timeline(samples=still, said=[(20.0, "Okay.")], end=30.0)) == []
    turned = [Sample(s.t, s.facts, (1.0, 1.0, 0.2 if s.t >= 20 else 0.0)) for s in still]
    assert stalls(Timeline(samples=turned, end=30.0)) == []
    switched = [
        Sample(s.t, changed(START, (("light_off", "hallway_light"), ("light_on", "hallway_light"))), s.pose)
        if s.t >= 20
        else s
        for s in still
    ]
    assert stalls(Timeline(samples=switched, end=30.0)) == []


def score(total: int, penalties: int = 0, time_s: float = 100.0, dq: bool = False) -> Score:
    achieved = {"entered_room": total}
    return Score(achieved, {"entered_room": 9}, {"bumps": penalties}, {"person_hits": int(dq)}, time_s)


def test_ranking_follows_the_sheet() -> None:
    runs = {
        "dq_best": score(9, dq=True),
        "many": score(5, penalties=3, time_s=500),
        "few": score(3),
        "few_bumped": score(3, penalties=1),
        "few_slow": score(3, time_s=300),
    }
    order = sorted(runs, key=lambda n: rank_key(runs[n]))
    assert order == ["many", "few", "few_slow", "few_bumped", "dq_best"]


def test_summary_shares_and_median() -> None:
    a = judge(episode(), full_run())
    b = judge(episode(), Timeline(samples=[Sample(0.0, frozenset(START), (0, 0, 0))], end=600.0))
    s = summarise([a, b])
    assert s["episodes"] == 2 and s["achievements_share"] == 0.5
    assert s["achievements"]["devices"] == {"achieved": 2, "achievable": 4}
    assert s["time_median_s"] == 320.0
