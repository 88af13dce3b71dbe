"""Phrasings found with the sixth blind set (people6): going to a person ("go to tracy": the robot seeks her
out, and "her" then names her); questions and wishes that are requests ("is there any way you could ...",
"I could really do with ..."); short trips ("nip to the kitchen", "swing by the nursery"); "go on and ...";
a room said for its only dimmer or blinds when a level is asked ("dim the lounge to 40"); a question about the
request said before talk that names nothing ("light on please, I can't see": which light?); a room said right
after whom a thing goes to is where they are ("the juice to granny in the living room": handed to her); "it"
for a device named before ("the hall light, switch it off"); an action said without its objects after several
were named takes them all ("apple and lemon, bring to me")."""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read

READ = [
    ("go to tracy", [{"frame": "MOTION", "goal": "tracy"}]),
    (
        "go to tracy and give her the mug",
        [
            {"frame": "MOTION", "goal": "tracy"},
            {"frame": "BRINGING", "theme": "mug", "beneficiary": "tracy"},
        ],
    ),
    (
        "is there any way you could bring me the tablet",
        [{"frame": "BRINGING", "theme": "tablet", "beneficiary": "me"}],
    ),
    ("I could really do with the tissues", [{"frame": "BRINGING", "theme": "tissues", "beneficiary": "me"}]),
    ("I could do with my glasses", [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}]),
    ("I really need the remote", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]),
    ("could you nip to the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    (
        "nip to the kitchen and fetch me the juice",
        [
            {"frame": "MOTION", "goal": "kitchen"},
            {"frame": "BRINGING", "theme": "juice", "source": "kitchen", "beneficiary": "me"},
        ],
    ),
    ("dim the lounge to 40", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "40"}]),
    ("set the bedroom to half", [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"}]),
    ("the hall light, switch it off", [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}]),
    ("the dimmer, set it to half", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "50"}]),
    (
        "apple and lemon bring to me please",
        [
            {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"},
            {"frame": "BRINGING", "theme": "lemon", "beneficiary": "me"},
        ],
    ),
    (
        "the cup and the mug, put in the bin",
        [
            {"frame": "PLACING", "theme": "cup", "goal": "bin"},
            {"frame": "PLACING", "theme": "mug", "goal": "bin"},
        ],
    ),
]

READ_IN_THE_OTHER_HOUSE = [
    ("dim the lounge to 40", [{"frame": "OPERATING", "device": "lounge_dimmer", "state": "40"}]),
    ("swing by the nursery", [{"frame": "MOTION", "goal": "nursery"}]),
    ("stop by the garage", [{"frame": "MOTION", "goal": "garage"}]),
    (
        "go on and leave the hammer on the workbench",
        [{"frame": "PLACING", "theme": "hammer", "goal": "workbench"}],
    ),
    (
        "any chance you could put the stapler on the desk",
        [{"frame": "PLACING", "theme": "stapler", "goal": "desk"}],
    ),
    ("go to oscar", [{"frame": "MOTION", "goal": "oscar"}]),
]


@pytest.mark.parametrize(("text", "frames"), READ)
def test_read_as_meant(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(("text", "frames"), READ_IN_THE_OTHER_HOUSE)
def test_read_as_meant_in_the_other_house(
    other_house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(other_house, text, "maria") == frames


def test_going_to_a_person_seeks_them_out(vocabulary: Vocabulary) -> None:
    result = understand("go to tracy", vocabulary)
    assert [str(g) for g in result.goals] == ["(found tracy)"]


def test_coming_to_the_speaker_still_asks_where(vocabulary: Vocabulary) -> None:
    result = understand("come to me", vocabulary)
    assert not result.accepted and "which room" in result.question


def test_a_room_without_a_dimmer_is_no_device(vocabulary: Vocabulary) -> None:
    result = understand("dim the kitchen to 40", vocabulary)
    assert not result.accepted and "kitchen" in result.reason


def test_a_room_said_without_a_level_is_no_device(vocabulary: Vocabulary) -> None:
    assert not understand("turn on the lounge", vocabulary).accepted


def test_the_question_about_the_request_beats_the_talk_after_it(other_house: Vocabulary) -> None:
    result = understand("light on please, I can't see", other_house, speaker="maria")
    assert not result.accepted and result.question.startswith("Which light do you mean")


def test_a_room_after_the_person_a_thing_goes_to_is_where_they_are(vocabulary: Vocabulary) -> None:
    from knic.language.goals import hints

    result = understand("bring the juice to granny in the living room", vocabulary, speaker="tracy")
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "BRINGING", "theme": "juice", "goal": "living_room", "beneficiary": "annie"}
    ]
    assert [str(g) for g in result.goals] == ["(has annie juice)"]
    assert "(possibly_at annie living_room)" in [str(h) for h in hints(result.frames, vocabulary)]


def test_a_room_after_the_thing_is_still_where_it_is(vocabulary: Vocabulary) -> None:
    result = understand("bring me the mug in the kitchen", vocabulary)
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "BRINGING", "theme": "mug", "source": "kitchen", "beneficiary": "me"}
    ]


def test_it_after_an_object_is_no_device(vocabulary: Vocabulary) -> None:
    assert not understand("bring me the mug and switch it off", vocabulary).accepted
