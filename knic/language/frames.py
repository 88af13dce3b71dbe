"""Command frames in the ERL speech benchmark's representation.

A frame is a kind (``BRINGING``, ``SEARCHING``, ``MOTION``, ``PLACING``, ``ACCOMPANYING``, ``OPERATING``)
with arguments among ``theme``, ``source``, ``goal``, ``ground``, ``beneficiary``, ``device``, ``state``.
Argument values are knowledge-base symbols (``"glasses"``, ``"living_room"``), a lexicon group name for
several devices (``"all_lights"``), ``"me"`` for the speaker, a device state (``"on"``, ``"off"``,
``"open"``, ``"closed"``) or a percentage (``"50"``). Pronouns ("it", "her", "him", "them") are resolved by
the reader (:mod:`knic.language.reader`), so "locate the tablet and bring it to me" gives
``SEARCHING(theme: tablet)``, ``BRINGING(theme: tablet, beneficiary: me)``. TAKING (picking something up)
appears in a chain whose later action carries the object on ("take the cups and bring them to ...").
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from core.errors import LanguageError

FRAME_KINDS = ("BRINGING", "TAKING", "SEARCHING", "MOTION", "PLACING", "ACCOMPANYING", "OPERATING")
ROLES = ("theme", "source", "goal", "ground", "beneficiary", "device", "state")
SPEAKER = "me"
#: what a thing of a type is called in a reply ("'bin' is not an object"), and several of them
KIND_NAMES = {
    "item": "an object",
    "person": "a person",
    "room": "a room",
    "furniture": "a piece of furniture",
    "device": "a device",
    "light": "a light",
}

KIND_PLURALS = {
    "item": "objects",
    "person": "people",
    "room": "rooms",
    "furniture": "furniture",
    "device": "devices",
}


def not_of_kinds(said: str, categories: Sequence[str], device: bool) -> str:
    """The reply to a thing said where an action needs one of ``categories`` ("'bin' is not an object"); a
    device said so (``device``) is said to be one ("is the hallway light on?", "bring me the dimmer")."""
    if device and "device" not in categories:
        if said.endswith("s") and not said.endswith("ss"):
            are = "are devices: I can switch or set them, not find or carry them or say how they are"
            return f"the {said} {are}"
        return f"the {said} is a device: I can switch or set it, not find or carry it or say how it is"
    return f"'{said}' is not " + " or ".join(KIND_NAMES.get(c, c) for c in categories)


@dataclass(frozen=True)
class CommandFrame:
    """One understood action.

    Attributes:
        kind: one of :data:`FRAME_KINDS`.
        args: role -> value, roles from :data:`ROLES`.
    """

    kind: str
    args: Mapping[str, str]

    def __getitem__(self, role: str) -> str:
        return self.args[role]

    def get(self, role: str) -> str | None:
        """The value of a role, or None when the frame lacks it."""
        return self.args.get(role)

    def to_dict(self) -> dict[str, str]:
        """``{"frame": kind, role: value, ...}`` with roles in :data:`ROLES` order (the JSON form)."""
        result = {"frame": self.kind}
        result.update({r: self.args[r] for r in ROLES if r in self.args})
        return result

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> CommandFrame:
        """Inverse of :meth:`to_dict`.

        Raises:
            LanguageError: unknown frame kind or role.
        """
        kind = str(data.get("frame", ""))
        if kind not in FRAME_KINDS:
            raise LanguageError(f"unknown command frame {kind!r}; expected one of {', '.join(FRAME_KINDS)}")
        args = {str(k): str(v) for k, v in data.items() if k != "frame"}
        unknown = sorted(set(args) - set(ROLES))
        if unknown:
            raise LanguageError(f"frame {kind}: unknown argument(s) {', '.join(unknown)}")
        return cls(kind, args)

    def __str__(self) -> str:
        inner = ", ".join(f'{r}:"{self.args[r]}"' for r in ROLES if r in self.args)
        return f"{self.kind}({inner})"
