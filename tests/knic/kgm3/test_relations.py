"""KP' for person_near, sound_at and device states."""

from __future__ import annotations

from dataclasses import replace

from knic.bus import Bus
from knic.kgm1.locations import build_location_model
from knic.kgm3.relations import DeviceStateKP, PersonNearKP, SoundAtKP, level_of
from knic.spatial import LocationModel
from knic.units import Kind
from knowledge_base import BeliefStatus, Fact, KnowledgeBase
from tests.knic.kgm3.helpers import cku, send
from tests.knic.places import publish_place_ckus
from worlds.model import World


def test_person_near_with_hysteresis_both_orders(paper_kb: KnowledgeBase) -> None:
    paper_kb.add_instance("person", "jack", source="test", at=0.0)
    bus = Bus()
    kp = PersonNearKP(bus, paper_kb, needed=2)

    def tick(t: float, jack_x: float) -> None:
        send(bus, cku("annie", Kind.PERSON, (1.0, 6.0, 1.0), t, cls="person"))
        send(bus, cku("jack", Kind.PERSON, (jack_x, 6.0, 1.0), t, cls="person"))
        kp.step(t)

    tick(0.0, 2.0)
    assert not paper_kb.facts("person_near")
    tick(0.2, 2.0)
    assert paper_kb.holds("person_near", "annie", "jack") and paper_kb.holds("person_near", "jack", "annie")
    tick(0.4, 2.55)  # inside the band: no change
    tick(0.6, 3.0)
    assert paper_kb.holds("person_near", "annie", "jack")
    tick(0.8, 3.0)
    assert not paper_kb.facts("person_near")


def test_person_near_reads_the_octomaps_voxels(paper_kb: KnowledgeBase) -> None:
    bus = Bus()
    kp = PersonNearKP(bus, paper_kb, needed=2)
    for t in (1.0, 1.2):
        annie = cku("annie", Kind.PERSON, (1.0, 6.5, 0.9), t, cls="person")
        jack = cku("jack", Kind.PERSON, (1.8, 6.5, 0.9), t, cls="person")
        # jack's tree holds his voxels 3 m away from the centroid the CKU carries (a corrupted tree)
        far = cku("jack", Kind.PERSON, (4.8, 6.5, 0.9), t, cls="person")
        send(bus, annie)
        send(bus, replace(jack, keys=far.keys))
        kp.step(t)
    assert not paper_kb.facts("person_near")


def test_sound_at_lives_for_its_ttl(home_kb: KnowledgeBase, home_world: World) -> None:
    locations: LocationModel = build_location_model(home_world)
    bus = Bus()
    publish_place_ckus(bus, locations)
    kp = SoundAtKP(bus, home_kb, ttl_s=2.0)
    send(bus, cku("doorbell", Kind.SOUND, (4.1, 0.2, 1.5), 3.0, cls="doorbell"))
    kp.step(3.0)
    assert home_kb.facts("sound_at") == [Fact("sound_at", ("doorbell", "entrance_hall"))]
    kp.step(4.5)
    assert home_kb.facts("sound_at")
    kp.step(5.1)
    assert not home_kb.facts("sound_at")


def test_a_sound_heard_just_outside_the_walls_is_in_the_nearest_room(
    home_kb: KnowledgeBase, home_world: World
) -> None:
    locations: LocationModel = build_location_model(home_world)
    bus = Bus()
    publish_place_ckus(bus, locations)
    kp = SoundAtKP(bus, home_kb, ttl_s=2.0)
    # the door bell hangs 0.2 m inside the entrance hall's outer wall: a noisy estimate 0.3 m outside it
    send(bus, cku("doorbell", Kind.SOUND, (4.1, -0.1, 1.5), 3.0, cls="doorbell"))
    kp.step(3.0)
    assert home_kb.facts("sound_at") == [Fact("sound_at", ("doorbell", "entrance_hall"))]
    # far outside the home: nobody's door bell
    send(bus, cku("doorbell", Kind.SOUND, (4.1, -3.0, 1.5), 6.0, cls="doorbell"))
    kp.step(6.0)
    assert not home_kb.facts("sound_at")


def test_device_states(home_kb: KnowledgeBase) -> None:
    bus = Bus()
    kp = DeviceStateKP(bus, home_kb)
    send(bus, cku("bedroom_left_light", Kind.DEVICE, (0, 0, 0), 1.0, cls="light", state=True))
    send(bus, cku("living_room_dimmer", Kind.DEVICE, (0, 0, 0), 1.0, cls="dimmer", state=61.0))
    send(bus, cku("door_bell", Kind.DEVICE, (0, 0, 0), 1.0, cls="bell", state=True))
    kp.step(1.0)
    assert home_kb.holds("light_on", "bedroom_left_light") and not home_kb.holds(
        "light_off", "bedroom_left_light"
    )
    assert home_kb.facts("device_level", "living_room_dimmer") == [
        Fact("device_level", ("living_room_dimmer", "l50"))
    ]
    why = home_kb.why(Fact("light_on", ("bedroom_left_light",)))
    assert why is not None and why.status is BeliefStatus.OBSERVED
    assert level_of(88) == "l100" and level_of(12.4) == "l0"


def test_people_near_stay_near_while_unseen_until_seen_apart(paper_kb: KnowledgeBase) -> None:
    paper_kb.add_instance("person", "jack", source="test", at=0.0)
    bus = Bus()
    kp = PersonNearKP(bus, paper_kb, needed=2, ttl_s=120.0)
    for t in (0.0, 0.2):  # sitting together
        send(bus, cku("annie", Kind.PERSON, (1.0, 6.0, 1.0), t, cls="person"))
        send(bus, cku("jack", Kind.PERSON, (1.8, 6.0, 1.0), t, cls="person"))
        kp.step(t)
    assert paper_kb.holds("person_near", "annie", "jack")
    kp.step(60.0)  # the robot looked elsewhere for a minute: nothing says they parted
    assert paper_kb.holds("person_near", "annie", "jack")
    send(bus, cku("jack", Kind.PERSON, (6.0, 6.0, 1.0), 61.0, cls="person"))  # jack seen in the kitchen
    kp.step(61.0)
    assert not paper_kb.facts("person_near")
