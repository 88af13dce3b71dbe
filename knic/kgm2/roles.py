"""Robot roles as data (seed 004's motivational principles): what the cognitive layer processes, how often and
how urgently.

A role file (default :data:`ROLES_FILE`, ``knic/roles.yaml``) maps role names to a default policy, per-class
and per-room policies (``rate_hz`` in simulated time, ``priority``), the time to live of unseen people and two
flags read by the executive (``confirm_actions``, ``operator_only``). The pipeline never branches on a role's
name: it asks :meth:`Role.policy` for each percept.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from core.errors import InferenceError
from core.inputs import read_yaml

#: The shipped role file.
ROLES_FILE = Path(__file__).resolve().parent.parent / "roles.yaml"


@dataclass(frozen=True)
class Policy:
    """How a class of percepts is processed: at most ``rate_hz`` updates per entity per simulated second
    (0: ignored), ``priority`` orders processing within a step (larger first)."""

    rate_hz: float
    priority: int

    @property
    def period(self) -> float:
        """Minimum simulated seconds between two updates of one entity (infinite when ignored)."""
        return 1.0 / self.rate_hz if self.rate_hz > 0 else float("inf")


@dataclass(frozen=True)
class Revisit:
    """What the robot goes back to look at when idle (read by :class:`knic.kgm2.attention.Revisits`).

    ``people``: go where a person is believed with an aged belief; ``rooms`` and ``items``: rooms (and the
    rooms where these items are believed) revisited ``priority_weight`` times as often as the others. The
    empty default revisits every room in turn.
    """

    people: bool = False
    rooms: tuple[str, ...] = ()
    items: tuple[str, ...] = ()
    priority_weight: float = 1.0


@dataclass(frozen=True)
class Role:
    """One role: policies by class and by room, a default, and executive flags."""

    name: str
    description: str
    default: Policy
    classes: Mapping[str, Policy] = field(default_factory=dict)
    rooms: Mapping[str, Policy] = field(default_factory=dict)
    person_ttl_s: float = 30.0
    confirm_actions: bool = False
    operator_only: bool = False
    revisit: Revisit = field(default_factory=Revisit)

    def policy(self, cls: str, room: str | None = None) -> Policy:
        """The policy for a percept of class ``cls`` seen in ``room`` (None when outside every room)."""
        found = [p for p in (self.classes.get(cls), self.rooms.get(room) if room else None) if p is not None]
        if not found:
            return self.default
        return Policy(max(p.rate_hz for p in found), max(p.priority for p in found))

    def max_rate(self, exclude: tuple[str, ...] = ()) -> float:
        """The highest rate any class (but ``exclude``) or room gets: what a sensor KP needs to run at, Hz."""
        rates = [self.default.rate_hz, *(p.rate_hz for c, p in self.classes.items() if c not in exclude)]
        rates += [p.rate_hz for p in self.rooms.values()]
        return max(rates)


def _policy(raw: Any, where: str) -> Policy:
    if not isinstance(raw, Mapping) or set(raw) - {"rate_hz", "priority"} or "rate_hz" not in raw:
        raise InferenceError(f"{where}: expected {{rate_hz: float, priority: int}}, got {raw!r}")
    rate, priority = raw["rate_hz"], raw.get("priority", 0)
    if not isinstance(rate, int | float) or rate < 0 or not isinstance(priority, int):
        raise InferenceError(f"{where}: rate_hz must be a number >= 0 and priority an integer")
    return Policy(float(rate), priority)


def _role(name: str, raw: Any, where: str) -> Role:
    if not isinstance(raw, Mapping):
        raise InferenceError(f"{where}: role {name!r} must be a mapping")
    allowed = {
        "description",
        "default",
        "classes",
        "rooms",
        "person_ttl_s",
        "confirm_actions",
        "operator_only",
        "revisit",
    }
    unknown = set(raw) - allowed
    if unknown:
        raise InferenceError(f"{where}: role {name!r} has unknown keys {sorted(unknown)}")
    if "default" not in raw:
        raise InferenceError(f"{where}: role {name!r} has no default policy")
    classes = raw.get("classes") or {}
    rooms = raw.get("rooms") or {}
    if not isinstance(classes, Mapping) or not isinstance(rooms, Mapping):
        raise InferenceError(f"{where}: role {name!r}: classes and rooms must be mappings")
    ttl = raw.get("person_ttl_s", 30.0)
    if not isinstance(ttl, int | float) or ttl <= 0:
        raise InferenceError(f"{where}: role {name!r}: person_ttl_s must be a positive number")
    return Role(
        name=name,
        description=str(raw.get("description", "")),
        default=_policy(raw["default"], f"{where}: {name}.default"),
        classes={str(c): _policy(p, f"{where}: {name}.classes.{c}") for c, p in classes.items()},
        rooms={str(r): _policy(p, f"{where}: {name}.rooms.{r}") for r, p in rooms.items()},
        person_ttl_s=float(ttl),
        confirm_actions=bool(raw.get("confirm_actions", False)),
        operator_only=bool(raw.get("operator_only", False)),
        revisit=_revisit(raw.get("revisit"), f"{where}: {name}.revisit"),
    )


def _revisit(raw: Any, where: str) -> Revisit:
    if raw is None:
        return Revisit()
    allowed = {"people", "rooms", "items", "priority_weight"}
    if not isinstance(raw, Mapping) or set(raw) - allowed:
        raise InferenceError(f"{where}: expected a mapping of {sorted(allowed)}, got {raw!r}")
    lists = {}
    for key in ("rooms", "items"):
        value = raw.get(key) or []
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise InferenceError(f"{where}.{key}: expected a list of names, got {value!r}")
        lists[key] = tuple(value)
    weight = raw.get("priority_weight", 1.0)
    if not isinstance(weight, int | float) or isinstance(weight, bool) or weight < 1:
        raise InferenceError(f"{where}.priority_weight: expected a number >= 1, got {weight!r}")
    return Revisit(bool(raw.get("people", False)), lists["rooms"], lists["items"], float(weight))


def load_roles(path: Path | str = ROLES_FILE) -> dict[str, Role]:
    """Read every role of a role file.

    Raises:
        InferenceError: the file is missing, not YAML, or a role is malformed (the message names it).
    """
    path = Path(path)
    data = read_yaml(path, "role file", InferenceError)
    if not isinstance(data, Mapping) or not isinstance(data.get("roles"), Mapping):
        raise InferenceError(f"role file {path}: expected a top-level 'roles:' mapping")
    return {str(n): _role(str(n), r, str(path)) for n, r in data["roles"].items()}


def load_role(name: str, path: Path | str = ROLES_FILE) -> Role:
    """One role by name.

    Raises:
        InferenceError: unknown role (the message lists the known ones) or a malformed file.
    """
    roles = load_roles(path)
    if name not in roles:
        raise InferenceError(f"unknown role {name!r} in {path}; known roles: {', '.join(sorted(roles))}")
    return roles[name]
