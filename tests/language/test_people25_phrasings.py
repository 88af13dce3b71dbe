"""Phrasings from the people25 development set (a bed-and-breakfast on two floors the reader was never tuned
on, ``tests/fixtures/language/people25/guest_house.yaml``) the reader first got wrong, each tried in the ERL
apartment as well:

* Jamaican English: "di", "tek", "mek", "pon", "inna", "likkle", "weh", "cyaan" for "the", "take", "make",
  "on", "in", "little", "where", "can't" (``commands.yaml``); "mi" for "I", "me" or "my" by where it stands,
  "him" for "he" or "his", "dem" after a thing its plural said again, "where X deh" for "where is X", "go a"
  for "go to", and "go" after the thing carried for "to" ("carry di teapot go a di kitchen")
  (``knic.language.dialects``);
* Northern English "tha" for "you" after a verb of asking ("has tha seen ..."), and "take it him": to him;
  Tagalog "paki-" before a verb ("pakibring"); "wait on me"; "make the lamp come on"; "like twenty" for a
  level; "up the stairs to ..." (``knic.language.dialects``);
* what is waited for after where the robot waits ("wait in the hall for the taxi driver") is dropped, as
  "wait for the postman" is (``knic.language.contracted``);
* "the ref" (Filipino English) is the fridge, "the CR" (comfort room) a toilet or bathroom, a "ball cap" a
  baseball cap (``synonyms.yaml``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

HOUSE = "tests/fixtures/language/people25/guest_house.yaml"


@lru_cache(maxsize=1)
def _house() -> Vocabulary:
    return world_of(HOUSE)


@pytest.fixture(scope="module")
def house() -> Vocabulary:
    """The bed-and-breakfast's vocabulary."""
    return _house()


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Tek di cup off di kitchen table and put it pon di counter",
            [
                {"frame": "TAKING", "theme": "cup", "source": "kitchen_table"},
                {"frame": "PLACING", "theme": "cup", "goal": "kitchen_counter"},
            ],
        ),
        ("Bring mi glasses, mi cyaan see", [{"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}]),
        ("Carry mi go a di bedroom", [{"frame": "ACCOMPANYING", "theme": "me", "goal": "bedroom"}]),
        (
            "Carry di apple and di lemon go a di kitchen",
            [
                {"frame": "BRINGING", "theme": "apple", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "lemon", "goal": "kitchen"},
            ],
        ),
        ("Where Tracy deh?", [{"frame": "SEARCHING", "theme": "tracy"}]),
        (
            "Close di blinds dem inna di bedroom",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
        (
            "Find Jack and give him him tablet",
            [
                {"frame": "SEARCHING", "theme": "jack"},
                {"frame": "BRINGING", "theme": "tablet", "beneficiary": "jack"},
            ],
        ),
    ],
)
def test_jamaican_english_in_the_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("text", "speaker", "frames"),
    [
        (
            "Carry di cornflakes and di marmalade from di sideboard go a di kitchen",
            "dolores",
            [
                {"frame": "BRINGING", "theme": "cornflakes", "source": "sideboard", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "marmalade", "source": "sideboard", "goal": "kitchen"},
            ],
        ),
        (
            "Tek di scrabble go a di lounge",
            "dolores",
            [{"frame": "BRINGING", "theme": "scrabble", "goal": "residents_lounge"}],
        ),
        (
            "Gimme di tea towel, mi hands wet",
            "dolores",
            [{"frame": "BRINGING", "theme": "tea_towel", "beneficiary": "me"}],
        ),
        ("Weh di first aid kit deh?", "dolores", [{"frame": "SEARCHING", "theme": "first_aid_kit"}]),
        ("Has tha seen me car keys?", "keith", [{"frame": "SEARCHING", "theme": "car_keys"}]),
        (
            "Mek di bedside lamp come on likkle bit, like twenty",
            "dolores",
            [{"frame": "OPERATING", "device": "bedside_lamp", "state": "20"}],
        ),
        ("Put the butter in the ref", "ligaya", [{"frame": "PLACING", "theme": "butter", "goal": "fridge"}]),
        ("Where's my ball cap at?", "beau", [{"frame": "SEARCHING", "theme": "baseball_cap"}]),
        (
            "Go and wait in the entrance hall for the taxi driver",
            "keith",
            [{"frame": "MOTION", "goal": "entrance_hall"}],
        ),
    ],
)
def test_the_voices_of_the_guest_house(
    house: Vocabulary, text: str, speaker: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(house, text, speaker) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        ("Has tha seen the remote?", [{"frame": "SEARCHING", "theme": "remote"}]),
        ("Turn on tha hallway light", [{"frame": "OPERATING", "device": "hallway_light", "state": "on"}]),
        (
            "Jack wants his tablet, take it him",
            [{"frame": "BRINGING", "theme": "tablet", "beneficiary": "jack"}],
        ),
        ("Pakibring the apple to the kitchen", [{"frame": "BRINGING", "theme": "apple", "goal": "kitchen"}]),
        (
            "Paki-close the bedroom blinds",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
        ("Go to the kitchen and wait on me", [{"frame": "MOTION", "goal": "kitchen"}]),
        (
            "Make the living room dimmer come on a little bit, like forty",
            [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "40"}],
        ),
        (
            "Make the hallway light go off",
            [{"frame": "OPERATING", "device": "hallway_light", "state": "off"}],
        ),
        (
            "Help me up the stairs to the bedroom",
            [{"frame": "ACCOMPANYING", "theme": "me", "goal": "bedroom"}],
        ),
        ("Go to the bedroom and wait in there for Tracy", [{"frame": "MOTION", "goal": "bedroom"}]),
        # "go" after "after that" starts an action of its own; "like" after "i'd" is the verb
        (
            "put the coke can in the bin and after that go to the hallway",
            [
                {"frame": "PLACING", "theme": "coke_can", "goal": "bin"},
                {"frame": "MOTION", "goal": "hallway"},
            ],
        ),
        ("I'd like forty apples", [{"frame": "BRINGING", "theme": "apple", "beneficiary": "me"}]),
    ],
)
def test_other_englishes_in_the_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames
