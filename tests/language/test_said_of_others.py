"""Wishes said of someone else, staying somewhere, and blinds closed "all the way"."""

from __future__ import annotations

from pathlib import Path

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        ("tracy needs the tablet", ["(has tracy tablet)"]),
        ("tracy would like a glass of water please", ["(has tracy water)"]),
        ("could you get the remote, tracy wants it", ["(has tracy remote)"]),
        ("fetch the mug and the glass, annie could use them", ["(has annie mug)", "(has annie glass)"]),
        ("i need the lemon", ["(has annie lemon)"]),
    ],
)
def test_a_wish_said_of_someone_is_brought_to_them(
    vocabulary: Vocabulary, text: str, goals: list[str]
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert sorted(str(g) for g in result.goals) == sorted(goals)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("wait next to the sofa", "(robot_at r2d2 living_room)"),
        ("stay in the kitchen please", "(robot_at r2d2 kitchen)"),
    ],
)
def test_waiting_somewhere_is_going_there(vocabulary: Vocabulary, text: str, goal: str) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == [goal]


@pytest.mark.parametrize(
    ("text", "level"),
    [
        ("close the blinds all the way", "l0"),
        ("shut the blinds fully", "l0"),
        ("lower the blinds a quarter", "l75"),
        ("close the blinds halfway", "l50"),
        ("open the blinds all the way", "l100"),
        ("set the blinds to 25 percent", "l25"),
    ],
)
def test_how_far_blinds_close_is_counted_from_open(vocabulary: Vocabulary, text: str, level: str) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == [f"(device_level bedroom_blinds {level})"]


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        # the living room's light is its dimmer; "the lamp" alone also names the bedroom's two lights
        (
            "go to the living room and switch on the lamp",
            ["(robot_at r2d2 living_room)", "(device_level living_room_dimmer l100)"],
        ),
        ("turn the lamp up to half", ["(device_level living_room_dimmer l50)"]),
        ("bring both the juice and the water to tracy", ["(has tracy juice)", "(has tracy water)"]),
    ],
)
def test_what_is_asked_and_where_narrow_the_device(
    vocabulary: Vocabulary, text: str, goals: list[str]
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == goals


def test_a_device_name_left_open_is_still_asked_about(vocabulary: Vocabulary) -> None:
    result = understand("go to the bedroom and switch on the lamp", vocabulary)
    assert not result.accepted and result.question is not None and "left light" in result.question


def test_a_device_is_also_called_by_its_type_in_its_room() -> None:
    """The bungalow's reading lamp has no lexicon name "light": its type names it, and its room is the
    world file's (the domain has no fact for a device's room)."""
    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    vocabulary, speaker = world_vocabulary("worlds/test_bungalow/test_bungalow.yaml", DEFAULT_DOMAIN, None)
    for text in ("turn on the light in the sitting room", "switch the sitting room lamp on"):
        result = understand(text, vocabulary, speaker=speaker or "walter")
        assert result.accepted, result.reason
        assert [str(g) for g in result.goals] == ["(light_on reading_lamp)"]
    result = understand("turn on the light in the hall", vocabulary, speaker=speaker or "walter")
    assert not result.accepted and "no light in the hall" in result.reason


@pytest.mark.parametrize("text", ["come here", "could you come over here please"])
def test_here_is_where_the_speaker_is(vocabulary: Vocabulary, text: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and result.question == "Where are you: in which room?"


@pytest.mark.parametrize(
    ("text", "goals"),
    [
        ("the remote, can you bring it over here", ["(has annie remote)"]),
        ("my glasses, where are they", ["(reported glasses)"]),
        ("tracy is in the kitchen, could you check on her", ["(reported tracy)"]),
    ],
)
def test_what_is_said_first_is_what_they_and_it_mean(
    vocabulary: Vocabulary, text: str, goals: list[str]
) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == goals


def test_a_world_is_read_with_the_lexicon_beside_it(tmp_path: Path) -> None:
    from knic.system.names import ERL_LEXICON, world_lexicon

    world = tmp_path / "flat.yaml"
    world.write_text("name: flat\n", encoding="utf-8")
    assert world_lexicon(world) == ERL_LEXICON  # none of its own: the ERL apartment's
    (tmp_path / "lexicon.yaml").write_text("names: {}\n", encoding="utf-8")
    assert world_lexicon(world) == tmp_path / "lexicon.yaml"


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("check whether the front door is open", "'front door'"),
        ("bring me my fuzzy slippers from the bedroom", "'fuzzy slippers'"),
    ],
)
def test_the_whole_name_the_world_lacks_is_named(vocabulary: Vocabulary, text: str, named: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and f"there is no {named} here" in result.reason
