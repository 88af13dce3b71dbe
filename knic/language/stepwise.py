"""Steps said one after another, as people give a robot a route or a list of jobs: with less than a whole
sentence each ("go to the bedroom, then the kitchen", "navigate to the living room, then, um, to the dining
room, and grab the candle"), out of order ("bring me the coke, but first switch on the light", "in the
kitchen, find the lemon"), or joined by a learner's words ("take the apple, and after you bring it to Sven",
"you go to search Hugo").

Called from :func:`knic.language.learners.learners_read` on the chunks of a command (:func:`listed_unknown`
first, before its other readings move the words).
"""

from __future__ import annotations

from core.errors import LanguageError
from knic.language.chunks import Chunk
from knic.language.vocabulary import Vocabulary


def steps_read(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """The chunks with the steps of this module said whole, in the order they are to be done."""
    said = first_put_first(after_you_in_order(gone_to_do(before_to(place_said_first(chunks, vocabulary)))))
    said = before_next(said)
    return came_back(each_given(goings_repeated(said, vocabulary), vocabulary))


def listed_unknown(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "the apple and the banana, bring them to me", "apple and banana, bring to me": a word the world does
    not know, listed with "and" beside a thing before the verb, was meant as a thing too; it is named in the
    refusal (the banana was dropped and the apple alone brought). Said first, it needs "the" before it ("oh
    and the apple, ..." lists nothing).

    Raises:
        LanguageError: such a word was said.
    """
    first = next((i for i, c in enumerate(chunks) if c.kind == "verb"), 0)
    said = [
        (c, i > 0 and chunks[i - 1].kind == "det") for i, c in enumerate(chunks[:first]) if c.kind != "det"
    ]
    for i, (chunk, determined) in enumerate(said):
        if chunk.kind != "unknown":
            continue
        pairs = [said[i - 2 : i], said[i + 1 : i + 3][::-1]] if determined else [said[i - 2 : i]]
        for pair in pairs:
            if len(pair) == 2 and pair[1][0].text == "and" and _names(pair[0][0], vocabulary, ("item",)):
                raise LanguageError(f"there is no '{chunk.text}' here: this world has nothing called that")
    return chunks


def came_back(chunks: list[Chunk]) -> list[Chunk]:
    """ "go to the kitchen and come back", "take the mug to the study, then go back": coming back, no place
    said, after the robot was sent somewhere, is coming back to the speaker (who then may be asked where they
    are); it was left out as talk, and the robot stayed where it was sent. Not after the robot was already
    sent to the speaker ("bring me the mug, then come back": nowhere else to come back to), nor after a thing
    fetched with no place to take it ("go to the kitchen, get the juice, come back": it is brought back)."""
    for i, chunk in enumerate(chunks):
        back = chunk.kind == "verb" and "MOTION" in chunk.frames and chunk.text.split()[-1] == "back"
        after = chunks[i + 1].kind if i + 1 < len(chunks) else "join"
        sent = any(c.kind == "verb" for c in chunks[:i]) and not any(c.kind == "me" for c in chunks[:i])
        last = next((j for j in range(i - 1, -1, -1) if chunks[j].kind == "verb"), None)
        if last is not None and {"BRINGING", "TAKING"} & set(chunks[last].frames):  # "get the juice, come
            sent = sent and any(c.kind == "prep" and c.role == "goal" for c in chunks[last:i])  # back": to me
        # an action said whole before it ("go get back and ...", a mishearing of "go get jack", is none)
        sent = (
            sent and last is not None and any(c.kind in ("entity", "pronoun", "me") for c in chunks[last:i])
        )
        if back and sent and after in ("join", "verb"):
            return [*chunks[: i + 1], Chunk("prep", "to", role="goal"), Chunk("me", "me"), *chunks[i + 1 :]]
    return chunks


def place_said_first(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "In the kitchen, find the lemon", "in the bedroom turn on the light", "from the fridge bring me the
    milk", "on the dining table put the apple": a room or a piece of furniture said first, with its
    preposition, before the verb, is said after the first action ("find the lemon in the kitchen"), where it
    says where that action is done."""
    at = 1 + (len(chunks) > 2 and chunks[1].kind == "det")
    opens = (
        len(chunks) > at + 1 and chunks[0].kind == "prep" and chunks[0].role in ("place", "source", "goal")
    )
    if not opens or not _place(chunks[at], vocabulary) or chunks[at + 1].kind != "verb":
        return chunks
    rest = range(at + 2, len(chunks) - 1)
    end = next((j for j in rest if chunks[j].kind == "join" and chunks[j + 1].kind == "verb"), len(chunks))
    return [*chunks[at + 1 : end], *chunks[: at + 1], *chunks[end:]]


def first_put_first(chunks: list[Chunk]) -> list[Chunk]:
    """ "bring me the coke, but first switch on the kitchen light", "go to the living room, and, er, wait,
    first switch on the floor lamp", "go to the kitchen, but before that switch on the light": an action
    said after another with "first" or "before that" before its verb is done first; what stood between the
    two ("but", "and", a hesitating "wait") goes with the first said."""
    for i in range(1, len(chunks) - 1):
        if not any(c.kind == "verb" for c in chunks[:i]) or chunks[i].kind != "unknown":
            continue
        that = chunks[i].text == "before" and chunks[i + 1].text in ("that", "this")
        at = i + 1 if chunks[i].text == "first" else i + 2 if that else len(chunks)
        if at >= len(chunks) or chunks[at].kind != "verb":
            continue
        verbs = range(at + 1, len(chunks) - 1)
        end = next(
            (j for j in verbs if chunks[j].kind == "join" and chunks[j + 1].kind == "verb"), len(chunks)
        )
        before = list(chunks[:i])
        while before and (before[-1].kind == "join" or before[-1].text == "but"):
            before.pop()
        return [*chunks[at:end], Chunk("join", "and"), *before, *chunks[end:]]
    return chunks


def after_you_in_order(chunks: list[Chunk]) -> list[Chunk]:
    """ "take the apple, and after you bring it to Sven" (a learner's "after": then): "after you" right after
    "and" goes on in order, where "bring me the tea after you switch on the light" puts the light first
    (:func:`knic.language.tidy.after_moved`)."""
    out: list[Chunk] = []
    i = 0
    while i < len(chunks):
        chunk = chunks[i]
        after = chunk.kind == "unknown" and chunk.text == "after" and out and out[-1].kind == "join"
        if after and i + 2 < len(chunks) and chunks[i + 1].text == "you" and chunks[i + 2].kind == "verb":
            i += 2  # the verb follows the "and" said before
            continue
        out.append(chunk)
        i += 1
    return out


def before_next(chunks: list[Chunk]) -> list[Chunk]:
    """ "switch the lights off before you close the blinds", "close the blinds before going to the kitchen":
    "before" between two actions says the first is done first, as "then" does ("before you" was read as a
    thing the world lacks). Said before the first action, it puts that one last
    (:func:`knic.language.tidy.before_moved`)."""
    for i in range(1, len(chunks) - 1):
        if chunks[i].kind != "unknown" or chunks[i].text != "before":
            continue
        at = i + 1 + (chunks[i + 1].text in _YOU and i + 2 < len(chunks))
        if chunks[at].kind == "verb" and any(c.kind == "verb" for c in chunks[:i]):
            return [*chunks[:i], Chunk("join", "then"), *before_next(chunks[at:])]
    return chunks


#: the robot said as the one who does the action after "before" ("before you close the blinds")
_YOU = frozenset({"you", "you've", "you're", "u"})


def gone_to_do(chunks: list[Chunk]) -> list[Chunk]:
    """ "you go to search Hugo in the kitchen", "come to get the apple": going "to" do a thing is going and
    doing it ("go and search Hugo"), not going to a place."""
    out = list(chunks)
    for i in range(len(out) - 2):
        going, to, verb = out[i : i + 3]
        if (
            going.kind == "verb"
            and going.frames[:1] == ("MOTION",)
            and to.text == "to"
            and verb.kind == "verb"
        ):
            out[i + 1] = Chunk("join", "and")
    return out


def before_to(chunks: list[Chunk]) -> list[Chunk]:
    """ "before to go to the kitchen, switch on the light" (a learner's "before going": Italian "prima di",
    French "avant de"): "to" between "before" and a verb is dropped, so that the action still comes after
    (:func:`knic.language.tidy.before_moved`)."""
    for i in range(len(chunks) - 2):
        before, to, verb = chunks[i : i + 3]
        if before.kind == "unknown" and before.text == "before" and to.text == "to" and verb.kind == "verb":
            return [*chunks[: i + 1], *chunks[i + 2 :]]
    return chunks


def each_given(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "bring the banana to Amara and the pear to Ines": a thing and whom or where it goes, then "and" with
    another thing and whom or where it goes, is the verb said again for the second (each to its own)."""
    verb: Chunk | None = None
    sent = False  # the verb's thing was said to go to someone or somewhere
    for i, chunk in enumerate(chunks):
        if chunk.kind == "verb":
            verb, sent = (chunk if {"BRINGING", "TAKING"} & set(chunk.frames) else None), False
        elif verb is not None and chunk.kind == "prep" and chunk.role == "goal":
            sent = True
        elif verb is not None and sent and chunk.kind == "join" and chunk.text == "and":
            at = i + 1 + (i + 1 < len(chunks) and chunks[i + 1].kind == "det")
            thing = at < len(chunks) and _names(chunks[at], vocabulary, ("item",))
            to = at + 1 < len(chunks) and chunks[at + 1].kind == "prep" and chunks[at + 1].role == "goal"
            if thing and to:
                return [*chunks[: i + 1], verb, *each_given(chunks[i + 1 :], vocabulary)]
    return chunks


def goings_repeated(chunks: list[Chunk], vocabulary: Vocabulary) -> list[Chunk]:
    """ "go to the bedroom, then the kitchen", "go to the hallway then to the study": a room or a piece of
    furniture said after "then" with no verb of its own, once the robot was sent to a place, is a second
    going, there (the verb said again), not the first place corrected ("no, the kitchen" still corrects)."""
    out: list[Chunk] = []
    going: Chunk | None = None
    placed = False  # the going has a place already
    for i, chunk in enumerate(chunks):
        out.append(chunk)
        if chunk.kind == "verb":
            going, placed = (chunk if chunk.frames[:1] == ("MOTION",) else None), False
        elif going is not None and _place(chunk, vocabulary):
            placed = True
        elif going is not None and placed and chunk.kind == "join" and "then" in chunk.text.split():
            at = i + 1
            at += at < len(chunks) and chunks[at].kind == "prep" and chunks[at].role == "goal"
            at += at < len(chunks) and chunks[at].kind == "det"
            if at < len(chunks) and _place(chunks[at], vocabulary):
                out.append(going)
                placed = False
    return out


def _place(chunk: Chunk, vocabulary: Vocabulary) -> bool:
    """Whether a chunk names only rooms and pieces of furniture."""
    return _names(chunk, vocabulary, ("room", "furniture"))


def _names(chunk: Chunk, vocabulary: Vocabulary, kinds: tuple[str, ...]) -> bool:
    """Whether a chunk names only things of ``kinds``."""
    return (
        chunk.kind == "entity"
        and bool(chunk.terms)
        and all(any(vocabulary.is_subtype(t.type, k) for k in kinds) for t in chunk.terms)
    )
