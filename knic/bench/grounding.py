"""``knic bench grounding``: how true the knowledge base stays against the simulator's ground truth.

One episode of ``--duration`` simulated seconds (default 600) in the seven-room apartment: the robot
patrols the rooms (a waypoint per room, a camera sweep on arrival) while people walk between rooms, a visitor
rings and objects are moved (:func:`bench_scenario`). The whole KnIC pipeline runs in the run's scheduler; no
goals, so the dispatcher is not stepped. Measured, in simulated time:

* every simulated second, the knowledge base's dynamic facts (``COMPARED`` predicates) against the ground
  truth: ``precision`` (share of believed facts that are true) and ``recall`` (share of true facts the robot
  could have perceived that are believed). A true fact about an item or person counts as perceivable once the
  entity was in a camera frame (the oracle's :meth:`~worlds.oracle.Oracle.frame_truth`) after the fact became
  true; the robot's room, devices and sounds always count. The visitor is a stranger to the robot: the
  instance perception makes for him (``visitor_1``) is compared as him (the stranger last in view).
* ``staleness_median_s``: for each change of a perceivable true fact (appearing or disappearing, sampled at
  5 Hz), the time until the knowledge base made the same change; changes it never made are counted in
  ``changes_unreflected``.
* the same episode under the companion role and under ``all_top_rate`` (every class at the top rate):
  ``cpu_s_*`` is the process CPU time spent in the pipeline's components (KGM-1, KGM-2, KGM-3) less the
  simulator's camera rendering inside them (``render_s_*``, the sensor's cost, reported apart),
  ``priority_staleness_*_s`` the median staleness of the companion's priority facts
  (people, and the glasses, remote and tablet).
* ``octomap_throughput_ratio`` from :mod:`knic.bench.octomap`.

* ``by_predicate_companion``: per compared predicate, over the companion episode's one-second samples, how
  many believed facts there were (``believed_samples``), how many of them were false (``false_samples``), how
  many true facts were perceivable (``perceivable_samples``) and how many of those were not believed
  (``missed_samples``): which fact kinds cost precision and recall.

* ``families``: per predicate family (:data:`FAMILIES`: ``robot_at``, ``object_at``, ``object_on``,
  ``person_at``, ``person_near``, ``device``) of the companion episode (an item a person carries is in no
  room's ``object_at`` but in their hands, ``(has ?p ?o)``: both are where an item is, the ``object_at``
  family): ``precision`` and ``recall`` pooled
  over the one-second samples, ``f1``, ``assert_latency_p50_s`` / ``assert_latency_p95_s`` and
  ``retract_latency_p50_s`` (from the truth's change to the knowledge base's, for the changes counted in
  the staleness), ``change_latency_after_seen_p50_s`` (the same from the first camera frame that showed the
  entities after the change: the part perception controls; the rest is where the robot was looking),
  ``precision_not_aged`` (precision over the beliefs not aged into ASSUMED: what the robot holds as
  observed; the aged ones are people and items not seen for their time to live, kept but not retracted),
  ``flaps_per_fact_minute`` (belief changes undone within :data:`FLAP_WINDOW_S` while the fact's truth did
  not change, per minute of believed fact).
* ``octomap_ratio_same_work``: KGM-2's octomap path against raw pyoctomap doing the same insertions (same
  discretised mode and ray length), from :mod:`knic.bench.octomap`.

With ``--seeds N`` the episodes run under N seeds and every figure is the mean over them (counts summed).
Figures that could not be measured (no sample) are ``null``.
Precision, recall and staleness are those of the companion episode (the default role of ``knic run``).
"""

from __future__ import annotations

import argparse
import bisect
import json
import logging
import math
import statistics
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from knic.bench.figures import FAMILIES, average_figures, percentile
from knic.bench.patrol import Patrol
from knic.system.loop import RunLoop
from knowledge_base import BeliefStatus, Fact

if TYPE_CHECKING:
    from core.robot import Camera
    from knic.system.assembly import Assembly
    from worlds.oracle import Oracle

#: predicates compared with the ground truth
COMPARED = frozenset(
    {
        "robot_at",
        "person_at",
        "object_at",
        "object_on",
        "has",
        "person_near",
        "sound_at",
        "light_on",
        "light_off",
        "device_level",
    }
)
#: simulated seconds within which a belief change undone counts as a flap
FLAP_WINDOW_S = 10.0
#: the companion role's priority entities (besides every person)
PRIORITY_ITEMS = frozenset({"glasses", "remote", "tablet"})
#: the episodes of the benchmark, by role
EPISODE_ROLES = ("companion", "all_top_rate")
Atom = tuple[str, ...]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--duration", "--sim-seconds", type=float, default=600.0, help="simulated seconds per episode (600)"
    )
    parser.add_argument(
        "--roles",
        default=",".join(EPISODE_ROLES),
        help="comma-separated episodes to run, of companion and all_top_rate (default both); the figures of"
        " an episode not run are null (a short smoke run: --sim-seconds 60 --roles companion)",
    )
    parser.add_argument("--seed", type=int, default=0, help="simulation seed (default 0)")
    parser.add_argument(
        "--seeds",
        type=int,
        default=1,
        help="episodes per role, seeds --seed .. --seed+N-1; the figures are their means (default 1)",
    )
    parser.add_argument("--skip-octomap", action="store_true", help="do not measure the octomap ratio")
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def run(args: argparse.Namespace) -> int:
    from core.errors import KnicError

    if args.duration <= 0:
        raise KnicError(f"knic bench grounding: --duration must be positive, got {args.duration}")
    roles = tuple(r.strip() for r in args.roles.split(",") if r.strip())
    unknown = sorted(set(roles) - set(EPISODE_ROLES))
    if not roles or unknown:
        raise KnicError(
            f"knic bench grounding: --roles {args.roles!r}: expected a comma-separated subset of"
            f" {', '.join(EPISODE_ROLES)}" + (f"; unknown: {', '.join(unknown)}" if unknown else "")
        )
    if args.seeds < 1:
        raise KnicError(f"knic bench grounding: --seeds must be at least 1, got {args.seeds}")
    logging.getLogger("knic.scheduler").setLevel(logging.ERROR)
    runs = [
        measure_grounding(duration=args.duration, seed=seed, octomap=False, roles=roles)
        for seed in range(args.seed, args.seed + args.seeds)
    ]
    figures = average_figures(runs)
    figures["seeds"] = list(range(args.seed, args.seed + args.seeds))
    if not args.skip_octomap:
        from knic.bench.octomap import measure_octomap_throughput

        octo = measure_octomap_throughput()
        figures["octomap_throughput_ratio"] = octo["octomap_throughput_ratio"]
        figures["octomap_ratio_same_work"] = octo["octomap_overhead_ratio_same_mode"]
    if args.json:
        print(json.dumps(figures, sort_keys=True))
    else:
        for key, value in sorted(figures.items()):
            print(f"{key:34s} {value}")
    return 0


def measure_grounding(
    *,
    duration: float = 600.0,
    seed: int = 0,
    octomap: bool = True,
    roles: tuple[str, ...] = EPISODE_ROLES,
) -> dict[str, Any]:
    """Run the companion and the all-top-rate episodes and return the figures (see the module docstring).

    Args:
        roles: the episodes to run (of :data:`EPISODE_ROLES`); the figures of an episode not run are None.
    """
    companion = _episode_of("companion", roles, duration, seed)
    top = _episode_of("all_top_rate", roles, duration, seed)
    figures: dict[str, Any] = {
        "duration_s": duration,
        "precision": companion["precision"],
        "recall": companion["recall"],
        "staleness_median_s": companion["staleness_median_s"],
        "changes_reflected": companion["changes_reflected"],
        "changes_unreflected": companion["changes_unreflected"],
        "samples": companion["samples"],
        "cpu_s_companion": companion["cpu_s"],
        "cpu_s_all_top_rate": top["cpu_s"],
        "render_s_companion": companion["render_s"],
        "render_s_all_top_rate": top["render_s"],
        "priority_staleness_companion_s": companion["priority_staleness_s"],
        "priority_staleness_all_s": top["priority_staleness_s"],
        "precision_all_top_rate": top["precision"],
        "recall_all_top_rate": top["recall"],
        "by_predicate_companion": companion["by_predicate"],
        "families": companion["families"],
        "wall_s": round(companion["wall_s"] + top["wall_s"], 1),
    }
    if octomap:
        from knic.bench.octomap import measure_octomap_throughput

        octo = measure_octomap_throughput()
        figures["octomap_throughput_ratio"] = octo["octomap_throughput_ratio"]
        figures["octomap_ratio_same_work"] = octo["octomap_overhead_ratio_same_mode"]
    return figures


class _NotRun(dict[str, Any]):
    """The figures of an episode that was not run: None for every figure, 0 wall-clock seconds."""

    def __missing__(self, key: str) -> Any:
        return None


def _episode_of(role: str, roles: tuple[str, ...], duration: float, seed: int) -> dict[str, Any]:
    """The episode of ``role`` when it is in ``roles``, else :class:`_NotRun` figures."""
    if role in roles:
        return run_episode(role, duration=duration, seed=seed)
    return _NotRun(wall_s=0.0)


def bench_scenario(duration: float) -> dict[str, Any]:
    """The episode's events as a scenario document: people walking, sitting down beside annie (people near
    each other), a visitor, objects moved, a dimmer set."""
    rooms = ("kitchen", "living_room", "bedroom", "dining_room", "hallway", "bathroom")
    events: list[dict[str, Any]] = [
        {"at": 0, "type": "person_to", "person": "annie", "furniture": "sofa", "teleport": True},
        {"at": 30, "type": "doorbell", "visitor": "jack", "to": "living_room"},
        {"at": 60, "type": "set_device", "device": "living_room_dimmer", "value": 50},
    ]
    moves = [
        ("mug", "dining_table"),
        ("remote", "tv_table"),
        ("glasses", "coffee_table"),
        ("apple", "dining_table"),
    ]
    t, i = 20.0, 0
    while t < duration - 20:
        person = "tracy" if i % 2 == 0 else "jack"
        if i % 4 == 2:  # sit down beside annie on the sofa for a while: people near each other
            events.append({"at": t, "type": "person_to", "person": person, "furniture": "sofa"})
        else:
            events.append({"at": t, "type": "person_to", "person": person, "room": rooms[i % len(rooms)]})
        if i % 3 == 1:
            item, to = moves[(i // 3) % len(moves)]
            events.append({"at": t + 5, "type": "move_object", "person": "tracy", "item": item, "to": to})
        t += 45.0
        i += 1
    return {"name": "grounding_bench", "description": "people walking, objects moved", "events": events}


@dataclass
class _Change:
    fact: Atom
    appeared: bool
    at: float
    entities: tuple[str, ...]
    reflected_at: float | None = None


@dataclass
class _Recorder:
    """Samples truth and beliefs; keeps the visibility history and the changes awaiting the knowledge base."""

    entities: frozenset[str]
    seen: dict[str, list[float]] = field(default_factory=dict)
    truth_since: dict[Atom, float] = field(default_factory=dict)
    pending: list[_Change] = field(default_factory=list)
    done: list[_Change] = field(default_factory=list)
    precision: list[float] = field(default_factory=list)
    recall: list[float] = field(default_factory=list)
    #: predicate -> [believed, believed but false, perceivable true, perceivable true but not believed]
    by_predicate: dict[str, list[int]] = field(default_factory=dict)
    #: predicate -> [believed and not aged (status other than ASSUMED), of those false]
    fresh: dict[str, list[int]] = field(default_factory=dict)

    #: fact -> (added, simulated time) of the knowledge base's latest change of it
    last_change: dict[Atom, tuple[bool, float]] = field(default_factory=dict)
    #: belief changes undone within :data:`FLAP_WINDOW_S`: (fact, change time, undo time)
    reversals: list[tuple[Atom, float, float]] = field(default_factory=list)
    #: fact -> simulated times at which its truth changed (sampled at 5 Hz)
    truth_changes: dict[Atom, list[float]] = field(default_factory=dict)
    #: people the robot does not know beforehand (the truth's names)
    strangers: frozenset[str] = frozenset()
    #: instance perception made for a stranger it met (``visitor_1``) -> the stranger's name in the truth
    aliases: dict[str, str] = field(default_factory=dict)

    def alias(self, atom: Atom) -> Atom:
        """The atom in the truth's names (a met visitor's instance as the stranger it is)."""
        return tuple(self.aliases.get(a, a) for a in atom)

    def bind(self, instance: str) -> None:
        """A person instance made for someone met is, for the referee, the stranger last in the camera's view
        and not bound yet (none: the instance stays unnamed and its facts count as false)."""
        free = [
            (self.seen[s][-1], s)
            for s in self.strangers
            if self.seen.get(s) and s not in self.aliases.values()
        ]
        if instance not in self.aliases and free:
            self.aliases[instance] = max(free)[1]

    def tally(self, facts: set[Atom], slot: int) -> None:
        for fact in facts:
            self.by_predicate.setdefault(fact[0], [0, 0, 0, 0])[slot] += 1

    def kb_change(self, atom: Atom, added: bool, at: float) -> None:
        """Note one change the knowledge base made; a change undone within the window is a flap."""
        previous = self.last_change.get(atom)
        if previous is not None and previous[0] != added and at - previous[1] <= FLAP_WINDOW_S:
            self.reversals.append((atom, previous[1], at))
        self.last_change[atom] = (added, at)

    def flaps(self, family: str) -> int:
        """Belief changes of the family undone within the window while the fact's truth did not change
        (within a second either side: the truth is sampled at 5 Hz)."""
        count = 0
        for atom, t0, t1 in self.reversals:
            if atom[0] not in FAMILIES[family]:
                continue
            if not any(t0 - 1.0 <= t <= t1 + 1.0 for t in self.truth_changes.get(atom, ())):
                count += 1
        return count

    def first_seen_after(self, names: tuple[str, ...], t: float) -> float:
        """The first camera frame at or after ``t`` in which every one of ``names`` was visible (``t`` when
        there are none; ``inf`` when never)."""
        latest = t
        for name in names:
            stamps = self.seen.get(name, [])
            k = bisect.bisect_left(stamps, t - 1e-9)
            if k == len(stamps):
                return math.inf
            latest = max(latest, stamps[k])
        return latest

    def visible_since(self, name: str, t: float) -> bool:
        stamps = self.seen.get(name)
        return bool(stamps) and stamps[-1] >= t - 1e-9  # type: ignore[index]

    def perceivable(self, fact: Atom, since: float) -> bool:
        names = [a for a in fact[1:] if a in self.entities]
        return all(self.visible_since(n, since) for n in names)


def run_episode(role: str, *, duration: float, seed: int) -> dict[str, Any]:
    """One patrolling episode under ``role``; returns precision, recall, staleness and CPU figures."""
    from knic.system.assembly import assemble
    from knic.system.config import RunConfig
    from worlds.api import load_world
    from worlds.scenario import scenario_from_dict

    world = load_world("erl_home")
    scenario = scenario_from_dict(bench_scenario(duration), world)
    parts = assemble(RunConfig(world=world.name, scenario=scenario, seed=seed, role=role, dispatch=False))
    try:
        return _episode(parts, duration)
    finally:
        parts.close()


def _episode(parts: Assembly, duration: float) -> dict[str, Any]:
    """Patrol the assembled robot (no dispatcher) for ``duration`` simulated seconds under the probes."""
    robot, oracle, kb, world = parts.robot, parts.oracle, parts.kb, parts.world
    entities = frozenset(world.items) | frozenset(world.people)
    rec = _Recorder(
        entities, strangers=frozenset(p for p, person in world.people.items() if not person.known)
    )
    camera_hz = parts.pipeline.component("kp.camera_objects").frequency
    loop: RunLoop[None] = RunLoop(parts.scheduler)
    loop.add_probe(Patrol.name, Patrol.frequency, Patrol(parts).step)
    loop.add_probe("bench.visibility", camera_hz, lambda now: _see(robot, oracle, rec))
    loop.add_probe("bench.changes", 5.0, lambda now: _changes(oracle, kb, rec, now))
    loop.add_probe("bench.compare", 1.0, lambda now: _compare(oracle, kb, rec, now))

    def reflect(change: Any) -> None:
        if change.kind.value == "add_instance" and change.name == "person" and change.args[0] not in entities:
            rec.bind(change.args[0])
        if change.kind.value not in ("add_fact", "remove_fact"):
            return
        atom = rec.alias((change.name, *change.args))
        added = change.kind.value == "add_fact"
        rec.kb_change(atom, added, change.time)
        for ch in rec.pending:
            if ch.fact == atom and ch.appeared == added and ch.reflected_at is None:
                ch.reflected_at = change.time

    unsubscribe = kb.subscribe(reflect)
    wall0 = time.perf_counter()
    loop.run(duration)
    unsubscribe()
    stats = parts.scheduler.stats()
    cpu = sum(stats[c.name].cpu_s for c in parts.pipeline)
    changes = rec.done + rec.pending
    counted = [c for c in changes if c.reflected_at is not None or rec.perceivable(c.fact, c.at)]
    reflected = [c for c in counted if c.reflected_at is not None]
    delays = [c.reflected_at - c.at for c in reflected if c.reflected_at is not None]
    priority = [
        c.reflected_at - c.at
        for c in reflected
        if c.reflected_at is not None and any(e in PRIORITY_ITEMS or e in world.people for e in c.entities)
    ]
    return {
        "precision": round(statistics.fmean(rec.precision), 4) if rec.precision else None,
        "recall": round(statistics.fmean(rec.recall), 4) if rec.recall else None,
        "staleness_median_s": round(statistics.median(delays), 3) if delays else None,
        "priority_staleness_s": round(statistics.median(priority), 3) if priority else None,
        "changes_reflected": len(reflected),
        "changes_unreflected": len(counted) - len(reflected),
        "samples": len(rec.precision),
        "cpu_s": round(cpu - parts.pipeline.camera.render_wall_s, 2),
        "render_s": round(parts.pipeline.camera.render_wall_s, 2),
        "wall_s": time.perf_counter() - wall0,
        "families": _families(rec, counted, duration),
        "by_predicate": {
            pred: {
                "believed_samples": n[0],
                "false_samples": n[1],
                "perceivable_samples": n[2],
                "missed_samples": n[3],
            }
            for pred, n in sorted(rec.by_predicate.items())
        },
    }


def _families(rec: _Recorder, counted: list[_Change], duration: float) -> dict[str, dict[str, Any]]:
    """Per family: precision and recall pooled over the one-second samples, F1, latencies, flaps."""
    out: dict[str, dict[str, Any]] = {}
    for family, predicates in FAMILIES.items():
        believed, false, perceivable, missed = (
            sum(rec.by_predicate.get(p, [0, 0, 0, 0])[i] for p in predicates) for i in range(4)
        )
        precision = (believed - false) / believed if believed else None
        recall = (perceivable - missed) / perceivable if perceivable else None
        f1 = (
            2 * precision * recall / (precision + recall)
            if precision is not None and recall is not None and precision + recall > 0
            else None
        )
        mine = [c for c in counted if c.fact[0] in predicates]
        asserted = [c.reflected_at - c.at for c in mine if c.appeared and c.reflected_at is not None]
        retracted = [c.reflected_at - c.at for c in mine if not c.appeared and c.reflected_at is not None]
        # the same from the first frame that showed the entities after the change (what perception controls)
        seen = [
            max(0.0, c.reflected_at - rec.first_seen_after(c.entities, c.at))
            for c in mine
            if c.reflected_at is not None and math.isfinite(rec.first_seen_after(c.entities, c.at))
        ]
        fact_minutes = believed / 60.0  # believed facts sampled once per simulated second
        fresh, fresh_false = (sum(rec.fresh.get(p, [0, 0])[i] for p in predicates) for i in range(2))
        out[family] = {
            "precision": round(precision, 4) if precision is not None else None,
            "recall": round(recall, 4) if recall is not None else None,
            "f1": round(f1, 4) if f1 is not None else None,
            "precision_not_aged": round((fresh - fresh_false) / fresh, 4) if fresh else None,
            "assert_latency_p50_s": percentile(asserted, 0.5),
            "assert_latency_p95_s": percentile(asserted, 0.95),
            "retract_latency_p50_s": percentile(retracted, 0.5),
            "change_latency_after_seen_p50_s": percentile(seen, 0.5),
            "flaps_per_fact_minute": round(rec.flaps(family) / fact_minutes, 4) if fact_minutes else None,
            "changes": len(mine),
            "changes_unreflected": sum(1 for c in mine if c.reflected_at is None),
        }
    return out


def _see(robot: Camera, oracle: Oracle, rec: _Recorder) -> None:
    robot.camera_frame()  # the frame the camera KP used at this instant (cached by the simulator)
    truth = oracle.frame_truth()  # which instances were really in it
    if truth is None:
        return
    for name in truth.visible:
        rec.seen.setdefault(name, []).append(truth.stamp)


def _truth(oracle: Oracle) -> set[Atom]:
    return {f for f in oracle.ground_truth_facts() if f[0] in COMPARED}


def _beliefs(kb: Any, rec: _Recorder) -> set[Atom]:
    return {rec.alias((f.predicate, *f.args)) for f in kb.facts() if f.predicate in COMPARED}


def _changes(oracle: Oracle, kb: Any, rec: _Recorder, now: float) -> None:
    truth = _truth(oracle)
    beliefs = _beliefs(kb, rec)
    for fact in truth ^ set(rec.truth_since):
        rec.truth_changes.setdefault(fact, []).append(now)
    for fact in truth - set(rec.truth_since):
        rec.truth_since[fact] = now
        if now > 0 and fact not in beliefs:
            rec.pending.append(_Change(fact, True, now, tuple(a for a in fact[1:] if a in rec.entities)))
    for fact in set(rec.truth_since) - truth:
        del rec.truth_since[fact]
        if fact in beliefs:
            rec.pending.append(_Change(fact, False, now, tuple(a for a in fact[1:] if a in rec.entities)))
    still: list[_Change] = []
    for ch in rec.pending:
        (rec.done if ch.reflected_at is not None else still).append(ch)
    rec.pending = still


def _compare(oracle: Oracle, kb: Any, rec: _Recorder, now: float) -> None:
    truth = _truth(oracle)
    beliefs = _beliefs(kb, rec)
    if beliefs:
        rec.precision.append(len(beliefs & truth) / len(beliefs))
    perceivable = {f for f in truth if rec.perceivable(f, rec.truth_since.get(f, now))}
    if perceivable:
        rec.recall.append(len(beliefs & perceivable) / len(perceivable))
    rec.tally(beliefs, 0)
    rec.tally(beliefs - truth, 1)
    for fact in beliefs:
        named = {v: k for k, v in rec.aliases.items()}  # back to the knowledge base's names
        prov = kb.why(Fact(fact[0], tuple(named.get(a, a) for a in fact[1:])))
        if prov is not None and prov.status != BeliefStatus.ASSUMED:
            counts = rec.fresh.setdefault(fact[0], [0, 0])
            counts[0] += 1
            counts[1] += fact not in truth
    rec.tally(perceivable, 2)
    rec.tally(perceivable - beliefs, 3)
