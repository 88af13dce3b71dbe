"""The recovery policy: what the dispatcher does after each kind of failure, as data.

A policy maps each :class:`~actions.base.Outcome` to a :class:`RecoveryRule`: retry the same action up to
``retries`` times (the at-start conditions are checked again before each try), then ``replan`` or
``drop_goal`` (drop the goals the rest of the plan was to reach, replan for the others).
``max_replans_per_goal`` bounds the replans any one goal may cause; past it the goal is dropped, so the
dispatch loop never spins forever.

A dropped goal may come back (:class:`GoalRetry`): at most ``times`` times, and only when knowledge relevant
to it changed since the drop (a fact naming one of the goal's subjects, its arguments that are not rooms,
furniture or levels, appeared or went) or its ``after_s`` back-off elapsed, and only while no action runs
(a retry never cancels an action in progress for another goal). ``times: 0`` (the default) keeps dropped
goals dropped.

The same plan step failing the same way again (same ground action, outcome and reason, numbers aside) is
not retried blindly (:class:`RepeatedFailure`): from its ``retract_after``-th occurrence the dispatcher
retracts the perceived beliefs the step rests on (the positions of the people and items it names, so
perception must find them again; with none to retract it backs off ``backoff_s`` seconds per occurrence
before planning again), and from its ``drop_after``-th it drops the goals the step served.

Policies load from plain dicts (e.g. a YAML file)::

    {"max_replans_per_goal": 5,
     "rules": {"execution failure": {"retries": 1, "then": "replan"},
               "timeout": {"retries": 0, "then": "drop_goal"}},
     "goal_retry": {"times": 20, "after_s": 10.0},
     "repeated": {"retract_after": 2, "drop_after": 4, "backoff_s": 3.0}}
"""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from actions.base import Outcome
from core.errors import KnicError


class Recovery(enum.StrEnum):
    """What to do after a failure once retries are used up."""

    RETRY = "retry"
    REPLAN = "replan"
    DROP_GOAL = "drop_goal"


@dataclass(frozen=True)
class RecoveryRule:
    """Retry the failed action ``retries`` times, then do ``then``."""

    retries: int = 0
    then: Recovery = Recovery.REPLAN


def _default_rules() -> dict[Outcome, RecoveryRule]:
    return {
        Outcome.PRECONDITION_FAILURE: RecoveryRule(0, Recovery.REPLAN),
        Outcome.ACTIVATION_FAILURE: RecoveryRule(1, Recovery.REPLAN),
        Outcome.EXECUTION_FAILURE: RecoveryRule(1, Recovery.REPLAN),
        Outcome.TIMEOUT: RecoveryRule(0, Recovery.REPLAN),
        Outcome.DEACTIVATION_FAILURE: RecoveryRule(0, Recovery.REPLAN),
        Outcome.POSTCONDITION_FAILURE: RecoveryRule(0, Recovery.REPLAN),
        Outcome.CANCELLED: RecoveryRule(0, Recovery.REPLAN),
    }


@dataclass(frozen=True)
class GoalRetry:
    """When a dropped goal comes back (see the module docstring).

    Attributes:
        times: retries per goal; 0: a dropped goal stays dropped.
        after_s: back-off in seconds of the dispatcher's clock after which a dropped goal comes back even
            without relevant new knowledge.
    """

    times: int = 0
    after_s: float = 10.0


@dataclass(frozen=True)
class RepeatedFailure:
    """What changes when the same step fails the same way again (see the module docstring).

    Attributes:
        retract_after: occurrence from which the beliefs the step rests on are retracted (or the robot backs
            off); 0: never.
        drop_after: occurrence from which the goals the step served are dropped; 0: never.
        backoff_s: seconds per occurrence the dispatcher waits before planning again when there is nothing
            to retract.
    """

    retract_after: int = 2
    drop_after: int = 4
    backoff_s: float = 3.0


@dataclass(frozen=True)
class RecoveryPolicy:
    """Per-outcome recovery rules plus the per-goal replan bound.

    Attributes:
        rules: outcome -> rule; outcomes not listed get ``RecoveryRule()`` (no retry, replan).
        max_replans_per_goal: replans one goal may cause before it is dropped.
        goal_retry: when a dropped goal comes back.
        repeated: what changes when the same step fails the same way again.
    """

    rules: Mapping[Outcome, RecoveryRule] = field(default_factory=_default_rules)
    max_replans_per_goal: int = 5
    goal_retry: GoalRetry = GoalRetry()
    repeated: RepeatedFailure = RepeatedFailure()

    def rule(self, outcome: Outcome) -> RecoveryRule:
        """The rule for ``outcome``."""
        return self.rules.get(outcome, RecoveryRule())

    def decide(self, outcome: Outcome, failures: int) -> Recovery:
        """What to do after the ``failures``-th consecutive failure (1-based) of the same plan step."""
        rule = self.rule(outcome)
        return Recovery.RETRY if failures <= rule.retries else rule.then

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> RecoveryPolicy:
        """Build a policy from a plain dict (see the module docstring); unlisted outcomes keep the defaults.

        Raises:
            KnicError: unknown outcome name, unknown recovery, or a negative count or back-off.
        """
        rules = _default_rules()
        for name, spec in dict(data.get("rules", {})).items():
            try:
                outcome = Outcome(name)
                then = Recovery(spec.get("then", "replan"))
            except ValueError as exc:
                raise KnicError(f"recovery policy: {exc} (rule {name!r})") from None
            retries = int(spec.get("retries", 0))
            if retries < 0:
                raise KnicError(f"recovery policy: retries for {name!r} must be >= 0, got {retries}")
            rules[outcome] = RecoveryRule(retries, then)
        bound = int(data.get("max_replans_per_goal", 5))
        if bound < 0:
            raise KnicError(f"recovery policy: max_replans_per_goal must be >= 0, got {bound}")
        retry = dict(data.get("goal_retry", {}))
        unknown = sorted(set(retry) - {"times", "after_s"})
        if unknown:
            raise KnicError(f"recovery policy: goal_retry has no setting {unknown[0]!r} (times, after_s)")
        goal_retry = GoalRetry(int(retry.get("times", 0)), float(retry.get("after_s", 10.0)))
        if goal_retry.times < 0 or goal_retry.after_s < 0:
            raise KnicError(f"recovery policy: goal_retry times and after_s must be >= 0, got {retry}")
        rep = dict(data.get("repeated", {}))
        unknown = sorted(set(rep) - {"retract_after", "drop_after", "backoff_s"})
        if unknown:
            raise KnicError(
                f"recovery policy: repeated has no setting {unknown[0]!r}"
                " (retract_after, drop_after, backoff_s)"
            )
        repeated = RepeatedFailure(
            int(rep.get("retract_after", 2)), int(rep.get("drop_after", 4)), float(rep.get("backoff_s", 3.0))
        )
        if repeated.retract_after < 0 or repeated.drop_after < 0 or repeated.backoff_s < 0:
            raise KnicError(f"recovery policy: repeated counts and backoff_s must be >= 0, got {rep}")
        return cls(rules, bound, goal_retry, repeated)

    def to_dict(self) -> dict[str, Any]:
        """The policy as a plain dict (round-trips through :meth:`from_dict`)."""
        return {
            "max_replans_per_goal": self.max_replans_per_goal,
            "rules": {o.value: {"retries": r.retries, "then": r.then.value} for o, r in self.rules.items()},
            "goal_retry": {"times": self.goal_retry.times, "after_s": self.goal_retry.after_s},
            "repeated": {
                "retract_after": self.repeated.retract_after,
                "drop_after": self.repeated.drop_after,
                "backoff_s": self.repeated.backoff_s,
            },
        }
