"""The message bus: hierarchical topics, prefix and wildcard subscriptions, stamps and authors."""

from __future__ import annotations

import pytest

from core.errors import InferenceError
from knic.bus import Bus, Message, topic_level


def test_prefix_subscription_receives_the_subtree_only() -> None:
    bus = Bus()
    got: list[Message] = []
    bus.subscribe("percept.vision", got.append)
    bus.publish("percept.vision.object.glasses", "g", source="kp.camera", stamp=1.5)
    bus.publish("percept.audio.sound.doorbell", "d", source="kp.sound", stamp=1.6)
    bus.publish("percept.visionary", "x", source="kp.other", stamp=1.7)
    assert [m.topic for m in got] == ["percept.vision.object.glasses"]
    assert (got[0].source, got[0].stamp, got[0].payload) == ("kp.camera", 1.5, "g")


def test_single_level_wildcard() -> None:
    bus = Bus()
    got: list[str] = []
    bus.subscribe("percept.*.person", lambda m: got.append(m.topic))
    bus.publish("percept.vision.person.jack", 1, source="a", stamp=0.0)
    bus.publish("percept.vision.object.glasses", 2, source="a", stamp=0.0)
    bus.publish("percept.thermal.person.annie", 3, source="a", stamp=0.0)
    assert got == ["percept.vision.person.jack", "percept.thermal.person.annie"]


def test_bad_topic_is_refused_and_nothing_delivered() -> None:
    bus = Bus()
    got: list[Message] = []
    bus.subscribe("percept", got.append)
    with pytest.raises(InferenceError, match="bad topic"):
        bus.publish("percept..glasses", 1, source="a", stamp=0.0)
    with pytest.raises(InferenceError, match="no publishing component"):
        bus.publish("percept.vision", 1, source="", stamp=0.0)
    with pytest.raises(InferenceError):
        bus.subscribe("percept.Vision", got.append)
    assert got == [] and bus.published == 0


def test_unsubscribe_and_latest_value_per_topic() -> None:
    bus = Bus()
    got: list[int] = []
    sub = bus.subscribe("cognition", lambda m: got.append(m.payload))
    bus.publish("cognition.object.mug", 1, source="kgm2", stamp=1.0)
    sub.cancel()
    bus.publish("cognition.object.mug", 2, source="kgm2", stamp=2.0)
    bus.publish("cognition.person.jack", 3, source="kgm2", stamp=3.0)
    assert got == [1]
    latest = bus.latest("cognition.object")
    assert [(m.payload, m.stamp) for m in latest] == [(2, 2.0)]
    assert [m.payload for m in bus.latest("cognition")] == [2, 3]


def test_inbox_keeps_order_and_drops_oldest_when_full() -> None:
    bus = Bus()
    box = bus.inbox("percept", capacity=3)
    for i in range(5):
        bus.publish("percept.vision.object.cup", i, source="kp", stamp=float(i))
    assert [m.payload for m in box.drain()] == [2, 3, 4]
    assert box.dropped == 2 and len(box) == 0


def test_topic_level_sanitises_symbols() -> None:
    assert topic_level("Coke-Can") == "coke_can"


def test_recent_keeps_a_bounded_time_stamped_history_per_topic() -> None:
    bus = Bus(history=3)
    for i in range(5):
        bus.publish("percept.pose.robot.r2d2", i, source="kp.robot_pose", stamp=0.1 * i)
    bus.publish("percept.audio.sound.doorbell", "ring", source="kp.sound", stamp=0.7)
    recent = bus.recent("percept.pose")
    assert list(recent) == ["percept.pose.robot.r2d2"]
    assert [m.payload for m in recent["percept.pose.robot.r2d2"]] == [2, 3, 4]  # oldest dropped
    assert [m.stamp for m in recent["percept.pose.robot.r2d2"]] == pytest.approx([0.2, 0.3, 0.4])
    assert sorted(bus.recent()) == ["percept.audio.sound.doorbell", "percept.pose.robot.r2d2"]
    with pytest.raises(InferenceError):
        bus.recent("Bad Pattern")
