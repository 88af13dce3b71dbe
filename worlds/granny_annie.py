"""The simulated side of the Granny Annie task: episodes drawn per seed, and Annie answering the robot.

A scenario with a ``task:`` section (``worlds/erl_home/scenarios/granny_annie.yaml``) describes the task::

    task:
      person: annie                 # who calls and asks
      seats: [bed, sofa]            # where she may wait (one drawn per seed)
      call_at: 2.0                  # when she calls from the tablet (simulated seconds)
      requests: [...]               # request texts of the voice bank (one drawn per seed)
      answer: "yes"                 # what she answers when the robot repeats her request back
      bank: voices/bank.yaml        # the voice bank, relative to the world folder (default: the ERL bank)

:func:`episode` turns it into concrete events for one seed (Annie seated) and the recordings she will say.
:class:`AnnieActor` is Annie herself: she calls the robot from her tablet at the episode's call time,
listens to what the robot says (as any person in the room hears it) and, a moment later, speaks the
recorded request when the robot asks what she needs, and the recorded answer when it asks whether it
understood her (said plainly, "yes", when it asks her to answer yes or no). The robot hears both through its
microphone only (the recordings reach it as audio); nothing here is read by the robot's side.
:func:`custom_episode` makes an episode for a run set up elsewhere (a benchmark's world and scenario).
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from core.errors import WorldError
from core.inputs import read_yaml
from worlds.scenario import CALL_TEXT, Event, Scenario

if TYPE_CHECKING:
    from core.robot import Utterance
    from worlds.model import World

#: who the task serves ("me") in a world that has her
DEFAULT_PERSON = "annie"
#: the voice bank shipped with the ERL apartment
DEFAULT_BANK = Path(__file__).resolve().parent / "erl_home" / "voices" / "bank.yaml"
#: words in what the robot says that Annie takes as "what do you need?" / "is that right?"
ASKS_REQUEST = ("what can i do for you", "how can i help")
ASKS_ANSWER = ("is that right",)
#: what the robot says when it did not get her answer: she then says it plainly
ASKS_PLAIN_ANSWER = ("please answer yes or no",)


def first_person(world: World) -> str | None:
    """Who "me" is in ``world`` when nobody is named: annie when the world knows her, else its first known
    person in file order, else None (the rule of ``knic goal --world``, ``knic run``, ``knic sweep --suite
    flat`` and the Granny Annie benchmark; strangers, ``known: false``, are never "me")."""
    known = [name for name, person in world.people.items() if person.known]
    return DEFAULT_PERSON if DEFAULT_PERSON in known else next(iter(known), None)


def served_person(world: World, name: str | None = None) -> str:
    """The person the Granny Annie task serves in ``world``: ``name`` when given, else :func:`first_person`.

    Raises:
        WorldError: ``name`` is not a known person of the world, or the world knows nobody.
    """
    known = [n for n, person in world.people.items() if person.known]
    if name is not None:
        if name not in known:
            offered = ", ".join(known) or "none"
            raise WorldError(f"world {world.name}: no known person {name!r} to serve (known: {offered})")
        return name
    chosen = first_person(world)
    if chosen is None:
        raise WorldError(f"world {world.name}: no known person to serve")
    return chosen


@dataclass(frozen=True)
class VoiceClip:
    """One recording of the voice bank: its WAV file, speaker, kind (request, yes, no) and words."""

    file: Path
    speaker: str
    kind: str
    text: str


def load_bank(path: Path = DEFAULT_BANK) -> list[VoiceClip]:
    """The recordings of a voice bank file (paths resolved beside it).

    Raises:
        WorldError: the file is missing or malformed.
    """
    data = read_yaml(path, "voice bank", WorldError)
    if not isinstance(data, dict) or not isinstance(data.get("utterances"), list):
        raise WorldError(f"voice bank {path}: needs a list 'utterances'")
    clips = []
    for i, u in enumerate(data["utterances"]):
        if not isinstance(u, dict) or not {"file", "speaker", "kind", "text"} <= set(u):
            raise WorldError(f"voice bank {path}: utterances[{i}] needs file, speaker, kind and text")
        clips.append(
            VoiceClip(path.parent / str(u["file"]), str(u["speaker"]), str(u["kind"]), str(u["text"]))
        )
    return clips


@dataclass(frozen=True)
class Episode:
    """One Granny Annie run: where Annie waits, what she asks and answers, and the concrete scenario.

    Attributes:
        seed: the seed it was drawn for.
        person: who calls and asks (``annie``).
        seat: the furniture she waits on.
        request: the recording of her request.
        answer: the recording of her answer to the robot's repeat-back.
        plain_answer: the same answer said plainly ("yes"), when the robot asks her to answer yes or no.
        no_answer: her plain "no", said when a judge finds the robot's repeat-back wrong (None: never).
        scenario: the scenario with her seat as an event, ready for the simulation.
        call_at: when she calls from the tablet (simulated seconds; she makes the call, see AnnieActor).
    """

    seed: int
    person: str
    seat: str
    request: VoiceClip
    answer: VoiceClip
    plain_answer: VoiceClip
    scenario: Scenario
    call_at: float = 2.0
    no_answer: VoiceClip | None = None


def episode(scenario: Scenario, seed: int, *, request: str | None = None, seat: str | None = None) -> Episode:
    """Draw one episode of a task scenario for ``seed`` (``request``/``seat`` override the draw).

    Raises:
        WorldError: the scenario has no task, or a request or seat is not offered.
    """
    task = scenario.task
    if task is None:
        raise WorldError(f"scenario {scenario.name!r} has no task section")
    rng = random.Random(seed)
    bank_path = DEFAULT_BANK
    if task.get("bank"):
        base = scenario.source.parent.parent if scenario.source is not None else DEFAULT_BANK.parent.parent
        bank_path = base / str(task["bank"])
    bank = load_bank(bank_path)
    person = str(task["person"])
    mine = [c for c in bank if c.speaker == person]
    requests = [c for c in mine if c.kind == "request"]
    if task.get("requests"):
        by_text = {c.text: c for c in requests}
        missing = [t for t in task["requests"] if t not in by_text]
        if missing:
            raise WorldError(f"the voice bank has no recording of the request {missing[0]!r} by {person}")
        requests = [by_text[t] for t in task["requests"]]
    offered = requests
    if request is not None:
        offered = [c for c in mine if c.kind == "request" and c.text == request.strip().lower()]
        if not offered:
            raise WorldError(f"the voice bank has no request {request!r} by {person}")
    if not offered:
        raise WorldError(f"the voice bank has no request by {person} that the task offers")
    seats = list(task.get("seats") or [])
    chosen_seat = seat if seat is not None else (rng.choice(seats) if seats else "")
    clip = offered[seed % len(offered)] if request is None else offered[0]
    kind = str(task.get("answer", "yes"))
    answers = [c for c in mine if c.kind == kind]
    if not answers:
        raise WorldError(f"the voice bank has no {kind!r} answer by {person}")
    answer = answers[rng.randrange(len(answers))]
    events: list[Event] = []
    if chosen_seat:
        events.append(Event(0.0, "person_to", {"person": person, "furniture": chosen_seat, "teleport": True}))
    events += list(scenario.events)
    events.sort(key=lambda e: e.at)
    concrete = Scenario(scenario.name, scenario.description, tuple(events), scenario.source, dict(task))
    plain = min(answers, key=lambda c: (len(c.text.split()), c.text))
    call_at = float(task.get("call_at", 2.0))
    noes = [c for c in mine if c.kind == "no"]
    no = min(noes, key=lambda c: (len(c.text.split()), c.text)) if noes else None
    return Episode(seed, person, chosen_seat, clip, answer, plain, concrete, call_at, no)


class SpeechWorld(Protocol):
    """What Annie uses of the simulation: the robot's speech she hears, her own voice, the clock."""

    @property
    def time(self) -> float:
        """Simulated seconds."""
        ...

    def spoken(self) -> list[Utterance]:
        """Everything the robot said, oldest first."""
        ...

    def hear(self, text: str, speaker: str = "annie", audio_path: str | None = None) -> None:
        """A person says ``text`` now (with its recording)."""
        ...


class AnnieActor:
    """Annie answering the robot (see the module docstring); call :meth:`step` with the simulated time.

    Args:
        world: the simulation (what the robot said; her voice).
        episode: what she asks and answers.
        delay_s: simulated seconds she takes to answer.
        hears: whether she hears the robot now (default: always; a test may make her deaf).
        judge: whether the robot's repeat-back (its words) is what she asked; when it is not she answers
            her plain "no" (default: she always gives the episode's answer).
    """

    def __init__(
        self,
        world: SpeechWorld,
        episode: Episode,
        *,
        delay_s: float = 1.5,
        hears: Callable[[], bool] | None = None,
        judge: Callable[[str], bool] | None = None,
    ) -> None:
        self.world = world
        self.judge = judge
        self.episode = episode
        self.delay_s = delay_s
        self.hears = hears or (lambda: True)
        self.said: list[tuple[float, str]] = []
        self.called = False
        self._seen = 0
        self._due: list[tuple[float, VoiceClip]] = []

    def step(self, now: float) -> None:
        """Call at the episode's call time; react to what the robot said since the last step; speak what is
        due."""
        if not self.called and now >= self.episode.call_at:
            self.called = True
            self.world.hear(CALL_TEXT, speaker=self.episode.person)  # the tablet call, where she sits
            self.said.append((now, CALL_TEXT))
        robot_said = self.world.spoken()
        for utterance in robot_said[self._seen :]:
            if self.hears():
                self._react(utterance.text.lower(), now)
        self._seen = len(robot_said)
        while self._due and self._due[0][0] <= now:
            _, clip = self._due.pop(0)
            audio = str(clip.file) if clip.file.is_file() else None
            self.world.hear(clip.text, speaker=self.episode.person, audio_path=audio)
            self.said.append((now, clip.text))

    def _react(self, text: str, now: float) -> None:
        if any(p in text for p in ASKS_REQUEST):
            self._due.append((now + self.delay_s, self.episode.request))
        elif any(p in text for p in ASKS_ANSWER):
            no = self.episode.no_answer
            wrong = self.judge is not None and no is not None and not self.judge(text)
            self._due.append((now + self.delay_s, no if wrong and no is not None else self.episode.answer))
        elif any(p in text for p in ASKS_PLAIN_ANSWER):
            self._due.append((now + self.delay_s, self.episode.plain_answer))


def clip_for(
    text: str, person: str, kind: str, audio: str | Path | None, bank_path: Path = DEFAULT_BANK
) -> VoiceClip:
    """A clip for ``text``: the given recording, else the bank's recording of that text by ``person``, else
    the words alone (no audio: the robot hears the text, as typed)."""
    if audio is not None:
        return VoiceClip(Path(audio), person, kind, text)
    for clip in load_bank(bank_path) if bank_path.is_file() else []:
        if clip.speaker == person and clip.text == text.strip().lower():
            return clip
    return VoiceClip(Path(), person, kind, text)


def custom_episode(
    person: str,
    request: str,
    *,
    request_audio: str | Path | None = None,
    answer: str = "yes",
    answer_audio: str | Path | None = None,
    call_at: float = 2.0,
    scenario: Scenario | None = None,
    seat: str = "",
) -> Episode:
    """An episode for a run that is already set up (a benchmark's own world and scenario): who calls, when,
    what they ask (a recording or the words) and answer."""
    ask = clip_for(request, person, "request", request_audio)
    said = clip_for(answer, person, answer, answer_audio)
    plain = clip_for(answer, person, answer, None)
    base = scenario or Scenario("custom", "", ())
    return Episode(-1, person, seat, ask, said, plain, base, call_at, clip_for("no", person, "no", None))


def requests_of(bank: Sequence[VoiceClip], person: str) -> list[str]:
    """The request texts a person has recordings for."""
    return [c.text for c in bank if c.speaker == person and c.kind == "request"]
