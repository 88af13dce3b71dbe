"""Phrasings from the people19 development set (a ground-floor garden flat the reader was never tuned on,
``tests/fixtures/language/people19/garden_flat.yaml``) the reader first got wrong:

* general English names: "the fridge" for a fridge freezer, "the tablet" for a tablet computer, "the garden
  room" for a conservatory, "wellies" for wellington boots, "the hall" for a passage or corridor;
* the words of a nearer subset of synonyms (``nearer`` in ``synonyms.yaml``): where a flat has a toilet and a
  wet room, "the bathroom" is the wet room and "the loo" the toilet; where it has only a bathroom, "the loo"
  is still the bathroom;
* a device is in a room its name says in whole words only: the den's lamp is the "den reading lamp", not the
  conservatory's, though that one is also the "garden room reading lamp";
* the singular of a plural name beyond a dropped "s" ("an ice lolly", "the shelf" for the pantry shelves) and
  of its last word ("open curtain of bedroom");
* a name only given (a synonym, a shorter name) that is the last word of another thing's own name is a last
  word like it: "the chair" asks between the wicker chair and the gaming chair (the armchair is a "chair"
  only by its one-word name), "the shelf in the pantry" is the pantry shelves, not the bookshelf;
* an object said only beside another, with no place after ("the crossword next to the magnifying glass"), says
  no place: the thing is sought or fetched wherever it is;
* a level asked of a room's lights said together where the room has a dimmer ("dim the lights in the lounge
  to 30 percent"): the dimmer; a room without one still refuses;
* where doors to the outside open into several rooms, the front door is the one with the doorbell (the
  conservatory's garden door is none);
* "go upstairs" where the world says no floors is refused naming the word;
* a place gone to is where the next action on a thing happens, past devices operated there ("go to the den,
  switch on the reading lamp there, and bring arthur his atlas": from the den);
* more of an older speaker's indirect English (``commands.yaml``, in text only): "it's ever so dark in the
  pantry" (and "pitch dark"), "I don't suppose there's any chance of a biscuit", "I fancy a biscuit", "I've no
  idea where the tv remote has got to";
* "for me" said before the thing taken ("take for me the slippers", as "get me the slippers") is whom it is
  for; said after it ("pick up the slippers for me") it stays a favour; "i need that you" opens a request as
  "i want that you" does;
* a verb's word after "my" or "the" that ends the name of a thing is that thing ("fetch me my stick": the
  walking stick), while "stick the slippers on the shoe bench" still places;
* people first said together ("bring tom and nadia a water bottle", "give tom and me the orange"): each is
  brought the thing.
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

GARDEN_FLAT = "tests/fixtures/language/people19/garden_flat.yaml"
TOWNHOUSE = "tests/fixtures/language/people18/townhouse.yaml"


@pytest.fixture(scope="module")
def flat() -> Vocabulary:
    """The garden flat's vocabulary."""
    return world_of(GARDEN_FLAT)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("put the milk in the fridge", [{"frame": "PLACING", "theme": "milk", "goal": "fridge_freezer"}]),
        ("gimme the tablet", [{"frame": "BRINGING", "theme": "tablet_computer", "beneficiary": "me"}]),
        (
            "you can take arthur to garden room?",
            [{"frame": "ACCOMPANYING", "theme": "arthur", "goal": "conservatory"}],
        ),
        (
            "put the wellies on the shoe bench",
            [{"frame": "PLACING", "theme": "wellington_boots", "goal": "shoe_bench"}],
        ),
        ("go to the hall", [{"frame": "MOTION", "goal": "passage"}]),
    ],
)
def test_general_english_names(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "priya") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("go to the bathroom", [{"frame": "MOTION", "goal": "wet_room"}]),
        ("go to the loo", [{"frame": "MOTION", "goal": "toilet"}]),
        ("help me to the loo please", [{"frame": "ACCOMPANYING", "theme": "me", "goal": "toilet"}]),
        (
            "fetch me the hand cream from the bathroom",
            [{"frame": "BRINGING", "theme": "hand_cream", "source": "wet_room", "beneficiary": "me"}],
        ),
    ],
)
def test_a_toilet_and_a_wet_room_told_apart(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "margaret") == frames


def test_the_loo_is_the_bathroom_where_there_is_no_toilet(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "go to the loo") == [{"frame": "MOTION", "goal": "bathroom"}]


def test_no_light_in_the_toilet_is_refused(flat: Vocabulary) -> None:
    result = understand("turn on the light in the loo", flat, speaker="margaret")
    assert not result.accepted
    assert "light" in result.reason


@pytest.mark.parametrize(
    ("text", "state"),
    [("lamp on in the den", "on"), ("lamp of den, switch off", "off"), ("turn on the lamp in the den", "on")],
)
def test_a_room_in_a_device_name_is_whole_words(flat: Vocabulary, text: str, state: str) -> None:
    assert frames_read(flat, text, "josh") == [
        {"frame": "OPERATING", "device": "den_reading_lamp", "state": state}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("can i have an ice lolly", [{"frame": "BRINGING", "theme": "ice_lollies", "beneficiary": "me"}]),
        (
            "robot, open curtain of bedroom",
            [{"frame": "OPERATING", "device": "bedroom_curtains", "state": "open"}],
        ),
        (
            "put the biscuits on the shelf in the pantry",
            [{"frame": "PLACING", "theme": "biscuits", "goal": "pantry_shelves"}],
        ),
        ("go to the armchair", [{"frame": "MOTION", "goal": "armchair"}]),
    ],
)
def test_singulars_and_last_words(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "priya") == frames


def test_the_chair_is_asked_about(flat: Vocabulary) -> None:
    assert_asked(flat, "go to the chair", "chair", "priya")


@pytest.mark.parametrize(
    "text",
    ["an of soda a a a a", "curtain a the of", "shelf shelf the a", "a the chair"],
)
def test_word_salad_stays_refused(flat: Vocabulary, vocabulary: Vocabulary, text: str) -> None:
    for world in (flat, vocabulary):
        assert not understand(text, world, speaker="priya").accepted


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "bring me the crossword next to the magnifying glass",
            [{"frame": "BRINGING", "theme": "crossword", "beneficiary": "me"}],
        ),
        ("find the address book by the phone", [{"frame": "SEARCHING", "theme": "address_book"}]),
        (
            "bring me the remote next to the armchair",
            [{"frame": "BRINGING", "theme": "tv_remote", "source": "armchair", "beneficiary": "me"}],
        ),
    ],
)
def test_an_object_as_a_landmark_says_no_place(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "margaret") == frames


def test_an_object_as_where_a_thing_goes_is_still_no_place(flat: Vocabulary) -> None:
    result = understand("put the crossword next to the magnifying glass", flat, speaker="margaret")
    assert not result.accepted


@pytest.mark.parametrize(
    ("world", "text", "device", "state"),
    [
        (GARDEN_FLAT, "dim the lights in the lounge to 30 percent", "standard_lamp", "30"),
        (GARDEN_FLAT, "set the lights in the sitting room to half", "standard_lamp", "50"),
        (TOWNHOUSE, "dim the lights in the living room to 40", "floor_lamp", "40"),
    ],
)
def test_a_rooms_lights_at_a_level_are_its_dimmer(world: str, text: str, device: str, state: str) -> None:
    speaker = "margaret" if world == GARDEN_FLAT else "nadia"
    assert frames_read(world_of(world), text, speaker) == [
        {"frame": "OPERATING", "device": device, "state": state}
    ]


@pytest.mark.parametrize(
    "text", ["dim the lights in the bedroom to 30 percent", "set the ceiling light in the lounge to 40"]
)
def test_lights_without_a_dimmer_at_a_level_still_refused(flat: Vocabulary, text: str) -> None:
    result = understand(text, flat, speaker="margaret")
    assert not result.accepted
    assert "on or off" in result.reason


def test_the_front_door_is_where_the_doorbell_is(flat: Vocabulary) -> None:
    from worlds.loader import load_world

    assert load_world(GARDEN_FLAT).entrances() == ["porch"]
    assert frames_read(flat, "go to the front door", "margaret") == [{"frame": "MOTION", "goal": "porch"}]


@pytest.mark.parametrize(
    ("text", "word"), [("go upstairs", "upstairs"), ("go downstairs please", "downstairs")]
)
def test_another_floor_is_refused_naming_it(flat: Vocabulary, text: str, word: str) -> None:
    result = understand(text, flat, speaker="margaret")
    assert not result.accepted
    assert word in result.reason


def test_a_place_gone_to_passes_devices_operated_there(flat: Vocabulary) -> None:
    assert frames_read(
        flat, "go to the den, switch on the reading lamp there, and bring arthur his atlas", "priya"
    ) == [
        {"frame": "MOTION", "goal": "den"},
        {"frame": "OPERATING", "device": "den_reading_lamp", "state": "on"},
        {"frame": "BRINGING", "theme": "atlas", "source": "den", "beneficiary": "arthur"},
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "it's ever so dark in the pantry",
            [{"frame": "OPERATING", "device": "pantry_light", "state": "on"}],
        ),
        (
            "it's pitch dark in the kitchen",
            [{"frame": "OPERATING", "device": "kitchen_light", "state": "on"}],
        ),
        (
            "I don't suppose there's any chance of a biscuit",
            [{"frame": "BRINGING", "theme": "biscuits", "beneficiary": "me"}],
        ),
        ("i fancy a biscuit", [{"frame": "BRINGING", "theme": "biscuits", "beneficiary": "me"}]),
        (
            "I've been sat here all afternoon and I've no idea where the tv remote has got to",
            [{"frame": "SEARCHING", "theme": "tv_remote"}],
        ),
    ],
)
def test_an_older_speakers_indirect_english(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "margaret") == frames


@pytest.mark.parametrize("text", ["any chance of of a a", "no idea where a the of", "i fancy the a of"])
def test_indirect_openings_alone_stay_refused(flat: Vocabulary, text: str) -> None:
    assert not understand(text, flat, speaker="margaret").accepted


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("take for me the slippers", [{"frame": "BRINGING", "theme": "slippers", "beneficiary": "me"}]),
        ("pick up the slippers for me", [{"frame": "TAKING", "theme": "slippers"}]),
        ("i need that you search the walking stick", [{"frame": "SEARCHING", "theme": "walking_stick"}]),
    ],
)
def test_learners_word_order(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "priya") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("fetch me my stick", [{"frame": "BRINGING", "theme": "walking_stick", "beneficiary": "me"}]),
        ("bring me the stick", [{"frame": "BRINGING", "theme": "walking_stick", "beneficiary": "me"}]),
        (
            "stick the slippers on the shoe bench",
            [{"frame": "PLACING", "theme": "slippers", "goal": "shoe_bench"}],
        ),
    ],
)
def test_a_verbs_word_after_my_ends_a_name(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "margaret") == frames


@pytest.mark.parametrize(
    ("text", "people"),
    [
        ("bring tom and nadia a water bottle", ["tom", "nadia"]),
        ("give tom and me the water bottle", ["tom", "me"]),
    ],
)
def test_people_said_together_are_each_brought_it(text: str, people: list[str]) -> None:
    assert frames_read(world_of(TOWNHOUSE), text, "nadia") == [
        {"frame": "BRINGING", "theme": "water_bottle", "beneficiary": who} for who in people
    ]


def test_things_said_together_are_still_things(flat: Vocabulary) -> None:
    assert frames_read(flat, "bring me the biscuits and the milk", "josh") == [
        {"frame": "BRINGING", "theme": "biscuits", "beneficiary": "me"},
        {"frame": "BRINGING", "theme": "milk", "beneficiary": "me"},
    ]
