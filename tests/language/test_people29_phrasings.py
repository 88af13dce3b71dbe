"""Phrasings from the people29 development set (a ground-floor flat adapted for a wheelchair user the reader
was never tuned on, ``tests/fixtures/language/people29/adapted_flat.yaml``) the reader first got wrong, each
tried in the ERL apartment as well, with sentences of the test's own:

* Trinidadian spellings that always stand for one plain word: "de" (the), "meh" (my), "dis", "dat", "doh"
  (don't), "leh" (let); "cardy" and "cardie" are a cardigan (``commands.yaml``, ``synonyms.yaml``);
* questions said in another order, put back (``knic.language.plainorder``): a thing said first and then asked
  about as "it" or "she" ("our Ellis, is she at the dining table?"); a statement asked with a question mark,
  said last ("the charger of the wheelchair is on the charging point?"); "X where? Y?" (British Sign
  Language order); a learner's "where she is"; Caribbean "it have" and "ent it have" (is there);
* a stammer's starts of a word written before it ("I-is", "c-c-can", "sw-sw-switch") are the word
  (``knic.language.tidy``);
* in an open-plan room ("kitchen living room"), "the light in the kitchen" and "the blinds in the living
  room" are the devices named so, not every light or blind of the room; a thing said by a piece of
  furniture whose own name is "<its noun>side" is that one ("the lamp by the bed": the bedside lamp)
  (``knic.language.placenames``);
* Caribbean "by" for where to after "carry", "take" or "bring" with no one and nowhere else said ("carry
  de bible by Kieran") (``knic.language.dialects``);
* "'s" before a past participle is "has" ("our Theo's cut his knee": a reason, no thing of Theo's), and
  "our" before a capitalised name is the name (``knic.language.plainorder``); "leg it" runs, "I have need
  of" wants (``commands.yaml``);
* British Sign Language order typed in English, the topic first and the verb last with no prepositions
  ("Ice pack — freezer take — Ottavio give", "Cushion, sofa take, garden bench put", "Sofa — go there",
  "Headphones Theo — sofa. Theo give"): the prepositions each verb asks for put in, and a long dash sets a
  stretch apart as " - " does (``knic.language.signorder``, ``knic.language.tidy``); where a thing is said
  as "recliner there" or "desk her", and "Fridge — milk there? Check"; a verb before a place with no
  preposition ("toolbox bring kitchen"); furniture said before its room ("cabinet wet room"); a two-word
  name with its describing word last ("mug spotty"); a thing said first and then "take Kieran" (taken to
  him) (``knic.language.signorder``);
* a plural said alone after going to a room ("..., then go to the bedroom and close the blinds") is that
  room's, as a singular already was; said with no room it still asks which (``knic.language.places``);
* "be" left out ("dis chair giving me trouble", "I hungry", "Wanjiru in she room?"), a meal said as what a
  thing is for ("for meh tea"), Caribbean "nah" urging a request and "she" after a preposition (her),
  "dey on de profiling bed" (they're), "umbrella bring me", "me go wet room. towel where?", "Tracy —
  kitchen? Check", "close dem" (``knic.language.plainorder``,
  ``knic.language.signorder``, ``knic.language.dialects``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

FLAT = "tests/fixtures/language/people29/adapted_flat.yaml"


@lru_cache(maxsize=1)
def _flat() -> Vocabulary:
    return world_of(FLAT)


def _said(vocabulary: Vocabulary, world: str, text: str, speaker: str) -> list[dict[str, str]]:
    """The frames of ``text`` said by ``speaker`` in the flat, or by annie in the ERL apartment."""
    return frames_read(_flat(), text, speaker) if world == "flat" else frames_read(vocabulary, text)


@pytest.fixture(scope="module")
def flat() -> Vocabulary:
    """The adapted flat's vocabulary."""
    return _flat()


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Pass me meh glasses from de bedside table",
            [{"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "me"}],
        ),
        (
            "Doh turn on de hallway light, close de bedroom blinds",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
        ("Leh me see, where is dat remote?", [{"frame": "SEARCHING", "theme": "remote"}]),
    ],
)
def test_trinidadian_spellings(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


def test_trinidadian_spellings_in_the_flat(flat: Vocabulary) -> None:
    assert frames_read(flat, "Open de blinds in de bedroom leh me see de sun", "merline") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "open"}
    ]
    assert frames_read(flat, "Take the cardie to Merline", "kieran") == [
        {"frame": "BRINGING", "theme": "cardigan", "beneficiary": "merline"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "the remote, is it on the coffee table?",
            [{"frame": "SEARCHING", "theme": "remote", "ground": "coffee_table"}],
        ),
        ("Tracy, is she in the bedroom?", [{"frame": "SEARCHING", "theme": "tracy", "ground": "bedroom"}]),
        ("Tracy is in the kitchen?", [{"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}]),
        ("Tracy where? Bedroom?", [{"frame": "SEARCHING", "theme": "tracy", "ground": "bedroom"}]),
        ("Annie, where she is now?", [{"frame": "SEARCHING", "theme": "annie"}]),
        (
            "ent it have juice in the kitchen?",
            [{"frame": "SEARCHING", "theme": "juice", "ground": "kitchen"}],
        ),
        (
            "it have a mug on the dining table?",
            [{"frame": "SEARCHING", "theme": "mug", "ground": "dining_table"}],
        ),
        (
            "the cup is on the kitchen table? bring it to me",
            [{"frame": "BRINGING", "theme": "cup", "source": "kitchen_table", "beneficiary": "me"}],
        ),
    ],
)
def test_questions_said_in_another_order(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Wanjiru where? Storage room?",
            [{"frame": "SEARCHING", "theme": "wanjiru", "ground": "storage_room"}],
        ),
        (
            "The hoist sling is on the profiling bed?",
            [{"frame": "SEARCHING", "theme": "hoist_sling", "ground": "profiling_bed"}],
        ),
        (
            "Ey, the hoist remote, is it on the bedside cabinet?",
            [{"frame": "SEARCHING", "theme": "hoist_remote", "ground": "bedside_cabinet"}],
        ),
        (
            "It have milk in the fridge?",
            [{"frame": "SEARCHING", "theme": "milk", "ground": "fridge_freezer"}],
        ),
    ],
)
def test_questions_said_in_another_order_in_the_flat(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "ellis") == frames


def test_a_question_inside_another_keeps_its_order(vocabulary: Vocabulary) -> None:
    result = understand("do you know where she is", vocabulary)
    assert not result.accepted  # "she" names nobody: not read as "where is she" on its own


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "erl",
            "I-is the c-cup on the k-kitchen table?",
            [{"frame": "SEARCHING", "theme": "cup", "ground": "kitchen_table"}],
        ),
        (
            "erl",
            "B-b-bring me the the remote",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
        (
            "erl",
            "Sw-sw-switch off the hallway light",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}],
        ),
        (
            "flat",
            "T-t-turn the bedside lamp to th-thirty",
            [{"frame": "OPERATING", "device": "bedside_lamp", "state": "30"}],
        ),
    ],
)
def test_a_stammer(vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _said(vocabulary, world, text, "theo") == frames


def test_a_hyphened_word_is_no_stammer(vocabulary: Vocabulary) -> None:
    result = understand("bring me the x-ray", vocabulary)
    assert not result.accepted and "x ray" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Out de light in de kitchen", [{"frame": "OPERATING", "device": "kitchen_light", "state": "off"}]),
        (
            "Put the blinds down in the living room",
            [{"frame": "OPERATING", "device": "living_room_blinds", "state": "0"}],
        ),
        (
            "close the blind in the living room",
            [{"frame": "OPERATING", "device": "living_room_blinds", "state": "0"}],
        ),
        (
            "turn off the lights in the kitchen",
            [
                {"frame": "OPERATING", "device": "kitchen_light", "state": "off"},
                {"frame": "OPERATING", "device": "under_cabinet_lights", "state": "off"},
            ],
        ),
    ],
)
def test_a_part_of_an_open_plan_room(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    got = frames_read(flat, text, "kieran")
    assert [{**f, "state": {"closed": "0"}.get(f["state"], f["state"])} for f in got] == frames


def test_the_lights_of_a_room_said_whole_are_all_of_them(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "turn off the lights in the bedroom") == [
        {"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}
    ]


@pytest.mark.parametrize(
    "text", ["Turn on de lamp by de bed", "Turn on the lamp of the bed", "switch on the lamp next to the bed"]
)
def test_a_lamp_by_the_bed_is_the_bedside_lamp(flat: Vocabulary, text: str) -> None:
    assert frames_read(flat, text, "merline") == [
        {"frame": "OPERATING", "device": "bedside_lamp", "state": "on"}
    ]


def test_a_table_next_to_the_bed(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me the glasses from the table next to the bed") == [
        {"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Carry dis spotty mug by de sink",
            [{"frame": "BRINGING", "theme": "spotty_mug", "goal": "sink"}],
        ),
        (
            "flat",
            "Carry de bible by Kieran",
            [{"frame": "BRINGING", "theme": "bible", "beneficiary": "kieran"}],
        ),
        (
            "erl",
            "bring the apple and the cup by the sofa",
            [
                {"frame": "BRINGING", "theme": "apple", "goal": "sofa"},
                {"frame": "BRINGING", "theme": "cup", "goal": "sofa"},
            ],
        ),
        ("erl", "carry the mug by Tracy", [{"frame": "BRINGING", "theme": "mug", "beneficiary": "tracy"}]),
        (
            "erl",
            "take the cup by the sofa to the kitchen",
            [{"frame": "BRINGING", "theme": "cup", "source": "sofa", "goal": "kitchen"}],
        ),
        (
            "erl",
            "bring me the cup by the sofa",
            [{"frame": "BRINGING", "theme": "cup", "source": "sofa", "beneficiary": "me"}],
        ),
    ],
)
def test_carried_by_a_place_or_a_person(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _said(vocabulary, world, text, "merline") == frames


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Bring the plasters from the wet room, our Theo's cut his knee",
            [{"frame": "BRINGING", "theme": "plasters", "source": "wet_room", "beneficiary": "me"}],
        ),
        ("erl", "take the cup to our Tracy", [{"frame": "BRINGING", "theme": "cup", "beneficiary": "tracy"}]),
        (
            "erl",
            "bring me the juice, the milk's gone off",
            [{"frame": "BRINGING", "theme": "juice", "beneficiary": "me"}],
        ),
        ("erl", "bring me tracy's cup", [{"frame": "BRINGING", "theme": "cup", "beneficiary": "me"}]),
        ("flat", "Leg it to the bistro table and wait there", [{"frame": "MOTION", "goal": "bistro_table"}]),
        ("erl", "leg it over to the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    ],
)
def test_family_and_what_has_happened(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _said(vocabulary, world, text, "kieran") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Cup, kitchen table take, bedside table put",
            [
                {"frame": "TAKING", "theme": "cup", "source": "kitchen_table"},
                {"frame": "PLACING", "theme": "cup", "goal": "bedside_table"},
            ],
        ),
        ("Kitchen — go there", [{"frame": "MOTION", "goal": "kitchen"}]),
        ("Bedroom — go, wait", [{"frame": "MOTION", "goal": "bedroom"}]),
        (
            "Remote — sofa — Tracy give",
            [{"frame": "BRINGING", "theme": "remote", "source": "sofa", "beneficiary": "tracy"}],
        ),
        (
            "Glasses Annie — bedside table. Annie give",
            [{"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "annie"}],
        ),
        (
            "go to the kitchen, take the cup and put it on the sofa",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "TAKING", "theme": "cup", "source": "kitchen"},
                {"frame": "PLACING", "theme": "cup", "goal": "sofa"},
            ],
        ),
    ],
)
def test_sign_language_order(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Ice pack — freezer take — Ottavio give",
            [
                {"frame": "TAKING", "theme": "ice_pack", "source": "fridge_freezer"},
                {
                    "frame": "BRINGING",
                    "theme": "ice_pack",
                    "source": "fridge_freezer",
                    "beneficiary": "ottavio",
                },
            ],
        ),
        (
            "Courtyard light on, courtyard go, wait",
            [
                {"frame": "OPERATING", "device": "courtyard_light", "state": "on"},
                {"frame": "MOTION", "goal": "courtyard"},
            ],
        ),
        (
            "Watering can — planter — put back",
            [{"frame": "PLACING", "theme": "watering_can", "goal": "raised_planter"}],
        ),
        (
            "Headphones Theo — sofa. Theo give",
            [{"frame": "BRINGING", "theme": "headphones", "source": "sofa", "beneficiary": "theo"}],
        ),
    ],
)
def test_sign_language_order_in_the_flat(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "ellis") == frames


def test_a_plural_said_alone_after_going_to_a_room_is_that_rooms(flat: Vocabulary) -> None:
    assert frames_read(
        flat, "Turn off the kitchen light, then go to the bedroom and close the blinds", "wanjiru"
    ) == [
        {"frame": "OPERATING", "device": "kitchen_light", "state": "off"},
        {"frame": "MOTION", "goal": "main_bedroom"},
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"},
    ]
    assert "all of them" in understand("close the blinds", flat, speaker="wanjiru").question


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Tracy in her room?", [{"frame": "SEARCHING", "theme": "tracy", "ground": "bedroom"}]),
        ("bring the cup for my tea", [{"frame": "BRINGING", "theme": "cup", "beneficiary": "me"}]),
        ("bring me the apple, I hungry", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
        ("pass me de remote nah", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]),
        ("bring me the mug, nah, the cup", [{"frame": "BRINGING", "theme": "cup", "beneficiary": "me"}]),
    ],
)
def test_be_left_out_and_what_is_said_around(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_remark_with_be_left_out_is_no_request(vocabulary: Vocabulary) -> None:
    result = understand("Steups, dis remote giving me trouble whole day", vocabulary)
    assert not result.accepted and "no request" in result.reason


def test_be_left_out_in_the_flat(flat: Vocabulary) -> None:
    assert frames_read(flat, "Wanjiru in she room?", "merline") == [
        {"frame": "SEARCHING", "theme": "wanjiru", "ground": "wanjiru_room"}
    ]
    result = understand("Bring me a roti nah, I hungry", flat, speaker="merline")
    assert not result.accepted and "roti" in result.reason
    assert "mug" in understand("Bring meh mug for meh tea", flat, speaker="merline").question


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Glasses — bedside table there. Bring me",
            [{"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "me"}],
        ),
        (
            "Remote Tracy — sofa her. Bring me",
            [{"frame": "BRINGING", "theme": "remote", "source": "sofa", "beneficiary": "me"}],
        ),
        ("Kitchen — juice there? Check", [{"frame": "SEARCHING", "theme": "juice", "ground": "kitchen"}]),
    ],
)
def test_where_a_thing_is_in_sign_language_order(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_where_a_thing_is_in_sign_language_order_in_the_flat(flat: Vocabulary) -> None:
    assert frames_read(flat, "Fridge — milk there? Check", "ellis") == [
        {"frame": "SEARCHING", "theme": "milk", "ground": "fridge_freezer"}
    ]
    assert frames_read(flat, "Laptop Wanjiru — desk her. Bring me", "ellis") == [
        {"frame": "BRINGING", "theme": "laptop", "source": "desk", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Apple, kitchen table — bring bedroom",
            [{"frame": "BRINGING", "theme": "apple", "source": "kitchen_table", "goal": "bedroom"}],
        ),
        ("Cup — bring kitchen", [{"frame": "BRINGING", "theme": "cup", "goal": "kitchen"}]),
        (
            "Kitchen, go. Cup bring bedroom",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "cup", "source": "kitchen", "goal": "bedroom"},
            ],
        ),
        ("Box cardboard — bin put", [{"frame": "PLACING", "theme": "cardboard_box", "goal": "bin"}]),
    ],
)
def test_a_verb_before_a_place_with_no_preposition(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_furniture_said_before_its_room_in_sign_language_order(flat: Vocabulary) -> None:
    assert frames_read(flat, "Plasters, cabinet wet room — Theo bring", "ellis") == [
        {"frame": "BRINGING", "theme": "plasters", "source": "mirror_cabinet", "beneficiary": "theo"}
    ]
    assert frames_read(flat, "Tea finish. Mug spotty — sink put", "ellis") == [
        {"frame": "PLACING", "theme": "spotty_mug", "goal": "sink"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "erl",
            "bring me my glasses, they on the bedside table",
            [{"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "me"}],
        ),
        (
            "flat",
            "Bring meh slippers, dey on de profiling bed",
            [{"frame": "BRINGING", "theme": "slippers", "source": "profiling_bed", "beneficiary": "me"}],
        ),
        (
            "flat",
            "The slippers, bring them by Merline",
            [{"frame": "BRINGING", "theme": "slippers", "beneficiary": "merline"}],
        ),
        (
            "flat",
            "Hallway, go. Umbrella bring me",
            [
                {"frame": "MOTION", "goal": "hallway"},
                {"frame": "BRINGING", "theme": "umbrella", "source": "hallway", "beneficiary": "me"},
            ],
        ),
        ("erl", "Apple bring me", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
    ],
)
def test_where_it_is_said_with_be_left_out_and_bring_me_said_last(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _said(vocabulary, world, text, "merline") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Me go bedroom. Glasses where?", [{"frame": "SEARCHING", "theme": "glasses"}]),
        ("Tracy — kitchen? Check", [{"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}]),
        ("open di blinds dem", [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "open"}]),
        ("de blinds, close dem", [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}]),
    ],
)
def test_signed_and_caribbean_shortcuts(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_person_and_a_place_said_alone_is_no_question(vocabulary: Vocabulary) -> None:
    assert not understand("Tracy, kitchen", vocabulary).accepted  # unclear without "check"


def test_what_looks_like_be_left_out_inside_a_request_stays(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "turn off the bedroom's left light") == [
        {"frame": "OPERATING", "device": "bedroom_left_light", "state": "off"}
    ]
    assert "table" in understand("bring me that mug sitting on the table", vocabulary).question


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Glasses, bedside table — take Tracy",
            [{"frame": "BRINGING", "theme": "glasses", "source": "bedside_table", "beneficiary": "tracy"}],
        ),
        ("Glasses — give Jack", [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "jack"}]),
    ],
)
def test_a_thing_said_first_then_taken_to_a_person(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_place_said_first_then_take_a_person_still_asks_where(vocabulary: Vocabulary) -> None:
    assert "which room" in understand("the kitchen, take Tracy", vocabulary).question


def test_i_have_need_of(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "I have need of the tissues") == [
        {"frame": "BRINGING", "theme": "tissues", "beneficiary": "me"}
    ]
