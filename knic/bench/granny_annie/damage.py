"""The damage model of the Granny Annie referee: when the robot damages the testbed, as data.

The score sheet disqualifies a run that damages the testbed. The simulator counts contacts (bumps, person
hits) and drops but has no notion of damage; the referee derives it from ground truth with the thresholds of
``damage.yaml`` (:class:`DamageModel`):

* a **hard contact**: the base started touching furniture or a wall while its true speed over the last
  ``contact_window_s`` was at least ``hard_contact_m_s`` (:class:`ImpactProbe` measures the speed of every
  contact as the run goes, from the oracle's true pose and bump counter);
* a **broken item**: the robot dropped an item named (or of a detector class named) ``fragile``; which item
  fell is read from the ground-truth samples around the drop (held before, not held after).

Both are read only from the oracle (true pose, counters, true facts), never from the robot's beliefs.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from core.errors import KnicError

if TYPE_CHECKING:
    from knic.bench.granny_annie.referee import Timeline
    from worlds.model import World
    from worlds.oracle import Oracle

DEFAULT_DAMAGE = Path(__file__).with_name("damage.yaml")
_FIELDS = {"hard_contact_m_s", "contact_window_s", "fragile"}


@dataclass(frozen=True)
class DamageModel:
    """What damages the testbed (see the module docstring).

    Attributes:
        hard_contact_m_s: base speed (m/s) at the start of a contact with furniture or a wall from which the
            contact damages the testbed.
        contact_window_s: simulated seconds of true base motion the contact speed is measured over.
        fragile: item names and detector classes that break when dropped.
    """

    hard_contact_m_s: float = 0.5
    contact_window_s: float = 0.3
    fragile: frozenset[str] = frozenset()

    @classmethod
    def from_dict(cls, data: Any, source: str = "<damage model>") -> DamageModel:
        """Build a model from a parsed ``damage.yaml`` document.

        Raises:
            KnicError: one line naming ``source`` and the field: not a mapping, unknown field, a threshold
                that is not a positive number, ``fragile`` not a list of names.
        """
        if not isinstance(data, dict):
            raise KnicError(f"{source}: the damage model must be a mapping ({', '.join(sorted(_FIELDS))})")
        unknown = sorted(str(k) for k in set(data) - _FIELDS)
        if unknown:
            raise KnicError(f"{source}: unknown field {unknown[0]!r} ({', '.join(sorted(_FIELDS))})")
        numbers = {}
        for key in ("hard_contact_m_s", "contact_window_s"):
            value = data.get(key, getattr(cls, key))
            if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
                raise KnicError(f"{source}: {key} must be a positive number, got {value!r}")
            numbers[key] = float(value)
        fragile = data.get("fragile", [])
        if not isinstance(fragile, list) or not all(isinstance(f, str) and f for f in fragile):
            raise KnicError(f"{source}: fragile must be a list of item names or classes, got {fragile!r}")
        return cls(numbers["hard_contact_m_s"], numbers["contact_window_s"], frozenset(fragile))

    def for_world(self, world: World) -> DamageModel:
        """The model with ``fragile`` widened to the names of ``world``'s items of a fragile class."""
        names = {it.name for it in world.items.values() if it.cls in self.fragile or it.name in self.fragile}
        return replace(self, fragile=self.fragile | names)


@cache
def shipped_damage() -> DamageModel:
    """The shipped ``damage.yaml``, read once."""
    return load_damage(DEFAULT_DAMAGE)


def load_damage(path: str | Path = DEFAULT_DAMAGE) -> DamageModel:
    """Read a damage model file (default: the shipped ``damage.yaml``).

    Raises:
        KnicError: the file cannot be read or is not a valid damage model (one line naming it).
    """
    from core.inputs import read_yaml

    return DamageModel.from_dict(read_yaml(path, "damage model"), str(path))


class ImpactProbe:
    """Measures the true base speed at the start of every furniture or wall contact (module docstring).

    Args:
        oracle: the simulator's ground truth (true pose, penalty counters).
        window_s: simulated seconds of motion the speed is measured over.

    Lifecycle: call :meth:`step` at a fixed rate (10 Hz in the recorder) from the start of the run; each new
    bump (the oracle's counter went up) appends ``(time, speed m/s)`` to :attr:`impacts`.
    """

    def __init__(self, oracle: Oracle, window_s: float = 0.3) -> None:
        self.oracle = oracle
        self.window_s = window_s
        self.impacts: list[tuple[float, float]] = []
        self._poses: deque[tuple[float, float, float]] = deque()
        self._bumps = 0

    def step(self, now: float) -> None:
        """Read the true pose and the bump counter at simulated time ``now``."""
        pose = self.oracle.true_robot_pose()
        self._poses.append((now, pose.x, pose.y))
        while len(self._poses) > 2 and self._poses[1][0] <= now - self.window_s + 1e-9:
            self._poses.popleft()
        bumps = int(self.oracle.counters().bumps)
        if bumps > self._bumps:
            self.impacts.extend([(now, round(self.speed(), 3))] * (bumps - self._bumps))
        self._bumps = bumps

    def speed(self) -> float:
        """Mean true base speed (m/s) over the poses kept (about the last ``window_s`` seconds)."""
        (t0, x0, y0), (t1, x1, y1) = self._poses[0], self._poses[-1]
        return math.hypot(x1 - x0, y1 - y0) / (t1 - t0) if t1 > t0 else 0.0


def damage_events(timeline: Timeline, model: DamageModel) -> list[tuple[float, str]]:
    """The testbed damage of one run, ``(time, what)`` in time order: hard contacts and broken items."""
    out = [
        (t, f"hit furniture or a wall at {speed:.2f} m/s")
        for t, speed in timeline.impacts
        if speed >= model.hard_contact_m_s
    ]
    for t, item in dropped_items(timeline):
        if item in model.fragile:
            out.append((t, f"dropped the fragile {item}"))
    return sorted(out)


def dropped_items(timeline: Timeline) -> list[tuple[float, str]]:
    """``(time, item)`` of each drop: the item held in the last sample before it and not held at the drop's
    sample (``"?"`` when the samples do not tell)."""
    out = []
    samples = timeline.samples
    for t in timeline.drops:
        before = [s for s in samples if s.t < t - 1e-9]
        after = next((s for s in samples if s.t >= t - 1e-9), None)
        held = _held(before[-1].facts) if before else set()
        still = _held(after.facts) if after is not None else set()
        gone = sorted(held - still)
        out.append((t, gone[0] if gone else "?"))
    return out


def _held(facts: Iterable[tuple[str, ...]]) -> set[str]:
    return {f[2] for f in facts if f[0] == "holding"}
