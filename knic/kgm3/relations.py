"""KP' for relations and states: ``person_near``, ``sound_at``, lights and levels of devices."""

from __future__ import annotations

import itertools
import math

from knic.bus import Bus
from knic.kgm3.base import Confirmer, KPPrime
from knic.spatial import DEFAULT_RESOLUTION, key_centers
from knic.units import CKU
from knowledge_base import BeliefStatus, Fact, KnowledgeBase

#: device levels of the domain, percent -> constant
LEVELS = {0: "l0", 25: "l25", 50: "l50", 75: "l75", 100: "l100"}


class PersonNearKP(KPPrime):
    """``(person_near ?p ?q)`` (both orders) for recognised people closer than ``near_m`` on the floor
    (between the floor centres of their octomaps' occupied voxels, :func:`floor_centre`).

    Hysteresis: a pair becomes near after ``needed`` consecutive evaluations closer than ``near_m - band`` and
    stops being near after ``needed`` evaluations farther than ``near_m + band``; a pair whose members were
    not both seen within ``fresh_s`` is not evaluated. Retracted only on evidence or age, as person_at: when
    KGM-2 lost one of them (the camera looked where they were and they were gone), when one of them is seen
    farther than ``near_m + band`` from where the other was last seen, or when one of them has not been seen
    for ``ttl_s`` (two people sitting together stay together while the robot looks elsewhere).
    """

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        near_m: float = 1.5,
        band_m: float = 0.1,
        needed: int = 2,
        fresh_s: float = 1.0,
        ttl_s: float = 120.0,
        frequency: float = 5.0,
        name: str = "kp'.person_near",
    ) -> None:
        super().__init__(name, frequency, bus, kb, "cognition.person")
        self.near_m, self.band_m, self.fresh_s, self.ttl_s = near_m, band_m, fresh_s, ttl_s
        self.confirmer: Confirmer[bool] = Confirmer(needed)
        self.latest: dict[str, CKU] = {}

    def step(self, now: float) -> None:
        """Update positions, evaluate each fresh pair, expire pairs with a member unseen for the TTL."""
        assert self.inbox is not None
        for message in self.inbox.drain():
            cku: CKU = message.payload
            if cku.attributes.get("lost"):
                self.latest.pop(cku.symbol, None)
            elif self.is_a(cku.symbol, "person"):
                self.latest[cku.symbol] = cku
        for p, q in itertools.combinations(sorted(self.latest), 2):
            a, b = self.latest[p], self.latest[q]
            if now - min(a.stamp, b.stamp) > self.fresh_s:
                continue
            (ax, ay), (bx, by) = floor_centre(a), floor_centre(b)
            d = math.hypot(ax - bx, ay - by)
            current = self.kb.holds("person_near", p, q)
            if d < self.near_m - self.band_m:
                value = True
            elif d > self.near_m + self.band_m:
                value = False
            else:
                continue
            if self.confirmer.observe(f"{p}|{q}", value, 1.0, current, now):
                self._write(p, q, value, now, (a.uid, b.uid))
        for fact in self.kb.facts("person_near"):
            p, q = fact.args
            prov = self.kb.why(fact)
            if prov is None or prov.source != self.name:
                continue
            stamps = [self.latest[s].stamp if s in self.latest else -math.inf for s in (p, q)]
            if now - min(stamps) > self.ttl_s or self._seen_apart(p, q, now):
                self._write(min(p, q), max(p, q), False, now, ())

    def _seen_apart(self, p: str, q: str, now: float) -> bool:
        """One of the pair is seen now (within ``fresh_s``) farther than ``near_m + band`` from where the
        other was last seen, while the other is not seen now (a pair both seen is evaluated as a pair)."""
        a, b = self.latest.get(p), self.latest.get(q)
        if a is None or b is None:
            return False
        fresh = [now - a.stamp <= self.fresh_s, now - b.stamp <= self.fresh_s]
        if fresh[0] == fresh[1]:
            return False
        (ax, ay), (bx, by) = floor_centre(a), floor_centre(b)
        return math.hypot(ax - bx, ay - by) > self.near_m + self.band_m

    def _write(self, p: str, q: str, near: bool, at: float, support: tuple[str, ...]) -> None:
        with self.kb.batch():
            for a, b in ((p, q), (q, p)):
                if near:
                    self.assert_fact("person_near", a, b, at=at, support=support)
                else:
                    self.retract_fact("person_near", a, b, at=at, support=support)


def floor_centre(cku: CKU) -> tuple[float, float]:
    """Where an entity stands on the floor: the mean ``(x, y)`` of the occupied voxels its octomap holds
    (the CKU's keys, read from the tree), or its centroid when the tree gave none."""
    if len(cku.keys) == 0:
        return (cku.position[0], cku.position[1])
    centres = key_centers(cku.keys, DEFAULT_RESOLUTION)
    return (float(centres[:, 0].mean()), float(centres[:, 1].mean()))


#: metres outside every room within which a sound is still placed in the nearest room
SOUND_SNAP_M = 0.75


class SoundAtKP(KPPrime):
    """``(sound_at ?s ?room)``: the room holding the sound's source (rooms from the location CKUs), for
    ``ttl_s`` seconds after it was heard.

    The source's position is an estimate (microphone-array localisation is off by decimetres): one that
    falls just outside every room, as a door bell mounted on a wall does, is taken to be in the room whose
    outline is nearest, within ``snap_m`` metres; farther away it is outside the home and ignored.
    """

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        ttl_s: float = 2.0,
        snap_m: float = SOUND_SNAP_M,
        frequency: float = 10.0,
        name: str = "kp'.sound_at",
    ) -> None:
        super().__init__(name, frequency, bus, kb, "cognition.sound", places=True)
        self.ttl_s = ttl_s
        self.snap_m = snap_m
        self.heard: dict[tuple[str, str], float] = {}

    def step(self, now: float) -> None:
        """Assert sounds heard; retract those older than the TTL."""
        assert self.inbox is not None
        for message in self.inbox.drain():
            cku: CKU = message.payload
            room = self.locations.room_near(cku.position[0], cku.position[1], self.snap_m)
            if room is None or not self.is_a(cku.symbol, "sound"):
                continue
            self.heard[(cku.symbol, room)] = cku.stamp
            self.assert_fact("sound_at", cku.symbol, room, at=cku.stamp, support=(cku.uid, *cku.support))
        for (sound, room), stamp in list(self.heard.items()):
            if now - stamp >= self.ttl_s:
                del self.heard[(sound, room)]
                self.retract_fact("sound_at", sound, room, at=now)


def level_of(percent: float) -> str:
    """The domain's level constant nearest to a percentage (0-100)."""
    nearest = min(LEVELS, key=lambda p: abs(p - float(percent)))
    return LEVELS[nearest]


class DeviceStateKP(KPPrime):
    """Lights (complementary ``light_on`` / ``light_off``) and ``device_level`` of dimmers and blinds.

    Readings come from the home automation, so by default one reading is enough (``needed = 1``).
    """

    def __init__(
        self,
        bus: Bus,
        kb: KnowledgeBase,
        *,
        needed: int = 1,
        frequency: float = 2.0,
        name: str = "kp'.devices",
    ) -> None:
        super().__init__(name, frequency, bus, kb, "cognition.device")
        self.confirmer: Confirmer[str] = Confirmer(needed)

    def step(self, now: float) -> None:
        """Bring each device's facts in line with its reading."""
        assert self.inbox is not None
        for message in self.inbox.drain():
            cku: CKU = message.payload
            device, state = cku.symbol, cku.attributes.get("state")
            support = (cku.uid, *cku.support)
            if self.is_a(device, "light"):
                value = "on" if state else "off"
                current = "on" if self.kb.holds("light_on", device) else None
                if current is None and self.kb.holds("light_off", device):
                    current = "off"
                if self.confirmer.observe(device, value, 1.0, current, cku.stamp) or (
                    value == current and self._stale(f"light_{value}", device)
                ):
                    other = "off" if value == "on" else "on"
                    with self.kb.batch():
                        self.assert_fact(f"light_{value}", device, at=cku.stamp, support=support)
                        self.retract_fact(f"light_{other}", device, at=cku.stamp, support=support)
            elif (
                isinstance(state, int | float) and not isinstance(state, bool) and self.is_a(device, "device")
            ):
                if self.is_a(device, "bell"):
                    continue
                value = level_of(state)
                current = self.value_of("device_level", device)
                if self.confirmer.observe(device, value, 1.0, current, cku.stamp) or (
                    value == current and self._stale("device_level", device, value)
                ):
                    with self.kb.batch():
                        self.assert_fact("device_level", device, value, at=cku.stamp, support=support)

    def _stale(self, predicate: str, *args: str) -> bool:
        """True while a fact that matches the reading is not yet marked observed (an action's effect)."""
        prov = self.kb.why(Fact(predicate, tuple(args)))
        return prov is not None and prov.status != BeliefStatus.OBSERVED
