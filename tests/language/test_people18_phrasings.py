"""Phrasings from the people18 development set (a two-storey townhouse the reader was never tuned on,
``tests/fixtures/language/people18/townhouse.yaml``) the reader first got wrong:

* a world that calls one thing "blinds" and another "curtains" tells them apart by that word: neither gets the
  other's word as a synonym, and the type's own word ("the blinds") names only the things called so;
* "it" or "them" may be a device operated earlier in the command, and a device set again later ends as the
  last setting says ("open the blinds and set them to 40");
* general English names: "guest room" / "spare room" for a guest bedroom, "laundry room" for a utility room,
  "book" for a novel;
* a complaint of a dark place "on" it ("it's really dark on the landing"), and a complaint that one cannot see
  (or of glare) beside a device said to be off (or on): that device's other state;
* a container of a drink said by what it holds ("some water" for the water bottle);
* "bring her blanket" after a person is named ("look for nadia and bring her blanket"): to her, hers;
* the room a door to the outside opens into is "the front door" ("go to the front door", "the table by the
  front door"), where the world file says so;
* a thing's name followed, in an action, by a noun the world lacks is a longer name it lacks ("bring me a
  candle holder": 'candle holder', not the candle); a container after what it holds is still what it holds
  ("the water bottle": water), and a list said without commas stays a list ("the mug, lemon and apple");
* a kind said by its use ("a drink") is told by the last word of a name, or what its container holds: a "tea
  towel" is no drink, a "water bottle" is;
* a room said before a piece of furniture after "to" ("take the letters to the hallway table"): the furniture
  there is where the thing goes;
* a device said after another's state with no state of its own ("turn the desk lamp off and the landing
  light too"): the same state;
* an unknown word before a group of devices ("the garden lights") names lights the world lacks, not all;
* more general English room names ("kitchenette", "en suite", "living area", "lobby"), a room by the kind of
  room its name ends with ("open plan living room": the living room), and boxes and packets as containers
  ("the cereal" for a cereal box);
* an action said to come first after another ("bring me the orange once you've switched on the hallway
  light", "... when you have turned on ...", "... after you switch on ..."): done first;
* someone asked to come or go somewhere ("ask tom to come to the kitchen"): taken there;
* a word that ends the world's own name of some things beats a synonym that ends another's ("the table" in
  the bungalow is the dining table, not the nightstand that is also a "bedside table").
"""

from __future__ import annotations

from typing import Any

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read

TOWNHOUSE = "tests/fixtures/language/people18/townhouse.yaml"


@pytest.fixture(scope="module")
def townhouse() -> Vocabulary:
    """The townhouse's vocabulary, as the language bench and ``knic goal --world`` read it."""
    from pathlib import Path

    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    path = Path(__file__).resolve().parents[2] / TOWNHOUSE
    vocabulary: Any = world_vocabulary(str(path), DEFAULT_DOMAIN, None)[0]
    return vocabulary


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("open the blinds", "office_blinds", "open"),
        ("curtains open.", "bedroom_curtains", "open"),
        ("close the curtains", "bedroom_curtains", "closed"),
    ],
)
def test_blinds_and_curtains_told_apart(townhouse: Vocabulary, text: str, device: str, state: str) -> None:
    assert frames_read(townhouse, text, "nadia") == [{"frame": "OPERATING", "device": device, "state": state}]


def test_curtains_are_still_the_blinds_where_the_world_has_only_blinds(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "close the curtains") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}
    ]


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("open the blinds and set them to 40", "office_blinds", "40"),
        ("turn on the floor lamp and dim it to 30 percent", "floor_lamp", "30"),
    ],
)
def test_a_device_set_again_ends_as_last_said(
    townhouse: Vocabulary, text: str, device: str, state: str
) -> None:
    assert frames_read(townhouse, text, "nadia") == [{"frame": "OPERATING", "device": device, "state": state}]


def test_a_device_set_again_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    result = understand("open the blinds and then set them to 75 percent", vocabulary)
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "75"}
    ]
    assert [str(g) for g in result.goals] == ["(device_level bedroom_blinds l75)"]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("head to the spare room", [{"frame": "MOTION", "goal": "guest_bedroom"}]),
        (
            "take the laptop from the office to the guest room",
            [{"frame": "BRINGING", "theme": "laptop", "source": "home_office", "goal": "guest_bedroom"}],
        ),
        ("go to the laundry room", [{"frame": "MOTION", "goal": "utility_room"}]),
        ("bring me my book", [{"frame": "BRINGING", "theme": "novel", "beneficiary": "me"}]),
    ],
)
def test_general_english_names(townhouse: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(townhouse, text, "nadia") == frames


def test_two_bedrooms_still_asked_about(townhouse: Vocabulary) -> None:
    assert_asked(townhouse, "go to the bedroom", "bedroom", "nadia")


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("it's really dark on the landing", "landing_light", "on"),
        ("i can't see a thing in here, the desk lamp is off", "desk_lamp", "on"),
        ("it's far too bright in here, the blinds are open", "office_blinds", "closed"),
    ],
)
def test_complaints_ask_for_the_other_state(
    townhouse: Vocabulary, text: str, device: str, state: str
) -> None:
    assert frames_read(townhouse, text, "nadia") == [{"frame": "OPERATING", "device": device, "state": state}]


def test_a_device_said_off_alone_is_no_complaint(townhouse: Vocabulary) -> None:
    assert frames_read(townhouse, "the desk lamp is off", "nadia") == [
        {"frame": "OPERATING", "device": "desk_lamp", "state": "off"}
    ]


@pytest.mark.parametrize("text", ["bring me some water", "could i have a glass of water"])
def test_a_drink_names_its_container(townhouse: Vocabulary, text: str) -> None:
    assert frames_read(townhouse, text, "nadia") == [
        {"frame": "BRINGING", "theme": "water_bottle", "beneficiary": "me"}
    ]


def test_a_device_put_in_opposite_states_is_asked_about(vocabulary: Vocabulary) -> None:
    assert_asked(vocabulary, "switch on the left light and then switch it off", "which should it be")


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "look for nadia and bring her blanket",
            [
                {"frame": "SEARCHING", "theme": "nadia"},
                {"frame": "BRINGING", "theme": "spare_blanket", "beneficiary": "nadia"},
            ],
        ),
        (
            "find nadia and bring her slippers from the shoe rack",
            [
                {"frame": "SEARCHING", "theme": "nadia"},
                {"frame": "BRINGING", "theme": "slippers", "source": "shoe_rack", "beneficiary": "nadia"},
            ],
        ),
        ("bring her slippers", [{"frame": "BRINGING", "theme": "slippers", "beneficiary": "me"}]),
        (
            "find nadia and bring her slippers to the kitchen",
            [
                {"frame": "SEARCHING", "theme": "nadia"},
                {"frame": "BRINGING", "theme": "slippers", "goal": "kitchen"},
            ],
        ),
    ],
)
def test_bring_her_thing_after_she_is_named(
    townhouse: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(townhouse, text, "tom") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("go to the front door", [{"frame": "MOTION", "goal": "hallway"}]),
        (
            "grab the letters off the table by the front door",
            [{"frame": "TAKING", "theme": "letters", "source": "console_table"}],
        ),
    ],
)
def test_the_front_door_is_the_room_it_opens_into(
    townhouse: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(townhouse, text, "nadia") == frames


def test_the_front_door_in_the_simulators_test_flat() -> None:
    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    flat: Any = world_vocabulary("test_flat", DEFAULT_DOMAIN, None)[0]
    assert frames_read(flat, "go to the front door", "olga") == [{"frame": "MOTION", "goal": "foyer"}]


def test_world_entrances() -> None:
    from worlds.loader import load_world

    assert load_world("erl_home").entrances() == ["entrance_hall"]
    assert load_world("test_bungalow").entrances() == ["hall"]


@pytest.mark.parametrize(
    ("text", "word"),
    [("bring me a candle holder", "candle holder"), ("put the candle holder on the table", "candle holder")],
)
def test_a_longer_name_the_world_lacks_is_refused(vocabulary: Vocabulary, text: str, word: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted
    assert f"'{word}'" in result.reason, result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "bring me the mug, lemon and apple",
            [
                {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "lemon", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"},
            ],
        ),
        ("bring me the water bottle", [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}]),
        ("bring me the candle now", [{"frame": "BRINGING", "theme": "candle", "beneficiary": "me"}]),
        ("pick up the lemon lying on the sofa", [{"frame": "TAKING", "theme": "lemon", "source": "sofa"}]),
        ("fetch the mug quick", [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}]),
        ("bring me the glasses mate", [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}]),
        ("bring the cup round to tracy", [{"frame": "BRINGING", "theme": "cup", "beneficiary": "tracy"}]),
        ("take the mug upstairs to the bedroom", [{"frame": "BRINGING", "theme": "mug", "goal": "bedroom"}]),
        ("bring the mug mate to the sofa", [{"frame": "BRINGING", "theme": "mug", "goal": "sofa"}]),
    ],
)
def test_words_after_a_name_that_make_no_longer_name(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_kind_is_told_by_the_head_of_a_name(townhouse: Vocabulary) -> None:
    result = understand("fetch me a drink", townhouse, speaker="nadia")
    assert not result.accepted
    assert "the orange juice or the water bottle" in result.question
    assert "towel" not in result.question


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "take the letters to the hallway table",
            [{"frame": "BRINGING", "theme": "letters", "goal": "console_table"}],
        ),
        (
            "turn the desk lamp off and the landing light too",
            [
                {"frame": "OPERATING", "device": "desk_lamp", "state": "off"},
                {"frame": "OPERATING", "device": "landing_light", "state": "off"},
            ],
        ),
        (
            "desk lamp on please and the bedside lamp too",
            [
                {"frame": "OPERATING", "device": "desk_lamp", "state": "on"},
                {"frame": "OPERATING", "device": "bedside_lamp", "state": "on"},
            ],
        ),
        (
            "switch the hallway light on and the landing light off",
            [
                {"frame": "OPERATING", "device": "hallway_light", "state": "on"},
                {"frame": "OPERATING", "device": "landing_light", "state": "off"},
            ],
        ),
    ],
)
def test_what_a_later_phrase_takes_from_before(
    townhouse: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(townhouse, text, "nadia") == frames


def test_an_unknown_word_before_a_group_is_no_group(vocabulary: Vocabulary, townhouse: Vocabulary) -> None:
    for world in (vocabulary, townhouse):
        result = understand("turn on the garden lights", world, speaker="nadia")
        assert not result.accepted
        assert "'garden lights'" in result.reason, result.reason
    assert frames_read(vocabulary, "turn off all the lights") == [
        {"frame": "OPERATING", "device": "all_lights", "state": "off"}
    ]


STUDIO = {
    "rooms": [
        {"name": "open_plan_living_room", "polygon": [[0, 0], [6, 0], [6, 5], [0, 5]]},
        {"name": "kitchenette", "polygon": [[6, 0], [9, 0], [9, 3], [6, 3]]},
        {"name": "en_suite", "polygon": [[6, 3], [9, 3], [9, 5], [6, 5]]},
        {"name": "entrance_lobby", "polygon": [[0, -2], [3, -2], [3, 0], [0, 0]]},
    ],
    "doors": [
        {"rooms": ["entrance_lobby"], "position": [1.5, -2.0]},
        {"rooms": ["entrance_lobby", "open_plan_living_room"], "position": [1.5, 0.0]},
        {"rooms": ["open_plan_living_room", "kitchenette"], "position": [6.0, 1.5]},
        {"rooms": ["open_plan_living_room", "en_suite"], "position": [6.0, 4.0]},
    ],
    "furniture": [
        {"name": "worktop", "room": "kitchenette", "position": [8.6, 1.5], "size": [0.6, 2.0, 0.9]},
        {"name": "desk", "room": "open_plan_living_room", "position": [5.5, 0.5], "size": [0.8, 0.6, 0.75]},
    ],
    "items": [{"name": "cereal_box", "furniture": "worktop"}, {"name": "laptop", "furniture": "desk"}],
    "people": [{"name": "ines", "position": [3.0, 2.0]}],
    "devices": [
        {"name": "strip_light", "type": "light", "room": "kitchenette", "position": [8.7, 1.5, 1.5]},
        {"name": "mirror_light", "type": "light", "room": "en_suite", "position": [7.5, 4.0, 2.0]},
    ],
    "robot": {"name": "r2d2", "start": [3.0, 2.5, 0]},
}


@pytest.fixture(scope="module")
def studio(tmp_path_factory: pytest.TempPathFactory) -> Vocabulary:
    import yaml

    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    path = tmp_path_factory.mktemp("studio") / "studio.yaml"
    path.write_text(yaml.safe_dump({"name": "studio", **STUDIO}))
    vocabulary: Any = world_vocabulary(str(path), DEFAULT_DOMAIN, None)[0]
    return vocabulary


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("go to the kitchen", [{"frame": "MOTION", "goal": "kitchenette"}]),
        ("go to the bathroom", [{"frame": "MOTION", "goal": "en_suite"}]),
        ("go to the living room", [{"frame": "MOTION", "goal": "open_plan_living_room"}]),
        ("go to the front door", [{"frame": "MOTION", "goal": "entrance_lobby"}]),
        ("bring me the cereal", [{"frame": "BRINGING", "theme": "cereal_box", "beneficiary": "me"}]),
        (
            "turn on the light in the bathroom",
            [{"frame": "OPERATING", "device": "mirror_light", "state": "on"}],
        ),
        ("kitchen light on", [{"frame": "OPERATING", "device": "strip_light", "state": "on"}]),
    ],
)
def test_names_in_a_studio(studio: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(studio, text, "ines") == frames


@pytest.mark.parametrize(
    "text",
    [
        "bring me the orange after you switch on the hallway light",
        "bring me the orange once you've switched on the hallway light",
        "bring me the orange when you have turned on the hallway light",
    ],
)
def test_an_action_said_to_come_first(townhouse: Vocabulary, text: str) -> None:
    assert frames_read(townhouse, text, "nadia") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"},
        {"frame": "BRINGING", "theme": "orange", "beneficiary": "me"},
    ]


def test_when_said_of_something_else_moves_nothing(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me the mug when you are done") == [
        {"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("turn on the big light", "ceiling_light", "on"),
        ("switch off the main light", "ceiling_light", "off"),
        ("standard lamp to half", "floor_lamp", "50"),
    ],
)
def test_everyday_names_of_lights(townhouse: Vocabulary, text: str, device: str, state: str) -> None:
    assert frames_read(townhouse, text, "nadia") == [{"frame": "OPERATING", "device": device, "state": state}]


@pytest.mark.parametrize(
    ("text", "who", "goal"),
    [
        ("ask tom to come to the kitchen", "tom", "kitchen"),
        ("could you tell nadia to go to the living room", "nadia", "living_room"),
        ("get tom to come up to the office", "tom", "home_office"),
    ],
)
def test_someone_asked_to_come_is_taken_there(townhouse: Vocabulary, text: str, who: str, goal: str) -> None:
    assert frames_read(townhouse, text, "nadia") == [{"frame": "ACCOMPANYING", "theme": who, "goal": goal}]


def test_an_own_name_beats_a_synonym() -> None:
    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    bungalow: Any = world_vocabulary("test_bungalow", DEFAULT_DOMAIN, None)[0]
    assert frames_read(bungalow, "put the newspaper on the table", "walter") == [
        {"frame": "PLACING", "theme": "newspaper", "goal": "dining_table"}
    ]
    assert frames_read(bungalow, "put the newspaper on the bedside table", "walter") == [
        {"frame": "PLACING", "theme": "newspaper", "goal": "nightstand"}
    ]


def test_a_vocabulary_keeps_which_names_are_given() -> None:
    from knic.language.world import read_vocabulary

    vocabulary = read_vocabulary()
    assert Vocabulary.from_data(vocabulary.to_data()).terms == vocabulary.terms
    assert any(t.given for t in vocabulary.terms)
