"""Phrasings from the people28 development set (a mews house on three floors with a roof garden the reader was
never tuned on, ``tests/fixtures/language/people28/mews_house.yaml``) the reader first got wrong, each tried
in the ERL apartment as well:

* a request asked as what the robot is about to do ("are you going to switch off the hall light?", "are you
  gonna bring me the teapot?"): the verb said first, as "will you" already is; "are you going to be long?",
  "are you going to the kitchen?" and "why are you going to ...?" stay questions asking nothing of the robot
  (``knic.language.contracted``);
* "on" after the state "off" or "on" before where ("switch the light off on the landing", "all lights off on
  the balcony and the roof garden"): the place, not the state said again (``knic.language.contracted``);
* a short trip said as "whip down to", "whip round to", "mosey on over to" (British and American English) or
  "gan" (Geordie and Scots "go"): the robot goes there, as with "nip to" (``commands.yaml``);
* "hoy" (Geordie and Scots "throw"): "hoy us the tape measure" brings it, "hoy the wellies on the shoe rack"
  puts them there, "hoy the jump leads to Dwayne" gives them (``commands.yaml``, ``knic.language.learners``);
* "where'd my stetson get to?", "where did Pip get to?": "where is ..." (``knic.language.contracted``);
* "is" after a verb of giving and before a thing ("fetch is the hammer off the workbench", "bring is the
  teapot", Geordie and Scots): "me"; "where is the coke" stays (``knic.language.contracted``);
* a dimmer said alone "closed" ("close the desk lamp first, then open the study blind", Hong Kong English, as
  "close the light" is for a light): off; "turn the dimmer right up" stays full (``knic.language.roles``);
* "all the light", "all the lamp", "all the blind" (a learner's singular after "all"): every one, as "all the
  lights" is ("close all the light in the study": the study light and the desk lamp;
  ``knic.language.contracted``);
* when said after a request ("... this morning", "tonight") and "make it so" (a naval "do it") ask nothing
  more (``commands.yaml``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import assert_asked, frames_read, world_of

HOUSE = "tests/fixtures/language/people28/mews_house.yaml"


@lru_cache(maxsize=1)
def _house() -> Vocabulary:
    return world_of(HOUSE)


#: what each case of the tests below says: in the ERL apartment or not, the words, the frames they are read as
_SAID = ("erl", "text", "frames")
Frames = list[dict[str, str]]


def _said(erl_vocabulary: Vocabulary, erl: bool, text: str, speaker: str) -> Frames:
    """The frames ``text`` is read as in the ERL apartment (said by annie) or in the mews house (by
    ``speaker``)."""
    return frames_read(erl_vocabulary if erl else _house(), text, "annie" if erl else speaker)


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "Are you going to switch off the hall light?",
            [{"frame": "OPERATING", "device": "hall_light", "state": "off"}],
        ),
        (
            "are you gonna bring me the teapot?",
            [{"frame": "BRINGING", "theme": "teapot", "beneficiary": "me"}],
        ),
        (
            "so are you going to put the butter in the fridge, dear?",
            [{"frame": "PLACING", "theme": "butter", "goal": "fridge"}],
        ),
        (
            "Are you going to go to the study and take the laptop to Winnie?",
            [
                {"frame": "MOTION", "goal": "study"},
                {"frame": "BRINGING", "theme": "laptop", "source": "study", "beneficiary": "winnie"},
            ],
        ),
    ],
)
def test_a_request_asked_as_a_plan_is_the_request_in_the_house(
    text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(_house(), text, "odette") == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "are you going to bring me a coke from the kitchen?",
            [{"frame": "BRINGING", "theme": "coke_can", "source": "kitchen", "beneficiary": "me"}],
        ),
        (
            "are you going to open the bedroom blinds halfway?",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "50"}],
        ),
    ],
)
def test_a_request_asked_as_a_plan_is_the_request_in_the_apartment(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


def test_a_plan_asked_of_an_ambiguous_thing_asks_which() -> None:
    assert_asked(_house(), "Are you going to bring me the milk?", "milk", "odette")


@pytest.mark.parametrize(
    "text",
    [
        "are you going to be long?",
        "are you going to the kitchen?",
        "why are you going to open the study blind?",
    ],
)
def test_a_question_about_the_plan_itself_asks_nothing(vocabulary: Vocabulary, text: str) -> None:
    for world in (_house(), vocabulary):
        result = understand(text, world, speaker="odette" if world is _house() else "annie")
        assert not result.accepted and "no action" in result.reason, result.reason


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "switch the light off on the landing",
            [{"frame": "OPERATING", "device": "landing_light", "state": "off"}],
        ),
        (
            False,
            "all lights off on the balcony and the roof garden",
            [
                {"frame": "OPERATING", "device": "balcony_light", "state": "off"},
                {"frame": "OPERATING", "device": "roof_garden_lights", "state": "off"},
            ],
        ),
        (
            True,
            "switch the lights off on the bedroom",
            [{"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}],
        ),
    ],
)
def test_on_after_the_state_says_where(vocabulary: Vocabulary, erl: bool, text: str, frames: Frames) -> None:
    assert _said(vocabulary, erl, text, "dwayne") == frames


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "Could you whip down to the kitchen and grab us the orange juice",
            [
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "orange_juice", "source": "kitchen", "beneficiary": "me"},
            ],
        ),
        (False, "Mosey on over to the piano", [{"frame": "MOTION", "goal": "piano"}]),
        (False, "gan doon to the workshop", [{"frame": "MOTION", "goal": "workshop"}]),
        (True, "whip round to the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
        (True, "gan to the bedroom", [{"frame": "MOTION", "goal": "bedroom"}]),
    ],
)
def test_a_short_trip_in_other_words_goes_there(
    vocabulary: Vocabulary, erl: bool, text: str, frames: Frames
) -> None:
    assert _said(vocabulary, erl, text, "lenny") == frames


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "Howay man, hoy us the tape measure",
            [{"frame": "BRINGING", "theme": "tape_measure", "beneficiary": "me"}],
        ),
        (
            False,
            "Hoy the wellies on the shoe rack",
            [{"frame": "PLACING", "theme": "wellies", "goal": "shoe_rack"}],
        ),
        (
            False,
            "hoy the jump leads to Dwayne",
            [{"frame": "BRINGING", "theme": "jump_leads", "beneficiary": "dwayne"}],
        ),
        (True, "hoy us the coke", [{"frame": "BRINGING", "theme": "coke_can", "beneficiary": "me"}]),
        (False, "where did Pip get to?", [{"frame": "SEARCHING", "theme": "pip"}]),
        (True, "where'd my glasses get to?", [{"frame": "SEARCHING", "theme": "glasses"}]),
        (
            False,
            "Living room light to forty percent. Make it so.",
            [{"frame": "OPERATING", "device": "living_room_light", "state": "40"}],
        ),
        (
            False,
            "Are you going to open the bedroom curtains halfway this morning?",
            [{"frame": "OPERATING", "device": "bedroom_curtains", "state": "50"}],
        ),
        (
            True,
            "close the blinds tonight",
            [{"frame": "OPERATING", "device": "bedroom_blinds", "state": "closed"}],
        ),
    ],
)
def test_regional_words_and_what_asks_nothing_more(
    vocabulary: Vocabulary, erl: bool, text: str, frames: Frames
) -> None:
    assert _said(vocabulary, erl, text, "lenny") == frames


def test_a_lost_thing_the_world_lacks_is_named() -> None:
    result = understand("Where'd my stetson get to?", _house(), speaker="dwayne")
    assert not result.accepted and "no 'stetson'" in result.reason, result.reason


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "Fetch is the hammer off the workbench, pet",
            [{"frame": "BRINGING", "theme": "hammer", "source": "workbench", "beneficiary": "me"}],
        ),
        (
            False,
            "Am clamming for a cuppa, bring is the teapot",
            [{"frame": "BRINGING", "theme": "teapot", "beneficiary": "me"}],
        ),
        (True, "get is the coke", [{"frame": "BRINGING", "theme": "coke_can", "beneficiary": "me"}]),
        (True, "where is the coke", [{"frame": "SEARCHING", "theme": "coke_can"}]),
    ],
)
def test_is_after_a_verb_of_giving_is_me(
    vocabulary: Vocabulary, erl: bool, text: str, frames: Frames
) -> None:
    assert _said(vocabulary, erl, text, "lenny") == frames


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "Close the desk lamp first, then open the study blind",
            [
                {"frame": "OPERATING", "device": "desk_lamp", "state": "off"},
                {"frame": "OPERATING", "device": "study_blind", "state": "open"},
            ],
        ),
        (False, "close the floor lamp", [{"frame": "OPERATING", "device": "floor_lamp", "state": "off"}]),
        (True, "close the dimmer", [{"frame": "OPERATING", "device": "living_room_dimmer", "state": "off"}]),
    ],
)
def test_a_dimmer_closed_is_off(vocabulary: Vocabulary, erl: bool, text: str, frames: Frames) -> None:
    assert _said(vocabulary, erl, text, "winnie") == frames


@pytest.mark.parametrize(
    _SAID,
    [
        (
            False,
            "Close all the light in the study",
            [
                {"frame": "OPERATING", "device": "study_light", "state": "off"},
                {"frame": "OPERATING", "device": "desk_lamp", "state": "off"},
            ],
        ),
        (
            True,
            "switch off all the light in the bedroom",
            [{"frame": "OPERATING", "device": "bedroom_lights", "state": "off"}],
        ),
    ],
)
def test_all_before_a_singular_is_every_one(
    vocabulary: Vocabulary, erl: bool, text: str, frames: Frames
) -> None:
    assert _said(vocabulary, erl, text, "winnie") == frames
