"""Command frames in the ERL speech benchmark's representation.

A frame is a kind (``BRINGING``, ``SEARCHING``, ``MOTION``, ``PLACING``, ``ACCOMPANYING``, ``OPERATING``)
with arguments among ``theme``, ``source``, ``goal``, ``ground``, ``beneficiary``, ``device``, ``state``.
Argument values are knowledge-base symbols (``"glasses"``, ``"living_room"``), a lexicon group name for
several devices (``"all_lights"``), ``"me"`` for the speaker, a device state (``"on"``, ``"off"``,
``"open"``, ``"closed"``, ``"half-open"``) or a percentage (``"50"``). Pronouns ("it", "her", "him") are
resolved to the previous action's theme, so "locate the tablet and bring it to me" gives
``SEARCHING(theme: tablet)``, ``BRINGING(theme: tablet, beneficiary: me)``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from core.errors import LanguageError
from knic.language.grammar import PRONOUNS
from knic.language.parser import RawFrame
from knic.language.vocabulary import Term, Vocabulary, level_percent

FRAME_KINDS = ("BRINGING", "SEARCHING", "MOTION", "PLACING", "ACCOMPANYING", "OPERATING")
ROLES = ("theme", "source", "goal", "ground", "beneficiary", "device", "state")
SPEAKER = "me"


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


def build_frames(raw: Sequence[RawFrame], vocabulary: Vocabulary) -> list[CommandFrame]:
    """Turn parsed actions into frames, resolving pronouns against the previous actions.

    Raises:
        LanguageError: a pronoun has no referent (nothing was said before it, or it names the wrong kind of
            thing, e.g. "it" after a person).
    """
    frames: list[CommandFrame] = []
    for action in raw:
        args: dict[str, str] = {}
        for role, value in action.args:
            if isinstance(value, Term):
                args[role] = _term_value(value)
            elif value in PRONOUNS:
                args[role] = _resolve(value, frames, vocabulary)
            else:
                args[role] = value
        frames.append(CommandFrame(action.kind, args))
    return frames


def _term_value(term: Term) -> str:
    if term.type == "level":
        percent = level_percent(term.symbol)
        return str(percent) if percent is not None else term.symbol
    return term.symbol


def _resolve(pronoun: str, previous: Sequence[CommandFrame], vocabulary: Vocabulary) -> str:
    wanted = "item" if pronoun == "it" else "person"
    for frame in reversed(previous):
        for role in ("theme", "beneficiary"):
            value = frame.get(role)
            if value is None or value == SPEAKER:
                continue
            value_type = vocabulary.type_of(value)
            if value_type is not None and vocabulary.is_subtype(value_type, wanted):
                return value
    thing = "an object" if wanted == "item" else "a person"
    raise LanguageError(f"'{pronoun}' does not refer to {thing} named earlier in the command")
