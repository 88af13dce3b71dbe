"""Phrasings from the people33 development set (a top-floor city apartment with a roof terrace and a smart
home the reader was never tuned on, ``tests/fixtures/language/people33/rooftop_flat.yaml``) the reader first
got wrong, each tried in the ERL apartment as well:

* radio procedure (``knic.language.procedure``): numbers said digit by digit where a level goes ("six zero
  percent", "to four five", "one zero zero"); "my location" for the speaker; "confirm location of", "report
  the location of" for where; "task one, ...", "step two: ..." as the marks of a list; a radio check asks
  for no action;
* a request said in the passive ("my laptop is to be brought to me forthwith", "the desk lamp should be
  switched off", "the letters need to be taken to the office desk"); "the same" for the thing just named
  ("... and convey the same to the terrace table"); a claim of where a thing is, then "kindly confirm" or
  "can you check?": a search there (``knic.language.procedure``);
* "Otis his dummy" (a Dutch or German speaker's possessive) is Otis's dummy, but "give Tom his keys" still
  gives; "Femke where? Otis need bath": where Femke is (``knic.language.procedure``);
* a wish to go somewhere, then "kindly accompany me", "escort me" or "walk me" takes the speaker there
  (``knic.language.ordinary``); "by one half" asks how far as "by half" does, "for the half" is half
  (``commands.yaml``), not a purpose said last (``knic.language.regional``);
* "have a butcher's for" (Cockney rhyming slang), "have a gander for", "have a squiz for" search, as "have a
  look for" does (``knic.language.regional``);
* "take me roof", a learner's "take me" before a room with "to" left out, takes the speaker there
  (``knic.language.roles``); "take me the apple" still brings it;
* a place said bare after a thing before the verb ("Calpol, bathroom cabinet, bring to Hana") is where the
  thing is, and a place said after several things ("kimchi and whole milk, from refrigerator bring ...") is
  where each of them is; a thing of several said before a verb that then names none ("milk bring me
  please") is asked about, not "bring what?" (``knic.language.reader``);
* what a tired speaker trails off from and says again (``knic.language.trailing``): a request called off
  in a sentence of its own ("... no, leave it. Turn the nursery light off."); "in here... in the nursery",
  "the lights in here... the nursery light"; "the thing... the teething ring";
* "by half", "by a third" after "close", "lower" or "open" ask how far, not read as a landmark "by" the
  world lacks (``knic.language.selecting``); a learner's setting said before the verb said last ("living
  room light little bit dark make", ``knic.language.learners``), and "little bit dark", "more bright" for
  the comparative (``commands.yaml``), ask how far too;

and, from probing the six voices beyond the set: "Out." or ", over and out" said last signs off, not the
state off; "confirm (that) X is on Y", "confirm whether Tracy is in the kitchen"; "if Otis his blanket is
..."; a wish in the passive after "if" ("if the briefcase were brought to the sofa bed"); "it" or "them"
after a request called off is what it named; "dim the nursery light... dim it to twenty"; several things
before a verb said last ("barley tea and rice cooker, kitchen island put", ``knic.language.learners``);
"pull 'em down halfway" (``commands.yaml``); "take the mop there" after carrying a thing there is where
the mop goes too, "go to the kitchen and take the mop there" still takes it from there
(``knic.language.naming``); a number said alone after "to" ("down to, like, five") is the level, not a
list's number left out (``knic.language.regional``); "one bottle of soju", "one glass of wine" name what
the home lacks, as "a glass of wine" does, not the bottle or the glass (``knic.language.clauses``); and
"soju bring me one bottle", "water, bring me one glass" said topic first (``knic.language.learners``);
where from and where to said in two stretches before a verb said last ("porridge oats from larder, on
kitchen island put", ``knic.language.wherefromto``); "I go ... later" (a learner's present for what the
speaker will do) asks for no action, as "I'm going ..." does (``knic.language.procedure``); "forthwith",
"without delay", "at your earliest convenience" say no more than now; a claim then "Confirm." of a person
("I put it to you that Tracy is in the kitchen"); "the light above the island" is the island lights, a
dimmer named after the island, not the kitchen's plain light (``knic.language.places``, ``naming``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

FLAT = "tests/fixtures/language/people33/rooftop_flat.yaml"


@lru_cache(maxsize=1)
def _flat() -> Vocabulary:
    return world_of(FLAT)


def _read(world: str, erl: Vocabulary, text: str, speaker: str) -> list[dict[str, str]]:
    """The frames ``text`` is read as in the rooftop flat (said by ``speaker``) or in the ERL apartment."""
    return frames_read(_flat(), text, speaker) if world == "flat" else frames_read(erl, text)


@pytest.mark.parametrize(
    ("world", "text", "device", "state"),
    [
        ("flat", "Roger. Set the desk lamp to six zero percent, over.", "desk_lamp", "60"),
        ("flat", "Terrace lights to four five percent, over.", "terrace_lights", "45"),
        ("flat", "Dim the nursery light to one zero, over.", "nursery_light", "10"),
        ("flat", "Dim the nursery light to one zero zero percent", "nursery_light", "100"),
        ("erl", "Set the dimmer to six zero percent, over", "living_room_dimmer", "60"),
        ("erl", "Dimmer to two five, over", "living_room_dimmer", "25"),
    ],
)
def test_digits_said_one_by_one_are_the_level(
    vocabulary: Vocabulary, world: str, text: str, device: str, state: str
) -> None:
    assert _read(world, vocabulary, text, "idris") == [
        {"frame": "OPERATING", "device": device, "state": state}
    ]


def test_a_digit_alone_or_a_count_stays_as_it_was(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "Set the dimmer to two and close the blinds")[0]["state"] == "2"
    assert frames_read(vocabulary, "Bring me two apples") == [
        {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Nova, Idris. Request you bring my headphones from the office desk to my location, over.",
            [{"frame": "BRINGING", "theme": "headphones", "source": "office_desk", "beneficiary": "me"}],
        ),
        ("flat", "Confirm location of the car keys, over.", [{"frame": "SEARCHING", "theme": "car_keys"}]),
        ("flat", "Report location of Femke, over.", [{"frame": "SEARCHING", "theme": "femke"}]),
        (
            "erl",
            "Bring the glasses to my position, over",
            [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}],
        ),
        ("erl", "Report the location of the remote", [{"frame": "SEARCHING", "theme": "remote"}]),
        (
            "erl",
            "Task one, go to the kitchen. Task two, bring me an apple. Over.",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "apple", "source": "kitchen", "beneficiary": "me"},
            ],
        ),
        (
            "flat",
            "Nova, task one, turn on the corridor light. Task two, proceed to the guest room. Over.",
            [
                {"frame": "OPERATING", "device": "corridor_light", "state": "on"},
                {"frame": "MOTION", "goal": "guest_room"},
            ],
        ),
    ],
)
def test_radio_procedure(vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(world, vocabulary, text, "idris") == frames


@pytest.mark.parametrize(
    "text", ["Radio check, how do you read?", "Do you copy?", "Radio check, Nova, how do you read, over?"]
)
def test_a_radio_check_asks_for_no_action(vocabulary: Vocabulary, text: str) -> None:
    for said, speaker in ((vocabulary, "annie"), (_flat(), "idris")):
        result = understand(text, said, speaker=speaker)
        assert not result.accepted and "action" in result.reason


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "My laptop is to be brought to me forthwith",
            [{"frame": "BRINGING", "theme": "lucian_laptop", "beneficiary": "me"}],
        ),
        (
            "flat",
            "The desk lamp should be switched off",
            [{"frame": "OPERATING", "device": "desk_lamp", "state": "off"}],
        ),
        (
            "flat",
            "The letters need to be taken to the office desk",
            [{"frame": "BRINGING", "theme": "letters", "goal": "office_desk"}],
        ),
        (
            "erl",
            "The glasses are to be brought to me",
            [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}],
        ),
        (
            "erl",
            "Take the apple from the kitchen table and convey the same to the coffee table",
            [
                {"frame": "TAKING", "theme": "apple", "source": "kitchen_table"},
                {"frame": "BRINGING", "theme": "apple", "source": "kitchen_table", "goal": "coffee_table"},
            ],
        ),
        (
            "flat",
            "I put it to you that the car keys are on the coat rack. Kindly confirm.",
            [{"frame": "SEARCHING", "theme": "car_keys", "ground": "coat_rack"}],
        ),
        (
            "erl",
            "I think the remote is on the coffee table, can you check?",
            [{"frame": "SEARCHING", "theme": "remote", "ground": "coffee_table"}],
        ),
    ],
)
def test_formal_requests(vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(world, vocabulary, text, "lucian") == frames


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        ("flat", "Where is Otis his dummy?", [{"frame": "SEARCHING", "theme": "dummy"}]),
        (
            "flat",
            "Is Otis his dummy in the cot?",
            [{"frame": "SEARCHING", "theme": "dummy", "ground": "cot"}],
        ),
        (
            "erl",
            "Is Tracy her mug in the kitchen?",
            [{"frame": "SEARCHING", "theme": "mug", "ground": "kitchen"}],
        ),
        (
            "erl",
            "Give Tracy her glasses",
            [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "tracy"}],
        ),
        ("flat", "Femke where? Otis need bath", [{"frame": "SEARCHING", "theme": "femke"}]),
        ("erl", "Tracy where? I need her", [{"frame": "SEARCHING", "theme": "tracy"}]),
    ],
)
def test_learners_possessive_and_where(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "femke") == frames


@pytest.mark.parametrize(
    ("world", "text", "goal"),
    [
        ("flat", "I wish to go up to the roof terrace; kindly accompany me", "roof_terrace"),
        ("erl", "I'd like to go to the bedroom, would you walk me there?", "bedroom"),
        ("erl", "I need to go to the kitchen, please escort me", "kitchen"),
    ],
)
def test_a_wish_to_go_then_accompany_me(vocabulary: Vocabulary, world: str, text: str, goal: str) -> None:
    assert _read(world, vocabulary, text, "lucian") == [
        {"frame": "ACCOMPANYING", "theme": "me", "goal": goal}
    ]


def test_by_one_half_asks_how_far_and_for_the_half_is_half(vocabulary: Vocabulary) -> None:
    assert_asked(_flat(), "dim the desk lamp by one half", "how far", speaker="lucian")
    assert frames_read(vocabulary, "open the blinds for half") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Open the curtains in the living room for the half",
            [{"frame": "OPERATING", "device": "living_room_curtains", "state": "50"}],
        ),
        (
            "erl",
            "close the blinds for the half",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"}],
        ),
        (
            "flat",
            "Have a butcher's for me rubber gloves, would ya?",
            [{"frame": "SEARCHING", "theme": "rubber_gloves"}],
        ),
        ("erl", "have a gander for my glasses", [{"frame": "SEARCHING", "theme": "glasses"}]),
        ("erl", "have a squiz for the remote, mate", [{"frame": "SEARCHING", "theme": "remote"}]),
        (
            "flat",
            "Take me roof, I want sun",
            [{"frame": "ACCOMPANYING", "theme": "me", "goal": "roof_terrace"}],
        ),
        ("erl", "take me kitchen please", [{"frame": "ACCOMPANYING", "theme": "me", "goal": "kitchen"}]),
        ("erl", "take me the apple", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
        (
            "flat",
            "Calpol, bathroom cabinet, bring to Hana",
            [{"frame": "BRINGING", "theme": "calpol", "source": "bathroom_cabinet", "beneficiary": "hana"}],
        ),
        (
            "flat",
            "Kimchi and whole milk, from refrigerator bring to dining table",
            [
                {"frame": "BRINGING", "theme": "kimchi", "source": "fridge", "goal": "dining_table"},
                {"frame": "BRINGING", "theme": "whole_milk", "source": "fridge", "goal": "dining_table"},
            ],
        ),
        (
            "erl",
            "the mug, the kitchen, bring it to me",
            [{"frame": "BRINGING", "theme": "mug", "source": "kitchen", "beneficiary": "me"}],
        ),
    ],
)
def test_learners_and_londoners(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "soonja") == frames


def test_a_thing_of_several_said_before_its_verb_is_asked_about(vocabulary: Vocabulary) -> None:
    assert_asked(_flat(), "Milk bring me please", "milk", speaker="soonja")
    assert frames_read(vocabulary, "apple bring me please") == [
        {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Turn the night light... no, leave it. Turn the nursery light off.",
            [{"frame": "OPERATING", "device": "nursery_light", "state": "off"}],
        ),
        (
            "erl",
            "Bring me the apple. Forget it. Bring me the lemon.",
            [{"frame": "BRINGING", "theme": "lemon", "beneficiary": "me"}],
        ),
        (
            "flat",
            "Turn the big light off in here... in the nursery",
            [{"frame": "OPERATING", "device": "nursery_light", "state": "off"}],
        ),
        (
            "flat",
            "Dim the lights in here... the nursery light, to like fifteen percent",
            [{"frame": "OPERATING", "device": "nursery_light", "state": "15"}],
        ),
        (
            "erl",
            "switch on the light out here, I mean in the corridor",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "on"}],
        ),
        (
            "flat",
            "Can you find the, the thing... the teething ring",
            [{"frame": "SEARCHING", "theme": "teething_ring"}],
        ),
        (
            "erl",
            "bring me the whatsit, the remote",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
    ],
)
def test_what_a_tired_speaker_says_again(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "hana") == frames


def test_leave_it_before_a_place_still_places(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "take the apple and leave it on the coffee table")[-1] == {
        "frame": "PLACING",
        "theme": "apple",
        "goal": "coffee_table",
    }


@pytest.mark.parametrize(
    ("world", "text"),
    [
        ("flat", "The office blind is to be lowered by one half"),
        ("flat", "close the office blind by half"),
        ("flat", "Living room light little bit dark make"),
        ("flat", "Living room light a bit dimmer make"),
        ("erl", "open the blinds by half"),
        ("erl", "make the dimmer more bright"),
    ],
)
def test_a_change_said_from_the_present_level_asks_how_far(
    vocabulary: Vocabulary, world: str, text: str
) -> None:
    said, speaker = (_flat(), "soonja") if world == "flat" else (vocabulary, "annie")
    assert_asked(said, text, "how far", speaker=speaker)


def test_a_landmark_by_a_device_is_still_left_out_when_unknown(vocabulary: Vocabulary) -> None:
    assert_asked(vocabulary, "turn on the light by the door", "which light")


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Affirm. Switch on the hallway light. Out.",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "on"}],
        ),
        (
            "erl",
            "Switch on the hall light, over and out",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "on"}],
        ),
        (
            "erl",
            "Confirm the cup is on the kitchen table, over",
            [{"frame": "SEARCHING", "theme": "cup", "ground": "kitchen_table"}],
        ),
        (
            "erl",
            "Kindly confirm whether Tracy is in the kitchen",
            [{"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}],
        ),
        (
            "flat",
            "Can you even check if Otis his blanket is in the cot?",
            [{"frame": "SEARCHING", "theme": "baby_blanket", "ground": "cot"}],
        ),
        (
            "flat",
            "I should be grateful if the briefcase were brought to the sofa bed",
            [{"frame": "BRINGING", "theme": "briefcase", "goal": "sofa_bed"}],
        ),
        (
            "erl",
            "I should be obliged if the dimmer were set to thirty per cent",
            [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "30"}],
        ),
        (
            "erl",
            "Open the blinds... no, leave it. Close them.",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
        (
            "flat",
            "Dim the nursery light... dim it to twenty",
            [{"frame": "OPERATING", "device": "nursery_light", "state": "20"}],
        ),
        (
            "flat",
            "Please, barley tea and rice cooker, kitchen island put",
            [
                {"frame": "PLACING", "theme": "barley_tea", "goal": "kitchen_island"},
                {"frame": "PLACING", "theme": "rice_cooker", "goal": "kitchen_island"},
            ],
        ),
        (
            "erl",
            "the apple and the lemon, kitchen table put",
            [
                {"frame": "PLACING", "theme": "apple", "goal": "kitchen_table"},
                {"frame": "PLACING", "theme": "lemon", "goal": "kitchen_table"},
            ],
        ),
        (
            "flat",
            "Them blinds in the office, pull 'em down halfway",
            [{"frame": "OPERATING", "device": "office_blind", "state": "50"}],
        ),
        (
            "erl",
            "the blinds, pull them down",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
    ],
)
def test_the_six_voices_beyond_the_set(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "lucian") == frames


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Bring the bucket to the kitchen, then take the mop there an' all",
            [
                {"frame": "BRINGING", "theme": "bucket", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "mop", "goal": "kitchen"},
            ],
        ),
        (
            "erl",
            "take the cup to the kitchen and carry the apple there as well",
            [
                {"frame": "BRINGING", "theme": "cup", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "apple", "goal": "kitchen"},
            ],
        ),
        (
            "flat",
            "Go to the kitchen and take the mop there",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "TAKING", "theme": "mop", "source": "kitchen"},
            ],
        ),
    ],
)
def test_take_it_there_after_carrying_something_there(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "bev") == frames


@pytest.mark.parametrize(
    ("world", "text", "state"),
    [
        ("flat", "turn the night light down, down to, like, five?", "5"),
        ("erl", "set the dimmer to, um, five", "5"),
    ],
)
def test_a_level_said_alone_after_to_is_the_level(
    vocabulary: Vocabulary, world: str, text: str, state: str
) -> None:
    assert _read(world, vocabulary, text, "hana")[0]["state"] == state


def test_a_lists_numbers_said_alone_are_still_left_out(vocabulary: Vocabulary) -> None:
    assert [f["frame"] for f in frames_read(vocabulary, "1. open the blinds. 2. bring me the cup")] == [
        "OPERATING",
        "BRINGING",
    ]


@pytest.mark.parametrize(
    ("world", "text", "word"),
    [("flat", "bring me one bottle of soju", "soju"), ("erl", "bring me one glass of wine", "wine")],
)
def test_one_container_of_a_thing_the_home_lacks_names_it(
    vocabulary: Vocabulary, world: str, text: str, word: str
) -> None:
    said, speaker = (_flat(), "soonja") if world == "flat" else (vocabulary, "annie")
    result = understand(text, said, speaker=speaker)
    assert not result.accepted and f"'{word}'" in result.reason


def test_one_glass_of_water_is_the_water(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me one glass of water") == [
        {"frame": "BRINGING", "theme": "water", "beneficiary": "me"}
    ]


def test_a_topic_said_first_with_a_count_of_its_container(vocabulary: Vocabulary) -> None:
    result = understand("Soju bring me one bottle", _flat(), speaker="soonja")
    assert not result.accepted and "'soju'" in result.reason
    assert frames_read(vocabulary, "Water, bring me one glass") == [
        {"frame": "BRINGING", "theme": "water", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, "Tracy, bring me a cup") == [
        {"frame": "BRINGING", "theme": "cup", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            "flat",
            "Porridge oats from larder, on kitchen island put",
            [{"frame": "PLACING", "theme": "porridge_oats", "source": "larder", "goal": "kitchen_island"}],
        ),
        (
            "erl",
            "apple from kitchen table, on coffee table put",
            [{"frame": "PLACING", "theme": "apple", "source": "kitchen_table", "goal": "coffee_table"}],
        ),
    ],
)
def test_where_from_and_where_to_before_a_verb_said_last(
    vocabulary: Vocabulary, world: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(world, vocabulary, text, "soonja") == frames


@pytest.mark.parametrize(
    ("world", "text"),
    [
        ("flat", "I go with Otis to the park later, I hope it stays dry"),
        ("erl", "we go to the shops after lunch"),
    ],
)
def test_i_go_with_a_time_to_come_asks_for_no_action(vocabulary: Vocabulary, world: str, text: str) -> None:
    said, speaker = (_flat(), "femke") if world == "flat" else (vocabulary, "annie")
    result = understand(text, said, speaker=speaker)
    assert not result.accepted and "action" in result.reason


def test_i_go_to_a_room_now_is_still_a_going(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "I go to the kitchen") == [{"frame": "MOTION", "goal": "kitchen"}]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("The tablet is to be found forthwith", [{"frame": "SEARCHING", "theme": "tablet"}]),
        (
            "close the blinds at your earliest convenience",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
        (
            "I put it to you that Tracy is in the kitchen. Confirm.",
            [{"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}],
        ),
    ],
)
def test_a_barristers_words_in_the_erl_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "state"),
    [
        ("dim the light above the island to twenty", "20"),
        ("turn off the light over the kitchen island", "off"),
    ],
)
def test_the_light_above_a_thing_is_the_dimmer_named_after_it(text: str, state: str) -> None:
    assert frames_read(_flat(), text, "idris") == [
        {"frame": "OPERATING", "device": "island_lights", "state": state}
    ]


def test_the_light_above_the_dining_table_is_still_the_rooms(vocabulary: Vocabulary) -> None:
    assert frames_read(_flat(), "turn on the light above the dining table", "idris") == [
        {"frame": "OPERATING", "device": "living_room_light", "state": "on"}
    ]


def test_leave_it_without_no_is_no_calling_off(vocabulary: Vocabulary) -> None:
    assert frames_read(
        vocabulary, "Put the cup on the kitchen table, leave it. Then bring me the apple."
    ) == [
        {"frame": "PLACING", "theme": "cup", "goal": "kitchen_table"},
        {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"},
    ]
