"""What planning costs the robot on its clock: a plan starts only once the planner would have answered.

The dispatcher charges every planner call to the simulated (or wall) clock it runs on, so a slow fallback to
an external engine is not free inside a timed task. Three modes (``planning_time``): ``model`` charges a
modelled cost, ``wall`` the measured wall time, ``off`` nothing.
"""

from __future__ import annotations

import math

from planner.plan import PlanResult, PlanStatus

#: how planning time is charged on the dispatcher's clock
PLANNING_TIME = ("off", "model", "wall")
#: model: seconds an external engine (a Fast Downward fallback) is charged per call
EXTERNAL_ENGINE_S = 10.0


def thinking_seconds(result: PlanResult, mode: str, timeout: float) -> float:
    """Clock seconds a planner call costs the robot (see the module docstring), in tenths of a second.

    ``model``: 0.1 s plus 0.1 s per 2,000 ground actions for the in-process search, ``EXTERNAL_ENGINE_S``
    for another engine, the whole ``timeout`` for a call that timed out; ``wall``: the wall time spent,
    rounded up; ``off``: nothing.
    """
    if mode == "off":
        return 0.0
    if mode == "wall":
        return math.ceil(result.planning_ms / 100.0 - 1e-9) / 10.0
    if result.status == PlanStatus.TIMEOUT:
        return float(timeout)
    if result.engine and result.engine != "knic":
        return EXTERNAL_ENGINE_S
    return round(0.1 + math.floor(result.stats.get("ground_actions", 0.0) / 2000.0) / 10.0, 1)
