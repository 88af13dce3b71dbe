"""Phrasings from the people22 development set (a two-storey terraced family house the reader was never
tuned on, ``tests/fixtures/language/people22/terraced_house.yaml``) the reader first got wrong:

* a thing whose name holds a person's name ("kerry_keys", "maisie_lunchbox") is that person's
  (``knic.language.owned``): "my keys" said by kerry, "dave's keys", "daves keys", "her lunchbox" once maisie
  was named; said by someone who owns none of them, "my keys" still asks which;
* a person's name with an "s" and no apostrophe before a thing ("get tylers basketball") says whose the thing
  is, not whom to give it to;
* "all the lights" of a room are its dimmers too ("turn off all the lights in the main bedroom": the ceiling
  light and the bedside lamp); a level asked of them still sets the dimmers only; "the lights" there (as a
  dark room asks for) are still those named lights;
* "while you're at it" and "at all" ("where is it at all", Irish) are talk around the request;
* "help me (to)" before "on" or "off" (Nigerian English, where they are verbs: "please help me to on the
  landing light") is politeness; "help me to the bathroom" still goes along;
* "in" right after a verb of carrying and before a thing ("bring me in the post") says it comes indoors;
  "in here" is here; "outta" is "out of";
* a thing said before the request by an unknown word and a last word only a synonym gives ("my hearing aid,
  where is it") is refused naming it, as it is said after the verb;
* a command that opens with what the speaker wants ("I need the spare duvet from the airing cupboard") and
  then says what to do with it ("bring it to the back bedroom") is that one action, from where the wish said;
* "go to the landing and wait for me there": the place said twice is kept as the goal, not dropped as a
  place on the way;
* a room said with "in" right before a piece of furniture of a name that fits several ("put the hand soap in
  the downstairs toilet on the basin") is where that piece is;
* a word right after a word of a name, one edit from the word that ends the name, is that word though it is
  English ("the rubber duk": duck); a word ending "y" where a name ends it "ie" is that ("my hoody");
* a pain said last ("bring me the calpol my tummy hurts") gives the reason, no request of its own;
* "is it going to rain", "will it ...", "the house is very beautiful" ask or say something: no request;
  so do "why is the kitchen blind closed", "thanks for bringing the post" and "I've put the milk in the
  fridge" (what the speaker did); "why don't you bring me the post" still asks for it;
* "grab my keys" of the speaker's own keys is still for the speaker, as "grab my glasses" is;
* a device said in one room and then another ("close the curtains in the main bedroom and the back room") is
  the device of that name in each;
* "the spotty one", "the thing for the telly", "the telly thing": a word (or a synonym of it) that starts
  the name of one thing only, said before "one" or "thing" or after "thing for", is that thing;
* "i am wanting the tea bags", "hamish is wanting his headphones" (Indian English): a wish;
* "get the butter out the fridge": "out" before a place is "out of", not the state "off";
* a thing brought "for" a room or a piece of furniture ("i'm needing the sponge for the kitchen") goes there;
  "for annie" is still whom it is for;
* "bring apple me" (a learner's order): "me" said last after the thing is whom it is for;
* a correction that says the action again of "it" ("switch on the floor lamp, actually make it 40 percent")
  keeps the device the first action switched ("on" right after the verb is no preposition);
* the plural of a longer name's last word takes "es" after a hiss, as a one-word name's does ("both
  lunchboxes": maisie's and tyler's);
* "give tyler the headset and maisie the unicorn": the verb that gives is said again for the second person
  and thing;
* what the speaker did with a thing, said before a request ("i put the milk in the fridge, bring me the
  butter", "i've put my keys somewhere, can you find them"), is no action; the thing stays said for "them";
* "where did emeka put the calpol", "where has tyler left my keys": where the thing is;
* a mistyped word after politeness only is read as the command's first word ("pleas tke the glue": take,
  a verb, not the);
* a wish followed by a search for the thing ("i need my glasses, could you find them") is the search;
* a typo near several names is the one keeping most of its letters at both ends ("my glases": glasses, not
  glass); a tie is still asked about ("the cug": cup or mug);
* "my slippers, where did they go", "the remote, where has it gone": where the thing said before is;
* "the radio, turn it off" switches "it": where the thing is no device that is refused, not read as a
  request for the radio with the switching dropped as talk.

Known gaps of earlier rounds, closed in this one:

* a name said with the other word of an opposite pair (``synonyms.yaml`` opposites: front/back, left/right,
  ...) names nothing where the world has only the one: "go to the back door" in the bungalow, whose one door
  to the outside is the front door, is refused naming the back door, not read as the hall;
* a name said with synonyms of more than one of its words ("the telly clicker", "the clicker for the telly":
  the tv remote) is the world's name;
* "go on" (and "go on then", "hurry up") said last urges the request on: no motion;
* "secondly", "lastly" and "and finally" between chained actions join them;
* "chuck me the remote", "throw us the keys": given to the speaker;
* "all the lights in the bedroom" include its bedside dimmer (above);
* a modal verb said bare in a command of no verb ("no can not watching full of old photos") is no last word
  of a name (the watering can): no request.
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

HOUSE = "tests/fixtures/language/people22/terraced_house.yaml"
GARDEN_FLAT = "tests/fixtures/language/people19/garden_flat.yaml"
FLAT = "tests/fixtures/language/people21/accessible_flat.yaml"
BUNGALOW = "worlds/test_bungalow/test_bungalow.yaml"


@pytest.fixture(scope="module")
def house() -> Vocabulary:
    """The terraced house's vocabulary."""
    return world_of(HOUSE)


@pytest.mark.parametrize(
    ("speaker", "text", "frames"),
    [
        ("kerry", "where are my keys", [{"frame": "SEARCHING", "theme": "kerry_keys"}]),
        ("dave", "find my keys", [{"frame": "SEARCHING", "theme": "dave_keys"}]),
        (
            "emeka",
            "please help me to bring my keys from the writing desk",
            [{"frame": "BRINGING", "theme": "emeka_keys", "source": "writing_desk", "beneficiary": "me"}],
        ),
        (
            "kerry",
            "bring me dave's keys off the hooks",
            [{"frame": "BRINGING", "theme": "dave_keys", "source": "coat_hooks", "beneficiary": "me"}],
        ),
        (
            "kerry",
            "emeka's keys, put them on the hall table",
            [{"frame": "PLACING", "theme": "emeka_keys", "goal": "hall_table"}],
        ),
        ("ana", "bring me daves keys", [{"frame": "BRINGING", "theme": "dave_keys", "beneficiary": "me"}]),
        (
            "maisie",
            "I want my lunchbox",
            [{"frame": "BRINGING", "theme": "maisie_lunchbox", "beneficiary": "me"}],
        ),
        (
            "kerry",
            "give tyler his lunchbox",
            [{"frame": "BRINGING", "theme": "tyler_lunchbox", "beneficiary": "tyler"}],
        ),
        (
            "kerry",
            "find maisie and give her her lunchbox",
            [
                {"frame": "SEARCHING", "theme": "maisie"},
                {"frame": "BRINGING", "theme": "maisie_lunchbox", "beneficiary": "maisie"},
            ],
        ),
        (
            "kerry",
            "take maisie's lunchbox up to the box room",
            [{"frame": "BRINGING", "theme": "maisie_lunchbox", "goal": "box_room"}],
        ),
    ],
)
def test_a_thing_named_after_a_person_is_theirs(
    house: Vocabulary, speaker: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, speaker) == frames


@pytest.mark.parametrize(
    ("speaker", "text", "word"),
    [("ana", "where are my keys", "keys"), ("kerry", "bring me my lunchbox", "lunchbox")],
)
def test_my_thing_of_someone_who_owns_none_asks(
    house: Vocabulary, speaker: str, text: str, word: str
) -> None:
    assert_asked(house, text, word, speaker)


def test_a_name_with_an_s_before_a_thing_is_its_owner(house: Vocabulary) -> None:
    assert frames_read(house, "can you get tylers basketball", "maisie") == [
        {"frame": "BRINGING", "theme": "basketball", "beneficiary": "me"}
    ]
    assert frames_read(house, "get tyler the basketball", "maisie") == [
        {"frame": "BRINGING", "theme": "basketball", "beneficiary": "tyler"}
    ]


def test_all_the_lights_of_a_room_are_its_dimmers_too(house: Vocabulary) -> None:
    assert frames_read(house, "turn off all the lights in the main bedroom", "dave") == [
        {"frame": "OPERATING", "device": "main_bedroom_light", "state": "off"},
        {"frame": "OPERATING", "device": "bedside_lamp", "state": "off"},
    ]
    for text in ("switch on the light in the main bedroom", "it's dark in the main bedroom"):
        assert frames_read(house, text, "dave") == [
            {"frame": "OPERATING", "device": "main_bedroom_light", "state": "on"}
        ]


def test_a_level_of_the_lights_of_a_room_is_its_dimmers(house: Vocabulary) -> None:
    assert frames_read(house, "dim the lights in the main bedroom to 30 percent", "dave") == [
        {"frame": "OPERATING", "device": "bedside_lamp", "state": "30"}
    ]
    garden = world_of(GARDEN_FLAT)
    assert frames_read(garden, "dim the lights in the lounge to 30 percent", "margaret") == [
        {"frame": "OPERATING", "device": "standard_lamp", "state": "30"}
    ]


def test_while_you_are_at_it_is_talk(house: Vocabulary) -> None:
    assert frames_read(house, "oh and switch the hall light on while you're at it", "kerry") == [
        {"frame": "OPERATING", "device": "hall_light", "state": "on"}
    ]
    result = understand("whilst you are at it, close the kitchen blind", house, speaker="kerry")
    assert [f.to_dict() for f in result.frames] == [
        {"frame": "OPERATING", "device": "kitchen_blind", "state": "closed"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "please help me to on the landing light",
            [{"frame": "OPERATING", "device": "landing_light", "state": "on"}],
        ),
        (
            "kindly help me off the bathroom light",
            [{"frame": "OPERATING", "device": "bathroom_light", "state": "off"}],
        ),
        ("help me to the bathroom", [{"frame": "ACCOMPANYING", "theme": "me", "goal": "bathroom"}]),
        (
            "bring me in the post from the hall table",
            [{"frame": "BRINGING", "theme": "post", "source": "hall_table", "beneficiary": "me"}],
        ),
        ("bring the throw in here to me", [{"frame": "BRINGING", "theme": "throw", "beneficiary": "me"}]),
        ("bring the laptop in the kitchen", [{"frame": "BRINGING", "theme": "laptop", "goal": "kitchen"}]),
        ("where is my shawl at all", [{"frame": "SEARCHING", "theme": "shawl"}]),
        (
            "grab the milk outta the fridge",
            [{"frame": "TAKING", "theme": "milk", "source": "fridge"}],
        ),
    ],
)
def test_helped_to_carried_in_and_at_all(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "emeka") == frames


@pytest.mark.parametrize("text", ["my hearing aid, where is it at all", "find my hearing aid"])
def test_a_hearing_aid_said_first_is_no_plaster(house: Vocabulary, text: str) -> None:
    result = understand(text, house, speaker="bridget")
    assert not result.accepted and "no 'hearing aid'" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "please I need the spare duvet from the airing cupboard, bring it to the back bedroom",
            [
                {
                    "frame": "BRINGING",
                    "theme": "spare_duvet",
                    "source": "airing_cupboard",
                    "goal": "back_bedroom",
                }
            ],
        ),
        (
            "I want the laptop, put it on the dining table",
            [{"frame": "PLACING", "theme": "laptop", "goal": "dining_table"}],
        ),
        (
            "i want the laptop and the bible, bring them to the kitchen",
            [
                {"frame": "BRINGING", "theme": "laptop", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "bible", "goal": "kitchen"},
            ],
        ),
        ("i need the laptop", [{"frame": "BRINGING", "theme": "laptop", "beneficiary": "me"}]),
        (
            "I want to ask, is there milk in the fridge? if there is, bring it for me",
            [{"frame": "BRINGING", "theme": "milk", "source": "fridge", "beneficiary": "me"}],
        ),
    ],
)
def test_a_wish_then_what_to_do_with_it_is_one_action(
    house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, "emeka") == frames


@pytest.mark.parametrize(
    "text", ["I beg you, go to the landing and wait for me there", "go to the landing and stay there"]
)
def test_waiting_there_keeps_the_place(house: Vocabulary, text: str) -> None:
    result = understand(text, house, speaker="emeka")
    assert [str(g) for g in result.goals] == ["(robot_at robbie landing)"]


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("put the hand soap in the downstairs toilet on the basin", "hand_basin"),
        ("put the plasters in the bathroom on the basin", "washbasin"),
        ("put the laptop in the kitchen on the table", "dining_table"),
    ],
)
def test_a_room_said_before_the_furniture_tells_which(house: Vocabulary, text: str, goal: str) -> None:
    assert frames_read(house, text, "ana")[0]["goal"] == goal


def test_the_back_door_of_a_home_with_only_a_front_door_is_refused() -> None:
    bungalow = world_of(BUNGALOW)
    result = understand("go to the back door", bungalow, speaker="walter")
    assert not result.accepted and "no 'back door'" in result.reason
    assert frames_read(bungalow, "go to the front door", "walter") == [{"frame": "MOTION", "goal": "hall"}]
    flat = world_of(FLAT)  # a home with both doors
    assert frames_read(flat, "go to the back door", "dawn") == [{"frame": "MOTION", "goal": "kitchen"}]


@pytest.mark.parametrize(
    "text",
    [
        "bring the clicker for the telly",
        "bring me the telly clicker",
        "bring the remote control for the television",
    ],
)
def test_a_name_said_with_several_synonyms(text: str) -> None:
    assert frames_read(world_of(FLAT), text, "morag") == [
        {"frame": "BRINGING", "theme": "tv_remote", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("bring me the red mug, go on", [{"frame": "BRINGING", "theme": "red_mug", "beneficiary": "me"}]),
        ("bring me the red mug go on then", [{"frame": "BRINGING", "theme": "red_mug", "beneficiary": "me"}]),
        ("chuck me the remote", [{"frame": "BRINGING", "theme": "tv_remote", "beneficiary": "me"}]),
        ("throw us the glue", [{"frame": "BRINGING", "theme": "glue", "beneficiary": "me"}]),
        ("chuck the magazines on the sofa", [{"frame": "PLACING", "theme": "magazines", "goal": "sofa"}]),
        (
            "firstly go to the kitchen secondly take the milk and lastly bring it to me",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "TAKING", "theme": "milk", "source": "kitchen"},
                {"frame": "BRINGING", "theme": "milk", "source": "kitchen", "beneficiary": "me"},
            ],
        ),
        (
            "switch on the hall light and finally close the kitchen blind",
            [
                {"frame": "OPERATING", "device": "hall_light", "state": "on"},
                {"frame": "OPERATING", "device": "kitchen_blind", "state": "closed"},
            ],
        ),
    ],
)
def test_tags_joiners_and_chucking(text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(world_of(FLAT), text, "hamish") == frames


@pytest.mark.parametrize("text", ["tell me a joke, go on", "no can not watching full of old photos"])
def test_no_request_with_a_tag_or_a_bare_modal(text: str) -> None:
    result = understand(text, world_of(FLAT), speaker="hamish")
    assert not result.accepted and "no action" in result.reason


def test_the_can_is_still_the_watering_can() -> None:
    assert frames_read(world_of(FLAT), "the can please", "isla") == [
        {"frame": "BRINGING", "theme": "watering_can", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("speaker", "text", "frames"),
    [
        ("maisie", "wher is the rubber duk", [{"frame": "SEARCHING", "theme": "rubber_duck"}]),
        (
            "tyler",
            "brign my hoody to the living room",
            [{"frame": "BRINGING", "theme": "hoodie", "goal": "living_room"}],
        ),
        (
            "maisie",
            "pleeease can you bring me the calpol my tummy hurts",
            [{"frame": "BRINGING", "theme": "calpol", "beneficiary": "me"}],
        ),
        (
            "emeka",
            "bring me the plasters, my knee is killing me",
            [{"frame": "BRINGING", "theme": "plasters", "beneficiary": "me"}],
        ),
    ],
)
def test_typos_in_a_name_and_a_pain_said_last(
    house: Vocabulary, speaker: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, speaker) == frames


@pytest.mark.parametrize(
    "text",
    ["is it going to rain at all today", "will it be sunny later", "the house is very beautiful", "the cake"],
)
def test_weather_and_praise_are_no_request(house: Vocabulary, text: str) -> None:
    result = understand(text, house, speaker="bridget")
    assert not result.accepted
    assert "no action" in result.reason or "no 'cake'" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("grab my keys, I'm off out", [{"frame": "BRINGING", "theme": "kerry_keys", "beneficiary": "me"}]),
        (
            "close the curtains in the main bedroom and the back room",
            [
                {"frame": "OPERATING", "device": "main_bedroom_curtains", "state": "closed"},
                {"frame": "OPERATING", "device": "back_room_curtains", "state": "closed"},
            ],
        ),
        (
            "open the blinds in the kitchen and in the box room",
            [
                {"frame": "OPERATING", "device": "kitchen_blind", "state": "open"},
                {"frame": "OPERATING", "device": "box_room_blind", "state": "open"},
            ],
        ),
        ("bring me the spotty one", [{"frame": "BRINGING", "theme": "spotty_mug", "beneficiary": "me"}]),
    ],
)
def test_my_keys_devices_in_two_rooms_and_the_spotty_one(
    house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, "kerry") == frames


def test_switching_it_is_never_talk() -> None:
    farm = world_of("tests/fixtures/language/people20/farmhouse.yaml")
    assert not understand("the radio, turn it off", farm, speaker="ffion").accepted
    assert frames_read(farm, "the kitchen light, turn it off", "ffion") == [
        {"frame": "OPERATING", "device": "kitchen_light", "state": "off"}
    ]


@pytest.mark.parametrize(
    ("text", "theme"),
    [("my slippers, where did they go", "slippers"), ("the remote, where has it gone", "tv_remote")],
)
def test_where_a_thing_said_before_went(text: str, theme: str) -> None:
    garden = world_of(GARDEN_FLAT)
    assert frames_read(garden, text, "margaret") == [{"frame": "SEARCHING", "theme": theme}]
    assert not understand("where did you go", garden, speaker="margaret").accepted


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "get the butter out the fridge",
            [{"frame": "BRINGING", "theme": "butter", "source": "fridge", "beneficiary": "me"}],
        ),
        ("put the hall light out", [{"frame": "OPERATING", "device": "hall_light", "state": "off"}]),
        ("I am wanting the tea bags", [{"frame": "BRINGING", "theme": "tea_bags", "beneficiary": "me"}]),
        ("emeka is wanting his laptop", [{"frame": "BRINGING", "theme": "laptop", "beneficiary": "emeka"}]),
    ],
)
def test_out_the_and_the_progressive_wish(house: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(house, text, "kerry") == frames


def test_a_typo_keeps_its_ends(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring me my glases") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}
    ]
    assert_asked(vocabulary, "bring me the cug", "cup")


@pytest.mark.parametrize("text", ["bring me the thing for the telly", "bring me the telly thing"])
def test_the_thing_for_the_telly(house: Vocabulary, vocabulary: Vocabulary, text: str) -> None:
    assert frames_read(house, text, "kerry") == [
        {"frame": "BRINGING", "theme": "tv_remote", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, text) == [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]


def test_a_typo_after_politeness_and_a_wish_then_a_search(vocabulary: Vocabulary) -> None:
    flat = world_of(FLAT)
    assert frames_read(flat, "pleas tke the glue to workbenh", "tomasz") == [
        {"frame": "BRINGING", "theme": "glue", "goal": "workbench"}
    ]
    assert frames_read(vocabulary, "well um the thing is i need my glasses, could you find them") == [
        {"frame": "SEARCHING", "theme": "glasses"}
    ]


@pytest.mark.parametrize(
    "text",
    ["why is the kitchen blind closed", "thanks for bringing the post", "I've put the milk in the fridge"],
)
def test_questions_thanks_and_what_the_speaker_did_are_no_request(house: Vocabulary, text: str) -> None:
    result = understand(text, house, speaker="kerry")
    assert not result.accepted and "no action" in result.reason


def test_why_dont_you_still_asks(house: Vocabulary) -> None:
    assert frames_read(house, "why don't you bring me the post", "kerry") == [
        {"frame": "BRINGING", "theme": "post", "beneficiary": "me"}
    ]


def test_the_owner_said_is_there_for_her(house: Vocabulary) -> None:
    assert frames_read(house, "fetch maisie's lunchbox and give it to her", "kerry") == [
        {"frame": "TAKING", "theme": "maisie_lunchbox"},
        {"frame": "BRINGING", "theme": "maisie_lunchbox", "beneficiary": "maisie"},
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "i'm needing the sponge for the kitchen",
            [{"frame": "BRINGING", "theme": "sponge", "goal": "kitchen"}],
        ),
        ("bring the tissues for annie", [{"frame": "BRINGING", "theme": "tissues", "beneficiary": "annie"}]),
        ("bring apple me", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
        ("bring the apple me", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
    ],
)
def test_for_a_room_and_me_said_last(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "switch on the floor lamp, actually make it 40 percent",
            [{"frame": "OPERATING", "device": "floor_lamp", "state": "40"}],
        ),
        (
            "place the spotty mug on the worktop, correction, place it on the dining table",
            [{"frame": "PLACING", "theme": "spotty_mug", "goal": "dining_table"}],
        ),
    ],
)
def test_a_correction_of_it_keeps_the_device(
    house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, "kerry") == frames


def test_the_plural_of_a_last_word_in_es(house: Vocabulary) -> None:
    assert frames_read(house, "bring both lunchboxes to the kitchen", "kerry") == [
        {"frame": "BRINGING", "theme": "maisie_lunchbox", "goal": "kitchen"},
        {"frame": "BRINGING", "theme": "tyler_lunchbox", "goal": "kitchen"},
    ]


def test_a_second_person_and_thing_after_and(house: Vocabulary) -> None:
    assert frames_read(house, "give tyler the headset and maisie the unicorn", "kerry") == [
        {"frame": "BRINGING", "theme": "headset", "beneficiary": "tyler"},
        {"frame": "BRINGING", "theme": "stuffed_unicorn", "beneficiary": "maisie"},
    ]
    assert frames_read(house, "give maisie the unicorn and the lego", "kerry") == [
        {"frame": "BRINGING", "theme": "stuffed_unicorn", "beneficiary": "maisie"},
        {"frame": "BRINGING", "theme": "lego", "beneficiary": "maisie"},
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "i put the milk in the fridge, bring me the butter",
            [{"frame": "BRINGING", "theme": "butter", "beneficiary": "me"}],
        ),
        ("i've put my keys somewhere, can you find them", [{"frame": "SEARCHING", "theme": "kerry_keys"}]),
        ("we've moved the sofa, go to the living room", [{"frame": "MOTION", "goal": "living_room"}]),
        ("i want the milk, put it in the fridge", [{"frame": "PLACING", "theme": "milk", "goal": "fridge"}]),
    ],
)
def test_what_the_speaker_did_before_a_request(
    house: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, "kerry") == frames
    assert not understand("i put the milk in the fridge", house, speaker="kerry").accepted


@pytest.mark.parametrize(
    ("text", "theme"),
    [("where did emeka put the calpol", "calpol"), ("where has tyler left my keys", "kerry_keys")],
)
def test_where_someone_put_a_thing(house: Vocabulary, text: str, theme: str) -> None:
    assert frames_read(house, text, "kerry") == [{"frame": "SEARCHING", "theme": theme}]
