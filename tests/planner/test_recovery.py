"""The recovery policy as data."""

from __future__ import annotations

import pytest

from actions.base import Outcome
from core.errors import KnicError
from planner.recovery import GoalRetry, Recovery, RecoveryPolicy, RecoveryRule


def test_decide_retries_then_falls_back() -> None:
    policy = RecoveryPolicy({Outcome.EXECUTION_FAILURE: RecoveryRule(2, Recovery.DROP_GOAL)})
    assert [policy.decide(Outcome.EXECUTION_FAILURE, n) for n in (1, 2, 3)] == [
        Recovery.RETRY,
        Recovery.RETRY,
        Recovery.DROP_GOAL,
    ]
    assert policy.decide(Outcome.TIMEOUT, 1) == Recovery.REPLAN  # unlisted: no retry, replan


def test_policy_round_trips_through_a_dict_and_rejects_bad_entries() -> None:
    policy = RecoveryPolicy.from_dict(
        {"max_replans_per_goal": 3, "rules": {"timeout": {"retries": 1, "then": "drop_goal"}}}
    )
    assert policy.rule(Outcome.TIMEOUT) == RecoveryRule(1, Recovery.DROP_GOAL)
    assert policy.rule(Outcome.PRECONDITION_FAILURE) == RecoveryRule(0, Recovery.REPLAN)
    assert RecoveryPolicy.from_dict(policy.to_dict()) == policy
    with pytest.raises(KnicError, match="'exploded'"):
        RecoveryPolicy.from_dict({"rules": {"exploded": {"retries": 1}}})
    with pytest.raises(KnicError, match="retries for 'timeout' must be >= 0"):
        RecoveryPolicy.from_dict({"rules": {"timeout": {"retries": -1}}})


def test_goal_retry_is_a_rule_of_the_policy_and_round_trips() -> None:
    policy = RecoveryPolicy.from_dict({"goal_retry": {"times": 20, "after_s": 10}})
    assert policy.goal_retry == GoalRetry(20, 10.0)
    assert RecoveryPolicy.from_dict(policy.to_dict()) == policy
    assert RecoveryPolicy().goal_retry.times == 0  # by default a dropped goal stays dropped
    with pytest.raises(KnicError, match="goal_retry has no setting 'every'"):
        RecoveryPolicy.from_dict({"goal_retry": {"every": 3}})
    with pytest.raises(KnicError, match="must be >= 0"):
        RecoveryPolicy.from_dict({"goal_retry": {"times": -1}})
