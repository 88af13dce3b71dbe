"""The dispatcher's book of goals: which of the knowledge base's goals are active, achieved or dropped.

:class:`GoalBook` reads the goals from the knowledge base (cached until a goal change), and keeps:

* the **achieved** goals (a GOAL_ACHIEVED trace event the first time each holds; forgotten when it stops
  holding, so it is announced again when achieved again);
* the **dropped** goals with why (a GOAL_DROPPED trace event), and for each the drop time and what the
  knowledge base knew then about the goal's subjects (its arguments that are things, not rooms, furniture
  or levels: ``glasses`` in ``(object_at glasses bedroom)``);
* the replans each open goal caused (past :attr:`RecoveryPolicy.max_replans_per_goal
  <planner.recovery.RecoveryPolicy>` the goal is dropped);
* the **retries** of the recovery policy's :class:`~planner.recovery.GoalRetry` rule: a dropped goal comes
  back when what the knowledge base knows about its subjects changed since the drop, or its back-off elapsed,
  at most ``times`` times. Past that it is dropped for good.

A goal removed from the knowledge base and added again is a new goal. The book writes nothing to the
knowledge base; it is told about changes (:meth:`GoalBook.on_change`) and asked at each dispatcher step.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from knowledge_base import Change, ChangeKind, KnowledgeBase
from planner.model import Atom, atom_str
from planner.recovery import GoalRetry
from planner.trace import EventKind, Trace, TraceEvent

_GOAL_CHANGES = (ChangeKind.ADD_GOAL, ChangeKind.REMOVE_GOAL)
_FACT_CHANGES = (ChangeKind.ADD_FACT, ChangeKind.REMOVE_FACT)
#: argument types that are where things are, not what the goal is about
_PLACES_OR_CONSTANTS = frozenset({"room", "furniture", "level", None})


class GoalBook:
    """Active, achieved and dropped goals (see the module docstring).

    Args:
        kb: the knowledge base the goals are read from.
        trace: where GOAL_ACHIEVED, GOAL_DROPPED and retry (REPLAN) events go.
        clock: time source (seconds).
        retry: when a dropped goal comes back.

    Attributes:
        achieved: goals announced as achieved (and still holding when last looked at).
        dropped: dropped goal -> why.
    """

    def __init__(
        self, kb: KnowledgeBase, trace: Trace, clock: Callable[[], float], retry: GoalRetry | None = None
    ) -> None:
        self.kb = kb
        self.trace = trace
        self.clock = clock
        self.retry_rule = retry or GoalRetry()
        self.achieved: set[Atom] = set()
        self.dropped: dict[Atom, str] = {}
        self._goals: list[Atom] | None = None
        self._goal_set: frozenset[Atom] = frozenset()
        self._replans: dict[Atom, int] = {}
        self._retries: dict[Atom, int] = {}
        self._dropped_at: dict[Atom, float] = {}
        self._known_then: dict[Atom, frozenset[Atom]] = {}
        self._touched: set[Atom] = set()

    # -- the knowledge base's goals --------------------------------------------------------------------
    def goals(self) -> list[Atom]:
        """Every goal of the knowledge base, in its order."""
        if self._goals is None:
            self._goals = [(g.predicate, *g.args) for g in self.kb.goals()]
            self._goal_set = frozenset(self._goals)
        return self._goals

    def active(self) -> list[Atom]:
        """The goals being worked on: every goal not dropped."""
        goals = self.goals()
        if not self.dropped:
            return goals
        present = self._goal_set
        for gone in [g for g in self.dropped if g not in present]:
            self._forget_drop(gone)  # a goal removed and added again is a new goal
            self._retries.pop(gone, None)
        return [g for g in goals if g not in self.dropped]

    def on_change(self, change: Change) -> bool:
        """Note a knowledge-base change; True when it matters to an idle dispatcher (the goals changed, or a
        fact that is a goal appeared or went)."""
        if change.kind in _GOAL_CHANGES:
            self._goals = None
            return True
        if change.kind not in _FACT_CHANGES:
            return False
        if self.dropped:
            for goal in self.dropped:
                if any(a in change.args for a in self._subjects(goal)):
                    self._touched.add(goal)
        return self._goals is None or (change.name, *change.args) in self._goal_set

    # -- achieved ------------------------------------------------------------------------------------
    def announce(self, goals: Iterable[Atom], facts: frozenset[Atom] | set[Atom]) -> None:
        """Announce the goals that hold in ``facts`` for the first time; forget those that stopped holding."""
        now = self.clock()
        for goal in goals:
            if goal in facts and goal not in self.achieved:
                self.achieved.add(goal)
                self.trace.emit(TraceEvent(EventKind.GOAL_ACHIEVED, now, goal=atom_str(goal)))
            elif goal not in facts:
                self.achieved.discard(goal)

    # -- dropped -------------------------------------------------------------------------------------
    def drop(self, goal: Atom, reason: str) -> None:
        """Drop ``goal`` for ``reason`` (once; later drops of a dropped goal change nothing)."""
        if goal in self.dropped:
            return
        now = self.clock()
        self.dropped[goal] = reason
        self._dropped_at[goal] = now
        self._known_then[goal] = self._known_about(goal)
        self._touched.discard(goal)
        self.trace.emit(TraceEvent(EventKind.GOAL_DROPPED, now, goal=atom_str(goal), reason=reason))

    def superseded(
        self, conflicts: Iterable[tuple[Atom, Atom]], facts: frozenset[Atom]
    ) -> list[tuple[Atom, Atom]]:
        """The (new goal, older goal) pairs where a new goal can never hold together with an older goal that
        was already achieved and still holds ("the glasses to the living room", done; later "to the
        bedroom"): the new wish replaces the old one, which should leave the goals."""
        return [(g, o) for g, o in conflicts if o in self.achieved and o in facts and g not in facts]

    def count_replan(self, goals: list[Atom], facts: frozenset[Atom], bound: int) -> None:
        """Charge a replan to every open goal of ``goals``; drop those past ``bound`` replans."""
        for goal in goals:
            if goal in facts:
                continue
            count = self._replans.get(goal, 0) + 1
            self._replans[goal] = count
            if count > bound:
                self.drop(goal, f"gave up after {count - 1} replans")

    def reset_replans(self) -> None:
        """Every goal achieved or dropped: replan budgets start afresh."""
        self._replans.clear()

    def undrop(self, goal: Atom) -> bool:
        """Forget why ``goal`` was dropped (and its replans); False when it was not dropped."""
        if goal not in self.dropped:
            return False
        self._forget_drop(goal)
        self._replans.pop(goal, None)
        return True

    def _forget_drop(self, goal: Atom) -> None:
        del self.dropped[goal]
        self._dropped_at.pop(goal, None)
        self._known_then.pop(goal, None)
        self._touched.discard(goal)

    def give_up(self, goal: Atom, reason: str) -> None:
        """Drop ``goal`` for good (its retries used up): whoever told the user it gave up on it (a task flow)
        makes sure no retry brings it back. A goal not dropped yet is dropped for ``reason`` first."""
        self.drop(goal, reason)
        self._retries[goal] = max(self._retries.get(goal, 0), self.retry_rule.times)
        self._touched.discard(goal)

    def for_good(self) -> dict[str, str]:
        """Dropped goals (as PDDL text) whose retries are used up, with why."""
        times = self.retry_rule.times
        return {atom_str(g): why for g, why in self.dropped.items() if self._retries.get(g, 0) >= times}

    # -- retries -------------------------------------------------------------------------------------
    def due_retries(self) -> list[Atom]:
        """Dropped goals the retry rule hands back now, counted as retried and undropped, each with a REPLAN
        trace event; none while every goal holds."""
        rule = self.retry_rule
        if not self.dropped or rule.times <= 0:
            return []
        now = self.clock()
        due = []
        for goal in list(self.dropped):
            if self._retries.get(goal, 0) >= rule.times:
                continue
            elapsed = now - self._dropped_at.get(goal, now) >= rule.after_s
            if elapsed or (goal in self._touched and self._known_about(goal) != self._known_then.get(goal)):
                due.append(goal)
            self._touched.discard(goal)
        if not due or all(self.kb.holds(*g) for g in self.goals()):
            return []
        for goal in due:
            count = self._retries.get(goal, 0) + 1
            self._retries[goal] = count
            why = self.dropped[goal]
            self.undrop(goal)
            reason = f"retrying goal {atom_str(goal)} ({count}/{rule.times}) dropped for: {why}"
            self.trace.emit(TraceEvent(EventKind.REPLAN, now, reason=reason, goal=atom_str(goal)))
        return due

    def _subjects(self, goal: Atom) -> tuple[str, ...]:
        """The goal's arguments that are things (robot, people, items, devices), not places or levels."""
        return tuple(a for a in goal[1:] if self.kb.type_of(a) not in _PLACES_OR_CONSTANTS)

    def _known_about(self, goal: Atom) -> frozenset[Atom]:
        """The facts naming one of the goal's subjects."""
        subjects = self._subjects(goal)
        return frozenset(
            (f.predicate, *f.args) for f in self.kb.facts() if any(a in f.args for a in subjects)
        )
