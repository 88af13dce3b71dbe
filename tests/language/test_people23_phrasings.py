"""Phrasings from the people23 development set (a shared student house the reader was never tuned on,
``tests/fixtures/language/people23/student_house.yaml``) the reader first got wrong:

* where the speaker has a room named after them ("jas_room"), "my room" (or "my bedroom") is that room, and a
  device said with "my" ("open my blind", "my room light off") is the one of that name there
  (``knic.language.owned``); said by someone with no room of their own, "my room" still asks which;
* a device said to be on a piece of furniture ("the lamp on my desk") is the one of that name in the room of
  that furniture: devices stand in rooms, not on furniture; several such still ask which;
* a phrase a lexicon gives one thing that is another thing's own name is that other thing's: where a home
  has both a ``bedside_table`` and a ``night_stand``, "the night stand" is the night stand;
* a question word stressed ("where tf is", "where the hell are", "where on earth") asks as it would bare;
  "where has the rota got to" is where it is; a thing said and then "where" alone ("chopsticks, where?", "my
  keys where") asks where it is; "where might tomasz be", "do you happen to know where ...", "inform me of
  the whereabouts of ...", "kindly ascertain whether Miss Mei is at home": searches;
* "might I trouble you for the umbrella" asks for it; "I should be most grateful if you would ..." (and "much
  obliged", "very grateful") is a polite request, while "i should tidy my room later" still says what the
  speaker means to do.
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

HOUSE = "tests/fixtures/language/people23/student_house.yaml"
TERRACE = "tests/fixtures/language/people22/terraced_house.yaml"


@pytest.fixture(scope="module")
def house() -> Vocabulary:
    """The student house's vocabulary."""
    return world_of(HOUSE)


@pytest.mark.parametrize(
    ("speaker", "text", "frames"),
    [
        (
            "jas",
            "take the game controller to my room",
            [{"frame": "BRINGING", "theme": "game_controller", "goal": "jas_room"}],
        ),
        ("tomasz", "go to my bedroom", [{"frame": "MOTION", "goal": "tomasz_room"}]),
        (
            "jas",
            "can u open my blind halfway",
            [{"frame": "OPERATING", "device": "jas_room_blind", "state": "50"}],
        ),
        (
            "sol",
            "would you mind closing my blind?",
            [{"frame": "OPERATING", "device": "sol_room_blind", "state": "closed"}],
        ),
        ("dara", "my room light off", [{"frame": "OPERATING", "device": "dara_room_light", "state": "off"}]),
        (
            "mei",
            "close the light of my room",
            [{"frame": "OPERATING", "device": "mei_room_light", "state": "off"}],
        ),
        ("finn", "put my hoodie on my bed", [{"frame": "PLACING", "theme": "hoodie", "goal": "finn_bed"}]),
    ],
)
def test_my_room_and_my_device_are_in_the_room_named_after_the_speaker(
    house: Vocabulary, speaker: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, speaker) == frames


def test_my_room_of_someone_with_no_room_asks(house: Vocabulary) -> None:
    assert_asked(house, "take the iron to my room", "room", "hargreaves")
    assert_asked(house, "open my blind", "blind", "hargreaves")


@pytest.mark.parametrize(
    ("speaker", "text", "device"),
    [
        ("mei", "the lamp on my desk, turn off", "desk_lamp"),
        ("sol", "turn off the lamp on my desk", "easel_lamp"),
        ("finn", "turn off the lamp on the sofa", "floor_lamp"),
        ("hargreaves", "switch off the lamp on the desk in mei's room", "desk_lamp"),
    ],
)
def test_a_device_on_furniture_is_the_one_in_its_room(
    house: Vocabulary, speaker: str, text: str, device: str
) -> None:
    assert frames_read(house, text, speaker) == [{"frame": "OPERATING", "device": device, "state": "off"}]


def test_a_device_on_furniture_of_several_rooms_asks(house: Vocabulary) -> None:
    assert_asked(house, "turn off the lamp on the desk", "lamp", "finn")


def test_another_things_own_name_is_that_things(house: Vocabulary) -> None:
    assert frames_read(house, "earplugs from night stand. bring", "dara") == [
        {"frame": "BRINGING", "theme": "earplugs", "source": "night_stand", "beneficiary": "me"}
    ]
    assert frames_read(house, "go to the bedside table", "dara") == [
        {"frame": "MOTION", "goal": "bedside_table"}
    ]
    terrace = world_of(TERRACE)  # a home with only bedside tables: "the night stand" fits them still
    assert_asked(terrace, "go to the night stand", "bedside", "kerry")


@pytest.mark.parametrize(
    ("speaker", "text", "theme"),
    [
        ("jas", "where tf is the tv remote", "tv_remote"),
        ("jas", "where the hell are my keys", "jas_keys"),
        ("finn", "where on earth is the rugby ball", "rugby_ball"),
        ("hargreaves", "Pray, where has the rota got to?", "rota"),
        ("mei", "chopsticks, where?", "chopsticks"),
        ("dara", "my keys where", "dara_keys"),
        ("sol", "where might tomasz be?", "tomasz"),
        ("sol", "do you happen to know where the bike pump is?", "bike_pump"),
        ("hargreaves", "Be so good as to inform me of the whereabouts of the bike pump.", "bike_pump"),
        ("hargreaves", "Kindly ascertain whether Miss Mei is at home.", "mei"),
    ],
)
def test_ways_of_asking_where(house: Vocabulary, speaker: str, text: str, theme: str) -> None:
    assert frames_read(house, text, speaker) == [{"frame": "SEARCHING", "theme": theme}]


def test_where_alone_asks_nothing(house: Vocabulary) -> None:
    result = understand("do you know where", house, speaker="sol")
    assert not result.accepted


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Might I trouble you for the umbrella?",
            [{"frame": "BRINGING", "theme": "umbrella", "beneficiary": "me"}],
        ),
        (
            "I should be most grateful if you would switch on the landing light.",
            [{"frame": "OPERATING", "device": "landing_light", "state": "on"}],
        ),
        (
            "I should be much obliged if you would close the kitchen blind.",
            [{"frame": "OPERATING", "device": "kitchen_blind", "state": "closed"}],
        ),
    ],
)
def test_formal_requests(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "hargreaves") == frames


def test_what_the_speaker_should_do_is_still_no_request(house: Vocabulary) -> None:
    result = understand("i should tidy my room later", house, speaker="jas")
    assert not result.accepted and "no request" in result.reason
