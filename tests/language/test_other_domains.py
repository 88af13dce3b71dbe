"""Goals in a domain whose predicates are named otherwise than the ERL domain's
(``tests/fixtures/language/delivery``: ``(handed ?i - item ?p - person)``, ``(item_at ?i - item ?l - room)``):
each goal is said with the one predicate that takes its arguments (``knic.language.goals.fitted``), and the
planner plans it."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pytest

from knic.language import understand
from knic.language.goals import fitted
from knic.language.kinds import aliased
from knic.language.vocabulary import Vocabulary
from knic.language.world import read_vocabulary
from knowledge_base import Fact

FOLDER = Path(__file__).resolve().parents[1] / "fixtures" / "language" / "delivery"


@pytest.fixture(scope="module")
def delivery() -> Vocabulary:
    return read_vocabulary(FOLDER / "domain.pddl", FOLDER / "problem.pddl")


@pytest.mark.parametrize(
    ("said", "goal"),
    [
        ("bring the teapot to grandpa", "(handed teapot grandpa)"),
        ("could you give nurse joy the book", "(handed book nurse_joy)"),
        ("fetch me the remote control", "(handed remote_control grandpa)"),
        ("take the book to the lounge", "(item_at book lounge)"),
        ("go to the study", "(robot_at tiago study)"),  # the domain has this one
        ("pick up the teapot", "(holding tiago teapot)"),
    ],
)
def test_each_goal_is_said_with_the_predicate_that_takes_its_arguments(
    delivery: Vocabulary, said: str, goal: str
) -> None:
    assert [str(g) for g in understand(said, delivery, speaker="grandpa").goals] == [goal]


def test_a_goal_no_predicate_takes_is_refused_by_name(delivery: Vocabulary) -> None:
    found = understand("find the book", delivery, speaker="grandpa")
    assert not found.accepted and "no predicate 'reported'" in (found.reason or "")


def test_a_goal_two_predicates_take_is_left_as_said(tmp_path: Path) -> None:
    domain = (FOLDER / "domain.pddl").read_text(encoding="utf-8")
    domain = domain.replace("(free ?r - robot))", "(free ?r - robot) (admired ?p - person ?i - item))")
    (tmp_path / "domain.pddl").write_text(domain, encoding="utf-8")
    vocabulary = read_vocabulary(tmp_path / "domain.pddl", FOLDER / "problem.pddl")
    assert fitted(Fact("has", ("grandpa", "teapot")), vocabulary) == Fact("has", ("grandpa", "teapot"))
    found = understand("bring the teapot to grandpa", vocabulary, speaker="grandpa")
    assert not found.accepted and "no predicate 'has'" in (found.reason or "")


def test_the_erl_goals_keep_their_own_predicates(vocabulary: Vocabulary) -> None:
    assert fitted(Fact("has", ("annie", "mug")), vocabulary) == Fact("has", ("annie", "mug"))


def _planned(folder: Path, goals: Sequence[Fact], tmp_path: Path) -> list[str]:
    """The plan Fast Downward finds for ``goals`` in the folder's domain and problem (its goal replaced)."""
    from unified_planning.io import PDDLReader

    from planner.general import solve_problem
    from planner.plan import PlanStatus

    problem = (folder / "problem.pddl").read_text(encoding="utf-8")
    head = problem[: problem.index("(:goal")]
    (tmp_path / "problem.pddl").write_text(f"{head}(:goal (and {' '.join(map(str, goals))})))\n", "utf-8")
    parsed = PDDLReader().parse_problem(str(folder / "domain.pddl"), str(tmp_path / "problem.pddl"))
    result = solve_problem(parsed, engine="fast-downward")
    assert result.status == PlanStatus.SOLVED
    return [str(step) for step in result.plan]


def test_the_planner_plans_the_goal_said_in_the_domains_words(delivery: Vocabulary, tmp_path: Path) -> None:
    said = "bring the teapot to grandpa, then take the book to the lounge"
    goals = understand(said, delivery, speaker="grandpa").goals
    assert [str(g) for g in goals] == ["(handed teapot grandpa)", "(item_at book lounge)"]
    plan = _planned(FOLDER, goals, tmp_path)
    assert [step.split()[0] for step in plan].count("(give") == 1
    assert "(drop tiago book lounge)" in plan


ERRANDS = FOLDER.parent / "errands"


@pytest.fixture(scope="module")
def errands() -> Vocabulary:
    """A domain whose rooms are ``location``, people ``human`` and things ``thing``."""
    return read_vocabulary(ERRANDS / "domain.pddl", ERRANDS / "problem.pddl")


@pytest.mark.parametrize(
    ("said", "goal"),
    [
        ("bring the coffee mug to ada", "(delivered coffee_mug ada)"),
        ("go to the garage", "(at_robot pepper garage)"),
        ("take the wrench to the office", "(thing_at wrench office)"),
        ("could you fetch the mug for me", "(delivered coffee_mug bram)"),
        ("pick up the wrench", "(carrying pepper wrench)"),
    ],
)
def test_a_domains_own_names_for_rooms_people_and_things_are_read_as_them(
    errands: Vocabulary, said: str, goal: str
) -> None:
    assert [str(g) for g in understand(said, errands, speaker="bram").goals] == [goal]


def test_the_kinds_sit_above_the_domains_types_which_stay_as_written() -> None:
    types = {"object": None, "location": "object", "waypoint": "location", "human": "object", "room2": None}
    assert aliased(types) == {
        "object": None,
        "location": "room",
        "room": "object",
        "waypoint": "location",
        "human": "person",
        "person": "object",
        "room2": None,
    }
    erl = {"object": None, "room": "object", "location": "object"}
    assert aliased(erl) == erl  # the domain names rooms itself: its "location" is something else


def test_the_planner_plans_a_command_in_the_errands_domain(errands: Vocabulary, tmp_path: Path) -> None:
    said = "take the wrench to the office and bring ada the coffee mug"
    goals = understand(said, errands, speaker="bram").goals
    assert [str(g) for g in goals] == ["(thing_at wrench office)", "(delivered coffee_mug ada)"]
    assert "(put_down pepper wrench office)" in _planned(ERRANDS, goals, tmp_path)


def test_a_world_without_people_takes_commands_that_name_no_one() -> None:
    tidy = FOLDER.parent / "tidy"
    vocabulary = read_vocabulary(tidy / "domain.pddl", tidy / "problem.pddl")
    assert [str(g) for g in understand("head to the den please", vocabulary).goals] == ["(bot_in hsr den)"]
    placed = understand("could you put the stapler on the sideboard", vocabulary).goals
    assert [str(g) for g in placed] == ["(on_surface stapler sideboard)"]
    assert [str(g) for g in understand("grab the lunchbox", vocabulary).goals] == ["(gripping hsr lunchbox)"]
    brought = understand("bring me the stapler", vocabulary)  # "me" is no one here
    assert not brought.accepted and "not a person of this world" in brought.reason


def test_a_speaker_the_world_lacks_is_refused_where_the_world_has_people(delivery: Vocabulary) -> None:
    found = understand("go to the study", delivery, speaker="priya")
    assert not found.accepted and "speaker 'priya' is not a person of this world" in found.reason
