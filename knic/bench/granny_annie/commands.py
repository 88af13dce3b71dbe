"""Annie's command: 1-3 chained ERL requests in a world's vocabulary, each with the PDDL goals it means.

The goals are written here from the ERL request kinds, not by the language understanding under test:

==============================================  ==========================================
request                                         goals
==============================================  ==========================================
switch on/off a light (or a lexicon group)      ``(light_on d)`` / ``(light_off d)`` per light
set the dimmer to N percent                     ``(device_level d lN)``
open / close / half open the blinds             ``(device_level d l100)`` / ``l0`` / ``l50``
find / locate / look for / search for the X     ``(reported X)``
bring me / get me / fetch me the X             ``(has P X)``, P the served person
bring me ... the X from F                       also ``(taken_from X F)`` (when the domain has it)
lead / guide / escort / accompany P to the R    ``(person_at P R)``
==============================================  ==========================================

A device request always asks for a state the device is not in at the start (so it cannot pass untouched); an
accompany request names a person the robot knows other than the served person (never a stranger such as the
door-bell visitor, whom the robot has no name for) and a room the person is not in. Every phrase names
exactly one symbol of its kind. A command has at most one bring request (a simulated person holds one
object at a time) and at most one accompany request.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary
    from worlds.model import World

#: number of chained requests: 1, 2, 3 with these weights
CHAIN_WEIGHTS = (0.45, 0.35, 0.20)
#: request kinds and their weights when drawing a request
KIND_WEIGHTS = {"device": 0.3, "find": 0.25, "bring": 0.3, "accompany": 0.15}
#: percent levels the domain names (l0 ... l100)
LEVELS = (0, 25, 50, 75, 100)
#: blinds commands by target percent
BLIND_WORDS = {100: "open", 0: "close", 50: "half open"}
SEARCH_VERBS = ("find", "locate", "look for", "search for")
BRING_VERBS = ("bring me", "get me", "fetch me")
ACCOMPANY_VERBS = ("lead", "guide", "escort", "accompany")
SWITCH_VERBS = ("switch", "turn")
#: probability that a bring request names where the item stands ("from the kitchen cabinet")
SOURCE_P = 0.2
#: probability that a light request uses a lexicon group containing the light ("the bedroom lights")
GROUP_P = 0.3


@dataclass(frozen=True)
class Request:
    """One ERL request of Annie's command.

    Attributes:
        kind: ``device``, ``find``, ``bring`` or ``accompany``.
        text: the words, in the world's vocabulary ("switch on the hallway light").
        goals: the PDDL goals the request means, e.g. ``("(has annie remote)",)`` when annie asks; a device
            request has one goal per device it operates.
        targets: the devices, the item, or the person concerned.
        room: the destination room of an accompany request, else None.
    """

    kind: str
    text: str
    goals: tuple[str, ...]
    targets: tuple[str, ...]
    room: str | None = None


def pick(rng: np.random.Generator, options: list[Any], weights: list[float] | None = None) -> Any:
    """One of ``options``, uniformly or by ``weights`` (one draw from ``rng`` either way)."""
    if weights is None:
        return options[int(rng.integers(len(options)))]
    total = sum(weights)
    return options[int(rng.choice(len(options), p=[w / total for w in weights]))]


def join_requests(texts: list[str]) -> str:
    """``a``; ``a and b``; ``a, b and c``."""
    if len(texts) == 1:
        return texts[0]
    return ", ".join(texts[:-1]) + " and " + texts[-1]


def level_of(percent: float) -> int:
    """The domain level (percent) nearest to ``percent``."""
    return min(LEVELS, key=lambda lv: (abs(lv - percent), lv))


class _Phrases:
    """Unambiguous spoken phrases per symbol (a phrase naming two symbols is never used)."""

    def __init__(self, vocab: Vocabulary) -> None:
        owners: dict[str, set[str]] = {}
        for t in vocab.terms:
            owners.setdefault(t.phrase, set()).add(t.symbol)
        self.by_symbol: dict[str, list[str]] = {}
        self.groups: dict[str, tuple[tuple[str, ...], list[str]]] = {}
        for t in vocab.terms:
            if len(owners[t.phrase]) != 1:
                continue
            if t.is_group and t.phrase.split()[0] in ("all", "both"):
                continue  # "the all lights" is not said
            if t.is_group:
                self.groups.setdefault(t.symbol, (t.members, []))[1].append(t.phrase)
            else:
                self.by_symbol.setdefault(t.symbol, []).append(t.phrase)

    def of(self, rng: np.random.Generator, symbol: str) -> str:
        return str(pick(rng, self.by_symbol[symbol]))


def draw_requests(
    world: World, vocab: Vocabulary, rng: np.random.Generator, placements: dict[str, str], person: str
) -> list[Request]:
    """1-3 requests the world supports, with distinct targets, as ``person`` (the served person, "me") says
    them (see the module docstring)."""
    phrases = _Phrases(vocab)
    count = int(pick(rng, [1, 2, 3], list(CHAIN_WEIGHTS)))
    used: set[str] = set()
    out: list[Request] = []
    for _ in range(count):
        options = {
            "device": _devices(world, phrases, used),
            "find": [i for i in sorted(placements) if i not in used and i in phrases.by_symbol],
            "bring": [i for i in sorted(placements) if i not in used and i in phrases.by_symbol]
            if not any(r.kind == "bring" for r in out)
            else [],
            "accompany": _people(world, phrases, used, person)
            if not any(r.kind == "accompany" for r in out)
            else [],
        }
        kinds = [k for k in KIND_WEIGHTS if options[k]]
        if not kinds:
            break
        kind = pick(rng, kinds, [KIND_WEIGHTS[k] for k in kinds])
        target = pick(rng, options[kind])
        if kind == "device":
            request = _device_request(world, vocab, phrases, rng, target, used)
        elif kind == "find":
            verb = pick(rng, list(SEARCH_VERBS))
            request = Request(
                kind, f"{verb} the {phrases.of(rng, target)}", (f"(reported {target})",), (target,)
            )
        elif kind == "bring":
            verb = pick(rng, list(BRING_VERBS))
            text = f"{verb} the {phrases.of(rng, target)}"
            source = placements[target]
            goals: tuple[str, ...] = (f"(has {person} {target})",)
            if rng.random() < SOURCE_P and source in phrases.by_symbol:
                text += f" from the {phrases.of(rng, source)}"
                goals += _source_goal(vocab, target, source)
            request = Request(kind, text, goals, (target,))
        else:
            here = world.room_of(*world.people[target].position)
            rooms = [r for r in sorted(world.rooms) if r != here and r in phrases.by_symbol]
            room = pick(rng, rooms)
            verb = pick(rng, list(ACCOMPANY_VERBS))
            text = f"{verb} {phrases.of(rng, target)} to the {phrases.of(rng, room)}"
            request = Request(kind, text, (f"(person_at {target} {room})",), (target,), room)
        out.append(request)
        used.update(request.targets)
    return out


def _source_goal(vocab: Vocabulary, item: str, furniture: str) -> tuple[str, ...]:
    """``(taken_from item furniture)`` when the domain keeps a request's source, else nothing."""
    return (f"(taken_from {item} {furniture})",) if "taken_from" in vocab.predicates else ()


def _devices(world: World, phrases: _Phrases, used: set[str]) -> list[str]:
    return [
        d.name
        for d in sorted(world.devices.values(), key=lambda d: d.name)
        if d.kind in ("light", "dimmer", "blinds") and d.name not in used and d.name in phrases.by_symbol
    ]


def _people(world: World, phrases: _Phrases, used: set[str], person: str) -> list[str]:
    return [
        p.name
        for p in sorted(world.people.values(), key=lambda p: p.name)
        if p.present
        and p.known
        and p.name != person
        and p.name not in used
        and p.name in phrases.by_symbol
        and world.room_of(*p.position) is not None
        and len(world.rooms) > 1
    ]


def _device_request(
    world: World, vocab: Vocabulary, phrases: _Phrases, rng: np.random.Generator, name: str, used: set[str]
) -> Request:
    device = world.devices[name]
    if device.kind == "light":
        on = not bool(device.initial)
        state = "on" if on else "off"
        members: tuple[str, ...] = (name,)
        phrase = phrases.of(rng, name)
        groups = [
            (g, m, p)
            for g, (m, p) in sorted(phrases.groups.items())
            if name in m
            and len(m) > 1
            and not used & set(m)
            and all(x in world.devices and bool(world.devices[x].initial) == bool(device.initial) for x in m)
        ]
        use_group = rng.random() < GROUP_P
        if groups and use_group:
            _g, members, group_phrases = pick(rng, groups)
            phrase = pick(rng, group_phrases)
        verb = pick(rng, list(SWITCH_VERBS))
        goals = tuple(f"(light_{state} {m})" for m in members)
        return Request("device", f"{verb} {state} the {phrase}", goals, members)
    start = level_of(device.initial)
    if device.kind == "blinds":
        percent = int(pick(rng, [p for p in BLIND_WORDS if p != start]))
        text = f"{BLIND_WORDS[percent]} the {phrases.of(rng, name)}"
    else:
        percent = int(pick(rng, [p for p in LEVELS if p != start]))
        from knic.language.vocabulary import number_words

        text = f"set the {phrases.of(rng, name)} to {number_words(percent)} percent"
    level = vocab.level(percent) or f"l{percent}"
    return Request("device", text, (f"(device_level {name} {level})",), (name,))


# ------------------------------------------------------------------------------------ reading a command back


def candidate_requests(
    world: World, vocab: Vocabulary, placements: dict[str, str], person: str
) -> dict[str, Request]:
    """Every single request the world supports at the start as ``person`` says it, by its normalised wording
    (all verbs, phrases and determiners); used to read a recorded command back into requests
    (:func:`requests_of_text`). A wording naming anything the world lacks is not a candidate."""
    from knic.language.vocabulary import normalize, number_words

    phrases = _Phrases(vocab)
    out: dict[str, Request] = {}

    def add(text: str, request: Request) -> None:
        out.setdefault(
            normalize(text), Request(request.kind, text, request.goals, request.targets, request.room)
        )

    for name in _devices(world, phrases, set()):
        device = world.devices[name]
        if device.kind == "light":
            state = "off" if device.initial else "on"
            named: list[tuple[str, tuple[str, ...]]] = [(p, (name,)) for p in phrases.by_symbol[name]]
            named += [
                (p, m)
                for _g, (m, ps) in phrases.groups.items()
                if name in m and all(bool(world.devices[x].initial) == bool(device.initial) for x in m)
                for p in ps
            ]
            for phrase, members in named:
                goals = tuple(f"(light_{state} {m})" for m in members)
                for verb in SWITCH_VERBS:
                    add(f"{verb} {state} the {phrase}", Request("device", "", goals, members))
            continue
        start = level_of(device.initial)
        percents = [p for p in (BLIND_WORDS if device.kind == "blinds" else LEVELS) if p != start]
        for percent in percents:
            goals = (f"(device_level {name} {vocab.level(percent) or f'l{percent}'})",)
            for phrase in phrases.by_symbol[name]:
                request = Request("device", "", goals, (name,))
                if device.kind == "blinds":
                    add(f"{BLIND_WORDS[percent]} the {phrase}", request)
                add(f"set the {phrase} to {number_words(percent)} percent", request)
    dets = ("the", "my", "a", "an")
    for item in sorted(placements):
        for phrase in phrases.by_symbol.get(item, []):
            for det in dets:
                for verb in SEARCH_VERBS:
                    add(f"{verb} {det} {phrase}", Request("find", "", (f"(reported {item})",), (item,)))
                for verb in BRING_VERBS:
                    request = Request("bring", "", (f"(has {person} {item})",), (item,))
                    add(f"{verb} {det} {phrase}", request)
                    sourced = Request(
                        "bring", "", request.goals + _source_goal(vocab, item, placements[item]), (item,)
                    )
                    for source in phrases.by_symbol.get(placements[item], []):
                        add(f"{verb} {det} {phrase} from the {source}", sourced)
    for other in _people(world, phrases, set(), person):
        here = world.room_of(*world.people[other].position)
        for room in sorted(world.rooms):
            if room == here or room not in phrases.by_symbol:
                continue
            request = Request("accompany", "", (f"(person_at {other} {room})",), (other,), room)
            for verb in ACCOMPANY_VERBS:
                for who in phrases.by_symbol[other]:
                    for where in phrases.by_symbol[room]:
                        add(f"{verb} {who} to the {where}", request)
    return out


def requests_of_text(text: str, candidates: dict[str, Request]) -> list[Request] | None:
    """The requests of a chained command (``a, b and c``) when every part is a candidate request with
    distinct targets and at most one bring and one accompany request, else None (pronouns such as "bring it
    to me" are not read back)."""
    import re

    from knic.language.vocabulary import normalize

    parts = [p for p in re.split(r",\s*and\s+|,\s*|\s+and\s+", text.strip()) if p]
    requests = [candidates.get(normalize(p)) for p in parts]
    if not requests or len(requests) > 3 or any(r is None for r in requests):
        return None
    found = [r for r in requests if r is not None]
    targets = [t for r in found for t in r.targets]
    once = ("accompany", "bring")
    if len(set(targets)) != len(targets) or any(sum(r.kind == k for r in found) > 1 for k in once):
        return None
    return found
