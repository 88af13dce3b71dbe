"""The referee's running score, published while an episode runs: a JSON file next to the run's journal.

The referee judges from ground truth only (:mod:`.referee`); :class:`LiveScore` judges the timeline the
:class:`~.recording.Recorder` has gathered so far, once per simulated second, and writes the score sheet to
the *score file* of the run's journal (:func:`score_path`): ``run.sqlite`` -> ``run.score.json``. Whoever
follows the journal (``knic serve``, ``knic run --serve``) reads that file the same way (:func:`read_score`):
the core never imports the reader, and the reader needs nothing but the file.

The file is replaced atomically (written beside it, then renamed), so a reader never sees half of it. Its
content (JSON)::

    {"benchmark": "granny_annie", "episode": 0, "request": "bring me my glasses", "sim_time": 41.0,
     "final": false, "score": {<Score.to_dict()>}}

Mid-run, an achievement judged "at the end" (a device switched, an object brought, a person accompanied) is
judged on the latest ground-truth sample: the sheet says what would count if the run ended now; ``final``
is true once the run ended and the referee's verdict is written.

A journal staged by ``knic run --journal FILE`` (``.FILE.<pid>.partial``, see :mod:`knic.cli.outputs`) has
the score file of ``FILE``, so followers of either name find it.
"""

from __future__ import annotations

import dataclasses
import json
import os
import re
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from knic.bench.granny_annie.episodes import Episode
    from knic.bench.granny_annie.recording import Recorder
    from knic.bench.granny_annie.referee import Score
    from knic.scheduler import Scheduler

#: the largest score file a reader accepts (bytes)
MAX_SCORE_BYTES = 256 * 1024
#: simulated seconds between two judgements; wall seconds between two writes of an unchanged sheet
JUDGE_PERIOD_S, REWRITE_WALL_S = 1.0, 1.0
_PARTIAL = re.compile(r"^\.(?P<name>.+)\.\d+\.partial$")


def score_path(journal: str | Path) -> Path:
    """The score file of a run's journal: ``run.sqlite`` -> ``run.score.json`` in the same folder (a staged
    ``.run.sqlite.<pid>.partial`` has the score file of ``run.sqlite``)."""
    journal = Path(journal)
    match = _PARTIAL.match(journal.name)
    name = match.group("name") if match else journal.name
    return journal.with_name(Path(name).stem + ".score.json")


def read_score(path: Path) -> dict[str, Any] | None:
    """The score file's content, or None when it is missing, too large or not a score (a reader polls it)."""
    try:
        if path.stat().st_size > MAX_SCORE_BYTES:
            return None
        data = json.loads(path.read_bytes())
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or not isinstance(data.get("score"), dict):
        return None
    return data


class LiveScore:
    """Judges the episode's timeline so far and publishes the sheet (see the module docstring).

    Lifecycle: construct after the :class:`Recorder`, :meth:`attach` to the run's scheduler before the run
    (it is stepped after the recorder's probes, every ``period_s``), :meth:`finish` with the
    referee's final score after it.

    Args:
        recorder: the run's recorder (its timeline is read, never changed).
        episode: the episode the referee judges.
        understood: the goals the robot has announced so far (None: none yet), asked at each judgement.
        path: the score file (:func:`score_path` of the journal); None keeps the sheet in memory only.
        spoken_name: how the robot says a symbol (the referee's ``spoken_name``).
        period_s: simulated seconds between two judgements (the benchmark runner judges less often: each
            judgement reads the whole timeline so far).
    """

    name = "bench.score"

    def __init__(
        self,
        recorder: Recorder,
        episode: Episode,
        understood: Callable[[], tuple[str, ...] | None],
        path: Path | None,
        spoken_name: Callable[[str], str] | None = None,
        period_s: float = JUDGE_PERIOD_S,
    ) -> None:
        self.period_s = period_s
        self.recorder = recorder
        self.episode = episode
        self.understood = understood
        self.path = path
        self.spoken_name = spoken_name
        self.latest: dict[str, Any] | None = None
        self.writes = 0
        self._written: tuple[str, float] | None = None

    def attach(self, scheduler: Scheduler) -> None:
        """Judge once per :attr:`period_s` simulated seconds during the run."""
        from knic.system.loop import Probe

        def step(now: float) -> None:
            self.judge(now)

        scheduler.add(Probe(self.name, 1.0 / self.period_s, step))

    def judge(self, now: float) -> dict[str, Any] | None:
        """Judge the timeline up to ``now`` and publish the sheet; returns it (None before the first
        sample)."""
        from knic.bench.granny_annie.referee import judge

        timeline = self.recorder.timeline
        if not timeline.samples:
            return None
        so_far = dataclasses.replace(timeline, end=now, understood=self.understood(), finished=False)
        return self._publish(judge(self.episode, so_far, self.spoken_name), now, final=False)

    def finish(self, score: Score, end: float) -> dict[str, Any]:
        """Publish the referee's final verdict (``final`` true)."""
        return self._publish(score, end, final=True)

    def _publish(self, score: Score, now: float, *, final: bool) -> dict[str, Any]:
        sheet = score.to_dict()
        record: dict[str, Any] = {
            "benchmark": "granny_annie",
            "episode": self.episode.index,
            "request": self.episode.text,
            "sim_time": round(now, 2),
            "final": final,
            "score": sheet,
        }
        self.latest = record
        if self.path is not None:
            key = json.dumps({**sheet, "time_s": None}, sort_keys=True)
            wall = time.monotonic()
            last = self._written
            if final or last is None or last[0] != key or wall - last[1] >= REWRITE_WALL_S:
                write_atomically(self.path, json.dumps(record, sort_keys=True))
                self._written = (key, wall)
                self.writes += 1
        return record


def write_atomically(path: Path, text: str) -> None:
    """Replace ``path`` with ``text`` in one rename (a reader sees the old file or the new one)."""
    staged = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    staged.write_text(text, encoding="utf-8")
    os.replace(staged, path)


# ------------------------------------------------------------------ knic run --scenario granny_annie
#: goal predicate -> the benchmark's request kind (reading a command's goals back into requests)
_KIND_OF = {
    "has": "bring",
    "reported": "find",
    "person_at": "accompany",
    "light_on": "device",
    "light_off": "device",
    "device_level": "device",
}


def episode_of_task(
    world: Any, text: str, seat: str | None, seed: int, goals: list[str], person: str = "annie"
) -> Episode:
    """The benchmark episode the referee judges for a task scenario's run (``knic run --scenario
    granny_annie``): Annie's words read back into the benchmark's requests (:func:`.commands.
    requests_of_text`), else one request per goal her words mean (``goals``); items where the world file puts
    them; ``person`` is who asked (the task's person).
    """
    from knic.bench.granny_annie.commands import Request, candidate_requests, requests_of_text
    from knic.bench.granny_annie.episodes import Episode, lexicon_of, world_vocabulary

    placements = {name: item.on for name, item in world.items.items() if item.on}
    requests = requests_of_text(text, candidate_requests(world, world_vocabulary(world), placements, person))
    if requests is None:
        requests = []
        for goal in goals:
            words = goal.strip("()").split()
            kind = _KIND_OF.get(words[0], "device")
            room = words[2] if kind == "accompany" and len(words) > 2 else None
            target = words[2] if words[0] == "has" and len(words) > 2 else words[1]
            requests.append(Request(kind, text, (goal,), (target,), room))
    room = world.furniture[seat].room if seat and seat in world.furniture else ""
    lexicon = lexicon_of(world)
    return Episode(
        index=0,
        seed=seed,
        world=world.name,
        lexicon=str(lexicon) if lexicon else None,
        person_on=seat or None,
        person_room=room,
        placements=placements,
        off_prior=(),
        requests=tuple(requests),
        text=text,
        person=person,
    )
