"""The action interface (seed 004, Algorithm 1) and the registry from PDDL action names to implementations.

Lifecycle of one :class:`Action`, driven by the dispatcher (:class:`planner.dispatch.Dispatcher`), one call
per scheduler tick, all on the same thread, never overlapping:

1. **construction** -- ``factory(args)`` builds the action for one ground PDDL action, e.g.
   ``("r2d2", "kitchen", "bedroom")`` for ``(move r2d2 kitchen bedroom)``. Construct offline: no motion, no
   blocking I/O; only remember the arguments and the handles the factory closed over (robot, world, KB).
2. ``activation() -> bool`` -- called once, after the dispatcher has checked the PDDL at-start conditions
   against the knowledge base. Start the behaviour (send a goal to the base, open the gripper...).
   Return ``False`` when it cannot start: the outcome is *activation failure* and ``deactivation`` is **not**
   called.
3. ``step() -> ActionStatus`` -- called repeatedly (once per tick) while it returns ``RUNNING``. Do a bounded
   amount of work and return at once; never sleep or wait. Return ``SUCCEEDED`` when the behaviour finished
   and ``FAILED`` when it cannot finish (set :attr:`Action.failure_reason`): *execution failure*. The
   dispatcher enforces a per-action time limit on its own clock (*timeout*) and may cancel a running action
   when a knowledge-base change breaks the plan (*cancelled*).
4. ``deactivation() -> bool`` -- called once after every activation that returned ``True``, however the
   action ended; :attr:`Action.ending` tells how (``"succeeded"``, ``"failed"``, ``"timeout"``,
   ``"cancelled"``). Stop motors, release resources. Return ``False`` if that failed: after a successful
   ``step`` the outcome is then *deactivation failure*.

Actions never write the PDDL effects themselves: after a successful ending the dispatcher checks the at-end
conditions and writes the effects with belief status "effect". Sensing actions (``sensing:`` in the domain's
meta file) leave their sensed effects to perception: the dispatcher checks them afterwards
(*postcondition failure* if perception did not assert them).

Exceptions escaping an action method are treated as an execution failure of that action, with the exception's
message as the reason; they never stop the dispatcher.
"""

from __future__ import annotations

import enum
from abc import ABC, abstractmethod
from collections.abc import Callable, Iterable, Mapping

from core.errors import ActionError


class ActionStatus(enum.StrEnum):
    """What :meth:`Action.step` reports."""

    RUNNING = "running"
    SUCCEEDED = "succeeded"
    FAILED = "failed"


class Outcome(enum.StrEnum):
    """How the dispatch of one action ended (the names the trace and the recovery policy use)."""

    SUCCEEDED = "succeeded"
    PRECONDITION_FAILURE = "precondition failure"
    ACTIVATION_FAILURE = "activation failure"
    EXECUTION_FAILURE = "execution failure"
    TIMEOUT = "timeout"
    DEACTIVATION_FAILURE = "deactivation failure"
    POSTCONDITION_FAILURE = "postcondition failure"
    CANCELLED = "cancelled"

    def __str__(self) -> str:
        return self.value


class Action(ABC):
    """One running instance of a PDDL action. See the module docstring for the lifecycle.

    Args:
        name: the PDDL action name.
        args: the ground arguments, in the order of the action's parameters.

    Attributes:
        failure_reason: one line set by the action when ``step`` returns FAILED or ``activation`` False.
        ending: set by the dispatcher right before ``deactivation``: "succeeded", "failed", "timeout" or
            "cancelled".
    """

    def __init__(self, name: str, args: tuple[str, ...]) -> None:
        self.name = name
        self.args = args
        self.failure_reason = ""
        self.ending = ""

    def activation(self) -> bool:
        """Start the behaviour; ``False`` means it could not start (activation failure). Default: True."""
        return True

    @abstractmethod
    def step(self) -> ActionStatus:
        """Advance the behaviour by a bounded amount of work; report RUNNING, SUCCEEDED or FAILED."""

    def deactivation(self) -> bool:
        """Stop the behaviour and release what it holds; ``False`` means that failed. Default: True."""
        return True

    def __str__(self) -> str:
        return "(" + " ".join((self.name, *self.args)) + ")"


ActionFactory = Callable[[tuple[str, ...]], Action]


class ActionRegistry:
    """PDDL action name -> ``factory(args) -> Action``; filled explicitly, never by import side effects.

    Args:
        factories: initial entries.
    """

    def __init__(self, factories: Mapping[str, ActionFactory] | None = None) -> None:
        self._factories: dict[str, ActionFactory] = dict(factories or {})

    def register(self, name: str, factory: ActionFactory) -> None:
        """Map PDDL action ``name`` to ``factory`` (replacing an earlier entry)."""
        self._factories[name] = factory

    def create(self, name: str, args: tuple[str, ...]) -> Action:
        """Build the action for ``(name *args)``.

        Raises:
            ActionError: no factory is registered for ``name``, or the factory refused the arguments.
        """
        factory = self._factories.get(name)
        if factory is None:
            known = ", ".join(sorted(self._factories)) or "none"
            raise ActionError(f"no implementation registered for PDDL action {name!r} (registered: {known})")
        try:
            return factory(args)
        except ActionError:
            raise
        except (TypeError, ValueError, KeyError) as exc:
            raise ActionError(f"implementation of {name!r} refused arguments {args}: {exc}") from exc

    def missing(self, action_names: Iterable[str]) -> list[str]:
        """The names in ``action_names`` with no registered implementation (check a domain before running)."""
        return [n for n in action_names if n not in self._factories]

    def names(self) -> list[str]:
        """Registered PDDL action names, sorted."""
        return sorted(self._factories)

    def __contains__(self, name: object) -> bool:
        return name in self._factories
