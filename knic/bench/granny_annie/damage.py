"""The damage model of the Granny Annie referee: when the robot damages the testbed, as data.

The score sheet disqualifies a run that damages the testbed. The simulator counts contacts (bumps, person
hits) and drops but has no notion of damage; the referee derives it from ground truth with the thresholds of
``damage.yaml`` (:class:`DamageModel`):

* a **hard contact**: the base started touching furniture or a wall while closing in on it at
  ``hard_contact_m_s`` or more: the true clearance to the nearest furniture or wall surface shrank that
  fast over the last ``contact_window_s`` (:class:`ImpactProbe` measures it for every contact as the run
  goes, from the oracle's true pose and bump counter and the world's geometry). A base grazing a door frame
  at full speed closes in slowly and stays a bump; one driving straight into a wall does not;
* a **broken item**: the robot dropped an item named (or of a detector class named) ``fragile``; which item
  fell is read from the ground-truth samples around the drop (held before, not held after).

Both are read only from the oracle (true pose, counters, true facts), never from the robot's beliefs.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from core.errors import KnicError

if TYPE_CHECKING:
    from worlds.model import World
    from worlds.oracle import Oracle

DEFAULT_DAMAGE = Path(__file__).with_name("damage.yaml")


class SampleView(Protocol):
    """One ground-truth sample as the damage model reads it (:class:`~.referee.Sample` fits)."""

    @property
    def t(self) -> float: ...

    @property
    def facts(self) -> frozenset[tuple[str, ...]]: ...


class TimelineView(Protocol):
    """What the damage model reads of a run (:class:`~.referee.Timeline` fits; no import: the referee
    imports this module)."""

    @property
    def samples(self) -> Sequence[SampleView]: ...

    @property
    def drops(self) -> Sequence[float]: ...

    @property
    def impacts(self) -> Sequence[tuple[float, float]]: ...


_FIELDS = {"hard_contact_m_s", "contact_window_s", "fragile"}


@dataclass(frozen=True)
class DamageModel:
    """What damages the testbed (see the module docstring).

    Attributes:
        hard_contact_m_s: closing speed (m/s) towards the nearest furniture or wall surface at the start of
            a contact from which the contact damages the testbed.
        contact_window_s: simulated seconds the closing speed is measured over.
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
    """Measures how fast the base closed in on furniture or walls as each contact started (module docstring).

    Args:
        oracle: the simulator's ground truth (true pose, penalty counters).
        world: the world whose furniture and walls are the obstacles.
        window_s: simulated seconds the closing speed is measured over.

    Lifecycle: call :meth:`step` at a fixed rate (10 Hz in the recorder) from the start of the run; each new
    bump (the oracle's counter went up) appends ``(time, closing speed m/s)`` to :attr:`impacts`.
    """

    def __init__(self, oracle: Oracle, world: World, window_s: float = 0.3) -> None:
        from worlds.sim.contacts import ContactMonitor

        self.oracle = oracle
        self.window_s = window_s
        self.impacts: list[tuple[float, float]] = []
        self._geometry = ContactMonitor(world)
        self._clearance: deque[tuple[float, float]] = deque()
        self._bumps = 0

    def step(self, now: float) -> None:
        """Read the true pose and the bump counter at simulated time ``now``."""
        pose = self.oracle.true_robot_pose()
        self._clearance.append((now, self._geometry.clearance(pose.x, pose.y)))
        while len(self._clearance) > 2 and self._clearance[1][0] <= now - self.window_s + 1e-9:
            self._clearance.popleft()
        bumps = int(self.oracle.counters().bumps)
        if bumps > self._bumps:
            self.impacts.extend([(now, round(self.closing_speed(), 3))] * (bumps - self._bumps))
        self._bumps = bumps

    def closing_speed(self) -> float:
        """How fast (m/s) the clearance to the nearest furniture or wall shrank over the kept window."""
        (t0, c0), (t1, c1) = self._clearance[0], self._clearance[-1]
        return max(0.0, c0 - c1) / (t1 - t0) if t1 > t0 else 0.0


def damage_events(timeline: TimelineView, model: DamageModel) -> list[tuple[float, str]]:
    """The testbed damage of one run, ``(time, what)`` in time order: hard contacts and broken items."""
    out = [
        (t, f"drove into furniture or a wall at {speed:.2f} m/s")
        for t, speed in timeline.impacts
        if speed >= model.hard_contact_m_s
    ]
    for t, item in dropped_items(timeline):
        if item in model.fragile:
            out.append((t, f"dropped the fragile {item}"))
    return sorted(out)


def dropped_items(timeline: TimelineView) -> list[tuple[float, str]]:
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
