"""The world's names told to Whisper before it hears a command (:mod:`knic.language.whisperpass`): its
decoder takes them as the text said before, and writes names it would not guess ("Ffion", "the scullery")
when they are said. A large world's names are more than the decoder has room for, so the prompt keeps those
most worth telling."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary


def world_prompt(vocabulary: Vocabulary) -> str:
    """The world's names as the decoder's previous text: the people (capitalised), then rooms, furniture,
    objects and devices, each by its first name, in the world's order; level names and the robot left out.
    A world with more names than :data:`MAX_PROMPT_CHARS` holds keeps the people, then as many of the rooms,
    objects, furniture and devices as fit, in that order (:data:`_PROMPT_KINDS`)."""
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


def _written(people: list[str], things: list[str]) -> str:
    return ", ".join(people) + (". " if people else "") + ", ".join(things) + ("." if things else "")


#: the longest prompt :func:`world_prompt` writes: Whisper's decoder has 448 positions for the prompt and the
#: transcript, and a prompt of about 130 tokens (the ERL apartment's 560 characters) already doubles its time;
#: a farmhouse of 140 names (2,300 characters, 550 tokens) made every hearing fail
MAX_PROMPT_CHARS = 700
#: Whisper's decoder's positions left to the prompt at most, whatever its text (as Whisper's own decoding)
MAX_PROMPT_TOKENS = 223
#: which names a long prompt keeps first (after the people), by their kind: the devices last, whose names
#: are mostly everyday words ("kitchen light") Whisper writes well unprompted
_PROMPT_KINDS = ("room", "item", "furniture", "device")
