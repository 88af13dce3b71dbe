"""People's phrasings in the speech model: patterns without the world's names, filled with another world's."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.errors import LanguageError
from knic.language.lmfiles import build_model
from knic.language.lmspeech import model_words
from knic.language.phrasings import delexicalize, load_patterns, main, sample_phrasings
from knic.language.vocabulary import Vocabulary
from knic.language.world import read_vocabulary

OTHER_WORLD = Path(__file__).resolve().parents[1] / "fixtures" / "language" / "other_world" / "problem.pddl"


def test_names_become_slots_of_their_type_and_levels_stay(vocabulary: Vocabulary) -> None:
    said = "Would you be a dear and put the reading glasses on the kitchen table, then dim it to 40%?"
    assert delexicalize(said, vocabulary) == (
        "would you be a dear and put the {item=reading glasses} on the {furniture=kitchen table} then dim it"
        " to forty percent"
    )
    said = "take Tracy to the bedroom"
    assert delexicalize(said, vocabulary) == "take {person=tracy} to the {room=bedroom}"


def test_slots_are_filled_with_the_world_s_own_names(vocabulary: Vocabulary) -> None:
    other = read_vocabulary(problem=OTHER_WORLD)
    patterns = ["could you bring me the {item=apple} from the {room} love", "ring the {no_such_type}"]
    sentences = sample_phrasings(other, 20, patterns=patterns)
    assert len(sentences) == 20  # the pattern with a type the world lacks is left out
    items = {t.phrase for t in other.terms if t.type == "item"}
    rooms = {t.phrase for t in other.terms if t.type == "room"}
    for sentence in sentences:
        assert sentence.startswith("could you bring me the ") and sentence.endswith(" love")
        middle = sentence.removeprefix("could you bring me the ").removesuffix(" love")
        item, room = middle.split(" from the ")
        assert item in items and room in rooms
    assert sample_phrasings(other, 3, patterns=patterns, exclude_words=frozenset({"love"})) == []
    kept = sample_phrasings(vocabulary, 200, patterns=["bring me my {item=glasses}"])
    said = kept.count("bring me my glasses")  # the name said, about half the time, where the world has it
    assert 60 <= said <= 140 and len(set(kept)) > 10


def test_the_shipped_patterns_load_and_reach_the_speech_model(vocabulary: Vocabulary) -> None:
    patterns = load_patterns()
    assert len(patterns) > 100 and all(p == p.lower() for p in patterns)
    with_them = model_words(build_model(vocabulary, 300, phrasings=1))
    without = model_words(build_model(vocabulary, 300, phrasings=0))
    assert "parched" in with_them and "parched" not in without  # "i'm quite parched dear ..."


def test_a_bad_pattern_file_names_its_line(tmp_path: Path) -> None:
    bad = tmp_path / "phrasings.txt"
    bad.write_text("# comment\nbring me the {item}\nexec(open('x'))\n", encoding="utf-8")
    with pytest.raises(LanguageError, match=r"phrasings.txt:3: not a phrasing pattern"):
        load_patterns(bad)
    bad.write_text("bring me the {item\n", encoding="utf-8")
    with pytest.raises(LanguageError, match=r":1: not a phrasing pattern"):
        load_patterns(bad)


def test_patterns_are_made_from_a_set_of_commands(tmp_path: Path) -> None:
    cases = tmp_path / "set.yaml"
    cases.write_text(
        "cases:\n- text: 'Pop into the kitchen and fetch me an apple, love'\n"
        "- text: 'take the apple to the kitchen'\n  world: other\n",
        encoding="utf-8",
    )
    out = tmp_path / "out.txt"
    with pytest.raises(SystemExit, match="give --other-world"):
        main([str(cases), "--out", str(out)])
    assert main([str(cases), "--other-world", str(OTHER_WORLD), "--out", str(out)]) == 0
    patterns = load_patterns(out)
    assert patterns[0] == "pop into the {room=kitchen} and fetch me an {item=apple} love"
    assert len(patterns) == 2
