"""Phrasings from the people21 development set (a ground-floor, wheelchair-accessible flat the reader was
never tuned on, ``tests/fixtures/language/people21/accessible_flat.yaml``) the reader first got wrong:

* Scottish and texting spellings (``commands.yaml`` spellings): "fae" from, "tae" to, "aff" off, "gie" give,
  "ma" my, "n" and, "gonnae" (would you), "pleas" please; "keep" a thing somewhere is to put it there (Indian
  English, "keep the saucepan on the hob"); "is possible to" and "it is possible to" are politeness, as "is it
  possible to" is;
* a piece of furniture made of drawers is "the drawers" and "the drawer" (``synonyms.yaml`` units): a
  "drawer unit" as a "chest of drawers"; "the drawer in the study" is the drawer unit there, and where a
  home has both, "the drawers" alone asks which (a world file says where furniture is, not where things
  are, so "the stamps from the drawers" asks too); a name's plural has "es" only after a hiss or an "o"
  ("boxes", "potatoes"), so "drawres" is still a typo of "drawers" alone;
* the room another door to the outside opens into is "the back door" (``World.back_entrances``: where the
  doorbell tells the front door from the others), and "the door" alone is then the front door;
* a thing said before the request that fits several ("there's a mug on the coffee table, take it ...", where
  the robot knows the table but not which mug is on it) makes "it" ask which, rather than refer to nothing;
* "him" or "her" where no person was named is a thing ("my teddy is on the sofa, put him on the day bed");
* a piece of furniture whose name fits several is the one in the room an earlier action went to ("first go
  to the wet room, then take the shampoo from the cabinet": the bathroom cabinet, not the bedside one);
* a thing said before the request "from" a place has it as its source, as one said "on" it does ("care
  folder from the desk, bring it to the bedroom"); a thing said only to tell where another is ("the toaster
  near the kettle, bring it ...") is not what "it" is;
* words before a type's noun that name a device with another noun of the type ("the bedside light" for the
  bedside lamp, a dimmer; "the reading light" for a reading lamp) name it;
* "the light" in a room with a light and a device of a plural name ("under cupboard lights") is the light;
  "the lights" there are both;
* "bring" or "carry" a thing "in" a room said last, with no one and nowhere else said, takes it into the room
  (a learner's "in" for "into": "bring the egg basket in the kitchen"); "bring me the milk jug in the kitchen"
  and "fetch the torch in the boot room" still name where the thing is;
* "my bed" (or desk, ...) said by someone with a room named after them is the one in that room, where the
  world has several (``knic.language.owned``): "hoodie from my bed" said by rhys is his single bed;
* a command of one sentence opening "are you" asks about the robot, no request ("are you a boy robot or a
  girl robot"), unless a request follows ("are you able to bring me the tablet");
* a learner's "batteries, where they are?" (or "where it is") asks for a search;
* "you" said between the thing and the verb ("toolbox you take from shelf") is whom the speaker tells;
* a command that opens asking whether a thing is somewhere and then acts on it ("is there a parcel on the
  hall table? bring it to me") takes the place as where the thing is, with no search of its own;
* a pill dispenser is a pill box (``synonyms.yaml``), not the box of tissues; a white cane is a "white
  stick" (British);
* "the chair" where the world has a wicker chair and an armchair fits both (a one-word compound is what its
  end names, as a two-word name is) and is asked about;
* a thing said by an unknown word and the last word of a name only a synonym gives, where no name of the
  world's own ends so, is refused naming both ("find my hearing aid" is not the plasters' "band aids");
* a thing that "would be lovely" (nice, great, wonderful) is asked for ("a glass of water would be lovely");
* a one-word lexicon phrase that ends the name of another thing of the same type is left out
  (``shortnames.own_phrases``): the ERL lexicon's "blinds" for ``bedroom_blinds`` is no name of the accessible
  flat's bedroom blinds alone, so "close the blinds" there asks which of them all, as plurals of devices in
  several rooms do;
* "a third" and "two thirds" are levels (33 and 67 percent; commands.yaml levels), not the number two;
* "me" said again for "my" ("fetch me me slippers");
* only a two-word name ending in a container says what it holds ("water bottle": some water): a "hot water
  bottle" is no drink;
* what a person is, said after their name as "the" and a word the world has no name for, only says who they
  are ("find tomasz the handyman");
* a word between a verb that gives and a thing is whom it is for: one the world lacks is refused by name
  ("give bethan the plasters" where there is no bethan), not dropped to give the thing to the speaker;
* "where did my glasses go", "where has the hairbrush gone", "where'd the keys go" ask where the thing is;
* a dark room complained of otherwise than "it's dark in ..." (``knic.language.complaints``): "it's pitch
  black in the hall", "it's gloomy in the bedroom", "I can't see a thing in the wet room", "the living room is
  too dark", "the bedroom's dark" ask for its lights;
* a thing said "along with", "together with" or "as well as" another thing carried or put is carried or put
  too ("bring me the stamps along with the envelopes"); a person said so still goes along;
* "one of the mugs" is one mug, asked which where several fit, not every mug;
* of several words a typo is one edit from, the one that ends a phrase of the language with the words before
  it ("can i hav my teddy": have, so no "can" of the watering can), and a command's first word a verb ("fnd my
  glasses": find, not and);
* "send" a thing somewhere takes it there; "tidy" or "clear" a thing away puts it somewhere (asked where when
  not said); a place asked for names the thing as said ("the fruit bowl", not its symbol);
* "remind me to take my pills" asks for a reminder, which the robot cannot give: no request to bring them;
* "come and find me in the study" and "meet me in the kitchen" go where the speaker is;
* "the lights in the study" are all its lights (its light and its desk lamp); "the light in the study" is
  still the one its name calls a light;
* what a thing needs ("the orchid needs water, take it to the kitchen") is said of it, no request for the
  thing; "hamish needs his headphones" still is;
* a room with no lights is refused in English ("there are no lights in the utility room"; one lamp: "there
  is no lamp ...");
* a command of no verb that opens with a name, a determiner and another name says a name as a verb the robot
  has not ("light the candle", as "water the plant"): no action, not a question which light.
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

FLAT = "tests/fixtures/language/people21/accessible_flat.yaml"


@pytest.fixture(scope="module")
def flat() -> Vocabulary:
    """The accessible flat's vocabulary."""
    return world_of(FLAT)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "gonnae bring us ma headphones fae the study",
            [{"frame": "BRINGING", "theme": "headphones", "source": "study", "beneficiary": "me"}],
        ),
        (
            "turn the bedroom light aff n the hall light on",
            [
                {"frame": "OPERATING", "device": "bedroom_light", "state": "off"},
                {"frame": "OPERATING", "device": "hall_light", "state": "on"},
            ],
        ),
        (
            "get the toolbox fae the shelves n gie it tae tomasz",
            [
                {"frame": "TAKING", "theme": "toolbox", "source": "utility_shelves"},
                {
                    "frame": "BRINGING",
                    "theme": "toolbox",
                    "source": "utility_shelves",
                    "beneficiary": "tomasz",
                },
            ],
        ),
        ("take the laptop tae dawn", [{"frame": "BRINGING", "theme": "laptop", "beneficiary": "dawn"}]),
        ("keep the saucepan on the hob", [{"frame": "PLACING", "theme": "saucepan", "goal": "hob"}]),
        (
            "take the eggs out of the fridge and keep them on the worktop",
            [
                {"frame": "TAKING", "theme": "eggs", "source": "fridge_freezer"},
                {"frame": "PLACING", "theme": "eggs", "goal": "low_worktop"},
            ],
        ),
    ],
)
def test_scots_and_texting_spellings_and_keep(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "callum") == frames


@pytest.mark.parametrize(
    ("text", "word"),
    [("is possible to bring ladder", "ladder"), ("bring me ma phone charger", "phone charger")],
)
def test_learners_politeness_leaves_the_missing_thing_named(flat: Vocabulary, text: str, word: str) -> None:
    result = understand(text, flat, speaker="tomasz")
    assert not result.accepted
    assert f"no '{word}'" in result.reason


GARDEN_FLAT = "tests/fixtures/language/people19/garden_flat.yaml"
FARMHOUSE = "tests/fixtures/language/people20/farmhouse.yaml"


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "put screwdriver in drawer in study",
            [{"frame": "PLACING", "theme": "screwdriver", "goal": "drawer_unit"}],
        ),
        (
            "bring the stamps from the drawer in the study",
            [{"frame": "BRINGING", "theme": "stamps", "source": "drawer_unit", "beneficiary": "me"}],
        ),
        (
            "bring me the hand cream from the drawers in the bedroom",
            [{"frame": "BRINGING", "theme": "hand_cream", "source": "chest_of_drawers", "beneficiary": "me"}],
        ),
    ],
)
def test_a_drawer_unit_is_the_drawers(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "hamish") == frames


@pytest.mark.parametrize("text", ["get the stamps from the drawers", "put the socks in the drawer"])
def test_the_drawers_of_two_are_asked_about(flat: Vocabulary, text: str) -> None:
    assert_asked(flat, text, "drawer unit", "hamish")


def test_the_drawer_in_the_den_and_a_typo_of_drawers() -> None:
    garden = world_of(GARDEN_FLAT)
    assert frames_read(garden, "get me the batteries from the drawer in the den", "arthur") == [
        {"frame": "BRINGING", "theme": "batteries", "source": "drawer_unit", "beneficiary": "me"}
    ]
    farm = world_of(FARMHOUSE)
    assert frames_read(farm, "put teh earbuds on the chest of drawres", "rhys") == [
        {"frame": "PLACING", "theme": "earbuds", "goal": "chest_of_drawers"}
    ]


@pytest.mark.parametrize(
    ("world", "speaker", "text", "room"),
    [
        (FLAT, "dawn", "go to the back door", "kitchen"),
        (FLAT, "tomasz", "you go to back door please", "kitchen"),
        (FLAT, "dawn", "go and answer the door", "hall"),
        (FLAT, "dawn", "go to the front door", "hall"),
        (FARMHOUSE, "ffion", "go to the back door", "boot_room"),
        (GARDEN_FLAT, "arthur", "go to the back door", "conservatory"),
    ],
)
def test_the_back_door_is_the_room_of_another_outside_door(
    world: str, speaker: str, text: str, room: str
) -> None:
    assert frames_read(world_of(world), text, speaker) == [{"frame": "MOTION", "goal": room}]


def test_back_entrances_leave_the_front_door_out() -> None:
    from pathlib import Path

    from worlds.loader import load_world

    root = Path(__file__).resolve().parents[2]
    flat = load_world(root / FLAT)
    assert (flat.entrances(), flat.back_entrances()) == (["hall"], ["kitchen"])
    assert load_world("erl_home").back_entrances() == []


@pytest.mark.parametrize(
    "text",
    [
        "there's a mug on the coffee table, take it through to the kitchen",
        "the mug on the kitchen table, bring it here to me",
    ],
)
def test_it_of_a_thing_said_of_several_asks_which(flat: Vocabulary, text: str) -> None:
    assert_asked(flat, text, "red mug", "morag")


def test_a_named_mug_said_before_stays_it(flat: Vocabulary) -> None:
    assert frames_read(flat, "the red mug is on the coffee table, bring it to me", "morag") == [
        {"frame": "BRINGING", "theme": "red_mug", "source": "coffee_table", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "my teddy is on the sofa, put him on the day bed",
            [{"frame": "PLACING", "theme": "teddy", "goal": "day_bed"}],
        ),
        (
            "get the teddy and give him to callum",
            [
                {"frame": "TAKING", "theme": "teddy"},
                {"frame": "BRINGING", "theme": "teddy", "beneficiary": "callum"},
            ],
        ),
        (
            "find isla and give her the teddy",
            [
                {"frame": "SEARCHING", "theme": "isla"},
                {"frame": "BRINGING", "theme": "teddy", "beneficiary": "isla"},
            ],
        ),
    ],
)
def test_him_of_a_toy_where_no_person_is_named(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "isla") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "first go to the wet room, then take the shampoo from the cabinet and bring it to me",
            [
                {"frame": "MOTION", "goal": "wet_room"},
                {"frame": "TAKING", "theme": "shampoo", "source": "bathroom_cabinet"},
                {"frame": "BRINGING", "theme": "shampoo", "source": "bathroom_cabinet", "beneficiary": "me"},
            ],
        ),
        (
            "care folder from the desk, bring it to the bedroom",
            [{"frame": "BRINGING", "theme": "care_folder", "source": "desk", "goal": "bedroom"}],
        ),
        (
            "the toaster near the kettle, bring it to the kitchen table",
            [{"frame": "BRINGING", "theme": "toaster", "goal": "kitchen_table"}],
        ),
    ],
)
def test_places_said_around_the_request(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "priya") == frames


def test_the_cabinet_with_no_room_gone_to_is_asked_about(flat: Vocabulary) -> None:
    assert_asked(flat, "take the shampoo from the cabinet", "bedside cabinet", "priya")


@pytest.mark.parametrize(
    ("world", "text", "frames"),
    [
        (
            FLAT,
            "turn on the bedside light",
            [{"frame": "OPERATING", "device": "bedside_lamp", "state": "on"}],
        ),
        (FLAT, "turn on the floor light", [{"frame": "OPERATING", "device": "floor_lamp", "state": "on"}]),
        (
            FARMHOUSE,
            "turn on the reading light",
            [{"frame": "OPERATING", "device": "reading_lamp", "state": "on"}],
        ),
        (
            FLAT,
            "switch on the light in the kitchen",
            [{"frame": "OPERATING", "device": "kitchen_light", "state": "on"}],
        ),
        (
            FLAT,
            "switch off the lights in the kitchen",
            [
                {"frame": "OPERATING", "device": "kitchen_light", "state": "off"},
                {"frame": "OPERATING", "device": "under_cupboard_lights", "state": "off"},
            ],
        ),
    ],
)
def test_lamps_and_lights(world: str, text: str, frames: list[dict[str, str]]) -> None:
    vocabulary = world_of(world)
    speaker = "hamish" if world == FLAT else "ffion"
    assert frames_read(vocabulary, text, speaker) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "is it possible to bring the egg basket in the kitchen",
            [{"frame": "BRINGING", "theme": "egg_basket", "goal": "kitchen"}],
        ),
        (
            "bring me the milk jug in the kitchen",
            [{"frame": "BRINGING", "theme": "milk_jug", "source": "kitchen", "beneficiary": "me"}],
        ),
        (
            "fetch the torch in the boot room",
            [{"frame": "BRINGING", "theme": "torch", "source": "boot_room", "beneficiary": "me"}],
        ),
        (
            "bring the cheese in the kitchen to dai",
            [{"frame": "BRINGING", "theme": "cheese", "source": "kitchen", "beneficiary": "dai"}],
        ),
    ],
)
def test_bring_in_a_room_is_into_it(text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(world_of(FARMHOUSE), text, "jean_paul") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "hoodie from my bed pls",
            [{"frame": "BRINGING", "theme": "hoodie", "source": "single_bed", "beneficiary": "me"}],
        ),
        ("put my hoodie on my bed", [{"frame": "PLACING", "theme": "hoodie", "goal": "single_bed"}]),
    ],
)
def test_my_bed_is_the_one_in_my_room(text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(world_of(FARMHOUSE), text, "rhys") == frames


def test_my_bed_without_a_room_of_ones_own_is_asked_about() -> None:
    assert_asked(world_of(FARMHOUSE), "hoodie from my bed pls", "single bed", "ffion")


def test_are_you_asks_about_the_robot(flat: Vocabulary) -> None:
    result = understand("are you a boy robot or a girl robot", flat, speaker="isla")
    assert not result.accepted
    assert "no request" in result.reason and "action" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "are you able to bring me the tablet",
            [{"frame": "BRINGING", "theme": "tablet", "beneficiary": "me"}],
        ),
        (
            "are you there? bring me the tablet",
            [{"frame": "BRINGING", "theme": "tablet", "beneficiary": "me"}],
        ),
        ("batteries, where they are?", [{"frame": "SEARCHING", "theme": "batteries"}]),
        ("the glasses, where it is?", [{"frame": "SEARCHING", "theme": "glasses"}]),
        (
            "toolbox you take from shelf and you put on workbench",
            [
                {"frame": "TAKING", "theme": "toolbox", "source": "utility_shelves"},
                {"frame": "PLACING", "theme": "toolbox", "goal": "workbench"},
            ],
        ),
    ],
)
def test_learners_orders(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "tomasz") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "is there a parcel on the hall table? bring it to me",
            [{"frame": "BRINGING", "theme": "parcel", "source": "console_table", "beneficiary": "me"}],
        ),
        (
            "is the remote on the coffee table? put it on the sofa",
            [{"frame": "PLACING", "theme": "tv_remote", "goal": "sofa"}],
        ),
        ("are my glasses in the bedroom", [{"frame": "SEARCHING", "theme": "glasses", "ground": "bedroom"}]),
        (
            "bring the pill box from the kitchen table to morag",
            [
                {
                    "frame": "BRINGING",
                    "theme": "pill_dispenser",
                    "source": "kitchen_table",
                    "beneficiary": "morag",
                }
            ],
        ),
    ],
)
def test_asked_where_then_acted_on(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "morag") == frames


def test_a_white_stick_is_the_white_cane(flat: Vocabulary) -> None:
    assert frames_read(
        flat, "I can't find my white stick, it should be on the bench by the front door", "morag"
    ) == [{"frame": "SEARCHING", "theme": "white_cane", "ground": "shoe_bench"}]


def test_the_chair_of_a_chair_and_an_armchair_is_asked_about(flat: Vocabulary) -> None:
    assert_asked(flat, "put the cardigan on the chair", "armchair", "dawn")
    assert frames_read(flat, "put the cardigan on the wicker chair", "dawn") == [
        {"frame": "PLACING", "theme": "cardigan", "goal": "wicker_chair"}
    ]


def test_an_aid_that_only_a_synonym_names_is_refused(flat: Vocabulary) -> None:
    result = understand("find my hearing aid", flat, speaker="hamish")
    assert not result.accepted
    assert "no 'hearing aid'" in result.reason
    assert frames_read(flat, "bring me a band aid", "hamish") == [
        {"frame": "BRINGING", "theme": "plasters", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "theme"),
    [
        ("I'm parched, a glass of water would be lovely", "water_glass"),
        ("the chocolates would be nice", "chocolates"),
        ("some biscuits would be great, thanks", "biscuit_tin"),
    ],
)
def test_a_thing_that_would_be_lovely_is_asked_for(text: str, theme: str) -> None:
    assert frames_read(world_of(FARMHOUSE), text, "mary_ann") == [
        {"frame": "BRINGING", "theme": theme, "beneficiary": "me"}
    ]


def test_a_borrowed_lexicon_word_that_ends_other_names_is_not_one_things(flat: Vocabulary) -> None:
    # the plural said alone of blinds in five rooms asks which, offering all (knic.language.quantified)
    asked = understand("close the blinds", flat, speaker="dawn").question
    for blind in (
        "bedroom blinds",
        "conservatory blinds",
        "kitchen blind",
        "living room blinds",
        "study blind",
    ):
        assert f"the {blind}" in asked
    assert "all of them" in asked
    devices = [f["device"] for f in frames_read(flat, "close all the blinds", "dawn")]
    assert sorted(devices) == [
        "bedroom_blinds",
        "conservatory_blinds",
        "kitchen_blind",
        "living_room_blinds",
        "study_blind",
    ]
    assert frames_read(flat, "close the bedroom blinds", "dawn") == [
        {"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("set the floor lamp to a third", [{"frame": "OPERATING", "device": "floor_lamp", "state": "33"}]),
        (
            "put the bedside lamp at two thirds",
            [{"frame": "OPERATING", "device": "bedside_lamp", "state": "67"}],
        ),
        (
            "open the study blind a third of the way",
            [{"frame": "OPERATING", "device": "study_blind", "state": "33"}],
        ),
    ],
)
def test_thirds_are_levels(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "hamish") == frames


def test_me_said_again_is_my(flat: Vocabulary) -> None:
    assert frames_read(flat, "robot could ya bring me me glasses", "morag") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}
    ]


def test_a_hot_water_bottle_is_no_drink(flat: Vocabulary) -> None:
    assert_asked(flat, "could you bring me a drink", "orange juice", "isla")
    result = understand("could you bring me a drink", flat, speaker="isla")
    assert "hot water bottle" not in result.reason
    assert frames_read(flat, "fetch the hot water bottle", "isla") == [
        {"frame": "BRINGING", "theme": "hot_water_bottle", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("find tomasz the handyman", [{"frame": "SEARCHING", "theme": "tomasz"}]),
        (
            "give the toolbox to tomasz the handyman",
            [{"frame": "BRINGING", "theme": "toolbox", "beneficiary": "tomasz"}],
        ),
    ],
)
def test_what_a_person_is_said_after_the_name(
    flat: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(flat, text, "hamish") == frames


@pytest.mark.parametrize(
    ("text", "word"), [("give bethan the plasters", "bethan"), ("bring grandad his glasses", "grandad")]
)
def test_a_recipient_the_world_lacks_is_named(flat: Vocabulary, text: str, word: str) -> None:
    result = understand(text, flat, speaker="dawn")
    assert not result.accepted
    assert f"no '{word}'" in result.reason


@pytest.mark.parametrize(
    ("text", "theme"),
    [
        ("where did the hairbrush go", "hairbrush"),
        ("where has the hairbrush gone", "hairbrush"),
        ("where'd the house keys go", "house_keys"),
    ],
)
def test_where_a_thing_went_is_a_search(flat: Vocabulary, text: str, theme: str) -> None:
    assert frames_read(flat, text, "morag") == [{"frame": "SEARCHING", "theme": theme}]


@pytest.mark.parametrize(
    ("text", "device"),
    [
        ("it's pitch black in the hall", "hall_light"),
        ("it's gloomy in the bedroom", "bedroom_light"),
        ("I can't see a thing in the wet room", "wet_room_light"),
        ("the living room is too dark", "living_room_light"),
        ("the bedroom's dark", "bedroom_light"),
    ],
)
def test_a_dark_room_said_otherwise(flat: Vocabulary, text: str, device: str) -> None:
    assert frames_read(flat, text, "morag") == [{"frame": "OPERATING", "device": device, "state": "on"}]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "bring me the stamps along with the envelopes",
            [
                {"frame": "BRINGING", "theme": "stamps", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "envelopes", "beneficiary": "me"},
            ],
        ),
        (
            "bring me the milk as well as the orange juice",
            [
                {"frame": "BRINGING", "theme": "milk", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "orange_juice", "beneficiary": "me"},
            ],
        ),
        (
            "put the socks in the wardrobe together with the slippers",
            [
                {"frame": "PLACING", "theme": "socks", "goal": "wardrobe"},
                {"frame": "PLACING", "theme": "slippers", "goal": "wardrobe"},
            ],
        ),
        ("go to the kitchen with morag", [{"frame": "ACCOMPANYING", "theme": "morag", "goal": "kitchen"}]),
    ],
)
def test_things_said_along_with_others(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "hamish") == frames


@pytest.mark.parametrize(
    ("text", "word"), [("grab one of the mugs", "which mug"), ("turn on one of the lamps", "which lamp")]
)
def test_one_of_the_things_is_one(flat: Vocabulary, text: str, word: str) -> None:
    result = understand(text, flat, speaker="hamish")
    assert not result.accepted
    assert word in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("can i hav my teddy pleese", [{"frame": "BRINGING", "theme": "teddy", "beneficiary": "me"}]),
        ("fnd my glasses", [{"frame": "SEARCHING", "theme": "glasses"}]),
    ],
)
def test_typos_settled_by_the_words_before(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "isla") == frames


def test_send_tidy_and_clear() -> None:
    farm = world_of(FARMHOUSE)
    assert frames_read(farm, "send the letters up to the office", "ffion") == [
        {"frame": "BRINGING", "theme": "letters", "goal": "farm_office"}
    ]
    assert frames_read(farm, "tidy the jigsaw onto the card table", "ffion") == [
        {"frame": "PLACING", "theme": "jigsaw", "goal": "card_table"}
    ]
    assert_asked(farm, "tidy the jigsaw away", "jigsaw", "ffion")
    result = understand("clear the fruit bowl off the kitchen table", farm, speaker="ffion")
    assert not result.accepted
    assert "the fruit bowl where" in result.reason


def test_a_reminder_is_no_request_to_bring(flat: Vocabulary) -> None:
    result = understand("remind me to take my pills", flat, speaker="morag")
    assert not result.accepted
    assert "no request" in result.reason


@pytest.mark.parametrize(
    ("text", "room"),
    [
        ("come and find me in the study", "study"),
        ("meet me in the kitchen", "kitchen"),
        ("come find me, I'm in the bedroom", "bedroom"),
    ],
)
def test_find_me_somewhere_goes_there(flat: Vocabulary, text: str, room: str) -> None:
    assert frames_read(flat, text, "hamish") == [{"frame": "MOTION", "goal": room}]


def test_the_lights_of_a_room_are_all_of_them(flat: Vocabulary) -> None:
    frames = frames_read(flat, "switch on the lights in the study", "hamish")
    assert sorted(f["device"] for f in frames) == ["desk_lamp", "study_light"]
    assert frames_read(flat, "switch on the light in the study", "hamish") == [
        {"frame": "OPERATING", "device": "study_light", "state": "on"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "the orchid needs water, take it to the kitchen",
            [{"frame": "BRINGING", "theme": "orchid", "goal": "kitchen"}],
        ),
        (
            "hamish needs his headphones",
            [{"frame": "BRINGING", "theme": "headphones", "beneficiary": "hamish"}],
        ),
    ],
)
def test_what_a_thing_needs_is_said_of_it(flat: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(flat, text, "priya") == frames


def test_no_lights_in_a_room_is_said_in_english(other_house: Vocabulary) -> None:
    result = understand("turn on the lights in the nursery", other_house, speaker="maria")
    assert not result.accepted
    assert "there are no lights in the nursery" in result.reason


def test_light_the_candle_is_no_action(vocabulary: Vocabulary) -> None:
    result = understand("light the candle", vocabulary)
    assert not result.accepted and not result.question
    assert "no action" in result.reason
