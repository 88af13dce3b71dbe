"""An item a simulated person carries is held in front of them at hand height, outside the body."""

from __future__ import annotations

import math
from collections.abc import Callable

from worlds.sim.people import HAND_HEIGHT
from worlds.simulation import Simulation


def test_a_carried_item_is_held_in_front_of_the_carrier(make_sim: Callable[..., Simulation]) -> None:
    sim = make_sim("erl_home", scenario="moved_object")
    radius = sim.world.people["tracy"].radius
    checked = 0
    while sim.time < 90:
        sim.step(0.5)
        if ("has", "tracy", "glasses") not in sim.ground_truth_facts():
            continue
        item = sim.true_pose("glasses").position
        person = sim.true_pose("tracy").position
        # off the body's axis by more than its radius (a camera facing her sees it), within arm's reach
        assert radius < math.dist(item[:2], person[:2]) < radius + 0.3
        assert math.isclose(item[2], HAND_HEIGHT, abs_tol=1e-6)
        checked += 1
    assert checked > 0
