"""Phrasings from the people31 development set (the commands of robot competitions, RoboCup@Home's GPSR and
the ERL, in an arena set up as a small flat the reader was never tuned on,
``tests/fixtures/language/people31/arena_flat.yaml``, and in the ERL apartment) the reader first got wrong,
each tried in the family house of people24 or the ERL apartment as well:

* "the exit" is the room the front door opens into, as "the front door" is ("guide her to the exit", "go and
  wait at the exit"; ``knic.language.vocabulary``); in the ERL apartment, whose bench vocabulary has no
  doors, the entrance hall (``worlds/erl_home/lexicon.yaml``);
* a name said the other way round ("the clicker for the telly", the tv remote) is not made of a word that
  begins the next name: "search the tv bench for the tv clicker" searches the tv bench for the remote, not
  a "tv bench" made of "bench for the tv" (``knic.language.naming``; met by the grammar's samples once the
  ERL lexicon said "exit");
* a room or a piece of furniture said after "then" with no verb of its own, once the robot was sent to a
  place, is a second going ("go to the bedroom, then the kitchen", "navigate to the living room, then, um, to
  the dining room, and grab the candle"); "no, the kitchen" still corrects (``knic.language.stepwise``);
* the place gone to is the source of each thing of the next action, not only the first ("go to the kitchen
  and bring the milk and the coke to the dining table"; ``knic.language.chains``);
* an action said after another with "first" before its verb is done first ("bring me the coke, but first
  switch on the kitchen light", "go to the living room, and, er, wait, first switch on the floor lamp");
  a learner's "and after you" goes on in order ("take the apple, and after you bring it to Sven"), where
  "bring me the apple after you switch on the light" still puts the light first; going "to" do a thing is
  going and doing it ("you go to search Hugo in the kitchen", "come to get the remote")
  (``knic.language.stepwise``);
* a learner's "where stays the tv remote?" (Italian "dove sta", Spanish "dónde está") asks where it is
  (``commands.yaml``);
* what a person wants to do, said with no object before the request, is its reason ("Hugo wants to leave,
  guide him to the exit", "annie wants to sleep, close the blinds"), not a request told of them (as "tracy
  wants to fetch her glasses" still is); the person stays said for "him" or "her" (``knic.language.terse``).

Found by probing the voices beyond the set:

* a label said first ("your mission: find Ines and guide her to the exit", "the job, ...") is no thing the
  world lacks when the request's "her" or "it" follows a thing it names; "the fan, turn it on" is still
  refused naming the fan (``knic.language.remarks``);
* "where can I find the cleanser?" asks where it is; "ask Ines to follow you to the kitchen", "... to come
  with you to ..." is taken there, as "ask Ines to come to the kitchen" is (``commands.yaml``);
* "bring the banana to Amara and the pear to Ines": each thing goes to its own person, not both to the last
  said; "go to the kitchen, but before that switch on the light" switches first; a learner's "before to go
  to the kitchen, ..." is "before going"; a place said first with its preposition ("In the kitchen, find the
  lemon", "in the bedroom turn on the light", "from the fridge bring me the milk") is where the first action
  is done (``knic.language.stepwise``);
* where someone is, said out or guessed after a search ("find Hugo, he is in the kitchen", "she should be in
  the bedroom", "he is probably in the study") is where to look, as "he's in the den" was; "like" said as a
  filler between a preposition and a name ("bring it to Yuki at like the entrance") is dropped; "is he in the
  kitchen?" after a question or a request ("Find Hugo. Is he in the kitchen?") searches there
  (``knic.language.contracted``);
* "approach the dining table", "enter the kitchen", "visit the kitchen": a going there (``commands.yaml``);
* "dispose of the cardboard box", "get rid of the tissues", "throw out the cloth": into the world's one bin,
  as "throw away" and "bin the ..." are; a place said after still wins (``knic.language.household``);
* "crank it up to full", "whack it up to full", "bump it up to 60", "knock it down to twenty" (informal
  English for turning) set that level; "carry on to the study" goes there (``commands.yaml``);
* a learner's "bring the apple at Annie", "bring at me the glasses" ("a", "à"): "to" before a person
  (``knic.language.learners``); "Annie is where?", "the glasses are where" (asked back): where she or they
  are (``knic.language.household``).
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

ARENA = "tests/fixtures/language/people31/arena_flat.yaml"
HOUSE = "tests/fixtures/language/people24/family_house.yaml"
#: someone of each world to say what is said there
SPEAKERS = {ARENA: "ruben", HOUSE: "mark"}


@lru_cache(maxsize=2)
def _world(file: str) -> Vocabulary:
    return world_of(file)


def _read(file: str, text: str) -> list[dict[str, str]]:
    return frames_read(_world(file), text, SPEAKERS[file])


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (ARENA, "lead Hugo to the exit", [{"frame": "ACCOMPANYING", "theme": "hugo", "goal": "entrance"}]),
        (ARENA, "so, er, go and wait at the exit", [{"frame": "MOTION", "goal": "entrance"}]),
        (HOUSE, "take Joy to the exit", [{"frame": "ACCOMPANYING", "theme": "joy", "goal": "hallway"}]),
        (HOUSE, "wait at the exit for the postman", [{"frame": "MOTION", "goal": "hallway"}]),
    ],
)
def test_the_exit_is_where_the_front_door_opens(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_the_exit_of_the_erl_apartment_is_its_entrance_hall(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "escort Tracy to the exit, please") == [
        {"frame": "ACCOMPANYING", "theme": "tracy", "goal": "entrance_hall"}
    ]


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "search the tv bench for the tv clicker",
            [{"frame": "SEARCHING", "theme": "remote", "ground": "tv_table"}],
        ),
        (
            "bring me the clicker for the telly",
            [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}],
        ),
    ],
)
def test_a_name_turned_round_takes_no_word_of_the_next_name(
    vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary, text) == frames


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            ARENA,
            "Go to the bedroom, then the kitchen, then come back to the living room",
            [
                {"frame": "MOTION", "goal": "bedroom"},
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "MOTION", "goal": "living_room"},
            ],
        ),
        (
            HOUSE,
            "go to the garage then to the kitchen and get the butter",
            [
                {"frame": "MOTION", "goal": "garage"},
                {"frame": "MOTION", "goal": "kitchen"},
                {"frame": "BRINGING", "theme": "butter", "source": "kitchen", "beneficiary": "me"},
            ],
        ),
        (
            HOUSE,
            "head to the landing, then the family bathroom",
            [{"frame": "MOTION", "goal": "landing"}, {"frame": "MOTION", "goal": "family_bathroom"}],
        ),
        (ARENA, "go to the bedroom, no, the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    ],
)
def test_a_place_said_after_then_is_another_going(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_a_going_then_several_things_erl(vocabulary: Vocabulary) -> None:
    assert frames_read(
        vocabulary, "navigate to the living room, then, um, to the dining room, and grab the candle"
    ) == [
        {"frame": "MOTION", "goal": "living_room"},
        {"frame": "MOTION", "goal": "dining_room"},
        {"frame": "TAKING", "theme": "candle", "source": "dining_room"},
    ]
    assert frames_read(vocabulary, "go to the kitchen and bring the apple and the lemon to tracy") == [
        {"frame": "MOTION", "goal": "kitchen"},
        {"frame": "BRINGING", "theme": "apple", "source": "kitchen", "beneficiary": "tracy"},
        {"frame": "BRINGING", "theme": "lemon", "source": "kitchen", "beneficiary": "tracy"},
    ]


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            HOUSE,
            "go to the pantry and bring me the biscuits and the rice",
            [
                {"frame": "MOTION", "goal": "pantry"},
                {"frame": "BRINGING", "theme": "biscuits", "source": "pantry", "beneficiary": "me"},
                {"frame": "BRINGING", "theme": "rice", "source": "pantry", "beneficiary": "me"},
            ],
        ),
        (
            HOUSE,
            "go to the utility room and take the torch and the detergent to the garage",
            [
                {"frame": "MOTION", "goal": "utility_room"},
                {"frame": "BRINGING", "theme": "torch", "source": "utility_room", "goal": "garage"},
                {"frame": "BRINGING", "theme": "detergent", "source": "utility_room", "goal": "garage"},
            ],
        ),
    ],
)
def test_the_place_gone_to_is_where_each_thing_is_from(
    file: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(file, text) == frames


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            HOUSE,
            "bring me a beer, but first turn on the garden lights",
            [
                {"frame": "OPERATING", "device": "garden_lights", "state": "on"},
                {"frame": "BRINGING", "theme": "beer", "beneficiary": "me"},
            ],
        ),
        (
            ARENA,
            "Okay so, go to the living room, and, er, wait, first switch on the floor lamp",
            [
                {"frame": "OPERATING", "device": "floor_lamp", "state": "on"},
                {"frame": "MOTION", "goal": "living_room"},
            ],
        ),
        (
            HOUSE,
            "take the drill and after you bring it to Mark",
            [
                {"frame": "TAKING", "theme": "drill"},
                {"frame": "BRINGING", "theme": "drill", "beneficiary": "mark"},
            ],
        ),
        (
            ARENA,
            "Please, you go to search Hugo in the kitchen",
            [{"frame": "SEARCHING", "theme": "hugo", "ground": "kitchen"}],
        ),
        (
            HOUSE,
            "go to fetch the tiffin box",
            [{"frame": "BRINGING", "theme": "tiffin_box", "beneficiary": "me"}],
        ),
        (ARENA, "Where stays the tv remote?", [{"frame": "SEARCHING", "theme": "tv_remote"}]),
    ],
)
def test_steps_said_out_of_order_or_in_a_learners_words(
    file: str, text: str, frames: list[dict[str, str]]
) -> None:
    assert _read(file, text) == frames


@pytest.mark.parametrize(
    ("text", "frames"),
    [
        (
            "bring me the juice but first open the blinds",
            [
                {"frame": "OPERATING", "device": "bedroom_blinds", "state": "open"},
                {"frame": "BRINGING", "theme": "juice", "beneficiary": "me"},
            ],
        ),
        (
            "bring me the apple after you switch on the hallway light",
            [
                {"frame": "OPERATING", "device": "hallway_light", "state": "on"},
                {"frame": "BRINGING", "theme": "apple", "beneficiary": "me"},
            ],
        ),
        ("come to get the remote", [{"frame": "BRINGING", "theme": "remote", "beneficiary": "me"}]),
        ("where stays the tablet", [{"frame": "SEARCHING", "theme": "tablet"}]),
    ],
)
def test_steps_in_the_erl_apartment(vocabulary: Vocabulary, text: str, frames: list[dict[str, str]]) -> None:
    assert frames_read(vocabulary, text) == frames


def test_what_a_person_wants_to_do_is_the_reason_for_the_request(vocabulary: Vocabulary) -> None:
    assert _read(ARENA, "Hugo wants to leave, guide him to the exit") == [
        {"frame": "ACCOMPANYING", "theme": "hugo", "goal": "entrance"}
    ]
    assert _read(HOUSE, "Joy wants to rest, close the annexe curtains") == [
        {"frame": "OPERATING", "device": "annexe_curtains", "state": "closed"}
    ]
    assert frames_read(vocabulary, "annie wants to read, bring her the glasses", "tracy") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "annie"}
    ]
    assert frames_read(vocabulary, "tracy wants to fetch her glasses", "annie") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "tracy"}
    ]


def test_a_label_said_first_is_no_thing_the_world_lacks(vocabulary: Vocabulary) -> None:
    assert _read(ARENA, "Your mission: find Ines and guide her to the exit") == [
        {"frame": "SEARCHING", "theme": "ines"},
        {"frame": "ACCOMPANYING", "theme": "ines", "goal": "entrance"},
    ]
    assert _read(HOUSE, "the job, find Rosa and give her the detergent") == [
        {"frame": "SEARCHING", "theme": "rosa"},
        {"frame": "BRINGING", "theme": "detergent", "beneficiary": "rosa"},
    ]
    result = understand("the fan, turn it on", _world(HOUSE), speaker="mark")
    assert not result.accepted and "fan" in result.reason
    result = understand("the television, switch it on", vocabulary)
    assert not result.accepted and "television" in result.reason


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (ARENA, "Where can I find the cleanser?", [{"frame": "SEARCHING", "theme": "cleanser"}]),
        (HOUSE, "where can we find the torch", [{"frame": "SEARCHING", "theme": "torch"}]),
        (
            ARENA,
            "Tell Sven to follow you to the kitchen",
            [{"frame": "ACCOMPANYING", "theme": "sven", "goal": "kitchen"}],
        ),
        (
            HOUSE,
            "ask Joy to come with you to the kitchenette",
            [{"frame": "ACCOMPANYING", "theme": "joy", "goal": "kitchenette"}],
        ),
    ],
)
def test_where_to_find_and_asked_to_follow(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_asked_to_follow_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "ask jack to follow you to the living room") == [
        {"frame": "ACCOMPANYING", "theme": "jack", "goal": "living_room"}
    ]


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            ARENA,
            "Bring the banana to Amara and the pear to Ines",
            [
                {"frame": "BRINGING", "theme": "banana", "beneficiary": "amara"},
                {"frame": "BRINGING", "theme": "pear", "beneficiary": "ines"},
            ],
        ),
        (
            HOUSE,
            "Take the beer to Mark and the yoghurt to Priya",
            [
                {"frame": "BRINGING", "theme": "beer", "beneficiary": "mark"},
                {"frame": "BRINGING", "theme": "yoghurt", "beneficiary": "priya"},
            ],
        ),
        (
            ARENA,
            "Go to the kitchen, but before that switch on the corridor light",
            [
                {"frame": "OPERATING", "device": "corridor_light", "state": "on"},
                {"frame": "MOTION", "goal": "kitchen"},
            ],
        ),
        (
            HOUSE,
            "Before to go to the garage, switch on the garage light",
            [
                {"frame": "OPERATING", "device": "garage_light", "state": "on"},
                {"frame": "MOTION", "goal": "garage"},
            ],
        ),
    ],
)
def test_each_thing_to_its_own_and_before_that(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_each_thing_to_its_own_in_the_erl_apartment(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "bring the glasses to annie and the juice to tracy") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "annie"},
        {"frame": "BRINGING", "theme": "juice", "beneficiary": "tracy"},
    ]


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            ARENA,
            "Find Hugo, he is in the kitchen",
            [{"frame": "SEARCHING", "theme": "hugo", "ground": "kitchen"}],
        ),
        (
            ARENA,
            "Find Ines, she might be in the bedroom",
            [{"frame": "SEARCHING", "theme": "ines", "ground": "bedroom"}],
        ),
        (
            HOUSE,
            "find Arjun, he should be in the living room",
            [{"frame": "SEARCHING", "theme": "arjun", "ground": "living_room"}],
        ),
    ],
)
def test_where_someone_is_said_after_a_search(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_where_someone_is_said_after_a_search_erl(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "find tracy, she is probably in the kitchen") == [
        {"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}
    ]


@pytest.mark.parametrize(
    ("file", "text", "goal"),
    [
        (ARENA, "approach the dining table", "dining_table"),
        (ARENA, "Enter the kitchen", "kitchen"),
        (HOUSE, "visit the garden office", "home_office"),
        (HOUSE, "approach the barbecue", "barbecue"),
    ],
)
def test_approach_enter_and_visit_go_there(file: str, text: str, goal: str) -> None:
    assert _read(file, text) == [{"frame": "MOTION", "goal": goal}]


def test_at_a_person_and_asked_back_where(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "Bring the apple at Annie", "tracy") == [
        {"frame": "BRINGING", "theme": "apple", "beneficiary": "annie"}
    ]
    assert frames_read(vocabulary, "Bring at me the glasses") == [
        {"frame": "BRINGING", "theme": "glasses", "beneficiary": "me"}
    ]
    assert frames_read(vocabulary, "bring the coke at the kitchen table") == [
        {"frame": "BRINGING", "theme": "coke_can", "source": "kitchen_table", "beneficiary": "me"}
    ]
    assert _read(ARENA, "Give the crisps at Sven") == [
        {"frame": "BRINGING", "theme": "crisps", "beneficiary": "sven"}
    ]
    assert frames_read(vocabulary, "Annie is where?", "tracy") == [{"frame": "SEARCHING", "theme": "annie"}]
    assert _read(HOUSE, "the car keys are where?") == [{"frame": "SEARCHING", "theme": "car_keys"}]


def test_like_said_as_a_filler_before_a_name(vocabulary: Vocabulary) -> None:
    assert _read(ARENA, "The umbrella, bring it to Yuki at like the entrance") == [
        {"frame": "BRINGING", "theme": "umbrella", "goal": "entrance", "beneficiary": "yuki"}
    ]
    assert _read(HOUSE, "put the frozen peas back in like the chest freezer") == [
        {"frame": "PLACING", "theme": "frozen_peas", "goal": "chest_freezer"}
    ]
    assert frames_read(vocabulary, "I would like the juice") == [
        {"frame": "BRINGING", "theme": "juice", "beneficiary": "me"}
    ]


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            ARENA,
            "crank the floor lamp up to full",
            [{"frame": "OPERATING", "device": "floor_lamp", "state": "100"}],
        ),
        (
            ARENA,
            "the dining room light, bump it up to 60",
            [{"frame": "OPERATING", "device": "dining_room_light", "state": "60"}],
        ),
        (
            HOUSE,
            "knock the reading lamp down to twenty",
            [{"frame": "OPERATING", "device": "reading_lamp", "state": "20"}],
        ),
        (HOUSE, "carry on through to the kitchen", [{"frame": "MOTION", "goal": "kitchen"}]),
    ],
)
def test_informal_verbs_of_turning_and_going_on(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_is_he_there_asked_after_a_search(vocabulary: Vocabulary) -> None:
    assert _read(ARENA, "Find Hugo. Is he in the kitchen?") == [
        {"frame": "SEARCHING", "theme": "hugo", "ground": "kitchen"}
    ]
    assert _read(HOUSE, "where is the drill? is it in the garage?") == [
        {"frame": "SEARCHING", "theme": "drill", "ground": "garage"}
    ]
    assert frames_read(vocabulary, "where is tracy? is she in the kitchen?") == [
        {"frame": "SEARCHING", "theme": "tracy", "ground": "kitchen"}
    ]


@pytest.mark.parametrize(
    ("file", "text", "frames"),
    [
        (
            ARENA,
            "In the kitchen, find the lemon",
            [{"frame": "SEARCHING", "theme": "lemon", "ground": "kitchen"}],
        ),
        (
            ARENA,
            "In the bedroom turn on the light",
            [{"frame": "OPERATING", "device": "bedroom_light", "state": "on"}],
        ),
        (
            HOUSE,
            "from the fridge bring me the butter",
            [{"frame": "BRINGING", "theme": "butter", "source": "fridge", "beneficiary": "me"}],
        ),
        (
            HOUSE,
            "on the coffee table put the newspaper",
            [{"frame": "PLACING", "theme": "newspaper", "goal": "coffee_table"}],
        ),
    ],
)
def test_a_place_said_before_the_verb(file: str, text: str, frames: list[dict[str, str]]) -> None:
    assert _read(file, text) == frames


def test_a_place_said_before_the_verb_erl(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "in the living room, look for the remote") == [
        {"frame": "SEARCHING", "theme": "remote", "ground": "living_room"}
    ]


def test_disposed_of_into_the_one_bin(vocabulary: Vocabulary) -> None:
    assert frames_read(vocabulary, "Dispose of the cardboard box") == [
        {"frame": "PLACING", "theme": "cardboard_box", "goal": "bin"}
    ]
    assert frames_read(vocabulary, "get rid of the tissues") == [
        {"frame": "PLACING", "theme": "tissues", "goal": "bin"}
    ]
    assert _read(ARENA, "throw out the cloth") == [
        {"frame": "PLACING", "theme": "cloth", "goal": "trash_bin"}
    ]
    assert _read(ARENA, "get rid of the cloth in the sink") == [
        {"frame": "PLACING", "theme": "cloth", "goal": "sink"}
    ]
