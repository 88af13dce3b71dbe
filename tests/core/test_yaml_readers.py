"""Every YAML file KnIC reads goes through core.inputs' bounded, alias-free reader: a "billion laughs" file of
a few hundred bytes is one line naming the file and the line, never gigabytes of memory."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from core.errors import InferenceError, KnicError, LanguageError, WorldError
from core.inputs import MAX_YAML_BYTES, read_yaml

#: 9 levels of 9 aliases each: 9**9 (387 million) leaves from 400 bytes if a reader expands aliases
BOMB = "\n".join(
    ["a: &a [x, x, x, x, x, x, x, x, x]"]
    + [f"{n}: &{n} [{', '.join(['*' + p] * 9)}]" for p, n in zip("abcdefgh", "bcdefghi", strict=True)]
)


def _scenario(path: Path) -> Any:
    from worlds.api import load_world
    from worlds.scenario import load_scenario

    return load_scenario(path, load_world("erl_home"))


def _roles(path: Path) -> Any:
    from knic.kgm2.roles import load_roles

    return load_roles(path)


def _lexicon(path: Path) -> Any:
    from knic.language.vocabulary import Lexicon

    return Lexicon.load(path)


def _commands(path: Path) -> Any:
    from knic.language.commands import load_language

    return load_language(path)


def _answers(path: Path) -> Any:
    from knic.language.answers import load_answer_phrases

    return load_answer_phrases(path)


def _noise(path: Path) -> Any:
    from worlds.sim.noise import load_noise

    return load_noise(path)


def _voice_bank(path: Path) -> Any:
    from worlds.granny_annie import load_bank

    return load_bank(path)


def _language_set(path: Path) -> Any:
    from knic.bench.language import evaluate

    return evaluate(path)


READERS: dict[str, tuple[Callable[[Path], Any], type[KnicError]]] = {
    "scenario": (_scenario, WorldError),
    "role file": (_roles, InferenceError),
    "lexicon": (_lexicon, LanguageError),
    "answer phrases": (_answers, LanguageError),
    "command language": (_commands, LanguageError),
    "noise model": (_noise, WorldError),
    "voice bank": (_voice_bank, WorldError),
    "language set": (_language_set, KnicError),
}


@pytest.mark.parametrize("kind", sorted(READERS))
def test_an_alias_bomb_is_one_line_naming_the_file(kind: str, tmp_path: Path) -> None:
    reader, error = READERS[kind]
    path = tmp_path / "bomb.yaml"
    path.write_text(BOMB, encoding="utf-8")
    with pytest.raises(error) as caught:
        reader(path)
    message = str(caught.value)
    assert "\n" not in message
    assert f"{path}:2: YAML aliases (*name) are not accepted" in message


@pytest.mark.parametrize("kind", sorted(READERS))
def test_bad_bytes_and_oversized_files_are_refused(kind: str, tmp_path: Path) -> None:
    reader, error = READERS[kind]
    latin = tmp_path / "latin.yaml"
    latin.write_bytes(b"roles:\n  caf\xe9: {}\n")
    with pytest.raises(error, match=r"latin.yaml:2: .* is not UTF-8"):
        reader(latin)
    big = tmp_path / "big.yaml"
    big.write_bytes(b"#" * (MAX_YAML_BYTES + 1))
    with pytest.raises(error, match="more than the limit"):
        reader(big)


def test_read_yaml_reads_a_plain_document(tmp_path: Path) -> None:
    path = tmp_path / "ok.yaml"
    path.write_text("a: [1, {b: two}]\n", encoding="utf-8")
    assert read_yaml(path, "test file") == {"a": [1, {"b": "two"}]}
    with pytest.raises(KnicError, match="cannot read test file"):
        read_yaml(tmp_path / "missing.yaml", "test file")


@pytest.mark.parametrize("libyaml", [True, False], ids=["libyaml", "pure-python"])
def test_both_yaml_parsers_read_alike_and_refuse_alike(
    libyaml: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    import yaml

    from core.inputs import safe_yaml

    if libyaml and not yaml.__with_libyaml__:
        pytest.skip("PyYAML without libyaml")
    monkeypatch.setattr(yaml, "__with_libyaml__", libyaml)
    assert safe_yaml("a: [1, {b: two}]\nc: null\n", "ok.yaml") == {"a": [1, {"b": "two"}], "c": None}
    assert safe_yaml("x: " + "[" * 63 + "]" * 63, "deep.yaml", max_depth=64) is not None
    with pytest.raises(KnicError, match=r"^bomb\.yaml:2: YAML aliases"):
        safe_yaml(BOMB, "bomb.yaml")
    with pytest.raises(KnicError, match=r"^deep\.yaml:1: YAML nested deeper than 64 levels$"):
        safe_yaml("x: " + "[" * 64 + "]" * 64, "deep.yaml")
    with pytest.raises(KnicError, match=r"^bad\.yaml:2: not valid YAML"):
        safe_yaml("a: 1\n b: [\n", "bad.yaml")
