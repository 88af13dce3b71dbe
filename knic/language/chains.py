"""Chains of actions in one command: pronouns and what one action hands on to the next.

Pronouns ("it", "them", "her", "him") take the latest earlier action's theme or beneficiary of their type; a
TAKING followed by a carry of the same object hands it its source; a MOTION followed by an action on a thing
gives it its source or ground ("go to the dining table and take the cups"); a carry with nowhere said that
nothing carries on is a BRINGING to the speaker, and "pick up the box" a TAKING (the robot holds it).
"""

from __future__ import annotations

import contextlib
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field, replace

from core.errors import LanguageError
from knic.language.chunks import Chunk
from knic.language.frames import KIND_NAMES, SPEAKER, CommandFrame, not_of_kinds
from knic.language.vocabulary import Vocabulary


class AmbiguityError(LanguageError):
    """A name fits several things, or something needed is left unsaid; the message is the question to ask
    back."""


@dataclass
class Reading:
    """Frames read from a command, before goals."""

    frames: list[CommandFrame]
    waypoints: set[int] = field(default_factory=set)  # indices of MOTION frames whose place went on


#: the roles a pronoun can refer back to: a thing, whom it was for, or a person gone to ("go to tracy and give
#: her the mug")
_REFERRED_ROLES = ("theme", "beneficiary", "goal", "device")


def referent(
    chunk: Chunk,
    categories: Sequence[str],
    groups: list[list[CommandFrame]],
    vocabulary: Vocabulary,
) -> list[str]:
    """What a pronoun stands for: the latest earlier action's themes or beneficiaries of the pronoun's type
    and of one of ``categories`` (all of them for "them", the last one otherwise); "him" or "her" said where
    no person was named is a thing (a child's teddy).

    Raises:
        LanguageError: nothing said earlier in the command fits.
    """
    wanted = chunk.role
    if wanted == "item" and "item" not in categories:  # "the hall light, switch it off": "it" is a device
        wanted = "any"
    for group in reversed(groups):
        found: list[str] = []
        for frame in group:
            for role in _REFERRED_ROLES:
                value = frame.get(role)
                if value is None or value == SPEAKER:
                    continue
                value_type = vocabulary.type_of(value) or ""
                fits = any(vocabulary.is_subtype(value_type, c) for c in categories)
                if (
                    fits
                    and (wanted == "any" or vocabulary.is_subtype(value_type, wanted))
                    and value not in found
                ):
                    found.append(value)
        if found:
            return found if chunk.text in ("them", "em") else found[-1:]  # "em": them, said short
    said = [f.get(r) for g in groups for f in g for r in _REFERRED_ROLES]
    people = any(s and vocabulary.is_of(s, "person") for s in said)
    if wanted == "person" and "item" in categories and not people:  # "my teddy's on the sofa, put him ..."
        with contextlib.suppress(LanguageError):
            return referent(replace(chunk, role="item"), categories, groups, vocabulary)
    thing = "an object" if wanted == "item" else "a person" if wanted == "person" else "anything"
    unsaid = f"'{chunk.text}' does not refer to {thing} named earlier in the command"
    # "bring me the mug and switch it on": what it would be (the last action's first thing) is said too
    last = [f.get(r) for f in (groups[-1] if groups else []) for r in _REFERRED_ROLES if f.get(r) != SPEAKER]
    other = next((s for s in last if s and (wanted != "person" or vocabulary.is_of(s, "person"))), None)
    if other is not None:
        what, device = vocabulary.phrase_of(other), vocabulary.is_of(other, "device")
        kinds = " or ".join(KIND_NAMES.get(c, c) for c in categories)
        the = "" if vocabulary.is_of(other, "person") else "the "
        unsaid = f"'{chunk.text}' does not refer to {kinds} named earlier in the command: " + (
            not_of_kinds(what, categories, True) if device else f"{the}{what} is not one"
        )
    raise LanguageError(unsaid)


def settled(reading: Reading, vocabulary: Vocabulary) -> Reading:
    """The reading with each device set once: a device set again later to a level ends at that level ("open
    the blinds and set them to 40"), the first setting goes (see :func:`_set_again`); and each thing brought
    once: a bringing said again later with more ("I fancy a sherry, bring me the bottle from the sideboard")
    is that later one.

    Raises:
        AmbiguityError: a device is put in opposite states ("switch on the light and switch it off").
    """
    frames = reading.frames
    drop = {
        i
        for i, frame in enumerate(frames)
        if frame.kind == "OPERATING" and _set_again(frame, frames[i + 1 :], vocabulary)
    }
    drop |= {
        i
        for i, frame in enumerate(frames)
        if frame.kind == "BRINGING"
        and any(f.kind == "BRINGING" and frame.args.items() <= f.args.items() for f in frames[i + 1 :])
    }
    # "i need the charger, it is on my desk, bring it please": the bringing said again with less is the same
    drop |= {
        i
        for i, frame in enumerate(frames)
        if frame.kind == "BRINGING"
        and any(f.kind == "BRINGING" and frame.args.items() < f.args.items() for f in frames[:i])
    }
    if not drop:
        return reading
    kept = [i for i in range(len(frames)) if i not in drop]
    return Reading([frames[i] for i in kept], {kept.index(i) for i in reading.waypoints if i in kept})


def _set_again(frame: CommandFrame, later: list[CommandFrame], vocabulary: Vocabulary) -> bool:
    """Whether a device operated is set again later in the command to a level ("open the blinds and set them
    to 40": the level is meant, the first setting goes).

    Raises:
        AmbiguityError: it is later put in the opposite state ("switch on the light and switch it off").
    """
    again = next((f for f in later if f.kind == "OPERATING" and f.get("device") == frame.get("device")), None)
    state, then = frame.get("state") or "", (again.get("state") or "") if again else ""
    if again is None or then == state:
        return False
    if then.isdigit():
        return True
    device = vocabulary.phrase_of(frame.get("device") or "")
    raise AmbiguityError(f"the {device} cannot be {state} and {then} at once: which should it be?")


def chain(
    frames: list[CommandFrame],
    vocabulary: Vocabulary,
    *,
    ask_where: Collection[int] = (),
    held: Collection[int] = (),
) -> Reading:
    """Hand sources on along a chain; a carry with nowhere said that nothing carries on is for the speaker.

    A carry with no destination said ("fetch the book") reads as a TAKING, so a destination said later for
    the same object ("... and put it in the lounge", "... then take it to the kitchen") replaces the speaker
    as where it ends. A TAKING of a verb that only takes ("pick up the box", in ``held``) that nothing
    carries on stays a TAKING: the robot ends up holding the thing. A person fetched with no room said
    ("fetch tracy") is taken wherever a later action takes them ("... and bring her to the bedroom"); that
    frame then goes.

    Args:
        frames: the frames of the clauses, in order.
        vocabulary: the world's names (for the questions).
        ask_where: indices of TAKING frames said with a destination left unsaid ("take the cup away"): when
            nothing later carries them on, the reader asks where instead of bringing them to the speaker.
        held: indices of TAKING frames said with a verb that only takes ("pick up", "take").

    Raises:
        AmbiguityError: where to is not said for a frame that needs it (the message asks).
    """
    # "come and find me in the study": the speaker is there, so go there
    out = [
        CommandFrame("MOTION", {"goal": f.args["ground"]})
        if f.kind == "SEARCHING" and f.get("theme") == SPEAKER and f.get("ground")
        else f
        for f in frames
    ]
    dropped: set[int] = set()
    waypoints: set[int] = set()
    for index, frame in enumerate(out):
        later = out[index + 1 :]
        # the next action on a thing, past devices operated there ("go to the den, switch on the lamp there
        # and bring arthur his atlas": from the den)
        at = next((index + 1 + k for k, f in enumerate(later) if f.kind != "OPERATING"), None)
        if frame.kind == "MOTION" and at is not None:
            nxt = out[at]
            role = "ground" if nxt.kind == "SEARCHING" else "source"
            theme = nxt.get("theme")
            said = nxt.get(role) in (None, frame["goal"])  # "go to the kitchen and find the cup (there)"
            place = not vocabulary.is_of(frame["goal"], "person")
            if nxt.kind in ("SEARCHING", "TAKING", "BRINGING") and said and theme and place:
                out[at] = CommandFrame(nxt.kind, {**nxt.args, role: frame["goal"]})
                waypoints.add(index)
                # "go to the kitchen and bring the milk and the coke to the table": each thing of that action
                for j in range(at + 1, len(out)):
                    if (out[j].kind, _but_theme(out[j])) != (nxt.kind, _but_theme(nxt)):
                        break
                    out[j] = CommandFrame(nxt.kind, {**out[j].args, role: frame["goal"]})
            elif any(f.kind == "MOTION" for f in later):
                # "go to the garage, then come back", "go to the lounge, switch the dimmer off, then come to
                # the study": only the last place can be kept
                waypoints.add(index)
        if frame.kind == "TAKING":
            carried = [  # a later carry of the same object, not one fetched again from elsewhere
                j
                for j in range(index + 1, len(out))
                if out[j].kind in ("BRINGING", "PLACING", "TAKING")
                and out[j].get("theme") == frame.get("theme")
                and out[j].get("source") in (None, frame.get("source"))
            ]
            if carried:
                j = carried[0]
                handed = out[j].kind != "PLACING"  # where a thing is put is all a placing says
                if handed and out[j].get("source") is None and frame.get("source") is not None:
                    out[j] = CommandFrame(out[j].kind, {**out[j].args, "source": frame["source"]})
            elif any(
                f.kind == "BRINGING"
                and f.get("theme") == frame.get("theme")
                and f.get("beneficiary") != SPEAKER
                for f in out[:index]
                if f.get("beneficiary")
            ):
                dropped.add(
                    index
                )  # "tracy wants the apple, bring it": to her, as wanted; said twice, done once
            elif index in ask_where:
                thing = vocabulary.phrase_of(frame["theme"])
                raise AmbiguityError(f"where should I take the {thing}: to which room or piece of furniture?")
            elif index not in held:
                out[index] = CommandFrame("BRINGING", {**frame.args, "beneficiary": SPEAKER})
        if frame.kind == "ACCOMPANYING" and frame.get("goal") is None:
            later_same = [
                f for f in later if f.kind == "ACCOMPANYING" and f.get("theme") == frame.get("theme")
            ]
            if not any(f.get("goal") for f in later_same):
                who = frame.get("theme")
                name = "you" if who == SPEAKER else vocabulary.phrase_of(who or "")
                raise AmbiguityError(f"where should I take {name}: to which room?")
            dropped.add(index)  # "fetch tracy and bring her to the bedroom": the later action says where
        # "where are my glasses? look in the kitchen": one search, where it is said
        sought_again = any(f.kind == "SEARCHING" and f.get("theme") == frame.get("theme") for f in later)
        if frame.kind == "SEARCHING" and frame.get("ground") is None and sought_again:
            dropped.add(index)
    kept_frames: dict[int, CommandFrame] = {}
    for index, frame in enumerate(out):  # "tracy wants her mug, take it to her": said twice, done once
        if index in dropped:
            continue
        twin = next((k for k, f in kept_frames.items() if (frame.kind, frame.args) == (f.kind, f.args)), None)
        if twin is None:
            kept_frames[index] = frame
            continue
        dropped.add(index)
        if index not in waypoints:  # "go to the landing and wait for me there": the place is kept
            waypoints.discard(twin)
    if dropped:
        kept = [i for i in range(len(out)) if i not in dropped]
        out = [out[i] for i in kept]
        waypoints = {kept.index(i) for i in waypoints if i in kept}
    return Reading(out, waypoints)


def _but_theme(frame: CommandFrame) -> dict[str, str]:
    """A frame's arguments but its theme (one action on several things: "bring the milk and the coke")."""
    return {k: v for k, v in frame.args.items() if k != "theme"}
