"""Two verdicts kept apart: the robot's own "done" from its beliefs, and the referee's from ground truth.

* :class:`BeliefVerdict` is what the robot can know: every goal holds in its knowledge base (and perception
  confirmed the perceivable ones, or had ``settle_s`` to do so), or every goal still open was dropped by the
  dispatcher's recovery policy and the robot stayed idle ``give_up_s`` (new knowledge may bring a goal back
  meanwhile); and no task flow (a scenario's dialogue with Annie) is still busy. A run stops on this verdict
  only.
* :class:`Referee` judges the same goals from the simulator's ground truth (the oracle). Only referees and
  benchmarks hold an oracle; nothing the robot runs reads it. It watches the run (:meth:`Referee.observe`,
  a probe of the run loop): what was true when the robot said something (a report is judged against where
  the entity was *then*) and which furniture each item was taken from.

Both are asked at the run loop's checks, in simulated time, and change nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Protocol

from knowledge_base import BeliefStatus, Fact, KnowledgeBase

#: goal predicates the simulator's ground truth decides directly
TRUTH_PREDICATES = frozenset(
    {
        "robot_at",
        "person_at",
        "object_at",
        "object_on",
        "holding",
        "hand_empty",
        "has",
        "light_on",
        "light_off",
        "device_level",
        "person_near",
    }
)
#: goal predicates a KP' can confirm (status OBSERVED) once an action made them true
PERCEIVED_PREDICATES = frozenset(
    {"robot_at", "person_at", "object_at", "object_on", "light_on", "light_off", "device_level"}
)


@dataclass(frozen=True)
class Stop:
    """Why a run stops: ``done`` when the robot believes every goal achieved, else the goals were dropped."""

    done: bool
    reason: str


class BeliefVerdict:
    """The robot's own stop condition, from its knowledge base and its dispatcher's book of goals.

    Args:
        kb: the knowledge base (goals, facts, provenance).
        dropped_for_good: the goals (as PDDL strings) the recovery policy dropped, with why; called at
            each check.
        idle: whether the dispatcher has nothing left to work on; called at each check.
        settle_s: simulated seconds to wait, once every goal holds, for perception to confirm the perceivable
            ones as observed.
        give_up_s: simulated seconds the dispatcher must stay idle with every open goal dropped.
        busy: callables telling whether a task flow still runs (the run does not stop while one does).
    """

    def __init__(
        self,
        kb: KnowledgeBase,
        dropped_for_good: Callable[[], Mapping[str, str]],
        idle: Callable[[], bool],
        settle_s: float = 8.0,
        give_up_s: float = 0.0,
        busy: list[Callable[[], bool]] | None = None,
    ) -> None:
        self.kb = kb
        self.dropped_for_good = dropped_for_good
        self.idle = idle
        self.settle_s = settle_s
        self.give_up_s = give_up_s
        self.busy = busy if busy is not None else []
        self._settle_from: float | None = None
        self._given_up_from: float | None = None

    def __call__(self, now: float) -> Stop | None:
        """The verdict at simulated time ``now``: a :class:`Stop`, or None while the run should go on."""
        if any(flow() for flow in self.busy):
            self._settle_from = self._given_up_from = None
            return None
        goals = self.kb.goals()
        missing = [g for g in goals if not self.kb.holds(g)]
        if not missing:
            self._settle_from = now if self._settle_from is None else self._settle_from
            if not self.unconfirmed() or now - self._settle_from >= self.settle_s:
                return Stop(True, "the robot believes every goal achieved")
            return None
        self._settle_from = None
        dropped = self.dropped_for_good()
        gone = sorted(str(g) for g in missing if str(g) in dropped)
        if not (gone and len(gone) == len(missing) and self.idle()):
            self._given_up_from = None
            return None
        self._given_up_from = now if self._given_up_from is None else self._given_up_from
        if now - self._given_up_from >= self.give_up_s:
            return Stop(False, f"goal {gone[0]} dropped: {dropped[gone[0]]}")
        return None

    def unconfirmed(self) -> list[Fact]:
        """Goal facts of perceivable predicates that hold but not (yet) as OBSERVED."""
        out = []
        for goal in self.kb.goals():
            if goal.predicate not in PERCEIVED_PREDICATES:
                continue
            prov = self.kb.why(goal)
            if prov is None or prov.status != BeliefStatus.OBSERVED:
                out.append(goal)
        return out


class GroundTruth(Protocol):
    """What the referee reads: the oracle's true facts and what the robot said aloud."""

    def ground_truth_facts(self, include_static: bool = False) -> set[tuple[str, ...]]:
        """The true dynamic facts of the ERL domain as tuples."""
        ...


class Referee:
    """Judges goals against ground truth (never the robot's beliefs).

    Args:
        oracle: the simulator's ground truth.
        said: the robot's utterances so far (what a human referee hears), oldest first.
        spoken_name: how the robot says a symbol aloud (``coke_can`` -> ``coke can``).
    """

    def __init__(
        self,
        oracle: GroundTruth,
        said: Callable[[], Iterable[str]],
        spoken_name: Callable[[str], str],
    ) -> None:
        self.oracle = oracle
        self.said = said
        self.spoken_name = spoken_name
        #: (utterance, the true dynamic facts when it was said), in order (filled by :meth:`observe`)
        self.heard: list[tuple[str, frozenset[tuple[str, ...]]]] = []
        #: (item, furniture) pairs: the robot took the item off the furniture (filled by :meth:`observe`)
        self.taken_from: set[tuple[str, str]] = set()
        self._last_on: dict[str, str] = {}

    def observe(self, now: float) -> None:
        """Note what is true now for what the robot said since the last call, and where items leave from.

        Called by a probe of the run loop after the robot's parts at the same instant (simulated time)."""
        said = list(self.said())
        truth: frozenset[tuple[str, ...]] | None = None
        if len(said) > len(self.heard):
            truth = frozenset(self.oracle.ground_truth_facts())
            self.heard += [(text, truth) for text in said[len(self.heard) :]]
        truth = truth if truth is not None else frozenset(self.oracle.ground_truth_facts())
        on = {f[1]: f[2] for f in truth if f[0] == "object_on"}
        for item in {f[2] for f in truth if f[0] == "holding"}:
            if item in self._last_on:
                self.taken_from.add((item, self._last_on.pop(item)))
        self._last_on.update(on)

    def holds(self, goal: Fact) -> bool:
        """Whether ground truth agrees with ``goal`` (goals it cannot judge count as true).

        ``reported`` is judged from what the robot said: a report ("I found the ...") naming the entity and
        the room where it truly was when the robot said it (or now, for utterances :meth:`observe` did not
        see), or the gripper when the robot held it. ``taken_from`` is judged from what :meth:`observe` saw.
        """
        truth = self.oracle.ground_truth_facts()
        if goal.predicate in TRUTH_PREDICATES:
            return (goal.predicate, *goal.args) in truth
        if goal.predicate == "taken_from":
            return (goal.args[0], goal.args[1]) in self.taken_from
        if goal.predicate == "reported":
            entity = goal.args[0]
            claim = f"i found the {self.spoken_name(entity)}"
            judged = [(text, then) for text, then in self.heard]
            judged += [(text, frozenset(truth)) for text in list(self.said())[len(self.heard) :]]
            return any(
                text.lower().startswith(claim) and any(p in text.lower() for p in self._places(entity, then))
                for text, then in judged
            )
        return True

    def _places(self, entity: str, truth: Iterable[tuple[str, ...]]) -> list[str]:
        """How a report may say where ``entity`` is, given the true facts ``truth``."""
        return true_places(entity, truth, self.spoken_name)

    def unmet(self, goals: Iterable[Fact]) -> list[Fact]:
        """The goals that do not hold in ground truth."""
        return [g for g in goals if not self.holds(g)]


def true_places(
    entity: str, truth: Iterable[tuple[str, ...]], spoken_name: Callable[[str], str]
) -> list[str]:
    """The phrases a true report of where ``entity`` is may contain, given the true facts ``truth``: its room,
    "in my gripper" when the robot holds it, or the room of the person who has it (an item already handed
    over is where that person is)."""
    facts = list(truth)
    rooms = {f[1]: f[2] for f in facts if f[0] in ("object_at", "person_at")}
    places = [f"in the {spoken_name(rooms[entity])}"] if entity in rooms else []
    for f in facts:
        if f[0] == "holding" and f[2] == entity:
            places.append("in my gripper")
        if f[0] == "has" and f[2] == entity and f[1] in rooms:
            places.append(f"in the {spoken_name(rooms[f[1]])}")
    return places
