"""Fixtures for the language tests: the ERL apartment's knowledge base and vocabulary, loaded once."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from knic.language.vocabulary import Vocabulary
from knic.language.world import load_world, read_vocabulary

SPEECH_FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "speech"


@pytest.fixture(autouse=True)
def _short_lived_say_daemons(monkeypatch: pytest.MonkeyPatch) -> None:
    """A say daemon a test's ``knic say`` leaves (knic.language.sayd) goes 20 s after its last use, not 10
    minutes: the suite leaves no process behind for long."""
    from knic.language.sayd import IDLE_ENV

    monkeypatch.setenv(IDLE_ENV, "20")


@pytest.fixture(scope="session")
def erl_world() -> tuple[Any, Vocabulary]:
    """(knowledge base, vocabulary) of worlds/erl_home (read-only: tests that write build their own KB)."""
    return load_world()


@pytest.fixture(scope="session")
def vocabulary(erl_world: tuple[Any, Vocabulary]) -> Vocabulary:
    return erl_world[1]


@pytest.fixture()
def fresh_kb() -> Any:
    """A new knowledge base of the ERL apartment, for tests that add goals."""
    return load_world()[0]


@pytest.fixture(scope="session")
def other_house() -> Vocabulary:
    """The vocabulary of the language bench's other house (tests/fixtures/language/other_world)."""
    from knic.bench.language import OTHER_WORLD

    return read_vocabulary(problem=OTHER_WORLD)


def frames_read(vocabulary: Vocabulary, text: str, speaker: str = "annie") -> list[dict[str, str]]:
    """The frames ``text`` is read as (as data), asserting that it is accepted."""
    from knic.language import understand

    result = understand(text, vocabulary, speaker=speaker)
    assert result.accepted, result.reason
    return [frame.to_dict() for frame in result.frames]


@pytest.fixture(scope="session")
def grammar_recognizer(vocabulary: Vocabulary) -> Any:
    """The grammar decoder's recogniser of the ERL apartment with its default (adapted) acoustic model,
    built once (about five seconds); decoding with it does not depend on what it decoded before."""
    from knic.language.speech import Recognizer
    from knic.language.understanding import default_grammar

    return Recognizer(default_grammar(), vocabulary)


def assert_asked(vocabulary: Vocabulary, text: str, word: str, speaker: str = "annie") -> None:
    """``text`` is not done but asked about, with ``word`` in the question."""
    from knic.language.understanding import understand

    result = understand(text, vocabulary, speaker=speaker)
    assert not result.accepted
    assert result.reason.startswith("ambiguous"), result.reason
    assert word in result.reason


def world_of(file: str) -> Vocabulary:
    """A world file's vocabulary (``file`` relative to the project), as the language bench and ``knic goal
    --world`` read it."""
    from knic.cli.goal import world_vocabulary
    from knic.language.world import DEFAULT_DOMAIN

    path = Path(__file__).resolve().parents[2] / file
    vocabulary: Any = world_vocabulary(str(path), DEFAULT_DOMAIN, None)[0]
    return vocabulary
