"""Phrasings found by trying the reader on sentences written on the spot, in three apartments: wishes said of
someone else, staying somewhere, blinds closed "all the way", devices narrowed by what is asked and where,
"here", "they", and names the world lacks."""

from __future__ import annotations

from pathlib import Path

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

READ = [
    # a wish said of someone: for them
    ("tracy needs the tablet", ["(has tracy tablet)"]),
    ("tracy would like a glass of water please", ["(has tracy water)"]),
    ("could you get the remote, tracy wants it", ["(has tracy remote)"]),
    ("fetch the mug and the glass, annie could use them", ["(has annie mug)", "(has annie glass)"]),
    ("i need the lemon", ["(has annie lemon)"]),
    # waiting somewhere is going there
    ("wait next to the sofa", ["(robot_at r2d2 living_room)"]),
    ("stay in the kitchen please", ["(robot_at r2d2 kitchen)"]),
    # how far blinds close is counted from open
    ("close the blinds all the way", ["(device_level bedroom_blinds l0)"]),
    ("shut the blinds fully", ["(device_level bedroom_blinds l0)"]),
    ("lower the blinds a quarter", ["(device_level bedroom_blinds l75)"]),
    ("close the blinds halfway", ["(device_level bedroom_blinds l50)"]),
    ("open the blinds all the way", ["(device_level bedroom_blinds l100)"]),
    ("set the blinds to 25 percent", ["(device_level bedroom_blinds l25)"]),
    ("lower the blinds to a quarter", ["(device_level bedroom_blinds l25)"]),  # "to": where, not how far
    # the living room's light is its dimmer; "the lamp" alone also names the bedroom's two lights
    (
        "go to the living room and switch on the lamp",
        ["(robot_at r2d2 living_room)", "(device_level living_room_dimmer l100)"],
    ),
    ("turn the lamp up to half", ["(device_level living_room_dimmer l50)"]),
    ("bring both the juice and the water to tracy", ["(has tracy juice)", "(has tracy water)"]),
    # what was said first is what "it", "they", "her" mean; "here" is the speaker
    ("the remote, can you bring it over here", ["(has annie remote)"]),
    ("my glasses, where are they", ["(reported glasses)"]),
    ("tracy is in the kitchen, could you check on her", ["(reported tracy)"]),
]

NOT_READ = [  # (text, what the question or the refusal says)
    ("come here", "Where are you: in which room?"),
    ("could you come over here please", "Where are you: in which room?"),
    ("go to the bedroom and switch on the lamp", "the left light or the right light"),
    ("check whether the front door is open", "there is no 'front door' here"),
    ("bring me my fuzzy slippers from the bedroom", "there is no 'fuzzy slippers' here"),
]


@pytest.mark.parametrize(("text", "goals"), READ)
def test_read_as_meant(vocabulary: Vocabulary, text: str, goals: list[str]) -> None:
    result = understand(text, vocabulary)
    assert result.accepted, result.reason
    assert sorted(str(g) for g in result.goals) == sorted(goals)


@pytest.mark.parametrize(("text", "said"), NOT_READ)
def test_asked_back_or_named(vocabulary: Vocabulary, text: str, said: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and said in (result.question or result.reason)


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


def test_a_world_is_read_with_the_lexicon_beside_it(tmp_path: Path) -> None:
    from knic.system.names import ERL_LEXICON, world_lexicon

    world = tmp_path / "flat.yaml"
    world.write_text("name: flat\n", encoding="utf-8")
    assert world_lexicon(world) == ERL_LEXICON  # none of its own: the ERL apartment's
    (tmp_path / "lexicon.yaml").write_text("names: {}\n", encoding="utf-8")
    assert world_lexicon(world) == tmp_path / "lexicon.yaml"


def test_a_plural_name_is_also_said_in_the_singular() -> None:
    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    vocabulary, _ = world_vocabulary("worlds/test_bungalow/test_bungalow.yaml", DEFAULT_DOMAIN, None)
    result = understand("could you bring me the car key", vocabulary, speaker="walter")
    assert result.accepted, result.reason
    assert [str(g) for g in result.goals] == ["(has walter car_keys)"]
