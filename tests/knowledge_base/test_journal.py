"""The history journal: replay, state_at, checkpoints, reopening, concurrent readers, SIGKILL durability."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from core.errors import JournalError, KnowledgeBaseError
from knowledge_base import Fact, KnowledgeBase, State
from knowledge_base import journal as journal_module
from knowledge_base.model import apply_change

from .conftest import DELIVERY_DOMAIN, ERL_DOMAIN, PAPER_PROBLEM, FakeClock


def replay(kb: KnowledgeBase) -> State:
    state = State(instances=dict(kb.domain.constants))
    for change in kb.changes():
        apply_change(state, change)
    return state


def churn(kb: KnowledgeBase, clock: FakeClock, steps: int) -> None:
    """Move the robot around and toggle exploration, one write per simulated second."""
    rooms = ["kitchen", "entrance", "living_room", "bedroom"]
    for i in range(steps):
        clock.t += 1.0
        kb.add_fact("robot_at", "r2d2", rooms[i % 4], source="kp.pose", status="observed")
        if i % 3 == 0:
            kb.add_fact("explored", rooms[i % 4], source="kp.explore")
        elif i % 3 == 1:
            kb.remove_fact("explored", rooms[(i - 1) % 4], source="kp.explore")


@pytest.fixture
def small_checkpoints(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(journal_module, "CHECKPOINT_MIN_EVENTS", 7)


@pytest.mark.parametrize("on_disk", [False, True])
def test_state_at_matches_replay_across_checkpoints(
    tmp_path: Path, small_checkpoints: None, on_disk: bool
) -> None:
    clock = FakeClock(100.0)
    path = tmp_path / "kb.sqlite" if on_disk else None
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=clock)
    history: dict[float, State] = {100.0: kb.snapshot()}
    for _ in range(30):
        churn(kb, clock, 2)
        history[clock.t] = kb.snapshot()
    if on_disk:
        assert len(kb.journal._checkpoint_seqs) > 3  # type: ignore[attr-defined]
    for t, expected in history.items():
        assert kb.state_at(t).same_content(expected)
        assert kb.state_at(t + 0.5).same_content(expected)
    assert kb.state_at(99.0).facts == {}
    assert kb.state_at(99.0).instances == dict(kb.domain.constants)
    assert replay(kb).same_content(kb.snapshot())


def _mixed_history(kb: KnowledgeBase, clock: FakeClock) -> None:
    """Every kind of event: instances come and go (with anchors), facts are re-asserted with new provenance,
    goals are added and dropped, enough facts that state_at takes both its forward and its reverse path."""
    churn(kb, clock, 12)
    for i in range(60):
        clock.t += 1.0
        with kb.batch():
            kb.add_instance("item", f"cup{i}")
            kb.add_fact("object_at", f"cup{i}", ("kitchen", "bedroom")[i % 2], source="kp.objects")
            if i % 4 == 0:
                kb.set_anchor(f"cup{i}", {"center": [i, 0.0, 0.8]}, source="kp.objects")
            if i % 5 == 4:
                kb.add_fact("object_at", f"cup{i - 1}", "entrance", source="kp.objects", confidence=0.6)
            if i % 7 == 6:
                kb.remove_fact("object_at", f"cup{i - 2}", ("kitchen", "bedroom")[i % 2])
                for fact in kb.facts("object_at", f"cup{i - 4}"):
                    kb.remove_fact(fact.predicate, *fact.args)
                kb.remove_instance(f"cup{i - 4}")
            if i % 9 == 0:
                kb.add_goal("found", "glasses", source="language")
            elif i % 9 == 4:
                kb.remove_goal("found", "glasses")
        churn(kb, clock, 1)


def _prefix_states(kb: KnowledgeBase) -> list[State]:
    """The state after each event, by replaying the journal from the start (the definition of state_at)."""
    state = State(instances=dict(kb.domain.constants))
    states = [state.copy()]
    for change in kb.changes():
        apply_change(state, change)
        states.append(state.copy())
    return states


def test_every_past_state_equals_the_replayed_prefix(tmp_path: Path) -> None:
    clock = FakeClock(10.0)
    path = tmp_path / "kb.sqlite"
    writers = [KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, p, clock=clock) for p in (None, path)]
    for kb in writers:
        clock.t = 10.0
        _mixed_history(kb, clock)
    expected = _prefix_states(writers[0])
    assert [c.describe() for c in writers[1].changes()] == [c.describe() for c in writers[0].changes()]
    writers[1].close()
    reopened = KnowledgeBase.from_journal(path)  # its timeline is built from the events on first use
    for kb in (writers[0], reopened):
        for seq, state in enumerate(expected):
            past = kb.journal.state_at_seq(seq)
            assert past.same_content(state), seq
            assert (past.seq, past.time) == (state.seq, state.time)
    for t in (9.0, 10.0, 30.5, 55.0, clock.t):
        assert reopened.state_at(t).same_content(writers[0].state_at(t))
    assert reopened.journal.timeline().spans > len(reopened.facts())


def test_state_at_after_switching_from_wall_to_sim_time(tmp_path: Path) -> None:
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, tmp_path / "kb.sqlite")  # wall clock
    sim = FakeClock(0.0)
    kb.set_clock(sim)
    sim.t = 5.0
    kb.add_fact("robot_at", "r2d2", "kitchen")
    sim.t = 9.0
    kb.add_fact("found", "glasses")
    at_7 = kb.state_at(7.0)
    assert at_7.holds(Fact("robot_at", ("r2d2", "kitchen")))  # the problem (wall-time stamps) came before
    assert at_7.holds(Fact("hand_empty", ("r2d2",)))
    assert not at_7.holds(Fact("found", ("glasses",)))


def test_reopen_restores_exact_state(tmp_path: Path, small_checkpoints: None) -> None:
    path = tmp_path / "kb.sqlite"
    clock = FakeClock(1.0)
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=clock)
    churn(kb, clock, 25)
    kb.set_anchor("kitchen", {"region": [[0, 0], [3, 0], [3, 3]]}, source="map")
    kb.add_goal("found", "glasses", source="language")
    expected = kb.snapshot()
    kb.close()
    # with the problem again: the journal already holds it, so it is not loaded twice
    again = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path)
    assert again.snapshot() == expected
    assert again.problem_name == "erl_paper_glasses"
    assert again.goals() == [Fact("object_at", ("glasses", "bedroom")), Fact("found", ("glasses",))]
    again.add_fact("found", "glasses")
    assert again.changes()[-1].seq == expected.seq + 1
    again.close()
    alone = KnowledgeBase.from_journal(path, read_only=True)
    assert alone.holds("found", "glasses") and alone.anchor("kitchen") == {"region": [[0, 0], [3, 0], [3, 3]]}
    with pytest.raises(KnowledgeBaseError, match="read-only"):
        alone.add_fact("explored", "kitchen")
    assert alone.journal.last_seq == expected.seq + 1


def test_journal_of_another_domain_or_garbage_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "kb.sqlite"
    KnowledgeBase.from_pddl(ERL_DOMAIN, None, path).close()
    with pytest.raises(JournalError, match="another domain"):
        KnowledgeBase.from_pddl(DELIVERY_DOMAIN, None, path)
    garbage = tmp_path / "garbage.sqlite"
    garbage.write_bytes(b"this is not a database" * 100)
    with pytest.raises(JournalError, match="not a readable KnIC journal"):
        KnowledgeBase.from_journal(garbage)
    with pytest.raises(JournalError, match="no such journal"):
        KnowledgeBase.from_journal(tmp_path / "missing.sqlite")


def test_reader_follows_a_writer(tmp_path: Path) -> None:
    path = tmp_path / "kb.sqlite"
    writer = KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path, clock=FakeClock(3.0))
    reader = KnowledgeBase.from_journal(path, read_only=True)
    seen: list[str] = []
    reader.subscribe(lambda c: seen.append(c.describe()))
    with writer.batch():
        writer.add_fact("robot_at", "r2d2", "kitchen", source="kp.pose")
        writer.add_fact("explored", "kitchen")
    assert [c.seq for c in reader.refresh()] == [writer.journal.last_seq - 2 + i for i in (0, 1, 2)]
    assert reader.snapshot() == writer.snapshot()
    assert seen[0] == "t=3.00 remove_fact (robot_at r2d2 bedroom) by kp.pose [given]"
    assert reader.refresh() == []


def _spawn_writer(path: Path, batch: int) -> subprocess.Popen[str]:
    script = Path(__file__).with_name("journal_writer.py")
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    return subprocess.Popen(
        [sys.executable, str(script), str(path), str(batch)], stdout=subprocess.PIPE, text=True, env=env
    )


@pytest.mark.parametrize("batch", [1, 25])
def test_every_acknowledged_write_survives_sigkill(tmp_path: Path, batch: int) -> None:
    path = tmp_path / "kb.sqlite"
    KnowledgeBase.from_pddl(ERL_DOMAIN, PAPER_PROBLEM, path).close()
    child = _spawn_writer(path, batch)
    assert child.stdout is not None
    try:
        assert child.stdout.readline().strip() == "ready"
        # read while the child writes: another process can open the journal at any time
        acked = -1
        for n in range(60):
            line = child.stdout.readline()
            assert line.startswith("ack "), line
            acked = int(line.split()[1])
            if n == 10:
                live = KnowledgeBase.from_journal(path, read_only=True)
                assert live.type_of("obj0") == "item"
                live.close()
        assert child.poll() is None  # still running
        child.send_signal(signal.SIGKILL)
        child.wait(timeout=30)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == -signal.SIGKILL
    rooms = ("kitchen", "bedroom", "entrance", "living_room")
    reopened = KnowledgeBase.from_journal(path)
    for i in range(acked + 1):
        assert reopened.holds("object_at", f"obj{i}", rooms[i % 4]), f"acknowledged write {i} lost"
    # a transaction is all or nothing: every object that got in has its fact
    placed = {f.args[0] for f in reopened.facts("object_at")}
    assert set(reopened.instances("item")) - placed == {"glasses"}
    assert acked <= len(placed) - 1 < 100_000  # every ack is in, and the child was not done writing
    assert replay(reopened).same_content(reopened.snapshot())
