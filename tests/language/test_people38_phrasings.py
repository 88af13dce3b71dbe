"""Phrasings from the people38 development set (a two-storey duplex in Lagos with a boys' quarters the reader
was never tuned on, ``tests/fixtures/language/people38/lagos_duplex.yaml``) the reader first got wrong, each
tried with sentences of its own in that house, in the family house of people24 or in the ERL apartment:

* a name that fits an item as well as devices or furniture ("light", the head of the item "torchlight", and
  the end of every light's name) is narrowed by the room said after it as a device's or a piece of
  furniture's would be: "the light in the study" is the study's light; the robot knows where furniture and
  devices are, not where things lie (``knic.language.places``);
* Nigerian Pidgin said plainly: "am" for "it", "wetin" for "what", "dey" for "is" ("where my sunglasses
  dey?"), "make you" for "please", "for" as the preposition of place after a verb of putting or after "it"
  carried ("put the umbrella for the shoe rack", "bring am for study"), "give" and "come" as "to" after a
  thing carried ("carry the football from the bench give Tobi", "bring the car keys come the compound"), "go
  the X"; the particles "oya", "o", "sha", "jare", "abi", "ehen" and Yoruba "e jo", "omo mi" dropped; "small"
  said last after a device is "a bit"; "on it" and "off it" opening a stretch switch it ("is the security
  light off? please on it"), and "help me on the fan" names the fan the home lacks (``knic.language.pidgin``);
* Nigerian English "light" for the mains power, bare after taking or bringing it or opening a remark ("NEPA
  has taken light again", "light don go"): no device to ask about (``knic.language.pidgin``);
* a two-word room's initials name it ("the BQ", the boys' quarters; "the LR"), unless they spell a word
  (``knic.language.shortnames``);
* an interruption set off by two dashes where the sentence broke off, or that exclaims or asks ("bring me
  the — Tobi, leave that thing! — the palm oil"), or that calls someone by name ("— Tobi, stop jumping on the
  sofa —"), is dropped, with dashes typed as "--" too; so is a stretch between commas that calls someone or
  waits, cutting into a sentence broken off after an article ("put the mug on the, Jack stop it, on the
  dining table"); a description or a correction between dashes
  is kept (``knic.language.asides``);
* a title before a person's name ("Mama Adunni's room", "Oga Olumide", "my sister Funmilayo", "Aunty
  Tracy") is dropped; "Ese, have you seen it?" before a request is said to Ese (but "Jack, have you seen the
  remote? ... find it" names what "it" is); "Jack said the hallway light should be off" passes the request
  on; "why is the X still off?"
  before "put it on" is a complaint, as "the X is still off" is; "there" after "what is inside the deep
  freezer?" or after a place said alone ("the closet, is the tablet there?") is that place
  (``knic.language.asides``);
* "off the kitchen light and the store light, on the security light": "on" or "off" straight after a
  device, where a state was said before it, is the verb again with that state (``knic.language.learners``);
* office and pulpit English said plainly: "revert with" and "loop me in on" are "tell me", "FYI" is
  dropped; a thing that "should be" or "must be" on a place is to be put there, and "please see to it" asks
  nothing more; a purpose said formally ("that the light may enter") is dropped; "let there be light" turns
  the light on; the name a request is made in ("in Jesus name") is dropped (``knic.language.registers``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

HOUSE = "tests/fixtures/language/people38/lagos_duplex.yaml"
FAMILY = "tests/fixtures/language/people24/family_house.yaml"


@lru_cache(maxsize=2)
def _world(file: str) -> Vocabulary:
    return world_of(file)


@pytest.fixture(scope="module")
def house() -> Vocabulary:
    """The Lagos duplex's vocabulary."""
    return _world(HOUSE)


@pytest.fixture(scope="module")
def family() -> Vocabulary:
    """The family house's vocabulary (people24)."""
    return _world(FAMILY)


@pytest.mark.parametrize(
    ("text", "device"),
    [
        ("Turn on the light in the study", "study_light"),
        ("switch the light in the store off", "store_light"),
        ("Put on the light in my room o", "adunni_room_light"),
        ("could you turn off the light in the boys' quarters", "bq_light"),
    ],
)
def test_a_light_narrowed_by_its_room_beside_an_item_called_a_light(
    house: Vocabulary, text: str, device: str
) -> None:
    frames = frames_read(house, text, "adunni")
    assert [(f["frame"], f["device"]) for f in frames] == [("OPERATING", device)]


def test_the_item_is_still_brought_by_its_own_name(house: Vocabulary) -> None:
    assert frames_read(house, "bring me the torchlight", "musa") == [
        {"frame": "BRINGING", "theme": "torchlight", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Make you carry the umbrella go give Oga Olumide",
            [{"frame": "BRINGING", "theme": "umbrella", "beneficiary": "olumide"}],
        ),
        (
            "Carry the football from the bench give Tobi",
            [{"frame": "BRINGING", "theme": "football", "source": "bench", "beneficiary": "tobi"}],
        ),
        (
            "Bring the car keys from the shoe rack come the compound",
            [{"frame": "BRINGING", "theme": "car_keys", "source": "shoe_rack", "goal": "compound"}],
        ),
        (
            "Put the umbrella for the shoe rack",
            [{"frame": "PLACING", "theme": "umbrella", "goal": "shoe_rack"}],
        ),
        ("Where my sunglasses dey?", [{"frame": "SEARCHING", "theme": "sunglasses"}]),
        (
            "oya carry the bucket go the compound",
            [{"frame": "BRINGING", "theme": "bucket", "goal": "compound"}],
        ),
        (
            "Carry the suitcase from the guest room put am for the car",
            [
                {"frame": "TAKING", "theme": "suitcase", "source": "guest_room"},
                {"frame": "PLACING", "theme": "suitcase", "goal": "car"},
            ],
        ),
        (
            "Go the car, carry the umbrella, bring am for study",
            [
                {"frame": "MOTION", "goal": "car"},
                {"frame": "TAKING", "theme": "umbrella", "source": "car"},
                {"frame": "BRINGING", "theme": "umbrella", "source": "car", "goal": "study"},
            ],
        ),
        (
            "Omo mi, e jo, bring my walking stick o",
            [{"frame": "BRINGING", "theme": "walking_stick", "beneficiary": "me"}],
        ),
    ],
)
def test_nigerian_pidgin(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "musa") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("make you bring the mug come", [{"frame": "BRINGING", "theme": "mug", "beneficiary": "me"}]),
        ("carry the apple give Tracy", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "tracy"}]),
        (
            "abeg carry the candle, put am for the side table",
            [
                {"frame": "TAKING", "theme": "candle"},
                {"frame": "PLACING", "theme": "candle", "goal": "side_table"},
            ],
        ),
        # English "for" and "give" stay: who a thing is for, and giving as a verb of its own
        (
            "put the candle on the side table for annie",
            [{"frame": "PLACING", "theme": "candle", "goal": "side_table"}],
        ),
        (
            "take the apple and give it to tracy",
            [
                {"frame": "TAKING", "theme": "apple"},
                {"frame": "BRINGING", "theme": "apple", "beneficiary": "tracy"},
            ],
        ),
    ],
)
def test_nigerian_pidgin_in_the_erl_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text, "tracy") == frames


def test_small_said_last_asks_how_far(vocabulary: Vocabulary) -> None:
    assert_asked(vocabulary, "open the bedroom blinds small", "how far", "tracy")
    assert not understand("wetin dey inside the closet sha", vocabulary, speaker="tracy").accepted


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Robbie, bring me the — Tobi, leave that thing! — the palm oil from the store",
            [{"frame": "BRINGING", "theme": "palm_oil", "source": "store", "beneficiary": "me"}],
        ),
        (
            "Take the towel from the bathtub to the — Tobi, drop it! — to the children's room",
            [{"frame": "BRINGING", "theme": "towel", "source": "bathtub", "goal": "children_room"}],
        ),
        (
            "Put Tobi's school bag on the shoe rack — Tobi, wear your shoes! — by the door",
            [{"frame": "PLACING", "theme": "school_bag", "goal": "shoe_rack"}],
        ),
        (
            "Put the plastic cup in the — sorry, the enamel cup — in the sink",
            [{"frame": "PLACING", "theme": "enamel_cup", "goal": "sink"}],
        ),
        (
            "put the radio on the - hello? can you hear me? - on the side table",
            [{"frame": "PLACING", "theme": "radio", "goal": "side_table"}],
        ),
    ],
)
def test_an_interruption_between_dashes(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "funmilayo") == frames


def test_an_interruption_between_dashes_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me the — Jack, stop that! — the remote") == [
        {"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}
    ]
    # a description between dashes is kept: it says which
    assert frames_read(vocabulary, "bring me the juice — the one on the kitchen table — please") == [
        {"frame": "BRINGING", "theme": "juice", "source": "kitchen_table", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Turn off the light in Mama Adunni's room",
            [{"frame": "OPERATING", "device": "adunni_room_light", "state": "off"}],
        ),
        (
            "Find my sister Funmilayo and bring her the headtie from the dressing table",
            [
                {"frame": "SEARCHING", "theme": "funmilayo"},
                {
                    "frame": "BRINGING",
                    "theme": "headtie",
                    "source": "dressing_table",
                    "beneficiary": "funmilayo",
                },
            ],
        ),
        ("Pastor Ikenna, where is he?", [{"frame": "SEARCHING", "theme": "ikenna"}]),
        (
            "Where is my headtie? Ese, have you seen it? Robbie, find it",
            [{"frame": "SEARCHING", "theme": "headtie"}],
        ),
        (
            "Ah ah, why is the security light still off? Put it on jare",
            [{"frame": "OPERATING", "device": "security_light", "state": "on"}],
        ),
    ],
)
def test_titles_and_words_to_others(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "ikenna") == frames


def test_titles_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "take the apple to Aunty Tracy") == [
        {"frame": "BRINGING", "theme": "apple", "beneficiary": "tracy"}
    ]
    assert frames_read(vocabulary, "why are the bedroom blinds still open? close them", "tracy") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}
    ]


def test_a_state_straight_after_a_device_is_the_verb_again(house: Vocabulary, vocabulary: Vocabulary) -> None:
    assert frames_read(house, "Off the kitchen light and the store light, on the security light", "musa") == [
        {"frame": "OPERATING", "device": "kitchen_light", "state": "off"},
        {"frame": "OPERATING", "device": "store_light", "state": "off"},
        {"frame": "OPERATING", "device": "security_light", "state": "on"},
    ]
    assert frames_read(vocabulary, "switch off the hallway light, on the bedroom left light") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "off"},
        {"frame": "OPERATING", "device": "bedroom_left_light", "state": "on"},
    ]
    # a state said after each device stays each one's
    assert frames_read(vocabulary, "switch the hallway light on, the bedroom left light off") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"},
        {"frame": "OPERATING", "device": "bedroom_left_light", "state": "off"},
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Kindly revert with the location of my car keys", [{"frame": "SEARCHING", "theme": "car_keys"}]),
        (
            "Per my earlier instruction, the calculator should be on the study desk, please see to it",
            [{"frame": "PLACING", "theme": "calculator", "goal": "study_desk"}],
        ),
        (
            "Let there be light in the children's room!",
            [{"frame": "OPERATING", "device": "children_room_light", "state": "on"}],
        ),
        (
            "Open the study blind to seventy-five percent, that the light may enter",
            [{"frame": "OPERATING", "device": "study_blind", "state": "75"}],
        ),
    ],
)
def test_office_and_pulpit_english(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "olumide") == frames


def test_office_and_pulpit_english_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "please revert with the location of the tablet") == [
        {"frame": "SEARCHING", "theme": "tablet"}
    ]
    assert frames_read(vocabulary, "the candle must be on the dining table") == [
        {"frame": "PLACING", "theme": "candle", "goal": "dining_table"}
    ]
    assert frames_read(vocabulary, "the hallway light should be on") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"}
    ]
    assert frames_read(vocabulary, "let there be light in the hallway") == [
        {"frame": "OPERATING", "device": "hallway_light", "state": "on"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Bring the umbrella give me", [{"frame": "BRINGING", "theme": "umbrella", "beneficiary": "me"}]),
        (
            "Close the parlour curtains — Tobi, stop jumping on the sofa — halfway",
            [{"frame": "OPERATING", "device": "parlour_curtains", "state": "50"}],
        ),
        (
            "Robbie, the palm oil, bring it — hello? yes, I'm here — bring it to the kitchen",
            [{"frame": "BRINGING", "theme": "palm_oil", "goal": "kitchen"}],
        ),
        (
            "FYI the study light is on, switch it off",
            [{"frame": "OPERATING", "device": "study_light", "state": "off"}],
        ),
        ("Please loop me in on where Musa is", [{"frame": "SEARCHING", "theme": "musa"}]),
        (
            "Can you revert on the whereabouts of my sunglasses",
            [{"frame": "SEARCHING", "theme": "sunglasses"}],
        ),
    ],
)
def test_the_voices_beyond_the_set(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "funmilayo") == frames


def test_there_is_the_place_asked_about_before(house: Vocabulary, vocabulary: Vocabulary) -> None:
    assert frames_read(
        house, "Wetin dey inside the deep freezer? Check if the chicken dey there", "musa"
    ) == [{"frame": "SEARCHING", "theme": "chicken", "ground": "deep_freezer"}]
    assert frames_read(vocabulary, "what is on the kitchen table? is the apple there?") == [
        {"frame": "SEARCHING", "theme": "apple", "ground": "kitchen_table"}
    ]
    assert frames_read(vocabulary, "the closet, is the tablet there?") == [
        {"frame": "SEARCHING", "theme": "tablet", "ground": "closet"}
    ]


def test_on_it_and_help_me_on(house: Vocabulary) -> None:
    assert frames_read(house, "Is the security light off? Please on it", "ese") == [
        {"frame": "OPERATING", "device": "security_light", "state": "on"}
    ]
    result = understand("Abeg help me on the fan", house, speaker="ese")
    assert not result.accepted and "fan" in result.reason


def test_a_room_called_by_its_initials(house: Vocabulary, family: Vocabulary) -> None:
    assert frames_read(house, "Please go and bring the bucket from the BQ", "ese") == [
        {"frame": "BRINGING", "theme": "bucket", "source": "boys_quarters", "beneficiary": "me"}
    ]
    assert frames_read(house, "switch off the BQ light", "ese") == [
        {"frame": "OPERATING", "device": "bq_light", "state": "off"}
    ]
    assert frames_read(family, "take the newspaper to the LR", "mark") == [
        {"frame": "BRINGING", "theme": "newspaper", "goal": "living_room"}
    ]


def test_light_for_the_mains_power(house: Vocabulary, vocabulary: Vocabulary) -> None:
    result = understand("Ah, NEPA has taken light again", house, speaker="funmilayo")
    assert not result.accepted and not result.question and "action" in result.reason
    assert frames_read(house, "light has gone, bring the torchlight", "musa") == [
        {"frame": "BRINGING", "theme": "torchlight", "beneficiary": "me"}
    ]
    result = understand("there is no light since morning", vocabulary, speaker="annie")
    assert not result.accepted and not result.question
    # a light said with its article is still a device
    assert_asked(vocabulary, "turn on the light", "light")


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "bring me the -- Jack, stop that! -- the remote",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
        (
            "put the mug on the, Jack stop it, on the dining table",
            [{"frame": "PLACING", "theme": "mug", "goal": "dining_table"}],
        ),
        (
            "bring me the, hold on, the remote",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
    ],
)
def test_a_sentence_cut_into_in_the_erl_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_sentence_cut_into_twice(house: Vocabulary) -> None:
    assert frames_read(
        house, "Switch on the, wait, Tobi come here, switch on the chandelier", "funmilayo"
    ) == [{"frame": "OPERATING", "device": "chandelier", "state": "on"}]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Jack said the light in the hallway should be off",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}],
        ),
        (
            "Jack, have you seen the remote? Robot, find it please",
            [{"frame": "SEARCHING", "theme": "remote"}],
        ),
        (
            "Brethren, I decree that the hallway light be switched off in Jesus name",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}],
        ),
        (
            "in the name of Jesus, bring me the water",
            [{"frame": "BRINGING", "theme": "water", "beneficiary": "me"}],
        ),
    ],
)
def test_words_passed_on_and_said_in_a_name(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text, "tracy") == frames
