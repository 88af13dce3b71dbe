"""The benchmark's baselines, all run on the same episodes through the run's public parts.

* ``knic``: the whole system as ``knic run`` assembles it, under the chosen role.
* ``static``: the closed-world robot of the paper's situation without KnIC (which had to seed its problem with
  a guessed fact to get a plan at all). At t=0 it is given the initial map as a team writes it into its
  problem file: every item and person where their likeliest prior says (an entity without priors where the
  world file has it), as facts with ``found``, and there for the actions to steer to; the devices' states
  and the robot's room as seeded. Then its facts are frozen: the KP' components (KGM-3) are not stepped, so
  only the dispatcher's action effects change the knowledge base. Device actions assume their effect (no
  KP' confirms the reading). KGM-1 and KGM-2 still run: the actions also steer by what the camera sees.
* ``oracle``: facts straight from ground truth. The KP' components are not stepped; a probe writes the
  oracle's true dynamic facts into the knowledge base at :data:`ORACLE_HZ` (only the changes, as observed)
  with ``found`` for every entity placed, and the true position of every item and person is handed to the
  perception the actions steer by at the same rate (the camera is noise-free too): no perception errors.

Both keep the request bookkeeping that a KP' derives from the goals, not from perception: ``(to_accompany
?p)`` exactly for the people a goal wants somewhere (:func:`accompany_requests`, at :data:`ORACLE_HZ`), as a
team writes an accompany request into its problem; without it no plan may meet and guide a person.

:func:`prepare` applies a baseline to an assembled :class:`~knic.system.KnicSystem` before its goals are
given; it uses only the system's parts (scheduler, knowledge base, action registry, simulator).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from core.errors import KnicError
from knic.system.loop import Probe
from knic.system.verdict import TRUTH_PREDICATES as JUDGED_FROM_TRUTH
from knowledge_base import BeliefStatus

if TYPE_CHECKING:
    from knic.scheduler import Component
    from knic.system import KnicSystem
    from worlds.model import Prior, World

BASELINES = ("knic", "static", "oracle")
#: rate (Hz, simulated time) of the oracle baseline's fact writes
ORACLE_HZ = 5.0
#: the predicates of the ground truth written by the static and oracle baselines
TRUTH_PREDICATES = (*sorted(JUDGED_FROM_TRUTH), "sound_at")
DEVICE_ACTIONS = ("switch_on", "switch_off", "set_level")


def check_baselines(names: list[str]) -> list[str]:
    """The baselines named, validated.

    Raises:
        KnicError: an unknown name or none at all.
    """
    unknown = [n for n in names if n not in BASELINES]
    if unknown or not names:
        raise KnicError(
            f"--baseline: expected a comma-separated subset of {', '.join(BASELINES)}"
            + (f"; unknown: {', '.join(unknown)}" if unknown else "")
        )
    return names


def kp_primes(system: KnicSystem) -> list[Component]:
    """The run's KGM-3 components (the KP' writing facts)."""
    return [c for c in system.pipeline if type(c).__module__.startswith("knic.kgm3")]


def prepare(system: KnicSystem, baseline: str, known: World | None = None) -> None:
    """Turn an assembled system into ``baseline`` (see the module docstring); ``knic`` changes nothing.

    Args:
        known: the world as the robot knew it before the episode (its priors, the world file's places) for
            the static baseline's initial map; default: the system's world.
    """
    if baseline == "knic":
        return
    check_baselines([baseline])
    for component in kp_primes(system):
        system.scheduler.remove(component.name)
    if "to_accompany" in system.kb.domain.predicates:
        accompany_requests(system)
        system.scheduler.add(Probe("bench.requests", ORACLE_HZ, lambda now: _keep_requests(system)))
    if baseline == "static":
        write_initial_map(system, known or system.world)
        _assume_device_effects(system)
    else:
        from worlds.api import NoiseConfig

        if hasattr(system.sim, "noise"):
            system.sim.noise = NoiseConfig.perfect()
        _sync(system)
        system.scheduler.add(Probe("bench.oracle_facts", ORACLE_HZ, lambda now: _sync(system)))


def accompany_requests(system: KnicSystem) -> int:
    """``(to_accompany ?p)`` exactly for the people a ``person_at`` goal wants somewhere (source
    ``request``); returns the number of writes."""
    kb = system.kb
    wanted = {g.args[0] for g in kb.goals() if g.predicate == "person_at"}
    have = {f.args[0] for f in kb.facts("to_accompany")}
    writes = 0
    if wanted != have:
        with kb.batch():
            for person in sorted(have - wanted):
                writes += bool(kb.remove_fact("to_accompany", person, source="request"))
            for person in sorted(wanted - have):
                writes += bool(kb.add_fact("to_accompany", person, source="request"))
    return writes


def _keep_requests(system: KnicSystem) -> None:
    accompany_requests(system)


def write_initial_map(system: KnicSystem, known: World) -> int:
    """The static baseline's initial map (see the module docstring); returns the number of facts written."""
    from actions.erl.perception import Sighting

    kb, writes = system.kb, 0
    places: dict[str, tuple[str, str | None]] = {}  # entity -> (room, furniture)
    for name, item in known.items.items():
        places[name] = _likeliest(known, item.priors, item.on, item.position[:2])
    for name, person in known.people.items():
        if person.present:
            places[name] = _likeliest(known, person.priors, person.on, person.position)
    with kb.batch():
        for name, (room, furniture) in sorted(places.items()):
            predicate = "object_at" if name in known.items else "person_at"
            writes += bool(kb.add_fact(predicate, name, room, source="initial_map"))
            if furniture is not None and name in known.items:
                writes += bool(kb.add_fact("object_on", name, furniture, source="initial_map"))
            writes += bool(kb.add_fact("found", name, source="initial_map"))
    for name, (room, furniture) in places.items():
        if furniture is not None:
            f = known.furniture[furniture]
            x, y, z = f.position[0], f.position[1], f.height
        else:
            (x, y), z = known.rooms[room].waypoint, 0.0
        system.perceived.record(name, Sighting((x, y, z + 0.05), 0.0))
    return writes


def _likeliest(
    world: World, priors: tuple[Prior, ...], on: str | None, xy: tuple[float, ...]
) -> tuple[str, str | None]:
    """(room, furniture) of the likeliest prior, else of the world file's place."""
    if priors:
        best = max(priors, key=lambda p: p.probability)
        return best.room, best.furniture
    if on is not None:
        return world.furniture[on].room, on
    room = world.room_of(xy[0], xy[1])
    if room is None:
        raise KnicError(f"world {world.name}: a place at {xy} is in no room")
    return room, None


def _sync(system: KnicSystem) -> None:
    write_truth(system, source="oracle")
    true_sightings(system)


def true_sightings(system: KnicSystem) -> None:
    """Hand the true position of every item and every present person the robot knows to the perception the
    actions steer by (as if perceived now); a stranger has no symbol until perception meets them."""
    from actions.erl.perception import Sighting

    sim, now = system.sim, system.sim.time
    people = system.world.people
    names = [*system.world.items, *(p for p in people if people[p].known and sim.person_present(p))]
    for name in names:
        position = sim.true_pose(name).position
        system.perceived.record(name, Sighting((position[0], position[1], position[2]), now))


def write_truth(system: KnicSystem, *, source: str, status: BeliefStatus = BeliefStatus.OBSERVED) -> int:
    """Make the knowledge base's dynamic facts equal the oracle's (only the differences are written), and
    assert ``found`` for every entity the truth places; returns the number of writes."""
    kb = system.kb
    truth = {f for f in system.sim.ground_truth_facts() if f[0] in TRUTH_PREDICATES}
    known = set(kb.instances())
    truth = {f for f in truth if all(a in known for a in f[1:])}  # a visitor not yet met is no instance
    # a visitor met (visitor_1, ...) has no name in the truth: what perception believes of them stays
    met = {p for p in kb.instances("person") if p not in system.world.people}
    believed = {(f.predicate, *f.args) for p in TRUTH_PREDICATES for f in kb.facts(p)}
    believed = {f for f in believed if not met & set(f[1:])}
    placed = {f[1] for f in truth if f[0] in ("object_at", "person_at")}
    writes = 0
    with kb.batch():
        for fact in sorted(believed - truth):
            writes += bool(kb.remove_fact(*fact, source=source, status=status))
        for fact in sorted(truth - believed):
            writes += bool(kb.add_fact(*fact, source=source, status=status))
        for entity in sorted(placed):
            if not kb.holds("found", entity):
                writes += bool(kb.add_fact("found", entity, source=source, status=status))
    return writes


def _assume_device_effects(system: KnicSystem) -> None:
    """Device actions that do not wait for a KP' to confirm the device reading."""
    from actions.base import Action
    from actions.erl.devices import DeviceAction

    ctx = system.context

    def factory(name: str) -> object:
        def build(args: tuple[str, ...]) -> Action:
            return DeviceAction(name, args, ctx, confirm=False)

        return build

    for name in DEVICE_ACTIONS:
        system.registry.register(name, factory(name))  # type: ignore[arg-type]
