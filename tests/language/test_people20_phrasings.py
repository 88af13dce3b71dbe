"""Phrasings from the people20 development set (a two-storey hill farmhouse the reader was never tuned on,
``tests/fixtures/language/people20/farmhouse.yaml``) the reader first got wrong:

* general English names (``synonyms.yaml``): "the wireless" for a radio, "a band-aid" for the plasters, "the
  post" or "the mail" for letters, "a pill box" for a pill organiser, "a cookie" for a biscuit (and so the
  biscuit tin), "the den" for a snug; a cloakroom is a downstairs toilet, so "the loo" is the cloakroom where
  the bathroom is another room; a one-word compound name ending in "shelves", "shelf" or "basin" is said by
  that word ("the shelves" for the bookshelves, "the basin" for the washbasin);
* "a couple of" and "a few" before a thing are determiners ("bring mary ann a couple of chocolates");
* "for me" (or for another) after a thing put somewhere is a favour, not whom it is for ("pop the tv remote
  on the footstool for me");
* a thing said with "of", "for" or "under" before another word is the world's name that puts the words the
  other way round (``knic.language.naming``): "the blind of the skylight", "a glass of water", "the cupboard
  under the stairs", "the shelf for books" (the bookshelf); a container the world has no name for, said of
  what it holds, is what it holds ("bring me a can of coke" is refused naming the coke);
* a room named after a person is "rhys's room", and "his bedroom" once rhys was named;
* a first name alone is the one person whose name it begins ("find jean"); where it begins several people's
  names ("mary" for mary ann and mary beth) the reader asks which;
* the last two words of a longer name name it too: "desk lamp on" asks between the office and the attic desk
  lamps (not among every lamp);
* of the devices a room narrows a word to, those whose own name ends in it: "the light in the attic" is the
  attic light, not the attic desk lamp;
* a room said after a room's lights with "and" ("lights off in the scullery and the boot room", "the lights in
  the kitchen and in the scullery") switches that room's lights too;
* "he's in the office" after a person given something is where the person is, not where the thing is taken
  from; after a search it is still where to look;
* "there" said of a device is the room of the place named last ("put the tartan blanket on the sofa and
  switch the lamp on in there": the snug's lamp);
* "where have I put", "where have I left" ask for a search as "where did I put" does;
* of several words a typo is one edit from, the one that makes a phrase of the language with the next word
  ("wher is the tv remote": where, not her or when);
* whether someone is about, asked before a request ("is bethan here yet? find her"): the question is
  dropped, the person stays said for "her";
* why the speaker asks, said after the request ("take me to the parlour, I want to play the piano": "i want
  to" before a word the language does not know), is talk;
* a piece of furniture said by the last word of its name with the room it is in, where another room has a
  thing of that whole name ("the desk in the den" in the garden flat, whose box room has a "desk"): the one
  in that room, as the source of a thing fetched too;
* a statement before a request that says something the world has no name for is somewhere, and asks for
  nothing ("the sun is in my eyes in the conservatory, pull the blinds down"): talk, unless "it" may point
  back to it;
* a name that fits several things fits the one said earlier in the command, and a bringing said again with
  more is that one ("I fancy a sherry, bring me the bottle from the sideboard": the sherry bottle, once);
* a noun after a thing's name that ends the command is a longer name the world lacks after "the" as after
  "a" ("bring me the candle holder" where the world has a candle); a word said to the person addressed
  ("the mug mate", "the candle grandma") is none;
* "could rosa have her hairbrush" (or "can", "may"; "get" for "have"), said by someone else, asks for it
  for rosa;
* after a command that opens with "first", "after you" goes on in order ("first you go in the scullery,
  after you take the rubber gloves, after you give them to ffion"); "I could murder a chocolate" asks for it;
* "us" is the speaker, as "me" is ("grab us a couple of jam jars");
* a place said after "to me" is where the speaker is, as after "to granny" ("bring the book to me in the
  lounge"); after "here" it is still where the thing is;
* what someone has done, said after the request ("fetch the first aid kit, tom's cut his finger"), is talk;
  so is what someone is or has been doing ("rosa has been looking for the teddy, take it to her"), the thing
  in it staying said for "it".
"""

from __future__ import annotations

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

FARMHOUSE = "tests/fixtures/language/people20/farmhouse.yaml"


@pytest.fixture(scope="module")
def farm() -> Vocabulary:
    """The farmhouse's vocabulary."""
    return world_of(FARMHOUSE)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "put the wireless on the kitchen table",
            [{"frame": "PLACING", "theme": "radio", "goal": "kitchen_table"}],
        ),
        ("bring me a band-aid", [{"frame": "BRINGING", "theme": "plasters", "beneficiary": "me"}]),
        ("where's my pill box got to", [{"frame": "SEARCHING", "theme": "pill_organiser"}]),
        ("bring me a cookie", [{"frame": "BRINGING", "theme": "biscuit_tin", "beneficiary": "me"}]),
        ("bring me the post", [{"frame": "BRINGING", "theme": "letters", "beneficiary": "me"}]),
        ("turn on the lights in the den", [{"frame": "OPERATING", "device": "snug_lamp", "state": "on"}]),
        ("go to the loo", [{"frame": "MOTION", "goal": "cloakroom"}]),
        ("go to the bathroom", [{"frame": "MOTION", "goal": "bathroom"}]),
        (
            "grab the recipe book from the shelves in the snug",
            [{"frame": "TAKING", "theme": "recipe_book", "source": "bookshelves"}],
        ),
        (
            "fetch the hand soap from the basin",
            [{"frame": "BRINGING", "theme": "hand_soap", "source": "washbasin", "beneficiary": "me"}],
        ),
    ],
)
def test_general_english_names(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "ffion") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "oh go on then, bring mary ann a couple of chocolates",
            [{"frame": "BRINGING", "theme": "chocolates", "beneficiary": "mary_ann"}],
        ),
        ("bring me a few chocolates", [{"frame": "BRINGING", "theme": "chocolates", "beneficiary": "me"}]),
        (
            "when you've a minute, pop the tv remote on the footstool for me",
            [{"frame": "PLACING", "theme": "tv_remote", "goal": "footstool"}],
        ),
        (
            "put the tartan blanket on the sofa for mary ann",
            [{"frame": "PLACING", "theme": "tartan_blanket", "goal": "sofa"}],
        ),
    ],
)
def test_quantities_and_favours(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "ffion") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "put the blind of the skylight at half",
            [{"frame": "OPERATING", "device": "skylight_blind", "state": "50"}],
        ),
        ("bring me a glass of water", [{"frame": "BRINGING", "theme": "water_glass", "beneficiary": "me"}]),
        (
            "get the hoover from the cupboard under the stairs",
            [
                {
                    "frame": "BRINGING",
                    "theme": "hoover",
                    "source": "under_stairs_cupboard",
                    "beneficiary": "me",
                }
            ],
        ),
        (
            "fetch the torch of the boot room",
            [{"frame": "BRINGING", "theme": "torch", "source": "boot_room", "beneficiary": "me"}],
        ),
    ],
)
def test_names_said_the_other_way_round(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "jean_paul") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "go and see if rhys is up, he'll be in his bedroom",
            [{"frame": "SEARCHING", "theme": "rhys", "ground": "rhys_bedroom"}],
        ),
        (
            "take the clean towels up to rhys's room",
            [{"frame": "BRINGING", "theme": "clean_towels", "goal": "rhys_bedroom"}],
        ),
        ("find jean", [{"frame": "SEARCHING", "theme": "jean_paul"}]),
        (
            "find mary ann's hairbrush and give it to her",
            [
                {"frame": "SEARCHING", "theme": "hairbrush"},
                {"frame": "BRINGING", "theme": "hairbrush", "beneficiary": "mary_ann"},
            ],
        ),
    ],
)
def test_people_and_their_rooms(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "ffion") == frames


@pytest.mark.parametrize("text", ["give mary the chocolates", "take mary's handbag to the annexe"])
def test_a_first_name_of_two_people_is_asked_about(farm: Vocabulary, text: str) -> None:
    assert_asked(farm, text, "mary ann or mary beth", "ffion")


@pytest.mark.parametrize("text", ["desk lamp on", "turn on the desk lamp"])
def test_the_last_two_words_of_a_name(farm: Vocabulary, text: str) -> None:
    assert_asked(farm, text, "the attic desk lamp or the office desk lamp", "dai")


@pytest.mark.parametrize(
    ("text", "device", "state"),
    [
        ("please, you can close the light in the attic?", "attic_light", "off"),
        ("switch on the light in the attic", "attic_light", "on"),
        ("turn on the lamp in the attic", "attic_desk_lamp", "on"),
    ],
)
def test_the_light_in_a_room_is_the_one_called_so(
    farm: Vocabulary, text: str, device: str, state: str
) -> None:
    assert frames_read(farm, text, "jean_paul") == [{"frame": "OPERATING", "device": device, "state": state}]


@pytest.mark.parametrize(
    ("text", "devices"),
    [
        (
            "right, lights off in the scullery and the boot room",
            ["scullery_light", "boot_room_light", "yard_light"],
        ),
        ("turn off the lights in the kitchen and in the scullery", ["kitchen_light", "scullery_light"]),
    ],
)
def test_lights_in_two_rooms(farm: Vocabulary, text: str, devices: list[str]) -> None:
    assert frames_read(farm, text, "ffion") == [
        {"frame": "OPERATING", "device": d, "state": "off"} for d in devices
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "give dai his reading glasses, he's in the office",
            [{"frame": "BRINGING", "theme": "reading_glasses", "beneficiary": "dai"}],
        ),
        (
            "take the reading glasses to dai, she's in the office",
            [{"frame": "BRINGING", "theme": "reading_glasses", "beneficiary": "dai"}],
        ),
        (
            "could you do me a favour and find dai, I think he's in the office",
            [{"frame": "SEARCHING", "theme": "dai", "ground": "farm_office"}],
        ),
        (
            "put the clean towels on the shelf in the scullery",
            [{"frame": "PLACING", "theme": "clean_towels", "goal": "scullery_shelf"}],
        ),
    ],
)
def test_where_a_person_is(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "ffion") == frames


def test_there_said_of_a_device_is_the_room(farm: Vocabulary) -> None:
    text = "take mary ann to the snug, put the tartan blanket on the sofa and switch the lamp on in there"
    assert frames_read(farm, text, "bethan") == [
        {"frame": "ACCOMPANYING", "theme": "mary_ann", "goal": "snug"},
        {"frame": "PLACING", "theme": "tartan_blanket", "goal": "sofa"},
        {"frame": "OPERATING", "device": "snug_lamp", "state": "on"},
    ]


@pytest.mark.parametrize(
    ("text", "theme"),
    [
        ("my pills, where have I put my pills", "pill_organiser"),
        ("where have i left the tv remote", "tv_remote"),
        ("wher is the tv remote", "tv_remote"),
        ("wher are my specs", "reading_glasses"),
    ],
)
def test_where_things_went(farm: Vocabulary, text: str, theme: str) -> None:
    assert frames_read(farm, text, "mary_ann") == [{"frame": "SEARCHING", "theme": theme}]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("is bethan here yet? find her for me, there's a dear", [{"frame": "SEARCHING", "theme": "bethan"}]),
        (
            "is rhys up yet? bring him his hoodie",
            [{"frame": "BRINGING", "theme": "hoodie", "beneficiary": "rhys"}],
        ),
        (
            "is dai back? take him the letters",
            [{"frame": "BRINGING", "theme": "letters", "beneficiary": "dai"}],
        ),
        (
            "is mary ann in the parlour? go and see",
            [{"frame": "SEARCHING", "theme": "mary_ann", "ground": "parlour"}],
        ),
    ],
)
def test_whether_someone_is_about(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "mary_ann") == frames


@pytest.mark.parametrize(
    ("text", "word"), [("bring me a can of coke", "coke"), ("bring me a bottle of wine", "wine")]
)
def test_a_container_the_world_lacks_is_what_it_holds(farm: Vocabulary, text: str, word: str) -> None:
    result = understand(text, farm, speaker="rhys")
    assert not result.accepted and f"'{word}'" in result.reason


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "take me through to the front parlour, I want to play the piano",
            [{"frame": "ACCOMPANYING", "theme": "me", "goal": "parlour"}],
        ),
        (
            "take me to the parlour I want to play the piano and then turn the chandelier on",
            [
                {"frame": "ACCOMPANYING", "theme": "me", "goal": "parlour"},
                {"frame": "OPERATING", "device": "parlour_chandelier", "state": "on"},
            ],
        ),
    ],
)
def test_why_the_speaker_asks_is_talk(farm: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(farm, text, "mary_ann") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("go to the desk in the den", [{"frame": "MOTION", "goal": "writing_desk"}]),
        (
            "fetch the pen from the desk in the den",
            [{"frame": "BRINGING", "theme": "fountain_pen", "source": "writing_desk", "beneficiary": "me"}],
        ),
        ("go to the desk", [{"frame": "MOTION", "goal": "desk"}]),
    ],
)
def test_furniture_told_by_its_room(text: str, frames: list[dict[str, str]]) -> None:
    assert (
        frames_read(world_of("tests/fixtures/language/people19/garden_flat.yaml"), text, "arthur") == frames
    )


@pytest.mark.parametrize(
    "text",
    [
        "the sun is in my eyes in the conservatory, pull the blinds down would you",
        "the sun is in my eyes, close the conservatory blinds",
    ],
)
def test_a_statement_before_a_request_is_talk(text: str) -> None:
    flat = world_of("tests/fixtures/language/people19/garden_flat.yaml")
    assert frames_read(flat, text, "margaret") == [
        {"frame": "OPERATING", "device": "conservatory_blinds", "state": "closed"}
    ]


def test_the_thing_said_before() -> None:
    flat = world_of("tests/fixtures/language/people19/garden_flat.yaml")
    assert frames_read(flat, "I fancy a sherry, bring me the bottle from the sideboard", "margaret") == [
        {"frame": "BRINGING", "theme": "sherry_bottle", "source": "sideboard", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("text", "refused"),
    [("bring me the candle holder", "candle holder"), ("bring me a candle holder", "candle holder")],
)
def test_a_longer_name_the_world_lacks(text: str, refused: str) -> None:
    result = understand(text, world_of("tests/fixtures/language/people18/townhouse.yaml"), speaker="nadia")
    assert not result.accepted and f"'{refused}'" in result.reason


@pytest.mark.parametrize("text", ["bring me the scented candle grandma", "fetch the coffee mug mate"])
def test_a_word_to_the_person_addressed_is_no_longer_name(text: str) -> None:
    assert (
        frames_read(world_of("tests/fixtures/language/people18/townhouse.yaml"), text, "nadia")[0]["frame"]
        == "BRINGING"
    )


@pytest.mark.parametrize(
    ("text", "theme"),
    [
        ("could rosa get her hairbrush", "hairbrush"),
        ("can rosa have her hairbrush", "hairbrush"),
        ("could rosa have the pepper grinder please", "pepper_mill"),
    ],
)
def test_asked_for_someone_else(text: str, theme: str) -> None:
    assert frames_read(world_of("worlds/test_bungalow/test_bungalow.yaml"), text, "walter") == [
        {"frame": "BRINGING", "theme": theme, "beneficiary": "rosa"}
    ]


def test_first_then_after_you(farm: Vocabulary) -> None:
    text = "first you go in the scullery, after you take the rubber gloves, after you give them to ffion"
    assert frames_read(farm, text, "jean_paul") == [
        {"frame": "MOTION", "goal": "scullery"},
        {"frame": "TAKING", "theme": "rubber_gloves", "source": "scullery"},
        {"frame": "BRINGING", "theme": "rubber_gloves", "source": "scullery", "beneficiary": "ffion"},
    ]
    assert frames_read(farm, "I could murder a chocolate", "mary_ann") == [
        {"frame": "BRINGING", "theme": "chocolates", "beneficiary": "me"}
    ]


def test_us_is_the_speaker(farm: Vocabulary) -> None:
    assert frames_read(farm, "grab us a couple of jam jars", "ffion") == [
        {"frame": "BRINGING", "theme": "jam_jars", "beneficiary": "me"}
    ]


def test_to_me_in_a_room() -> None:
    flat = world_of("worlds/test_flat/test_flat.yaml")
    assert frames_read(flat, "bring the book to me in the lounge", "olga") == [
        {"frame": "BRINGING", "theme": "book", "goal": "lounge", "beneficiary": "me"}
    ]
    assert frames_read(flat, "the book, bring it here would you, it's on the desk", "olga") == [
        {"frame": "BRINGING", "theme": "book", "source": "desk", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    "text",
    ["fetch the first aid kit, tom's cut his finger", "fetch the first aid kit, tom has cut his finger"],
)
def test_what_someone_has_done_is_talk(text: str) -> None:
    assert frames_read(world_of("tests/fixtures/language/people18/townhouse.yaml"), text, "nadia") == [
        {"frame": "BRINGING", "theme": "first_aid_kit", "beneficiary": "me"}
    ]


def test_the_shelf_for_books(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "Put the candle on the shelf for books.") == [
        {"frame": "PLACING", "theme": "candle", "goal": "bookshelf"}
    ]


@pytest.mark.parametrize(
    "text",
    [
        "rosa has been looking for the teddy, take it to her",
        "rosa's been looking for the teddy, take it to her",
        "rosa is looking for the teddy, take it to her",
    ],
)
def test_what_someone_has_been_doing_is_talk(text: str) -> None:
    assert frames_read(world_of("worlds/test_bungalow/test_bungalow.yaml"), text, "walter") == [
        {"frame": "BRINGING", "theme": "teddy_bear", "beneficiary": "rosa"}
    ]
