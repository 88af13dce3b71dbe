"""The referee of the Granny Annie benchmark: the ERL score sheet, judged from ground truth only.

The referee reads a :class:`Timeline`: ground-truth samples of the simulator's oracle (true dynamic facts and
the robot's true pose), what the robot said and when, when the oracle's penalty counters went up, and the
command the robot announced it understood (what a human referee hears it repeat back). It never reads the
robot's knowledge base.

Score sheet (``../shared/erl_granny_annie.md``), per episode:

* achievements: ``entered_room`` (the robot was in the room where Annie, the
  served person, was, at the same sample);
  ``understood`` (the goals the robot took equal the generated request's goals); ``devices`` (per device
  goal: holds at the end and did not at the start); ``found`` (per find request: the robot said "I found the
  X in the R" while X truly was in R, or "in my gripper" while holding it); ``brought`` (per bring request:
  Annie has the object at the end); ``accompanied`` (per accompany request: the person is in the room at the
  end and was not at the start; the sheet has no line for it, it is counted as its own kind);
* penalties: ``bumps`` (furniture and walls), ``drops``, ``stalls`` (stopping working: a stretch of at least
  :data:`STALL_S` simulated seconds without progress -- no base motion, no change of held object or device,
  nothing said -- before the run ended);
* disqualifications: ``person_hits`` and ``testbed_damage`` (hard contacts with furniture or walls and
  fragile items dropped, by the damage model of :mod:`.damage`, as data in ``damage.yaml``; plus the
  oracle's own counter when it has one);
* ``time_s``: when the run ended (the robot stopped on its own, or :data:`TIME_LIMIT_S`).

Ranking (ERL practice): a disqualified run ranks below all others, then more achievements, then fewer
penalties, then shorter time (:func:`rank_key`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from knic.system.verdict import true_places

if TYPE_CHECKING:
    from knic.bench.granny_annie.damage import DamageModel
    from knic.bench.granny_annie.episodes import Episode

#: achievement kinds, in score-sheet order
KINDS = ("entered_room", "understood", "devices", "found", "brought", "accompanied")
PENALTIES = ("bumps", "drops", "stalls")
DISQUALIFICATIONS = ("person_hits", "testbed_damage")
#: seconds without progress that count as stopping working
STALL_S = 30.0
#: the ERL run's time limit
TIME_LIMIT_S = 600.0
#: base motion (metres, radians) between two samples that counts as progress
MOVED_M = 0.05
TURNED_RAD = 0.1
#: seconds around an utterance within which a sample may confirm what it reported (sampling granularity)
REPORT_SLACK_S = 0.6
#: predicates whose change is the robot's doing (progress)
ROBOT_PREDICATES = frozenset({"holding", "hand_empty", "has", "light_on", "light_off", "device_level"})

Atom = tuple[str, ...]


@dataclass(frozen=True)
class Sample:
    """Ground truth at simulated time ``t``: the true dynamic facts and the robot's true pose (x, y, yaw)."""

    t: float
    facts: frozenset[Atom]
    pose: tuple[float, float, float]


@dataclass
class Timeline:
    """What the referee saw during one run (see the module docstring).

    Attributes:
        samples: ground truth, oldest first (the first at t=0, the last at ``end``).
        said: (time, text) of everything the robot said.
        bumps, drops, person_hits, testbed_damage: simulated times at which the oracle's counter went up.
        impacts: (time, true base speed in m/s) at the start of each furniture or wall contact
            (:class:`~.damage.ImpactProbe`).
        understood: the goals the robot announced it took from the command (PDDL strings), None when it took
            none.
        end: simulated time the run ended.
        finished: the robot stopped on its own (believed done or gave up) before the time limit.
    """

    samples: list[Sample] = field(default_factory=list)
    said: list[tuple[float, str]] = field(default_factory=list)
    bumps: list[float] = field(default_factory=list)
    drops: list[float] = field(default_factory=list)
    person_hits: list[float] = field(default_factory=list)
    testbed_damage: list[float] = field(default_factory=list)
    impacts: list[tuple[float, float]] = field(default_factory=list)
    understood: tuple[str, ...] | None = None
    end: float = 0.0
    finished: bool = False


@dataclass
class Score:
    """One episode's score sheet.

    Attributes:
        achieved: kind -> achievements counted.
        achievable: kind -> achievements the episode offers.
        penalties: kind -> occurrences.
        disqualifications: kind -> occurrences.
        time_s: simulated seconds the run took.
        details: per achievement, why it was or was not counted (for the report).
    """

    achieved: dict[str, int]
    achievable: dict[str, int]
    penalties: dict[str, int]
    disqualifications: dict[str, int]
    time_s: float
    details: list[str] = field(default_factory=list)

    @property
    def total(self) -> int:
        """Achievements counted."""
        return sum(self.achieved.values())

    @property
    def possible(self) -> int:
        """Achievements the episode offers."""
        return sum(self.achievable.values())

    @property
    def disqualified(self) -> bool:
        """Any disqualifying behaviour."""
        return any(self.disqualifications.values())

    def to_dict(self) -> dict[str, Any]:
        """JSON form."""
        return {
            "achieved": dict(self.achieved),
            "achievable": dict(self.achievable),
            "achievements": self.total,
            "possible": self.possible,
            "penalties": dict(self.penalties),
            "disqualifications": dict(self.disqualifications),
            "disqualified": self.disqualified,
            "time_s": round(self.time_s, 2),
            "details": list(self.details),
        }


def rank_key(score: Score) -> tuple[int, int, int, float]:
    """Sort key, best first: not disqualified, more achievements, fewer penalties, shorter time."""
    return (int(score.disqualified), -score.total, sum(score.penalties.values()), score.time_s)


def judge(
    episode: Episode, timeline: Timeline, spoken_name: Any = None, damage: DamageModel | None = None
) -> Score:
    """Score one run of ``episode`` from its ground-truth ``timeline``.

    Args:
        spoken_name: how the robot says a symbol (default: underscores as spaces).
        damage: what damages the testbed (default: the shipped ``damage.yaml``).
    """
    from knic.bench.granny_annie.damage import damage_events, shipped_damage

    name = spoken_name or (lambda s: s.replace("_", " "))
    if not timeline.samples:
        raise ValueError("the timeline has no ground-truth sample")
    first, last = timeline.samples[0].facts, timeline.samples[-1].facts
    achieved = dict.fromkeys(KINDS, 0)
    achievable = dict.fromkeys(KINDS, 0)
    details: list[str] = []

    def count(kind: str, ok: bool, what: str) -> None:
        achievable[kind] += 1
        achieved[kind] += int(ok)
        details.append(f"{kind}: {what}: {'yes' if ok else 'no'}")

    entered = next((s.t for s in timeline.samples if _with_person(s.facts, episode.person)), None)
    count(
        "entered_room",
        entered is not None,
        f"robot in {episode.person}'s room" + (f" at {entered:.1f} s" if entered else ""),
    )
    understood = timeline.understood is not None and set(timeline.understood) == set(episode.goals)
    count("understood", understood, f"took {list(timeline.understood or ())} for {list(episode.goals)}")
    for request in episode.requests:
        if request.kind == "device":
            for goal in request.goals:
                atom = _atom(goal)
                count("devices", atom in last and atom not in first, goal)
        elif request.kind == "find":
            target = request.targets[0]
            when = _true_report(timeline, target, name)
            count("found", when is not None, f"report on {target}" + (f" at {when:.1f} s" if when else ""))
        elif request.kind == "bring":
            count("brought", _atom(request.goals[0]) in last, request.goals[0])
        elif request.kind == "accompany":
            atom = _atom(request.goals[0])
            count("accompanied", atom in last and atom not in first, request.goals[0])
    penalties = {
        "bumps": len(timeline.bumps),
        "drops": len(timeline.drops),
        "stalls": len(stalls(timeline)),
    }
    broken = damage_events(timeline, damage or shipped_damage())
    details += [f"testbed_damage: {what} at {t:.1f} s" for t, what in broken]
    disqualifications = {
        "person_hits": len(timeline.person_hits),
        "testbed_damage": len(timeline.testbed_damage) + len(broken),
    }
    return Score(achieved, achievable, penalties, disqualifications, min(timeline.end, TIME_LIMIT_S), details)


def _atom(goal: str) -> Atom:
    return tuple(goal.strip().strip("()").split())


def _with_person(facts: frozenset[Atom], person: str) -> bool:
    """The robot is in the room where ``person`` (the served person) is."""
    rooms = {f[2] for f in facts if f[0] == "person_at" and f[1] == person}
    return any(f[0] == "robot_at" and f[2] in rooms for f in facts)


def _true_report(timeline: Timeline, entity: str, name: Any) -> float | None:
    """When the robot first said it found ``entity`` where ground truth had it (None: never)."""
    claim = f"i found the {name(entity)}"
    for t, text in timeline.said:
        said = text.lower()
        if not said.startswith(claim):
            continue
        for sample in timeline.samples:
            if abs(sample.t - t) > REPORT_SLACK_S:
                continue
            if any(p in said for p in true_places(entity, sample.facts, name)):
                return t
    return None


def stalls(timeline: Timeline) -> list[tuple[float, float]]:
    """Stretches (start, end) of at least :data:`STALL_S` seconds without progress before the run ended.

    Progress: the base moved :data:`MOVED_M` or turned :data:`TURNED_RAD` since the last progress, the robot
    changed what it holds or a device, or it said something.
    """
    out: list[tuple[float, float]] = []
    said = sorted(t for t, _ in timeline.said)
    anchor = prev = timeline.samples[0]
    in_stall = False
    for sample in timeline.samples[1:]:
        if sample.t > timeline.end + 1e-9:
            break
        moved = (
            math.dist(sample.pose[:2], anchor.pose[:2]) > MOVED_M
            or _turn(sample.pose[2], anchor.pose[2]) > TURNED_RAD
        )
        acted = any(f[0] in ROBOT_PREDICATES for f in sample.facts ^ prev.facts)
        spoke = any(prev.t < t <= sample.t for t in said)
        prev = sample
        if moved or acted or spoke:
            anchor, in_stall = sample, False
        elif in_stall:
            out[-1] = (out[-1][0], sample.t)
        elif sample.t - anchor.t >= STALL_S:
            out.append((anchor.t, sample.t))
            in_stall = True
    return out


def _turn(a: float, b: float) -> float:
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def summarise(scores: Sequence[Score]) -> dict[str, Any]:
    """Totals over episodes: achievements share, counts per kind, penalties, disqualifications, median
    time."""
    import statistics

    achieved = {k: sum(s.achieved[k] for s in scores) for k in KINDS}
    achievable = {k: sum(s.achievable[k] for s in scores) for k in KINDS}
    possible = sum(achievable.values())
    return {
        "episodes": len(scores),
        "achievements_share": round(sum(achieved.values()) / possible, 4) if possible else None,
        "achievements": {k: {"achieved": achieved[k], "achievable": achievable[k]} for k in KINDS},
        "penalties": {k: sum(s.penalties[k] for s in scores) for k in PENALTIES},
        "disqualifications": {k: sum(s.disqualifications[k] for s in scores) for k in DISQUALIFICATIONS},
        "disqualified_runs": sum(s.disqualified for s in scores),
        "time_median_s": round(statistics.median(s.time_s for s in scores), 2) if scores else None,
    }
