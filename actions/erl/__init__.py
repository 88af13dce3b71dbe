"""The robot's actions for the ERL apartment domain (``worlds/erl_home/domain.pddl``).

:func:`build_erl_registry` maps every action of the domain to its implementation:

=================  =====================================  ==========================================
PDDL action        module                                 what the robot does
=================  =====================================  ==========================================
move               :mod:`actions.erl.motion`              drive to the room's anchored waypoint
meet, guide        :mod:`actions.erl.motion`              approach a perceived person; walk with them
search_object      :mod:`actions.erl.search`              viewpoints and camera sweeps (sensing)
search_person      :mod:`actions.erl.search`              the same, for a person (sensing)
search_furniture   :mod:`actions.erl.sourced`             the same, the given furniture first (sensing)
pick_from          :mod:`actions.erl.sourced`             pick an item believed on the given furniture
pick, place, give  :mod:`actions.erl.manipulation`        gripper actions at perceived poses
report             :mod:`actions.erl.devices`             say where the entity was found
switch_on/off      :mod:`actions.erl.devices`             light commands, confirmed by the reading
set_level          :mod:`actions.erl.devices`             dimmer / blinds level, confirmed
speak              :mod:`actions.erl.devices`             say the arguments (not a domain action)
=================  =====================================  ==========================================

Usage::

    registry = build_erl_registry(robot, kb, perception=BusPerception(kb, pipeline.bus))
    dispatcher = Dispatcher(kb, planner, registry)
"""

from __future__ import annotations

from actions.base import Action, ActionFactory, ActionRegistry
from actions.erl.context import ErlContext
from actions.erl.devices import DeviceAction, ReportAction, SpeakAction
from actions.erl.manipulation import GiveAction, PickAction, PlaceAction
from actions.erl.motion import GuideAction, MeetAction, MoveAction
from actions.erl.perception import AnchorPerception, Perception
from actions.erl.search import SearchAction
from actions.erl.sourced import FurnitureSearchAction, PickFromAction
from core.robot import Robot
from knowledge_base import KnowledgeBase

#: number of ground arguments of every registered action (checked at construction)
ARITY = {
    "move": 3,
    "search_object": 3,
    "search_person": 3,
    "search_furniture": 4,
    "pick": 3,
    "pick_from": 4,
    "place": 4,
    "give": 4,
    "meet": 3,
    "guide": 4,
    "report": 2,
    "switch_on": 2,
    "switch_off": 2,
    "set_level": 4,
}


def build_erl_registry(
    robot: Robot,
    kb: KnowledgeBase,
    *,
    perception: Perception | None = None,
    robot_name: str = "r2d2",
    confirm_devices: bool | None = None,
    context: ErlContext | None = None,
) -> ActionRegistry:
    """The ERL actions bound to one robot, knowledge base and perception bus.

    Args:
        robot: the robot seam the actions command and read (the simulator implements it).
        kb: the knowledge base (anchors, facts) the actions read.
        perception: where perception last saw items and people (the inference side provides it); None:
            knowledge-base anchors only.
        robot_name: the robot's PDDL symbol.
        confirm_devices: device actions wait for the device reading in the knowledge base; default: only when
            ``perception`` is given (hence a perception pipeline runs).
        context: a prepared context (overrides ``robot``, ``kb``, ``perception`` and ``robot_name``).

    Returns:
        A registry with every action of ``worlds/erl_home/domain.pddl`` plus ``speak``. Factories raise
        ``ValueError`` (an :class:`~core.errors.ActionError` through the registry) for a wrong argument count.
    """
    ctx = context or ErlContext(robot, kb, perception or AnchorPerception(kb), robot_name=robot_name)
    confirm = (perception is not None) if confirm_devices is None else confirm_devices

    def checked(name: str, args: tuple[str, ...]) -> tuple[str, ...]:
        if len(args) != ARITY[name]:
            raise ValueError(f"{name} takes {ARITY[name]} arguments, got {len(args)}")
        return args

    registry = ActionRegistry()
    registry.register("move", lambda a: MoveAction(checked("move", a), ctx))
    registry.register(
        "search_object", lambda a: SearchAction("search_object", checked("search_object", a), ctx)
    )
    registry.register(
        "search_person", lambda a: SearchAction("search_person", checked("search_person", a), ctx)
    )
    registry.register(
        "search_furniture", lambda a: FurnitureSearchAction(checked("search_furniture", a), ctx)
    )
    registry.register("pick", lambda a: PickAction(checked("pick", a), ctx))
    registry.register("pick_from", lambda a: PickFromAction(checked("pick_from", a), ctx))
    registry.register("place", lambda a: PlaceAction(checked("place", a), ctx))
    registry.register("give", lambda a: GiveAction(checked("give", a), ctx))
    registry.register("meet", lambda a: MeetAction(checked("meet", a), ctx))
    registry.register("guide", lambda a: GuideAction(checked("guide", a), ctx))
    registry.register("report", lambda a: ReportAction(checked("report", a), ctx))
    for name in ("switch_on", "switch_off", "set_level"):
        registry.register(name, _device_factory(name, ctx, confirm))
    registry.register("speak", lambda a: SpeakAction(a, ctx))
    return registry


def _device_factory(name: str, ctx: ErlContext, confirm: bool) -> ActionFactory:
    def factory(args: tuple[str, ...]) -> Action:
        if len(args) != ARITY[name]:
            raise ValueError(f"{name} takes {ARITY[name]} arguments, got {len(args)}")
        return DeviceAction(name, args, ctx, confirm=confirm)

    return factory


__all__ = ["AnchorPerception", "ErlContext", "Perception", "build_erl_registry"]
