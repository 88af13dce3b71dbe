"""Command frames to PDDL goals, checked against the domain before they reach the knowledge base.

Goals by request kind (the team's mapping for the ERL domain):

=====================================  =====================================================
frame                                  goal
=====================================  =====================================================
BRINGING theme X, beneficiary P        ``(has P X)`` ("me" is the speaker), also with a goal room said for
                                       P ("to granny in the living room": a hint that P is there)
BRINGING / PLACING theme X, goal room  ``(object_at X room)``
BRINGING / PLACING theme X, goal f     ``(object_on X f)`` (f a piece of furniture)
... with source f (furniture)          also ``(taken_from X f)`` when the domain has that predicate
TAKING theme X (carried on later)      only ``(taken_from X f)``: the later action's goal says where X ends
TAKING theme X (nothing carries on)    ``(holding R X)`` (R the robot: "pick up the box")
SEARCHING theme X                      ``(reported X)``
MOTION goal room                       ``(robot_at R room)`` (R the world's robot)
MOTION goal f (furniture)              ``(robot_at R room)``, the room f is in (``furniture_in``)
MOTION goal P (person)                 ``(found P)``: the robot searches P out and is then where P is
MOTION whose place a later action uses none: it only says where that action happens
ACCOMPANYING theme P, goal room or f   ``(person_at P room)``
OPERATING light(s), on / off           ``(light_on d)`` / ``(light_off d)`` for each light
OPERATING blinds open / closed / half  ``(device_level d l100)`` / ``l0`` / ``l50``
OPERATING dimmer or blinds N percent   ``(device_level d lN)``
=====================================  =====================================================

Every goal is checked against the domain's predicate signatures and the world's instances (predicate known,
arity, each argument an instance or constant of the parameter's type), and the goals of one utterance must not
contradict each other. Any failure raises :class:`~core.errors.LanguageError` and no goal is produced.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterable, Sequence
from typing import Any, Protocol

from core.errors import KnicError, LanguageError
from knic.language.frames import SPEAKER, CommandFrame
from knic.language.vocabulary import Vocabulary, level_percent
from knowledge_base import Fact

#: Blind positions as percentages (closed, half-open, open).
BLIND_STATES = {"closed": 0, "half-open": 50, "open": 100}
#: Predicates holding one value per first argument: two goals that differ there contradict each other.
_SINGLE_VALUED = ("robot_at", "person_at", "object_at", "object_on", "device_level")
_COMPLEMENTS = (("light_on", "light_off"),)


def frames_to_goals(
    frames: Sequence[CommandFrame],
    vocabulary: Vocabulary,
    *,
    speaker: str,
    waypoints: Iterable[int] = (),
    notes: list[str] | None = None,
) -> list[Fact]:
    """The PDDL goals that satisfy the frames, in utterance order, without duplicates.

    Args:
        frames: understood actions (pronouns already resolved).
        vocabulary: the world (instances, types, the domain's predicate signatures).
        speaker: the person symbol that "me" stands for.
        waypoints: indices of MOTION frames that only say where the next action happens (no goal).
        notes: receives what the goals do differently from what was said, for the reply (a level the world
            lacks is set to the nearest one it has: "dimmer: 50 percent, the nearest level to 40 ...").

    Raises:
        LanguageError: a frame lacks an argument its kind needs, names something of the wrong type, asks
            for a level the domain has no constant for, or the goals contradict each other.
    """
    # a world of no people ("go to the den" in a tidying domain) asks for a speaker only when "me" is said
    needed = any(SPEAKER in f.args.values() for f in frames) or any(
        vocabulary.is_subtype(kind, "person") for kind in vocabulary.instances.values()
    )
    if needed and not vocabulary.is_of(speaker, "person"):
        raise LanguageError(f"speaker {speaker!r} is not a person of this world")
    goals: list[Fact] = []
    skip = set(waypoints)
    for index, frame in enumerate(frames):
        if index in skip:
            continue
        if frame.kind == "TAKING" and _carried_on(frames, index):
            # where it ends is the later action's; where it is taken from is this one's
            made = _sourced(frame, vocabulary, frame.get("theme") or "")
        else:
            made = _frame_goals(frame, vocabulary, speaker, notes if notes is not None else [])
        for goal in (fitted(one, vocabulary) for one in made):
            validate_goal(goal, vocabulary)
            if goal not in goals:
                goals.append(goal)
    _check_consistent(goals)
    return goals


def fitted(goal: Fact, vocabulary: Vocabulary) -> Fact:
    """``goal`` as a domain of other predicates says it: the goals above are named as the ERL domain names
    them, and when the domain lacks the predicate, the one predicate whose parameters take the goal's
    arguments, in their order or, of two, the other way round, says the same ("bring the teapot to grandpa":
    ``(has grandpa teapot)`` is ``(handed teapot grandpa)`` in a domain with ``(handed ?i - item ?p -
    person)``, ``(object_at book lounge)`` its ``(item_at book lounge)``). The goal is unchanged when the
    domain has its predicate, or none or several others fit (its check then names the predicate missing)."""
    if goal.predicate in vocabulary.predicates or any(a not in vocabulary.instances for a in goal.args):
        return goal
    orders = [goal.args, goal.args[::-1]] if len(goal.args) == 2 else [goal.args]
    fits = [
        Fact(name, args)
        for name, signature in vocabulary.predicates.items()
        for args in orders
        if len(signature) == len(args)
        and all(vocabulary.is_of(arg, kind) for arg, (_, kind) in zip(args, signature, strict=True))
    ]
    return fits[0] if len(fits) == 1 else goal


def validate_goal(goal: Fact, vocabulary: Vocabulary) -> None:
    """Check one goal against the domain: known predicate, arity, argument types.

    Raises:
        LanguageError: naming the goal and what is wrong with it.
    """
    signature = vocabulary.predicates.get(goal.predicate)
    if signature is None:
        raise LanguageError(f"goal {goal}: the domain has no predicate {goal.predicate!r}")
    if len(signature) != len(goal.args):
        raise LanguageError(f"goal {goal}: {goal.predicate} takes {len(signature)} argument(s)")
    for arg, (param, param_type) in zip(goal.args, signature, strict=True):
        arg_type = vocabulary.instances.get(arg)
        if arg_type is None:
            raise LanguageError(f"goal {goal}: the world has no {arg!r}")
        if not vocabulary.is_subtype(arg_type, param_type):
            raise LanguageError(f"goal {goal}: {arg} is a {arg_type}, {param} needs a {param_type}")


def add_goals(kb: GoalSink, goals: Iterable[Fact], *, source: str = "language") -> list[Fact]:
    """Add goals to a knowledge base in one batch: all of them or, on any refusal, none.

    Returns:
        The goals that were new.

    Raises:
        LanguageError: the knowledge base refused a goal (its message is kept); nothing was added.
    """
    added: list[Fact] = []
    try:
        with kb.batch():
            for goal in goals:
                if kb.add_goal(goal.predicate, *goal.args, source=source):
                    added.append(goal)
    except LanguageError:
        raise
    except KnicError as exc:
        raise LanguageError(f"the knowledge base refused the goals: {exc}") from exc
    return added


class GoalSink(Protocol):
    """The part of ``knowledge_base.KnowledgeBase`` that :func:`add_goals` writes to."""

    def batch(self) -> Any:
        """A context manager making the writes one all-or-nothing transaction."""

    def add_goal(self, predicate: str, *args: str, source: str = ...) -> bool:
        """Add one goal; True when it is new."""


def _frame_goals(frame: CommandFrame, vocabulary: Vocabulary, speaker: str, notes: list[str]) -> list[Fact]:
    def need(role: str) -> str:
        value = frame.get(role)
        if value is None:
            raise LanguageError(f"{frame.kind} needs a {role}: {frame}")
        return speaker if value == SPEAKER else value

    kind = frame.kind
    if kind in ("BRINGING", "PLACING"):
        theme = need("theme")
        sourced = _sourced(frame, vocabulary, theme)
        # "to granny in the living room": handed to her where she is, not left in the room
        person, room = frame.get("beneficiary"), frame.get("goal") or ""
        handed = person not in (None, SPEAKER) and vocabulary.is_of(room, "room")
        if frame.get("goal") is not None and not handed:
            place = need("goal")
            if vocabulary.is_of(place, "furniture"):
                return [*sourced, Fact("object_on", (theme, place))]
            return [*sourced, Fact("object_at", (theme, place))]
        if kind == "PLACING":
            raise LanguageError(f"PLACING needs a goal: {frame}")
        return [*sourced, Fact("has", (need("beneficiary"), theme))]
    if kind == "SEARCHING":
        return [Fact("reported", (need("theme"),))]
    if kind == "TAKING":
        if vocabulary.robot is None:
            raise LanguageError("the world has no robot to pick things up")
        theme = need("theme")
        return [*_sourced(frame, vocabulary, theme), Fact("holding", (vocabulary.robot, theme))]
    if kind == "MOTION":
        if vocabulary.robot is None:
            raise LanguageError("the world has no robot to move")
        # "go to tracy": find where she is (the robot is then there)
        if vocabulary.is_of(need("goal"), "person"):
            return [Fact("found", (need("goal"),))]
        return [Fact("robot_at", (vocabulary.robot, room_of(need("goal"), vocabulary)))]
    if kind == "ACCOMPANYING":
        return [Fact("person_at", (need("theme"), room_of(need("goal"), vocabulary)))]
    if kind == "OPERATING":
        return _operating_goals(frame, vocabulary, need("device"), need("state"), notes)
    raise LanguageError(f"no goal for frame kind {kind!r}")


def _carried_on(frames: Sequence[CommandFrame], index: int) -> bool:
    """Whether a later frame carries the object of ``frames[index]`` on (its goal says where it ends)."""
    theme = frames[index].get("theme")
    return any(
        f.kind in ("BRINGING", "PLACING", "TAKING") and f.get("theme") == theme for f in frames[index + 1 :]
    )


def _operating_goals(
    frame: CommandFrame, vocabulary: Vocabulary, device: str, state: str, notes: list[str]
) -> list[Fact]:
    devices = vocabulary.members(device)
    lights = all(vocabulary.is_of(d, "light") for d in devices)
    if state in ("on", "off") and lights:
        return [Fact(f"light_{state}", (d,)) for d in devices]
    if lights:
        raise LanguageError(f"the {vocabulary.phrase_of(device)} can only be switched on or off")
    if state in BLIND_STATES:
        percent = BLIND_STATES[state]
    elif state in ("on", "off"):
        percent = 100 if state == "on" else 0
    elif state.isdigit():
        percent = int(state)
    else:
        raise LanguageError(f"unknown device state {state!r}: {frame}")
    level = vocabulary.level(percent)
    if level is None:
        known = sorted(p for p in (level_percent(s) for s in vocabulary.instances) if p is not None)
        nearest = nearest_level(percent, known)
        if nearest is None:
            raise LanguageError(f"this world has no level of {percent} percent (it has none)")
        level = vocabulary.level(nearest) or ""
        notes.append(
            f"{vocabulary.phrase_of(device)}: {nearest} percent, the nearest level to {percent} this world "
            f"has ({', '.join(str(p) for p in known)})"
        )
    return [Fact("device_level", (d, level)) for d in devices]


def nearest_level(percent: int, known: Sequence[int]) -> int | None:
    """The level of ``known`` nearest to ``percent``; a level strictly between 0 and 100 goes to one strictly
    between them where there is one ("lower the blinds to 10 percent" leaves them a little open, not shut).
    Ties go to the lower level. None when ``known`` is empty."""
    inner = [p for p in known if 0 < p < 100]
    pool = inner if 0 < percent < 100 and inner else list(known)
    return min(pool, key=lambda p: (abs(p - percent), p)) if pool else None


def _sourced(frame: CommandFrame, vocabulary: Vocabulary, theme: str) -> list[Fact]:
    """``(taken_from X f)`` for an object asked for from a piece of furniture, when the domain has it."""
    source = frame.get("source")
    if source and "taken_from" in vocabulary.predicates and vocabulary.is_of(source, "furniture"):
        return [Fact("taken_from", (theme, source))]
    return []


def room_of(place: str, vocabulary: Vocabulary) -> str:
    """The room a place is: itself for a room, the room a piece of furniture is in (``furniture_in``).

    Raises:
        LanguageError: the world does not say which room the furniture is in.
    """
    if not vocabulary.is_of(place, "furniture"):
        return place
    rooms = [p for p in vocabulary.locations.get(place, ()) if vocabulary.is_of(p, "room")]
    if len(rooms) != 1:
        raise LanguageError(f"this world does not say which room the {vocabulary.phrase_of(place)} is in")
    return rooms[0]


def hints(frames: Sequence[CommandFrame], vocabulary: Vocabulary) -> list[Fact]:
    """Where the command says things are, as assumptions for the planner's search (not goals).

    ``(possibly_at X room)`` for a theme said to be somewhere ("the apple from the kitchen cabinet", "find the
    glasses in the bedroom"), when the domain has ``possibly_at`` and the world does not already place X; also
    ``(possibly_on X f)`` for a piece of furniture f when the domain has that predicate.
    """
    if "possibly_at" not in vocabulary.predicates:
        return []
    found: list[Fact] = []
    for frame in frames:
        theme, where = frame.get("theme"), frame.get("source") or frame.get("ground")
        if frame.kind == "BRINGING" and frame.get("beneficiary") not in (None, SPEAKER):
            theme, where = frame.get("beneficiary"), frame.get("goal")  # where the one it is for is
        if not theme or not where or theme == SPEAKER or vocabulary.locations.get(theme):
            continue
        candidates = [Fact("possibly_on", (theme, where))] if vocabulary.is_of(where, "furniture") else []
        with contextlib.suppress(LanguageError):  # furniture in no known room: no room hint
            candidates.append(Fact("possibly_at", (theme, room_of(where, vocabulary))))
        for fact in candidates:
            try:
                validate_goal(fact, vocabulary)
            except LanguageError:
                continue
            if fact not in found:
                found.append(fact)
    return found


def _check_consistent(goals: Sequence[Fact]) -> None:
    for i, first in enumerate(goals):
        for second in goals[i + 1 :]:
            clash = (
                first.predicate == second.predicate
                and first.predicate in _SINGLE_VALUED
                and first.args[0] == second.args[0]
            ) or any(
                {first.predicate, second.predicate} == set(pair) and first.args == second.args
                for pair in _COMPLEMENTS
            )
            if clash:
                raise LanguageError(f"the goals {first} and {second} contradict each other")
