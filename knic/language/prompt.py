"""The world's names told to Whisper before it hears a command (:mod:`knic.language.whisperpass`): its
decoder takes them as the text said before, and writes names it would not guess ("Ffion", "the scullery")
when they are said. A large world's names are more than the decoder has room for, so the prompt keeps those
most worth telling. Also how Whisper's text and a recogniser's words are written for each other
(:func:`forced_text`, :func:`unrepeated`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Collection

    from knic.language.vocabulary import Vocabulary


def world_prompt(vocabulary: Vocabulary) -> str:
    """The world's names as the decoder's previous text: the people (capitalised, each whole), then the words
    of the rooms, furniture, objects and devices, each by its first name, in the world's order, every word
    once (:func:`_written`); level names and the robot left out. A world with more names than
    :data:`MAX_PROMPT_CHARS` holds keeps the people, then as many of the rooms, objects, furniture and devices
    as fit, in that order (:data:`_PROMPT_KINDS`)."""
    people: list[str] = []
    things: list[tuple[int, str]] = []
    for instance in vocabulary.instances:
        kind = vocabulary.type_of(instance) or ""
        if instance == vocabulary.robot or not kind or vocabulary.is_subtype(kind, "level"):
            continue
        phrase = vocabulary.phrase_of(instance)
        if not phrase or phrase in people or phrase in (t for _, t in things):
            continue
        if vocabulary.is_subtype(kind, "person"):
            people.append(" ".join(word.capitalize() for word in phrase.split()))
        else:
            rank = next(
                (i for i, k in enumerate(_PROMPT_KINDS) if vocabulary.is_subtype(kind, k)), len(_PROMPT_KINDS)
            )
            things.append((rank, phrase))
    names = [t for _, t in things]
    if len(_written(people, names)) > MAX_PROMPT_CHARS:
        kept: set[int] = set()
        for index in sorted(range(len(things)), key=lambda i: things[i][0]):
            if (
                len(_written(people, [t for i, (_, t) in enumerate(things) if i in kept | {index}]))
                <= MAX_PROMPT_CHARS
            ):
                kept.add(index)
        names = [t for i, (_, t) in enumerate(things) if i in kept]
    return _written(people, names)


def told_people(prompt: str) -> list[str]:
    """The people's names a prompt :func:`world_prompt` wrote opens with, as written there ("Granny Annie,
    Tracy, Jack." before the things' words); none when it names nobody (Whisper's server is given the
    prompt's text only)."""
    head, stop, _ = prompt.partition(". ")
    names = [name.strip().rstrip(".") for name in head.split(",")] if stop or prompt.endswith(".") else []
    return [name for name in names if name and all(word[:1].isupper() for word in name.split())]


def _written(people: list[str], things: list[str]) -> str:
    """The prompt's text: the people's names, then the things' words, each word once ("kitchen counter,
    kitchen table" as "kitchen counter table"). The decoder reads the prompt once per beam of every
    hearing, so its length is paid on each (the apartment's 133 tokens took the beam search from 36 to 91 ms;
    its words once, 69 tokens, 56 ms); the words, not the phrases, are what Whisper would not guess. On the
    six spoken dev sets and ``speech_ood_dev2`` (519 commands, 186 other utterances; Whisper's window of
    8 s), frame+args and other speech rejected: phrases 474 and 182, words once 472 and 181."""
    words: list[str] = []
    for thing in things:
        words += [word for word in thing.split() if word not in words]
    return ", ".join(people) + (". " if people else "") + " ".join(words) + ("." if words else "")


#: the longest prompt :func:`world_prompt` writes: Whisper's decoder has 448 positions for the prompt and the
#: transcript, and each token of the prompt costs time (see :func:`_written`); a farmhouse of 140 names
#: (2,300 characters, 550 tokens as phrases) made every hearing fail, and its first 700 characters are about
#: 150 tokens
MAX_PROMPT_CHARS = 700
#: Whisper's decoder's positions left to the prompt at most, whatever its text (as Whisper's own decoding)
MAX_PROMPT_TOKENS = 223
#: which names a long prompt keeps first (after the people), by their kind: the devices last, whose names
#: are mostly everyday words ("kitchen light") Whisper writes well unprompted
_PROMPT_KINDS = ("room", "item", "furniture", "device")


def forced_text(text: str, names: Collection[str] = ()) -> str:
    """A recogniser's lowercase words as Whisper writes a sentence: capitalised, with a full stop, and "I"
    ("i'm": "I'm") and the words of ``names`` (people's names: "rosa") capitalised too."""
    said = " ".join(
        w.capitalize() if w in names or w == "i" or w.startswith("i'") else w for w in text.split()
    )
    return said[:1].upper() + said[1:] + "." if said else ""


def unrepeated(text: str) -> str:
    """``text`` without the repeats of a phrase of two words or more that it starts with, when nothing but
    that phrase's words follows: a decoder given silence after a short command sometimes writes the command
    again and again ("Pick up my glasses. Pick up my glasses. Pick up my"), which the dev sets showed for 4
    of 541 utterances ("take the cup, take the cup back" stays whole)."""
    words = text.split()
    plain = [word.strip(".,!?").lower() for word in words]
    for size in range(2, len(words) // 2 + 1):
        if plain[:size] == plain[size : 2 * size] and set(plain[size:]) <= set(plain[:size]):
            return " ".join(words[:size])
    return text
