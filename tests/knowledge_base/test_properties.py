"""Property tests: random sequences of valid and invalid operations against the invariants of the history.

* a refused operation (KnowledgeBaseError) changes nothing: state, journal, notifications;
* replaying the journal from the start gives the live state, and so does ``state_at(now)``;
* a SQLite journal reopened in a new knowledge base gives the live state (provenance included);
* what subscribers heard is exactly the journal.
"""

from __future__ import annotations

import contextlib
import tempfile
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from core.errors import KnowledgeBaseError
from knowledge_base import Change, KnowledgeBase, State
from knowledge_base.domain import DomainModel
from knowledge_base.model import apply_change
from knowledge_base.problem import ProblemContent

from .conftest import FakeClock

NAMES = ["r2d2", "annie", "glasses", "kitchen", "bedroom", "sofa", "l50", "ghost", "mug", "jack"]
TYPES = ["item", "room", "person", "robot", "furniture", "entity", "level", "nonsense"]
PREDICATES = [
    "robot_at",
    "object_at",
    "possibly_at",
    "found",
    "connected",
    "hand_empty",
    "device_level",
    "flying",
]
STATUSES = ["given", "observed", "assumed", "effect", "rumour"]

names = st.sampled_from(NAMES)
atom = st.tuples(st.sampled_from(PREDICATES), st.lists(names, max_size=3).map(tuple))
simple_op = st.one_of(
    st.tuples(st.just("add_instance"), st.sampled_from(TYPES), names),
    st.tuples(st.just("remove_instance"), names),
    st.tuples(st.just("add_fact"), atom, st.sampled_from(STATUSES), st.sampled_from([1.0, 0.5, 2.0])),
    st.tuples(st.just("remove_fact"), atom),
    st.tuples(st.just("add_goal"), atom),
    st.tuples(st.just("remove_goal"), atom),
    st.tuples(st.just("clear_goals")),
    st.tuples(st.just("set_anchor"), names, st.sampled_from([{"pose": [1.0, 2.0, 0.0]}, {"bad": {1, 2}}])),
)
operation = st.one_of(simple_op, st.tuples(st.just("batch"), st.lists(simple_op, max_size=4), st.booleans()))


class Abort(Exception):
    """Raised inside a batch to make it roll back."""


def apply(kb: KnowledgeBase, op: tuple[Any, ...]) -> None:
    kind = op[0]
    if kind == "add_instance":
        kb.add_instance(op[1], op[2], source="prop")
    elif kind == "remove_instance":
        kb.remove_instance(op[1], source="prop")
    elif kind == "add_fact":
        (pred, args), status, confidence = op[1], op[2], op[3]
        kb.add_fact(pred, *args, source="prop", status=status, confidence=confidence)
    elif kind == "remove_fact":
        kb.remove_fact(op[1][0], *op[1][1], source="prop")
    elif kind == "add_goal":
        kb.add_goal(op[1][0], *op[1][1], source="prop")
    elif kind == "remove_goal":
        kb.remove_goal(op[1][0], *op[1][1])
    elif kind == "clear_goals":
        kb.clear_goals()
    elif kind == "set_anchor":
        kb.set_anchor(op[1], op[2], source="prop")
    elif kind == "batch":
        with kb.batch():
            for inner in op[1]:
                with contextlib.suppress(KnowledgeBaseError):
                    apply(kb, inner)
            if op[2]:
                raise Abort


def replay(kb: KnowledgeBase) -> State:
    state = State(instances=dict(kb.domain.constants))
    for change in kb.changes():
        apply_change(state, change)
    return state


def run_sequence(kb: KnowledgeBase, clock: FakeClock, ops: list[tuple[Any, ...]]) -> list[Change]:
    heard: list[Change] = []
    kb.subscribe(heard.append)
    for op in ops:
        clock.t += 1.0
        before, seq, n_heard = kb.snapshot(), kb.journal.last_seq, len(heard)
        try:
            apply(kb, op)
        except (KnowledgeBaseError, Abort):
            assert kb.snapshot() == before, f"refused {op} changed the state"
            assert kb.journal.last_seq == seq and len(heard) == n_heard
    return heard


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(ops=st.lists(operation, max_size=25))
def test_replay_equals_live_state_in_memory(
    erl_domain: DomainModel, paper_problem: ProblemContent, ops: list[tuple[Any, ...]]
) -> None:
    clock = FakeClock(0.0)
    kb = KnowledgeBase(erl_domain, clock=clock)
    kb.load_problem(paper_problem)
    heard = run_sequence(kb, clock, ops)
    live = kb.snapshot()
    assert replay(kb).same_content(live)
    assert kb.state_at(clock.t).same_content(live)
    assert heard == kb.changes()[len(kb.changes()) - len(heard) :]
    assert [c.seq for c in kb.changes()] == list(range(1, live.seq + 1))


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(ops=st.lists(operation, max_size=20))
def test_reopened_sqlite_journal_equals_live_state(
    erl_domain: DomainModel, ops: list[tuple[Any, ...]]
) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "kb.sqlite"
        clock = FakeClock(0.0)
        problem = Path(erl_domain.source).with_name("paper_problem.pddl")
        kb = KnowledgeBase.from_pddl(erl_domain.source, problem, path, clock=clock)
        run_sequence(kb, clock, ops)
        live = kb.snapshot()
        kb.close()
        reopened = KnowledgeBase.from_journal(path)
        assert reopened.snapshot() == live
        assert replay(reopened).same_content(live)
        reopened.close()
