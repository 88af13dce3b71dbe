"""Phrasings from the people41 development set (one wing of a care home the reader was never tuned on,
``tests/fixtures/language/people41/care_wing.yaml``) the reader first got wrong, each tried in the ERL
apartment as well:

* being shown a place is being taken there ("can you show me where the dining room is", "show me the way to
  the bathroom"); the speaker asking to be taken in the passive ("I should like to be taken to the garden
  room", "could I be taken to the living room"); "where's the bathroom? can you take me there"; "where do you
  keep the sponge?" asks where it is (``knic.language.askedfor``);
* who asked for a request, said after it ("..., Fenella said to", "..., as Tracy said"), and what someone is
  due ("..., Hortense is due her obs") are left out; "is Clementine still here?" asks where she is;
* a thing moved "off" one place "and onto" or ", to" another, without a verb ("care folder off the filing
  cabinet and onto the station desk", "pill pot off the meds trolley, to Wilfred"): from the one to the other;
* a nurse's words: "query whether" asks as "check whether" does, so does "do you know if"; "stat" is at once
  (``commands.yaml``); "meds" and "medication" are medicine, "BP" blood pressure (``synonyms.yaml``);
* "my blind" (or "her blind" of the person named before it) is the one in the owner's room when the others
  are named in the plural ("the lounge blinds") (``knic.language.owned``);
* how a thing is to be done, said around a request ("shut, quietly", "softly", "gently") is no word of it;
  someone said by who they are and then by name ("that nurse, Fenella") is them; what two people want to do
  after the request ("..., Gran and Mabel want to do it after lunch") is a reason;
* a thing "returned to" a piece of furniture is put back on it ("return the poetry book to the bookshelf");
  returned to a person or a room, it is given or brought as before (``knic.language.askedfor.returned_read``);
* a thing that "may remain where it is", said after a request, asks nothing.
"""

from __future__ import annotations

from functools import lru_cache

import pytest

from knic.language import understand
from knic.language.vocabulary import Vocabulary

from .conftest import frames_read, world_of

WING = "tests/fixtures/language/people41/care_wing.yaml"


@lru_cache(maxsize=1)
def _wing() -> Vocabulary:
    return world_of(WING)


@pytest.fixture(scope="module")
def wing() -> Vocabulary:
    """The care wing's vocabulary."""
    return _wing()


def _one(frame: str, **roles: str) -> dict[str, str]:
    return {"frame": frame, **roles}


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("can you show me where the dining room is", "dining_room"),
        ("Show me the way to the quiet room, please", "quiet_room"),
        ("I should like to be taken to the garden room, if you would be so good.", "garden_room"),
        ("Sorry, I'm new, where's the assisted bathroom? Can you take me there", "assisted_bathroom"),
    ],
)
def test_shown_or_taken_to_a_place_in_the_wing(wing: Vocabulary, text: str, place: str) -> None:
    assert frames_read(wing, text, "delphine") == [_one("ACCOMPANYING", theme="me", goal=place)]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("could you show me where the kitchen is", "kitchen"),
        ("show me the way to the bathroom", "bathroom"),
        ("I'd like to be taken to the bedroom", "bedroom"),
        ("could I be taken to the living room", "living_room"),
        ("where's the bathroom? can you take me there", "bathroom"),
    ],
)
def test_shown_or_taken_to_a_place_in_the_apartment(vocabulary: Vocabulary, text: str, place: str) -> None:
    assert frames_read(vocabulary, text) == [_one("ACCOMPANYING", theme="me", goal=place)]


def test_where_something_is_kept_asks_where_it_is(vocabulary: Vocabulary, wing: Vocabulary) -> None:
    assert frames_read(vocabulary, "where do you keep the sponge?") == [_one("SEARCHING", theme="sponge")]
    assert frames_read(wing, "Where do we keep the thermometer?", "delphine") == [
        _one("SEARCHING", theme="thermometer")
    ]


#: commands read in the wing and in the ERL apartment, each with its speaker and its frames
READ = [
    # who asked for the request, what someone is due, "is ... still here"
    (WING, "Bring the pill pot to Lionel, Fenella said to", "delphine", [
        _one("BRINGING", theme="pill_pot", beneficiary="lionel")]),
    (WING, "Thermometer to Mabel stat, she's spiking a temp", "fenella", [
        _one("BRINGING", theme="thermometer", beneficiary="mabel")]),
    (WING, "Hopper, BP cuff to the quiet room please, Hortense is due her obs", "fenella", [
        _one("BRINGING", theme="blood_pressure_cuff", goal="quiet_room")]),
    (WING, "Is Clementine still here? Visiting's finished.", "kwame", [
        _one("SEARCHING", theme="clementine")]),
    ("erl", "bring me the glasses, Tracy said to", "annie", [
        _one("BRINGING", theme="glasses", beneficiary="me")]),
    ("erl", "bring the apple to Jack, as Tracy said", "annie", [
        _one("BRINGING", theme="apple", beneficiary="jack")]),
    ("erl", "bring the mug to the kitchen, Jack is due his tea", "annie", [
        _one("BRINGING", theme="mug", goal="kitchen")]),
    ("erl", "is Tracy still here?", "annie", [_one("SEARCHING", theme="tracy")]),
    ("erl", "glasses to Annie stat", "jack", [_one("BRINGING", theme="glasses", beneficiary="annie")]),
    # off one place and onto another
    (WING, "Care folder off the filing cabinet and onto the station desk please", "fenella", [
        _one("BRINGING", theme="care_folder", source="filing_cabinet", goal="station_desk")]),
    (WING, "Pill pot off the meds trolley, to Wilfred. Shh.", "kwame", [
        _one("BRINGING", theme="pill_pot", source="medicine_trolley", beneficiary="wilfred")]),
    (WING, "switch off the reading lamp, to save power", "hortense", [
        _one("OPERATING", device="reading_lamp", state="off")]),
    ("erl", "apple off the kitchen table and onto the dining table", "annie", [
        _one("BRINGING", theme="apple", source="kitchen_table", goal="dining_table")]),
    # a nurse's words
    (WING, "Query whether Wilfred is still in the garden room", "fenella", [
        _one("SEARCHING", theme="wilfred", ground="garden_room")]),
    (WING, "Do you know if Mabel is in the day lounge", "lionel", [
        _one("SEARCHING", theme="mabel", ground="day_lounge")]),
    (WING, "Barrier cream from the meds trolley to the assisted bathroom please", "fenella", [
        _one("BRINGING", theme="barrier_cream", source="medicine_trolley", goal="assisted_bathroom")]),
    (WING, "bring the bp cuff to the nurses' station", "delphine", [
        _one("BRINGING", theme="blood_pressure_cuff", goal="nurses_station")]),
    ("erl", "query whether Jack is in the kitchen", "annie", [
        _one("SEARCHING", theme="jack", ground="kitchen")]),
    ("erl", "do you know if the remote is in the living room", "annie", [
        _one("SEARCHING", theme="remote", ground="living_room")]),
    # how, who and why said around the request
    (WING, "Blinds in the lounge, shut, quietly.", "kwame", [
        _one("OPERATING", device="lounge_blinds", state="closed")]),
    (WING, "Where's that nurse, Fenella? I want a word with her", "lionel", [
        _one("SEARCHING", theme="fenella")]),
    (WING, "Put the jigsaw on the dining table, Gran and Mabel want to do it after lunch", "clementine", [
        _one("PLACING", theme="jigsaw", goal="dining_table")]),
    ("erl", "bedroom blinds down, softly", "annie", [
        _one("OPERATING", device="bedroom_blinds", state="closed")]),
    ("erl", "where is the lady, Tracy?", "annie", [_one("SEARCHING", theme="tracy")]),
    ("erl", "put the apple on the kitchen table, Jack and Tracy want to share it", "annie", [
        _one("PLACING", theme="apple", goal="kitchen_table")]),
    # returned to furniture, a person, a room
    (WING, "Be so good as to return the poetry book to the bookshelf in my room.", "hortense", [
        _one("PLACING", theme="poetry_book", goal="bookshelf")]),
    (WING, "return the bible to the side table", "hortense", [
        _one("PLACING", theme="bible", goal="side_table")]),
    (WING, "return the bible to Lionel", "hortense", [_one("BRINGING", theme="bible", beneficiary="lionel")]),
    (WING, "return the bible to the quiet room", "hortense", [
        _one("BRINGING", theme="bible", goal="quiet_room")]),
    ("erl", "return the apple to the kitchen table", "annie", [
        _one("PLACING", theme="apple", goal="kitchen_table")]),
    ("erl", "return the mug to the kitchen", "annie", [_one("BRINGING", theme="mug", goal="kitchen")]),
    # what may remain where it is
    (WING, "I require the bible from the quiet room; the chess set may remain where it is.", "hortense", [
        _one("BRINGING", theme="bible", source="quiet_room", beneficiary="me")]),
    ("erl", "bring me the apple from the kitchen, the mug can stay where it is", "annie", [
        _one("BRINGING", theme="apple", source="kitchen", beneficiary="me")]),
    ("erl", "take the mug to the kitchen. the glasses can stay there.", "annie", [
        _one("BRINGING", theme="mug", goal="kitchen")]),
]  # fmt: skip


@pytest.mark.parametrize(("world", "text", "speaker", "frames"), READ)
def test_read_in_the_wing_and_the_apartment(
    vocabulary: Vocabulary, world: str, text: str, speaker: str, frames: list[dict[str, str]]
) -> None:
    assert frames_read(vocabulary if world == "erl" else _wing(), text, speaker) == frames


def test_is_it_here_is_still_no_one(vocabulary: Vocabulary) -> None:
    assert not understand("is it here?", vocabulary, speaker="annie").accepted


@pytest.mark.parametrize(
    ("text", "speaker", "state"),
    [
        ("Firstly, draw my blind halfway; secondly, switch on my reading lamp.", "hortense", "50"),
        ("Gran Hortense asked if you could open her blind halfway", "clementine", "50"),
        ("close my blind", "hortense", "closed"),
    ],
)
def test_my_blind_beside_blinds_named_in_the_plural(
    wing: Vocabulary, text: str, speaker: str, state: str
) -> None:
    assert frames_read(wing, text, speaker)[0] == _one("OPERATING", device="hortense_room_blind", state=state)
