"""``knic goal TEXT``: understand a typed command and print its frames and PDDL goals.

Nothing is added to any knowledge base: the command shows what ``knic run --goal TEXT`` would add. A command
that is not understood prints its reason (in the JSON object with ``--json``) and exits with code 4; an
ambiguous one also prints the question to ask back.

``knic goal -`` reads one command per line on standard input and prints one JSON object per line (blank lines
are skipped); it exits 0 when every command was understood, else 4 after the last line.

The world's vocabulary is read straight from its PDDL files (:func:`knic.language.world.read_vocabulary`),
or with ``--world FILE`` from a world file as ``knic run --world`` takes (its rooms, furniture, objects,
people and devices, typed by the domain), so the command answers without importing the planning libraries.
"""

from __future__ import annotations

import argparse
import json
from typing import Any

from core.errors import KnicError, LanguageError


def add_world_arguments(parser: argparse.ArgumentParser) -> None:
    """Options shared by ``knic goal`` and ``knic say``: the world and the speaker."""
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--speaker",
        help="the person 'me' refers to (default: annie if the world has her, else its first known person)",
    )
    parser.add_argument(
        "--world",
        help="a world file (as for knic run, e.g. worlds/test_flat/test_flat.yaml) or name (erl_home): its "
        "rooms, furniture, objects, people and devices with the domain's types; instead of --problem",
    )
    parser.add_argument("--domain", help="PDDL domain (default: worlds/erl_home/domain.pddl)")
    parser.add_argument("--problem", help="PDDL problem (default: worlds/erl_home/erl_home_problem.pddl)")
    parser.add_argument(
        "--lexicon",
        help="spoken names (default: lexicon.yaml beside the problem, the world file or the domain; with "
        "--world and none beside it, the ERL lexicon, as knic run)",
    )


def load_vocabulary(args: argparse.Namespace) -> Any:
    """The vocabulary of the world chosen by the options; sets ``args.speaker`` when it was not given.

    Raises:
        KnicError: both --world and --problem, or a world file that is missing or invalid (one line).
    """
    from knic.language.world import DEFAULT_DOMAIN, DEFAULT_PROBLEM, read_vocabulary

    domain = args.domain or DEFAULT_DOMAIN
    if getattr(args, "world", None) is not None:
        if args.problem is not None:
            raise KnicError("--world and --problem both say what the world holds: give one of them")
        vocabulary, me = world_vocabulary(args.world, domain, args.lexicon)
        if args.speaker is None:
            args.speaker = me or "annie"
        return vocabulary
    problem = args.problem or (DEFAULT_PROBLEM if args.domain is None else None)
    vocabulary = read_vocabulary(domain, problem, args.lexicon)
    if args.speaker is None:  # annie, or the problem's first person where it has no annie
        people = sorted(s for s, t in vocabulary.instances.items() if vocabulary.is_subtype(t, "person"))
        args.speaker = "annie" if "annie" in people or not people else people[0]
    return vocabulary


def world_vocabulary(world: str, domain: Any, lexicon: str | None) -> tuple[Any, str | None]:
    """The vocabulary of a world file (what the robot knows before a run: its instances and which room each
    piece of furniture is in) with the domain's types, constants and predicates, and who "me" is there
    (:func:`worlds.granny_annie.first_person`; None when it knows nobody).

    Only the world file is read (no simulator, no planning library), so ``knic goal`` stays quick to start.

    Raises:
        WorldError: the world is neither a known name nor a valid world file.
        LanguageError: the domain or the lexicon is unreadable.
    """
    from knic.language.vocabulary import Lexicon, Vocabulary
    from knic.language.world import WORLDS, find_lexicon, read_vocabulary
    from worlds.granny_annie import first_person
    from worlds.loader import load_world, resolve_world_path

    path = resolve_world_path(world)
    model = load_world(path)
    base = read_vocabulary(domain, None, None)  # the domain's types, constants (levels) and predicates
    strangers = {name for name, person in model.people.items() if not person.known}
    instances = {**base.instances}
    instances.update({s: t for s, t in model.symbols().items() if s not in strangers})
    locations: dict[str, list[str]] = {}
    for predicate, *args in sorted(model.static_facts()):
        if predicate == "furniture_in":
            locations.setdefault(args[0], []).append(args[1])
    for device, room in model.device_rooms().items():
        locations.setdefault(device, []).append(room)
    lexicon_path = lexicon or find_lexicon(domain, path) or WORLDS / "erl_home" / "lexicon.yaml"
    names = Lexicon.load(lexicon_path).with_entrances(model.entrances(), model.back_entrances())
    vocabulary = Vocabulary.from_instances(instances, base.types, names, base.predicates, locations)
    return vocabulary, first_person(model)


def print_understanding(data: dict[str, Any], as_json: bool) -> None:
    """Print an understanding as JSON or as readable lines; raise LanguageError (exit 4) when rejected."""
    if as_json:
        print(json.dumps(data))
    else:
        if "transcript" in data:
            print(f"heard: {data['transcript'] or '(nothing)'}")
        for frame in data["frames"]:
            args = ", ".join(f"{k}: {v}" for k, v in frame.items() if k != "frame")
            print(f"frame: {frame['frame']}({args})")
        for goal in data["goals"]:
            print(f"goal: {goal}")
        if data.get("question"):
            print(f"question: {data['question']}")
        for note in data.get("notes", []):
            print(f"note: {note}")
    if not data["accepted"]:
        raise LanguageError(f"not understood: {data['reason']}")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "text", help='the command, e.g. "bring me my glasses"; "-": one command per line on stdin'
    )
    add_world_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from knic.language.understanding import understand

    vocabulary = load_vocabulary(args)
    if args.text == "-":
        return _batch(vocabulary, args.speaker)
    result = understand(args.text, vocabulary, speaker=args.speaker)
    print_understanding(result.to_dict(), args.json)
    return 0


def _batch(vocabulary: Any, speaker: str) -> int:
    import sys

    from knic.language.understanding import understand

    refused = 0
    for line in sys.stdin:
        if line.strip():
            result = understand(line.strip(), vocabulary, speaker=speaker)
            refused += not result.accepted
            print(json.dumps(result.to_dict()), flush=True)
    if refused:
        raise LanguageError(f"{refused} command(s) not understood")
    return 0
