"""One source for text and speech: the templates' JSGF form, the decoder's word graph, the samples and the
reader agree."""

from __future__ import annotations

from knic.language.commands import command_grammar
from knic.language.fsg import WordGraph, compile_word_graph
from knic.language.grammar import to_jsgf
from knic.language.sampling import sample_sentences
from knic.language.understanding import understand
from knic.language.vocabulary import Lexicon, Vocabulary, normalize, number_words

from .test_understanding import REJECTED

_INDEX: list[tuple[WordGraph, dict[tuple[int, str], set[int]]]] = []  # the latest graph and its index


def accepts(graph: WordGraph, text: str) -> bool:
    """Whether the word graph has a path from start to final that says exactly ``text``."""
    if not _INDEX or _INDEX[0][0] is not graph:  # index the transitions by (state, word) once per graph
        moves: dict[tuple[int, str], set[int]] = {}
        for src, dst, _, word in graph.transitions:
            moves.setdefault((src, word), set()).add(dst)
        _INDEX[:] = [(graph, moves)]
    moves = _INDEX[0][1]
    states = {graph.start}
    for word in text.split():
        states = {d for s in states for d in moves.get((s, word), ())}
    return graph.final in states


def test_jsgf_names_the_worlds_things(vocabulary: Vocabulary) -> None:
    jsgf = to_jsgf(command_grammar(), vocabulary)
    assert jsgf.startswith("#JSGF V1.0;")
    assert "public <utterance> = <command>;" in jsgf
    item_rule = next(line for line in jsgf.splitlines() if line.startswith("<item> ="))
    assert "reading glasses" in item_rule and "coke can" in item_rule and "banana" not in item_rule
    assert "<light_groups> = " in jsgf and "all the lights" in jsgf
    for verb in ("pinpoint", "look for", "deliver", "escort", "halfway"):
        assert verb in jsgf


def test_jsgf_loads_in_pocketsphinx(vocabulary: Vocabulary, tmp_path: object) -> None:
    from pocketsphinx import Jsgf

    path = f"{tmp_path}/command.gram"
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(to_jsgf(command_grammar(), vocabulary, garbage=["weather", "joke"]))
    grammar = Jsgf(path)
    assert grammar.get_rule("knic.utterance") is not None


def test_sampled_sentences_are_in_the_word_graph_and_read_with_their_frames(vocabulary: Vocabulary) -> None:
    graph = compile_word_graph(command_grammar(), vocabulary)
    samples = list(sample_sentences(vocabulary, 300, seed=7))
    assert len({s.text for s in samples}) > 250
    assert {f.kind for s in samples for f in s.frames} >= {"SEARCHING", "BRINGING", "OPERATING", "MOTION"}
    wrong = []
    for sample in samples:
        assert accepts(graph, sample.text), sample.text
        got = understand(sample.text, vocabulary).frames
        if [f.to_dict() for f in got] != [f.to_dict() for f in sample.frames]:
            wrong.append(sample.text)
    assert len(wrong) <= 3, (
        wrong
    )  # a few samples are truly ambiguous ("set the dimmer to half open the blinds")


def test_pronouns_are_sampled_for_what_was_said_before_and_read_the_same(vocabulary: Vocabulary) -> None:
    """The speech model hears "lead her" and "bring them", the pronouns the reader resolves (each stands for
    the latest earlier thing of its kind, and a sentence never starts with one)."""
    graph = compile_word_graph(command_grammar(), vocabulary)
    said: dict[str, int] = {}
    for sample in sample_sentences(vocabulary, 1500, seed=11):
        words = sample.text.replace("see to it that", "").split()  # that "it" stands for nothing
        pronouns = [w for w in words if w in ("it", "them", "her", "him")]
        if not pronouns:
            continue
        for word in pronouns:
            said[word] = said.get(word, 0) + 1
        assert sample.frames[0].get("theme") not in ("it", "them", "her", "him"), sample.text
        assert accepts(graph, sample.text), sample.text
        got = understand(sample.text, vocabulary).frames
        assert [f.to_dict() for f in got] == [f.to_dict() for f in sample.frames], sample.text
    assert set(said) == {"it", "them", "her", "him"}, said
    assert accepts(graph, "locate tracy and lead her to the kitchen")
    assert accepts(graph, "find my glasses and bring them to me")


def test_sampling_is_seeded(vocabulary: Vocabulary) -> None:
    first = [s.text for s in sample_sentences(vocabulary, 20, seed=3)]
    assert first == [s.text for s in sample_sentences(vocabulary, 20, seed=3)]
    assert first != [s.text for s in sample_sentences(vocabulary, 20, seed=4)]


def test_word_graph_rejects_what_the_grammar_does_not_cover(vocabulary: Vocabulary) -> None:
    graph = compile_word_graph(command_grammar(), vocabulary)
    for text, _ in REJECTED[:8]:
        assert not accepts(graph, normalize(text))


def test_filler_loop_runs_beside_the_commands(vocabulary: Vocabulary) -> None:
    graph = compile_word_graph(command_grammar(), vocabulary, fillers=["weather", "joke"], filler_weight=0.05)
    assert accepts(graph, "weather joke weather") and accepts(graph, "bring me my glasses")
    assert not accepts(graph, "bring me joke")
    assert "FSG_BEGIN" in graph.to_fsg() and "TRANSITION" in graph.to_fsg()


def test_vocabulary_from_lexicon(vocabulary: Vocabulary) -> None:
    phrases = {t.phrase: t.symbol for t in vocabulary.terms}
    assert phrases["reading glasses"] == "glasses" and phrases["glasses"] == "glasses"
    assert phrases["living room"] == "living_room" and phrases["granny annie"] == "annie"
    assert phrases["left light"] == "bedroom_left_light" and phrases["cardboard box"] == "cardboard_box"
    assert vocabulary.members("all_lights") == ("bedroom_left_light", "bedroom_right_light", "hallway_light")
    assert vocabulary.level(50) == "l50" and vocabulary.level(30) is None
    assert vocabulary.robot == "r2d2"
    assert "entrance" not in {
        t.symbol for t in vocabulary.terms
    }  # lexicon entry for a symbol not in the world


def test_vocabulary_of_a_smaller_world() -> None:
    lexicon = Lexicon(names={"glasses": ("reading glasses",), "sofa": ("couch",)})
    small = Vocabulary.from_instances(
        {"glasses": "item", "kitchen": "room", "r2d2": "robot"},
        {"item": "entity", "room": "object", "robot": "entity", "entity": "object"},
        lexicon,
        synonyms=[],  # the lexicon's names only (synonyms: test_corrections_and_talk)
    )
    assert [(t.phrase, t.symbol) for t in small.terms_of(("item",))] == [("reading glasses", "glasses")]
    assert small.terms_of(("furniture",)) == []


def test_normalize_and_numbers() -> None:
    assert normalize("Half-open the Blinds, please!") == "half open the blinds please"
    assert normalize("set the dimmer to 75%") == "set the dimmer to seventy five percent"
    assert normalize("dim it to 0.5") == "dim it to fifty percent"  # a share, not "zero five"
    assert normalize("the blinds to 30.5 %") == "the blinds to thirty one percent"  # not "thirty five"
    assert normalize("set it to 1.0.") == "set it to one hundred percent"
    assert normalize("open them 62.5") == "open them sixty three"
    # typed on a phone or in a word processor: curly apostrophes, accents, dashes
    assert normalize("I\u2019d like Zo\u00eb\u2019s caf\u00e9 \u2014 now") == "i'd like zoe's cafe now"
    assert [number_words(n) for n in (0, 13, 40, 99, 100)] == [
        "zero",
        "thirteen",
        "forty",
        "ninety nine",
        "one hundred",
    ]


def test_alone_templates_are_sampled_only_as_a_whole_command(
    vocabulary: Vocabulary, tmp_path: object
) -> None:
    """A question or a bare request ("is the cup in the kitchen", "the cup please") is never chained."""
    from pathlib import Path

    from knic.language.commands import load_language

    path = Path(str(tmp_path)) / "commands.yaml"
    path.write_text(
        "verbs:\n  search:\n    frames: [SEARCHING]\n    phrases: [find]\n"
        "joiners: [and]\nopeners: [please]\nclosers: [please]\n"
        "templates:\n  - 'SEARCHING: find {item:theme}'\n"
        "  - 'alone SEARCHING: is the {item:theme} in the {room:ground}'\n"
    )
    language = load_language(path)
    assert [f.alone for f in language.template_nodes()] == [False, True]
    samples = list(sample_sentences(vocabulary, 300, seed=5, grammar=command_grammar(language=language)))
    questions = [s for s in samples if s.text.removeprefix("please ").startswith("is the")]
    assert questions and all(len(s.frames) == 1 for s in questions)
    assert not any("find" in s.text and " is the " in s.text for s in samples)  # never after another action
    assert any(len(s.frames) > 1 for s in samples)  # the other template still chains
