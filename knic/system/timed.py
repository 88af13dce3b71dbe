"""Goals given while the robot runs, at set simulated times, through the goal intake (``knic run --goal-at``).

:class:`TimedGoals` is a task flow: busy until its last goal was given, so a run that starts with no goal
waits for them; each is submitted to one :class:`~knic.intake.GoalIntake` (understood, validated, confirmed
when the role asks, added in one batch) exactly as a user typing it at that moment would.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from knic.intake import GoalIntake, IntakeReply
from knic.system import TaskFlow

if TYPE_CHECKING:
    from knic.system import KnicSystem


class TimedGoals(TaskFlow):
    """Submits ``(time, text)`` goals when their simulated time comes.

    Args:
        system: the run.
        intake: the goal intake to submit to.
        later: (simulated seconds, command text) pairs.
        speaker: the person "me" stands for.
        source: provenance source of the goals.
        on_reply: called with the time, the text and the intake's reply (printing, tests).
    """

    name = "intake.timed"
    frequency = 10.0

    def __init__(
        self,
        system: KnicSystem,
        intake: GoalIntake,
        later: list[tuple[float, str]],
        *,
        speaker: str = "annie",
        source: str = "user",
        on_reply: Callable[[float, str, IntakeReply], None] | None = None,
    ) -> None:
        self.system = system
        self.intake = intake
        self.pending = sorted(later)
        self.speaker = speaker
        self.source = source
        self.on_reply = on_reply

    def busy(self) -> bool:
        """True while a goal is still to be given."""
        return bool(self.pending)

    def step(self, now: float) -> None:
        """Submit every goal whose time has come."""
        while self.pending and self.pending[0][0] <= now + 1e-9:
            _, text = self.pending.pop(0)
            reply = self.intake.submit(text, speaker=self.speaker, source=self.source)
            if self.on_reply is not None:
                self.on_reply(now, text, reply)
