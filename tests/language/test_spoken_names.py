"""Names a recogniser hears a little wrong, read as the name meant (the reader's side of spoken commands in a
home it was not tuned in: ``tests/fixtures/speech_world_dev``, the bungalow of ``worlds/test_bungalow``).

Heard there: "put the paper mill on the dining table" for the pepper mill. "paper" is a word of the world
(the newspaper is "the paper"), so no typo rule mended it, and the reader put down the newspaper and the
pepper mill. A word before the last word of a two-word name, two edits or fewer from that name's first word
and starting with its letter, is that word when the two said together name nothing
(``knic.language.typos``). "pick up mill alarm clock" (for "the alarm clock") took the pepper mill too: of a
thing said by a shorter name right before another said whole, the last is meant (``knic.language.chunks``).
"""

from __future__ import annotations

from .conftest import frames_read, world_of

BUNGALOW = "worlds/test_bungalow/test_bungalow.yaml"


def test_a_near_miss_of_a_names_first_word_before_its_last_is_that_name() -> None:
    bungalow = world_of(BUNGALOW)
    assert frames_read(bungalow, "put the paper mill on the dining table", "walter") == [
        {"frame": "PLACING", "theme": "pepper_mill", "goal": "dining_table"}
    ]
    assert frames_read(bungalow, "find the paper mill then bring it to rosa", "walter") == [
        {"frame": "SEARCHING", "theme": "pepper_mill"},
        {"frame": "BRINGING", "theme": "pepper_mill", "beneficiary": "rosa"},
    ]
    # the word alone, or before another word, keeps its own meaning
    assert frames_read(bungalow, "bring me the paper", "walter") == [
        {"frame": "BRINGING", "theme": "newspaper", "beneficiary": "me"}
    ]
    assert frames_read(bungalow, "put the paper on the dining table", "walter") == [
        {"frame": "PLACING", "theme": "newspaper", "goal": "dining_table"}
    ]


def test_of_two_things_said_one_after_the_other_the_last_said_whole_is_meant() -> None:
    bungalow = world_of(BUNGALOW)
    text = "pick up mill alarm clock from the nightstand and bring it to me"  # for "... the alarm clock"
    assert frames_read(bungalow, text, "walter") == [
        {"frame": "TAKING", "theme": "alarm_clock", "source": "nightstand"},
        {"frame": "BRINGING", "theme": "alarm_clock", "source": "nightstand", "beneficiary": "me"},
    ]
    # a room said before a thing, and two things each said whole, read as before
    assert frames_read(bungalow, "go to the bedroom nightstand", "walter") == [
        {"frame": "MOTION", "goal": "nightstand"}
    ]
    assert frames_read(bungalow, "bring me the car keys and the hairbrush", "walter") == [
        {"frame": "BRINGING", "theme": "car_keys", "beneficiary": "me"},
        {"frame": "BRINGING", "theme": "hairbrush", "beneficiary": "me"},
    ]
