"""The action interface and the registry."""

from __future__ import annotations

import pytest

from actions.base import Action, ActionRegistry, ActionStatus, Outcome
from core.errors import ActionError


class Wave(Action):
    """Finishes after two steps."""

    def __init__(self, args: tuple[str, ...]) -> None:
        super().__init__("wave", args)
        self.calls: list[str] = []

    def activation(self) -> bool:
        self.calls.append("activation")
        return True

    def step(self) -> ActionStatus:
        self.calls.append("step")
        return ActionStatus.SUCCEEDED if self.calls.count("step") == 2 else ActionStatus.RUNNING

    def deactivation(self) -> bool:
        self.calls.append("deactivation")
        return True


def wave_factory(args: tuple[str, ...]) -> Action:
    if len(args) != 1:
        raise ValueError(f"wave takes one argument, got {len(args)}")
    return Wave(args)


def test_registry_builds_actions_by_pdddl_name() -> None:
    registry = ActionRegistry({"wave": wave_factory})
    action = registry.create("wave", ("r2d2",))
    assert isinstance(action, Wave) and str(action) == "(wave r2d2)"
    assert "wave" in registry and registry.names() == ["wave"]
    assert registry.missing(["wave", "move", "pick"]) == ["move", "pick"]


def test_registry_errors_name_the_action() -> None:
    registry = ActionRegistry({"wave": wave_factory})
    with pytest.raises(ActionError, match="no implementation registered for PDDL action 'move'"):
        registry.create("move", ("r2d2", "a", "b"))
    with pytest.raises(ActionError, match="'wave' refused arguments"):
        registry.create("wave", ())


def test_lifecycle_defaults_and_outcome_names() -> None:
    class Minimal(Action):
        def step(self) -> ActionStatus:
            return ActionStatus.SUCCEEDED

    action = Minimal("noop", ())
    assert action.activation() and action.step() == ActionStatus.SUCCEEDED and action.deactivation()
    assert [str(o) for o in Outcome] == [
        "succeeded",
        "precondition failure",
        "activation failure",
        "execution failure",
        "timeout",
        "deactivation failure",
        "postcondition failure",
        "cancelled",
    ]
    with pytest.raises(TypeError):
        Action("abstract", ())  # type: ignore[abstract]
