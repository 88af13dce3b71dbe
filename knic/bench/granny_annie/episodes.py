"""Episodes of the Granny Annie benchmark, generated from a world's data and priors, deterministic per seed.

An :class:`Episode` is everything the referee and the runner need to know about one run, decided before it
starts:

* who is served ("Annie": the person who calls and asks, "me" in her requests): ``annie`` when the world
  knows her, else the world's first known person in file order, or the person named
  (:func:`worlds.granny_annie.served_person`);
* where she waits (on the bed or the sofa when her priors or the world offer them, else where the world file
  puts her);
* where every item stands: drawn from its priors (weighted), and with probability ``placement.OFF_PRIOR_P`` on
  furniture none of its priors names ("off-prior"); an item without priors stays where the world file puts it
  unless it is drawn off-prior. Only spots the robot can reach from a free floor point count
  (:func:`~knic.bench.granny_annie.placement.graspable`);
* Annie's command: 1-3 chained ERL requests (operate a device, find an object, bring an object, accompany a
  person to a room) phrased in the world's vocabulary (its lexicon), each with the PDDL goals it means
  (:mod:`~knic.bench.granny_annie.commands`). With probability :data:`BANK_P` the command is one of the voice
  bank's (``worlds/erl_home/voices/bank.yaml``) that this episode supports, read back into requests (only a
  command every name of which the world has: its items, places, devices and people, with "me" the served
  person; the bank speaks erl_home's names, so another apartment mostly gets generated commands); a
  command the bank has a recording of in the served person's voice (annie's: the bank is hers) is spoken
  with probability :data:`SPOKEN_P`, else typed;
* dynamic events as scenario events (:mod:`worlds.scenario`), timed from the moment the robot takes the
  command: the door bell with a visitor walking in, a person moving an object mid-run (often one Annie asked
  for), people walking between rooms.

Episode ``i`` of seed ``S`` draws from its own random stream ``(S, i)``: the same seed and index give the same
episode whatever the number of episodes. A world without priors, without devices or without other people
simply gets no request or event of the kinds it cannot support.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from core.errors import KnicError
from core.inputs import read_yaml
from knic.bench.granny_annie.commands import (
    Request,
    candidate_requests,
    draw_requests,
    join_requests,
    pick,
    requests_of_text,
)
from knic.bench.granny_annie.events import draw_events
from knic.bench.granny_annie.placement import draw_placements, draw_seat
from worlds.granny_annie import served_person

if TYPE_CHECKING:
    from knic.language.vocabulary import Vocabulary
    from worlds.model import World

#: probability that a command with a matching recording is spoken rather than typed
SPOKEN_P = 0.6
#: probability that the command is drawn from the voice bank's commands this episode supports
BANK_P = 0.35
VOICES = Path(__file__).resolve().parents[3] / "worlds" / "erl_home" / "voices"
ERL_LEXICON = Path(__file__).resolve().parents[3] / "worlds" / "erl_home" / "lexicon.yaml"


@dataclass(frozen=True)
class Episode:
    """One generated episode (see the module docstring); JSON-able through :meth:`to_dict`.

    Attributes:
        index: position in the run (0-based); with ``seed`` it names the random stream.
        seed: the run's seed; also the simulator's seed for this episode (``seed * 1000 + index``).
        world: the world name or file the episode was drawn for.
        lexicon: the lexicon file of the world's spoken names, or None.
        person_on: the furniture the served person waits on, or None (standing where the world file puts
            them).
        person_room: the room the served person waits in.
        placements: item -> furniture it stands on at the start.
        off_prior: items placed where none of their priors says.
        requests: the chained requests, in the order Annie says them.
        text: the whole command as said or typed.
        audio: the voice bank recording of ``text`` when the command is spoken, else None.
        events: scenario events at the start (``worlds.scenario`` format): the served person's placement.
        after_command: scenario events whose ``at`` is seconds after the robot took the command (door bell,
            moved object, people walking; :mod:`.events`).
        person: the served person: who calls and asks, "me" of the requests (``(has person X)``).
    """

    index: int
    seed: int
    world: str
    lexicon: str | None
    person_on: str | None
    person_room: str
    placements: dict[str, str]
    off_prior: tuple[str, ...]
    requests: tuple[Request, ...]
    text: str
    audio: str | None = None
    events: tuple[dict[str, Any], ...] = field(default_factory=tuple)
    after_command: tuple[dict[str, Any], ...] = field(default_factory=tuple)
    person: str = "annie"

    @property
    def name(self) -> str:
        """``ep<index>`` (file names in the output directory)."""
        return f"ep{self.index:03d}"

    @property
    def sim_seed(self) -> int:
        """The simulator's seed for this episode."""
        return self.seed * 1000 + self.index

    @property
    def goals(self) -> tuple[str, ...]:
        """Every goal of the command, in order, without duplicates."""
        out: list[str] = []
        for r in self.requests:
            out += [g for g in r.goals if g not in out]
        return tuple(out)

    def to_dict(self) -> dict[str, Any]:
        """JSON form (lists for tuples)."""
        return json_ready(asdict(self))

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> Episode:
        """The episode of :meth:`to_dict`'s output."""
        d = dict(data)
        d["requests"] = tuple(
            Request(r["kind"], r["text"], tuple(r["goals"]), tuple(r["targets"]), r.get("room"))
            for r in d["requests"]
        )
        d["off_prior"] = tuple(d["off_prior"])
        d["events"] = tuple(d["events"])
        d["after_command"] = tuple(d.get("after_command", ()))
        for old, new in (("annie_on", "person_on"), ("annie_room", "person_room")):  # files written before
            if old in d:
                d[new] = d.pop(old)
        return cls(**d)

    def scenario(self) -> dict[str, Any]:
        """The episode's events as a scenario document (for :func:`worlds.scenario.scenario_from_dict`)."""
        return {
            "name": f"granny_annie_{self.name}",
            "description": f"Granny Annie benchmark episode {self.index} of seed {self.seed}",
            "events": [dict(e) for e in self.events],
        }

    def later_scenario(self) -> dict[str, Any]:
        """The events timed from the command as a scenario document (``at``: seconds after the command)."""
        return {
            "name": f"granny_annie_{self.name}_after_command",
            "description": f"episode {self.index} of seed {self.seed}: events after the command",
            "events": [dict(e) for e in self.after_command],
        }


def json_ready(value: Any) -> Any:
    """Tuples as lists, recursively (for JSON and for equality after a JSON round trip)."""
    if isinstance(value, dict):
        return {k: json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v) for v in value]
    return value


# ---------------------------------------------------------------------------------------------- generation


def generate_episodes(world: str | Path, count: int, seed: int, person: str | None = None) -> list[Episode]:
    """``count`` episodes of ``world`` (a name or file) for ``seed``, serving ``person`` (default: annie when
    the world knows her, else its first known person).

    Raises:
        core.errors.WorldError: the world cannot be loaded, or it knows no such person.
        KnicError: the world has nothing the person could ask for (no device, item or other person).
    """
    from worlds.api import load_world

    loaded = load_world(world)
    served = served_person(loaded, person)
    vocab = world_vocabulary(loaded)
    return [generate_episode(loaded, str(world), seed, i, vocab, person=served) for i in range(count)]


def generate_episode(
    world: World,
    world_ref: str,
    seed: int,
    index: int,
    vocab: Vocabulary | None = None,
    *,
    person: str | None = None,
) -> Episode:
    """Episode ``index`` of ``seed`` in ``world`` serving ``person`` (see the module docstring; default
    :func:`worlds.granny_annie.served_person`); ``vocab`` defaults to :func:`world_vocabulary`."""
    rng = np.random.default_rng([seed, index])
    vocab = vocab or world_vocabulary(world)
    person = served_person(world, person)
    person_on, person_room = draw_seat(world, rng, person)
    placements, off_prior = draw_placements(world, rng, person, person_on)
    candidates = candidate_requests(world, vocab, placements, person)
    # a bank command is usable only when every name it says is the world's (and "me" is the served person)
    usable = [(t, w, rs) for t, w, _ in voice_bank() if (rs := requests_of_text(t, candidates)) is not None]
    from_bank = rng.random() < BANK_P
    if usable and from_bank:
        text, _wav, requests = pick(rng, usable)
    else:
        requests = draw_requests(world, vocab, rng, placements, person)
        if not requests:
            raise KnicError(f"world {world.name}: nothing {person} could ask for (no device, item or person)")
        text = join_requests([r.text for r in requests])
    recorded = bank_recording(text, person)
    spoken = rng.random() < SPOKEN_P
    audio = str(recorded) if recorded is not None and spoken else None
    events, after_command = draw_events(world, rng, requests, placements, person_on, person)
    return Episode(
        index=index,
        seed=seed,
        world=world_ref,
        lexicon=str(lexicon_of(world)) if lexicon_of(world) else None,
        person_on=person_on,
        person_room=person_room,
        placements=placements,
        off_prior=tuple(off_prior),
        requests=tuple(requests),
        text=text,
        audio=audio,
        events=tuple(events),
        after_command=tuple(after_command),
        person=person,
    )


def lexicon_of(world: World) -> Path | None:
    """The lexicon beside the world file, else the ERL apartment's (entries for absent symbols are
    ignored)."""
    if world.source is not None and (world.source.parent / "lexicon.yaml").is_file():
        return world.source.parent / "lexicon.yaml"
    return ERL_LEXICON if ERL_LEXICON.is_file() else None


def world_vocabulary(world: World, lexicon: str | Path | None = None) -> Vocabulary:
    """The spoken vocabulary of ``world``: its symbols in the ERL domain plus its lexicon."""
    from knic.language.vocabulary import Lexicon, Vocabulary
    from knic.seed import seed_kb_from_world
    from knic.system.config import DOMAIN
    from knowledge_base import KnowledgeBase

    kb = KnowledgeBase.from_pddl(DOMAIN)
    seed_kb_from_world(kb, world)
    chosen = lexicon or lexicon_of(world)
    names = (Lexicon.load(chosen) if chosen is not None else Lexicon()).with_entrances(
        world.entrances(), world.back_entrances()
    )
    return Vocabulary.from_knowledge_base(kb, names)


@lru_cache(maxsize=1)
def voice_bank() -> tuple[tuple[str, Path, str], ...]:
    """(text, WAV file, speaker) of the shipped voice bank's requests whose recording exists."""
    bank = VOICES / "bank.yaml"
    if not bank.is_file():
        return ()
    data = read_yaml(bank, "voice bank", KnicError) or {}
    return tuple(
        (str(u["text"]), VOICES / str(u["file"]), str(u.get("speaker", "")))
        for u in data.get("utterances", [])
        if u.get("kind") == "request" and (VOICES / str(u["file"])).is_file()
    )


def bank_recording(text: str, person: str = "annie") -> Path | None:
    """The voice bank's recording of exactly ``text`` (punctuation and case aside) in ``person``'s voice, or
    None (the bank speaks annie's requests: another served person types them)."""
    from knic.language.vocabulary import normalize

    wanted = normalize(text)
    return next((wav for t, wav, who in voice_bank() if who == person and normalize(t) == wanted), None)
