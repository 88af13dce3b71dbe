"""KGM-1 providers for the non-visual sensors: self-localisation, sound events and device readings."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from knic.bus import Bus
from knic.kgm1.base import KnowledgeProvider
from knic.kgm1.sources import DeviceSource, PoseSource, SoundSource
from knic.units import LLKU, Kind

if TYPE_CHECKING:
    from knowledge_base import KnowledgeBase


class RobotPoseKP(KnowledgeProvider):
    """The robot's pose from self-localisation: one ``robot`` LLKU per step (``percept.pose.robot.robot``).

    ``position`` is (x, y, 0) in the world frame; ``attributes["yaw"]`` the heading in radians.
    """

    def __init__(
        self,
        source: PoseSource,
        bus: Bus,
        robot: str,
        *,
        frequency: float = 10.0,
        name: str = "kp.robot_pose",
        confidence: float = 0.95,
    ) -> None:
        super().__init__(name, frequency, bus, None, "pose")
        self.source = source
        self.robot = robot
        self.confidence = confidence

    def step(self, now: float) -> None:
        """Read the pose estimate and publish it."""
        pose = self.source.robot_pose()
        self.publish(
            LLKU(
                kind=Kind.ROBOT,
                label="robot",
                source=self.name,
                sensor="localisation",
                stamp=pose.stamp,
                confidence=self.confidence,
                position=(pose.x, pose.y, 0.0),
                identity=self.robot,
                attributes={"yaw": pose.yaw},
            )
        )


class SoundKP(KnowledgeProvider):
    """Sound events from the microphone: one LLKU per event (``percept.audio.sound.<kind>``).

    The unit carries what was heard and where the robot localised it; what made the sound is the referee's to
    know (:meth:`worlds.oracle.Oracle.sounds_made`), not perception's. The first time a kind of sound is heard
    that the knowledge base does not know, it is added as a ``sound``.
    """

    def __init__(
        self,
        source: SoundSource,
        bus: Bus,
        kb: KnowledgeBase | None,
        *,
        frequency: float = 10.0,
        name: str = "kp.sound",
        confidence: float = 0.9,
    ) -> None:
        super().__init__(name, frequency, bus, kb, "audio")
        self.source = source
        self.confidence = confidence

    def step(self, now: float) -> None:
        """Publish every sound heard since the previous step."""
        for event in self.source.poll_sounds():
            unit = LLKU(
                kind=Kind.SOUND,
                label=event.kind,
                source=self.name,
                sensor="microphone",
                stamp=event.stamp,
                confidence=self.confidence,
                position=event.position,
                identity=event.kind,
            )
            self.meet("sound", event.kind, now, (unit.uid,))
            self.publish(unit)


class DeviceKP(KnowledgeProvider):
    """Device readings from the home automation: one LLKU per device per step
    (``percept.device.device.<kind>``).

    ``attributes["state"]`` is the reading (bool for lights and the bell, percent 0-100 for dimmers and
    blinds) and ``attributes["device_kind"]`` the device's PDDL type; devices the world does not list are
    published with kind ``device``.

    Args:
        kinds: device symbol -> PDDL type (light, dimmer, blinds, bell).
        positions: device symbol -> world-frame position (for the unit's geometry).
    """

    def __init__(
        self,
        source: DeviceSource,
        bus: Bus,
        kinds: Mapping[str, str],
        positions: Mapping[str, tuple[float, float, float]] | None = None,
        *,
        frequency: float = 2.0,
        name: str = "kp.devices",
    ) -> None:
        super().__init__(name, frequency, bus, None, "device")
        self.source = source
        self.kinds = dict(kinds)
        self.positions = dict(positions or {})

    def step(self, now: float) -> None:
        """Publish every device's current reading."""
        for device, state in sorted(self.source.device_states().items()):
            kind = self.kinds.get(device, "device")
            self.publish(
                LLKU(
                    kind=Kind.DEVICE,
                    label=kind,
                    source=self.name,
                    sensor="home_automation",
                    stamp=now,
                    confidence=1.0,
                    position=self.positions.get(device, (0.0, 0.0, 0.0)),
                    identity=device,
                    attributes={"state": state, "device_kind": kind},
                )
            )
