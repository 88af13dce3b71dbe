"""Actions that keep the source of a request: ``search_furniture`` looks for an item on one piece of
furniture, ``pick_from`` takes it from there (``(taken_from ?o ?f)``: "bring me an apple from the
kitchen cabinet").

Both reuse the room search and the pick; they differ in what they promise. ``search_furniture`` is a sensing
action: perception must confirm ``found``, ``object_at`` and ``object_on`` for the furniture (else the
dispatcher reports a postcondition failure and replans with what was seen). ``pick_from`` refuses at
activation when the knowledge base does not hold the item on that furniture.
"""

from __future__ import annotations

from actions.erl.context import ErlContext
from actions.erl.manipulation import PickAction
from actions.erl.search import SearchAction


class FurnitureSearchAction(SearchAction):
    """``(search_furniture ?r ?o ?f ?l)``: the room search of :class:`SearchAction` with furniture ``?f``
    looked at first (its viewpoint and sweep come before the room's waypoints)."""

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        robot, item, furniture, room = args
        super().__init__("search_object", (robot, item, room), ctx)
        self.name, self.args = "search_furniture", args
        self.furniture = furniture

    def activation(self) -> bool:
        """Plan the room's route, then move the furniture's viewpoint and its pans to the front."""
        if not super().activation():
            return False
        for i, task in enumerate(self.tasks):
            if task.kind == "nav" and task.what == self.furniture:
                pans = 1
                while i + pans < len(self.tasks) and self.tasks[i + pans].kind == "pan":
                    pans += 1
                self.tasks = self.tasks[i : i + pans] + self.tasks[:i] + self.tasks[i + pans :]
                break
        return True


class PickFromAction(PickAction):
    """``(pick_from ?r ?o ?f ?l)``: :class:`PickAction` for an item believed on furniture ``?f``."""

    def __init__(self, args: tuple[str, ...], ctx: ErlContext) -> None:
        robot, item, furniture, room = args
        super().__init__((robot, item, room), ctx)
        self.name, self.args = "pick_from", args
        self.furniture = furniture

    def activation(self) -> bool:
        """Refuse unless the item is believed on the furniture; then approach it as a pick does."""
        if not self.ctx.kb.holds("object_on", self.item, self.furniture):
            return self.refuse(f"{self.item} is not believed on {self.furniture}")
        return super().activation()


__all__ = ["FurnitureSearchAction", "PickFromAction"]
