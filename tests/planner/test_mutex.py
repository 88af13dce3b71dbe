"""Goals reachable alone but never together: proven by pair reachability (h^2), named, the rest planned."""

from __future__ import annotations

import pytest

from knowledge_base import KnowledgeBase
from planner.dispatch import Dispatcher
from planner.engines import TaskPlanner
from planner.grounding import ground_task
from planner.model import PlanningTask
from planner.mutex import compatible_goals, pair_reachability
from planner.plan import PlanStatus
from planner.problem import load_pddl
from planner.trace import EventKind, Trace
from planner.validate import check_plan
from tests.planner.doubles import ERL_DOMAIN, SimClock, World, scripted_registry
from tests.planner.examples import FIXTURES

FLAT = FIXTURES / "flat_give_or_place.pddl"
GIVEN = ("has", "olga", "book")
IN_LOUNGE = ("object_at", "book", "lounge")
TAKEN = ("taken_from", "book", "desk")


def flat() -> tuple[object, PlanningTask]:
    up_domain, _, task = load_pddl(str(ERL_DOMAIN), str(FLAT))
    return up_domain, task


def test_giving_and_placing_the_same_book_are_never_true_together() -> None:
    _, task = flat()
    grounded = ground_task(task)
    assert grounded.unreachable_goals == ()  # relaxed reachability cannot tell
    reach = pair_reachability(grounded.actions, task.facts)
    assert reach.together(TAKEN, GIVEN) and reach.together(TAKEN, IN_LOUNGE)
    assert not reach.together(GIVEN, IN_LOUNGE)
    assert reach.together(("object_at", "book", "study"), ("object_on", "book", "desk"))  # as in the start
    assert not reach.together(("holding", "r2d2", "book"), ("hand_empty", "r2d2"))
    kept, conflicts = compatible_goals([TAKEN, GIVEN, IN_LOUNGE], reach)
    assert kept == [TAKEN, GIVEN] and conflicts == {IN_LOUNGE: GIVEN}
    kept, conflicts = compatible_goals([IN_LOUNGE, GIVEN], reach)  # the first said wins
    assert kept == [IN_LOUNGE] and conflicts == {GIVEN: IN_LOUNGE}


def test_a_search_once_found_is_never_repeated() -> None:
    # before the book is found, only a search puts it in a room; (not (found book)) is compiled to an atom,
    # so the search that would put the given book back in the lounge is seen to be impossible
    _, task = flat()
    unknown = (
        task.facts - {("found", "book"), ("object_at", "book", "study"), ("object_on", "book", "desk")}
    ) | {
        ("possibly_at", "book", "lounge"),
        ("possibly_on", "book", "desk"),
    }
    later = PlanningTask(task.domain, task.objects, unknown, task.goals)
    grounded = ground_task(later)
    reach = pair_reachability(grounded.actions, later.facts)
    assert reach.together(GIVEN, ("found", "book"))
    assert not reach.together(GIVEN, ("not", "found", "book"))
    assert not reach.together(GIVEN, IN_LOUNGE)


@pytest.mark.parametrize("engine", ["knic", "fast-downward"])
def test_one_reachable_and_one_conflicting_goal_plan_the_first_and_name_the_second(engine: str) -> None:
    up_domain, task = flat()
    result = TaskPlanner(up_domain, engine=engine).solve(task)
    assert result.status == PlanStatus.PARTIAL
    assert result.unreachable_goals == (IN_LOUNGE,)
    assert result.conflicts == ((IN_LOUNGE, GIVEN),)
    assert result.message == "(object_at book lounge) can never hold together with (has olga book)"
    assert [str(s) for s in result.plan] == [
        "(move r2d2 corridor study)",
        "(pick_from r2d2 book desk study)",
        "(move r2d2 study corridor)",
        "(move r2d2 corridor lounge)",
        "(give r2d2 book olga lounge)",
    ]
    assert check_plan(task.domain, task.facts, result.plan, (TAKEN, GIVEN), task.objects).valid
    assert result.to_json()["conflicts"] == {"(object_at book lounge)": "(has olga book)"}


def test_the_dispatcher_drops_the_conflicting_goal_saying_which_goal_it_excludes() -> None:
    clock = SimClock()
    kb = KnowledgeBase.from_pddl(ERL_DOMAIN, FLAT, clock=clock)
    d = Dispatcher(kb, TaskPlanner(engine="knic"), scripted_registry(kb, World()), trace=Trace())
    report = d.run(max_ticks=300, on_tick=clock.tick)
    assert report.dropped == {
        "(object_at book lounge)": "unreachable: can never hold together with (has olga book)"
    }
    assert kb.holds(*GIVEN) and kb.holds(*TAKEN)
    assert [e.goal for e in d.trace.of_kind(EventKind.GOAL_DROPPED)] == ["(object_at book lounge)"]
