"""Commands as a recogniser gives them: lowercase words without punctuation. Where typed text separates the
request from the talk around it with commas and full stops, the reader finds the sentences from the words
(knic.language.segments); these sentences are read as their punctuated versions are."""

from __future__ import annotations

import pytest

from knic.bench.language import OTHER_WORLD, frame_spec
from knic.language import understand
from knic.language.vocabulary import Vocabulary, normalize
from knic.language.world import read_vocabulary

FRAMES = [
    # talk after the request: after an address word, a statement ("i'm", "it's"), a subject, "let"
    ("fetch me the juice dear i'm ever so thirsty", ["BRINGING theme=juice beneficiary=me"]),
    ("could you look for my glasses love i can't see a thing", ["SEARCHING theme=glasses"]),
    ("bring me the soap love i want to wash my hands", ["BRINGING theme=soap beneficiary=me"]),
    ("close the blinds it's far too bright", ["OPERATING device=bedroom_blinds state=closed"]),
    ("switch off the lights i'm going to bed", ["OPERATING device=all_lights state=off"]),
    ("open the blinds let some light in", ["OPERATING device=bedroom_blinds state=open"]),
    ("help me to the couch dear my legs are tired", ["ACCOMPANYING theme=me goal=sofa"]),
    (
        "set the blinds to a quarter dear not any more the glare is awful",
        ["OPERATING device=bedroom_blinds state=25"],
    ),
    # talk before it
    ("it's dark in here turn on the hallway light", ["OPERATING device=hallway_light state=on"]),
    ("i've lost my glasses can you find them", ["SEARCHING theme=glasses"]),
    # pointing at a thing, then the action on it
    ("see that apple put it in the bin", ["PLACING theme=apple goal=bin"]),
    ("see that mug bring it to jack", ["BRINGING theme=mug beneficiary=jack"]),
    (
        "see this candle on the shelf bring it here",
        ["BRINGING theme=candle source=entrance_shelf beneficiary=me"],
    ),
    # a person wants a thing, then the action for them
    ("jack wants the remote bring it to him", ["BRINGING theme=remote beneficiary=jack"]),
    ("tracy needs her glasses give them to her", ["BRINGING theme=glasses beneficiary=tracy"]),
    # corrections
    ("bring me the cup sorry the mug", ["BRINGING theme=mug beneficiary=me"]),
    ("take the lemon to the kitchen sorry i meant the apple", ["BRINGING theme=apple goal=kitchen"]),
    ("go to the kitchen no wait the bedroom", ["MOTION goal=bedroom"]),
    (
        "switch off the hallway light scratch that close the blinds",
        ["OPERATING device=bedroom_blinds state=closed"],
    ),
    # levels in words and in digits
    ("set the dimmer to forty five percent please", ["OPERATING device=living_room_dimmer state=45"]),
    ("set the dimmer to 45 percent please", ["OPERATING device=living_room_dimmer state=45"]),
    ("dimmer to sixty", ["OPERATING device=living_room_dimmer state=60"]),
    ("dimmer to 60", ["OPERATING device=living_room_dimmer state=60"]),
    ("open the blinds to 35%", ["OPERATING device=bedroom_blinds state=35"]),
]


def _frames(text: str, vocabulary: Vocabulary, speaker: str = "annie") -> list[dict[str, str]]:
    result = understand(text, vocabulary, speaker=speaker)
    assert result.accepted, result.reason
    return [f.to_dict() for f in result.frames]


@pytest.mark.parametrize(("text", "frames"), FRAMES)
def test_unpunctuated_commands_read(vocabulary: Vocabulary, text: str, frames: list[str]) -> None:
    assert _frames(text, vocabulary) == [frame_spec(f) for f in frames]


PUNCTUATED = [
    "Bring me the remote, dear. I want to watch the news.",
    "See that candle? Put it on the nightstand.",
    "Tracy wants her tablet, take it to her.",
    "Bring me the apple, sorry, I meant the lemon.",
    "Pick up the sponge, put it in the bin.",
    "The remote is on the sofa. Bring it to me.",
    "Go to the kitchen, then bring me a cup.",
]


@pytest.mark.parametrize("text", PUNCTUATED)
def test_as_typed_and_as_heard_read_alike(vocabulary: Vocabulary, text: str) -> None:
    assert _frames(normalize(text), vocabulary) == _frames(text, vocabulary)


def test_another_house(vocabulary: Vocabulary) -> None:
    other = read_vocabulary(problem=OTHER_WORLD)
    heard = _frames("bring me the keys love i'm late for work", other, speaker="maria")
    assert heard == [frame_spec("BRINGING theme=keys beneficiary=me")]


REFUSED = [
    ("find the newspaper dear i need it", "there is no 'newspaper' here"),
    ("bring me the banana i'm hungry", "there is no 'banana' here"),
    ("bring me the banana sorry i meant the cherry", "there is no 'cherry' here"),
]


@pytest.mark.parametrize(("text", "reason"), REFUSED)
def test_what_the_world_lacks_is_refused_unpunctuated(vocabulary: Vocabulary, text: str, reason: str) -> None:
    result = understand(text, vocabulary)
    assert not result.accepted and reason in result.reason


def test_see_that_with_a_state_is_still_making_sure(vocabulary: Vocabulary) -> None:
    assert _frames("see that the lights are off", vocabulary) == _frames(
        "make sure the lights are off", vocabulary
    )


def test_sorry_as_politeness_is_no_correction(vocabulary: Vocabulary) -> None:
    assert _frames("sorry can you grab the tissues", vocabulary) == [frame_spec("TAKING theme=tissues")]
    heard = _frames("sorry to bother you but bring me the remote", vocabulary)
    assert heard == [frame_spec("BRINGING theme=remote beneficiary=me")]
