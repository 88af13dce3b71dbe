"""People's phrasings for the speech model: sentences people wrote, with the world's names taken out.

The n-gram model (:mod:`knic.language.lmfiles`) is estimated from sentences sampled from the command
templates. People say the same requests more freely ("would you be a dear and fetch me my spectacles", "if
it's not too much trouble ..."), and a model that never saw such word sequences hears them badly even where
the reader understands them typed. :data:`PHRASINGS` holds patterns made from development sets of people's
commands: each sentence normalised, every name of its world replaced by a slot of the name's type with the
name said (``{item=spectacles}``, ``{room=kitchen}``, ...). :func:`sample_phrasings` fills the slots with the
world's names, so the patterns carry to any house.

The patterns are data, made offline by ``python -m knic.language.phrasings SET.yaml ... --out FILE`` from
development sets only (their ``world: other`` cases with ``--other-world``); never from a test set.
"""

from __future__ import annotations

import argparse
import random
import re
from collections.abc import Iterable
from pathlib import Path

from core.errors import LanguageError
from knic.language.vocabulary import Term, Vocabulary, normalize

#: The shipped patterns (see the module docstring for how they were made).
PHRASINGS = Path(__file__).resolve().with_name("phrasings.txt")
#: Types whose names stay as said: levels are numbers people say freely, the robot's name is fixed.
KEPT_TYPES = frozenset({"level", "robot"})
#: Share of a slot's fillings that keep the name said in the development set, where the world has it (people
#: say "my glasses", seldom "my apple": the rest spread the phrasing over the world's names).
KEEP_SAID = 0.5
_SLOT = re.compile(r"\{([a-z_]+)(?:=([a-z0-9' ]+))?\}")


def delexicalize(text: str, vocabulary: Vocabulary) -> str:
    """``text`` normalised, each world name (longest first, left to right) replaced by ``{type=name}``."""
    words = normalize(text).split()
    names: dict[tuple[str, ...], str] = {}
    for term in vocabulary.terms:
        if term.type not in KEPT_TYPES:
            names.setdefault(tuple(term.phrase.split()), term.type)
    longest = max((len(k) for k in names), default=0)
    out: list[str] = []
    index = 0
    while index < len(words):
        for size in range(min(longest, len(words) - index), 0, -1):
            kind = names.get(tuple(words[index : index + size]))
            if kind is not None:
                out.append("{" + kind + "=" + " ".join(words[index : index + size]) + "}")
                index += size
                break
        else:
            out.append(words[index])
            index += 1
    return " ".join(out)


def load_patterns(path: Path | None = None) -> list[str]:
    """The patterns of a phrasings file (default :data:`PHRASINGS`; one per line, ``#`` starts a comment).

    Raises:
        LanguageError: the file cannot be read, or a line has a character other than lowercase words,
            apostrophes and ``{type}`` slots.
    """
    path = path or PHRASINGS
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise LanguageError(f"{path}: cannot read the phrasings: {exc}") from exc
    patterns: list[str] = []
    for number, line in enumerate(lines, start=1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        bare = _SLOT.sub("", line)
        if not re.fullmatch(r"[a-z0-9' {}_=]+", line) or "{" in bare or "}" in bare:
            raise LanguageError(f"{path}:{number}: not a phrasing pattern: {line!r}")
        patterns.append(line)
    return patterns


def sample_phrasings(
    vocabulary: Vocabulary,
    per_pattern: int,
    *,
    seed: int = 0,
    patterns: Iterable[str] | None = None,
    exclude_words: frozenset[str] = frozenset(),
) -> list[str]:
    """Each pattern ``per_pattern`` times with its slots filled by names of the world: the name said in the
    development set (``{type=name}``) in :data:`KEEP_SAID` of the fillings where the world has it, else one
    drawn at random; a pattern with a slot type the world lacks, or a sentence with an excluded word, is
    left out."""
    rng = random.Random(seed)
    by_type: dict[str, list[Term]] = {}
    for term in vocabulary.terms:
        by_type.setdefault(term.type, []).append(term)
    sentences: list[str] = []

    def fill(slot: re.Match[str]) -> str:
        kind, said = slot.group(1), slot.group(2)
        if said and said in names[kind] and rng.random() < KEEP_SAID:
            return said
        return rng.choice(by_type[kind]).phrase

    names = {kind: {term.phrase for term in terms} for kind, terms in by_type.items()}
    for pattern in load_patterns() if patterns is None else patterns:
        kinds = [kind for kind, _ in _SLOT.findall(pattern)]
        if any(kind not in by_type for kind in kinds):
            continue
        for _ in range(per_pattern):
            text = _SLOT.sub(fill, pattern)
            if not exclude_words.intersection(text.split()):
                sentences.append(text)
    return sentences


def main(argv: list[str] | None = None) -> int:
    """Write the patterns of development sets (offline)."""
    import yaml

    from knic.language.world import read_vocabulary

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sets", nargs="+", help="development sets (YAML with cases: text, world)")
    parser.add_argument("--other-world", help="problem file of the cases marked world: other")
    parser.add_argument("--out", default=str(PHRASINGS))
    args = parser.parse_args(argv)
    worlds = {"erl": read_vocabulary()}
    if args.other_world:
        worlds["other"] = read_vocabulary(problem=args.other_world)
    patterns: list[str] = []
    for name in args.sets:
        for case in yaml.safe_load(Path(name).read_text(encoding="utf-8"))["cases"]:
            vocabulary = worlds.get(str(case.get("world", "erl")))
            if vocabulary is None:
                raise SystemExit(f"{name}: a case of world {case.get('world')!r}: give --other-world")
            pattern = delexicalize(str(case["text"]), vocabulary)
            if pattern and pattern not in patterns:
                patterns.append(pattern)
    header = "# People's phrasings for the speech model (knic.language.phrasings), made from: "
    lines = [header + ", ".join(args.sets), *patterns]
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{len(patterns)} patterns written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
