"""Actions: the activation / step / deactivation interface and the registry of implementations.

:mod:`actions.base` defines :class:`Action` (the lifecycle the dispatcher drives), :class:`ActionStatus`,
:class:`Outcome` (how a dispatch ended) and :class:`ActionRegistry` (PDDL action name -> factory).
Robot implementations live in subpackages (e.g. ``actions.erl``) and are registered explicitly by whoever
builds the registry.
"""

from actions.base import Action, ActionFactory, ActionRegistry, ActionStatus, Outcome

__all__ = ["Action", "ActionFactory", "ActionRegistry", "ActionStatus", "Outcome"]
