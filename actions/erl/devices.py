"""Device commands (``switch_on``, ``switch_off``, ``set_level``) and speech (``report``, ``speak``).

Device commands go to the home automation through the robot interface; with ``confirm`` the action then waits
until the device's own reading has reached the knowledge base (the device KP' asserted the new state), so a
command the device ignored is an execution failure rather than a silent effect. Failure modes: the command is
refused (unknown kind, wrong device type: activation failure); the reading does not confirm the new state
within ``confirm_s`` (execution failure).

``report`` says where the entity was found, from the knowledge base's place facts; ``speak`` says its
arguments (joined by spaces). Neither can fail once the robot can speak.
"""

from __future__ import annotations

from actions.base import ActionStatus
from actions.erl.common import ErlAction
from actions.erl.context import LEVEL_PERCENT, ErlContext


class DeviceAction(ErlAction):
    """``(switch_on ?r ?d)``, ``(switch_off ?r ?d)`` or ``(set_level ?r ?d ?from ?to)``.

    Args:
        name: the PDDL action name.
        args: its ground arguments.
        ctx: the action context.
        confirm: wait for the device reading in the knowledge base before succeeding.
        confirm_s: simulated seconds to wait for it.
    """

    def __init__(
        self,
        name: str,
        args: tuple[str, ...],
        ctx: ErlContext,
        *,
        confirm: bool = True,
        confirm_s: float = 3.0,
    ) -> None:
        super().__init__(name, args, ctx)
        self.device = args[1]
        self.confirm = confirm
        self.confirm_s = confirm_s
        if name == "set_level":
            level = args[3]
            if level not in LEVEL_PERCENT:
                raise ValueError(f"unknown level {level!r} (expected one of {', '.join(LEVEL_PERCENT)})")
            self.expected: tuple[str, ...] = ("device_level", self.device, level)
        else:
            self.expected = ("light_on" if name == "switch_on" else "light_off", self.device)

    def activation(self) -> bool:
        """Send the command; a refusal is an activation failure."""
        if self.name == "set_level":
            result = self.ctx.robot.set_level(self.device, LEVEL_PERCENT[self.args[3]])
        else:
            result = self.ctx.robot.set_light(self.device, self.name == "switch_on")
        if not result.ok:
            return self.refuse(f"{self.name} {self.device} refused: {result.reason}")
        self.enter("confirm")
        return True

    def step(self) -> ActionStatus:
        """Succeed once the reading confirms the new state (at once without ``confirm``)."""
        if not self.confirm or self.ctx.kb.holds(self.expected[0], *self.expected[1:]):
            return ActionStatus.SUCCEEDED
        if self.in_phase_for() > self.confirm_s:
            want = "(" + " ".join(self.expected) + ")"
            return self.fail(f"{self.device} did not report {want} within {self.confirm_s:g} s")
        return ActionStatus.RUNNING

    def deactivation(self) -> bool:
        """Nothing to stop."""
        return True


def spoken(symbol: str) -> str:
    """A symbol as words (``living_room`` -> ``living room``)."""
    return symbol.replace("_", " ")


class ReportAction(ErlAction):
    """``(report ?r ?e)``: say where the entity was found (its room, the gripper, or who has it)."""

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("report", args, ctx)
        self.entity = args[1]

    def activation(self) -> bool:
        """Compose and say the report."""
        kb, e = self.ctx.kb, self.entity
        places = kb.facts("object_at", e) or kb.facts("person_at", e)
        support = kb.facts("object_on", e)
        if support:
            where = (
                f"on the {spoken(support[0].args[1])} in the {spoken(places[0].args[1])}" if places else ""
            )
        elif places:
            where = f"in the {spoken(places[0].args[1])}"
        elif kb.facts("holding", None, e):
            where = "in my gripper"
        elif kb.facts("has", None, e):  # already handed over: with that person, where they are
            holder = kb.facts("has", None, e)[0].args[0]
            rooms = kb.facts("person_at", holder)
            where = f"with {spoken(holder)}" + (f" in the {spoken(rooms[0].args[1])}" if rooms else "")
        else:
            where = ""
        self.text = f"I found the {spoken(e)} {where}".strip() + "."
        self.ctx.say(self.text)
        return True

    def step(self) -> ActionStatus:
        """Speech is immediate."""
        return ActionStatus.SUCCEEDED

    def deactivation(self) -> bool:
        """Nothing to stop."""
        return True


class SpeakAction(ErlAction):
    """``(speak ...words)``: say the arguments as one sentence (for dialogue steps and scripted runs)."""

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        super().__init__("speak", args, ctx)
        if not args:
            raise ValueError("speak needs at least one word")

    def activation(self) -> bool:
        """Say the words."""
        self.ctx.say(" ".join(spoken(a) for a in self.args))
        return True

    def step(self) -> ActionStatus:
        """Speech is immediate."""
        return ActionStatus.SUCCEEDED

    def deactivation(self) -> bool:
        """Nothing to stop."""
        return True
