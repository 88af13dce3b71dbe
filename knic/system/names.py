"""The spoken names a run understands: its knowledge base's symbols with the lexicon that goes with its world.

A world's own ``lexicon.yaml`` sits beside its file; a world without one is read with the ERL apartment's
(its names for symbols the world lacks are left out, and its groups by type, "the lights", fit any world).
Devices are known to be in the room the world file puts them in (the domain has no fact for it), and the room
a door to the outside opens into is also "the front door".
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from knic.language.vocabulary import Lexicon, Vocabulary
from knic.language.world import LEXICON_NAME, WORLDS

if TYPE_CHECKING:
    from knic.system import KnicSystem

#: the ERL apartment's lexicon ("reading glasses" for glasses, "the lights" for every light)
ERL_LEXICON = WORLDS / "erl_home" / LEXICON_NAME


def world_lexicon(world_file: str | Path | None) -> Path | None:
    """The lexicon beside the world file, else the ERL apartment's (None when neither exists)."""
    if world_file is not None:
        beside = Path(world_file).parent / LEXICON_NAME
        if beside.is_file():
            return beside
    return ERL_LEXICON if ERL_LEXICON.is_file() else None


def run_vocabulary(system: KnicSystem, lexicon: str | Path | None = None) -> Vocabulary:
    """The vocabulary of a running system: ``lexicon``, else its world's (:func:`world_lexicon`)."""
    chosen = lexicon if lexicon is not None else world_lexicon(system.world.source)
    names = (Lexicon.load(chosen) if chosen is not None else Lexicon()).with_entrances(
        system.world.entrances(), system.world.back_entrances()
    )
    return Vocabulary.from_knowledge_base(system.kb, names, system.world.device_rooms())
