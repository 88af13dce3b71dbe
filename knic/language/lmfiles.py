"""The files of the n-gram recogniser's command model: the ARPA text sampled from the templates, the words'
pronunciations, and pocketsphinx's binary copy of the model, each kept in the temporary folder by content.
"""

from __future__ import annotations

import contextlib
import hashlib
import shutil
import tempfile
from pathlib import Path
from typing import Any

from core.errors import LanguageError
from knic.language.commands import command_language
from knic.language.vocabulary import Vocabulary

#: Sentences sampled for the model. Measured on the development sets with the templates of 28 Nov 2026 (263
#: commands in 10 voices, 134 other utterances; see :data:`knic.language.membership.CONFIDENCE_THRESHOLD`):
#: frame+args 0.817 with 4000, 0.852 with 12000, 0.829 with 30000 (more templates need more samples; past
#: that, no gain).
SENTENCES = 12000
#: Sentences made from each of people's phrasing patterns (:mod:`knic.language.phrasings`) besides the
#: template samples (0: none).
PHRASING_REPEATS = 8


def build_model(
    vocabulary: Vocabulary,
    sentences: int = SENTENCES,
    *,
    seed: int = 0,
    exclude: frozenset[str] = frozenset(),
    phrasings: int | None = None,
) -> str:
    """The ARPA text of the command model for a vocabulary (cached in the temporary folder by content):
    ``sentences`` template samples and ``phrasings`` (default :data:`PHRASING_REPEATS`) sentences of each
    of people's phrasing patterns.

    Raises:
        LanguageError: the phrasings file is unreadable.
    """
    from knic.language.phrasings import PHRASINGS, load_patterns, sample_phrasings

    phrasings = PHRASING_REPEATS if phrasings is None else phrasings
    patterns = load_patterns() if phrasings > 0 else []
    language = command_language()
    key = hashlib.sha256()
    key.update(Path(language.source).read_bytes() if language.source else b"")
    for term in vocabulary.terms:
        key.update(f"{term.phrase}|{term.type}|{term.is_group};".encode())
    from knic.language.sampling import FIRST_PHRASE_SHARE, sample_sentences  # only to build a model

    key.update(f"{sentences}|{seed}|{sorted(exclude)}|{FIRST_PHRASE_SHARE}|{phrasings}|{PHRASINGS}".encode())
    key.update("\n".join(patterns).encode())
    cache = Path(tempfile.gettempdir()) / f"knic-ngram-{key.hexdigest()[:20]}.arpa"
    if cache.is_file():
        return cache.read_text(encoding="utf-8")
    samples = sample_sentences(vocabulary, sentences, seed=seed, exclude_words=exclude, frames=False)
    texts = [s.text for s in samples]
    texts += sample_phrasings(vocabulary, phrasings, seed=seed, patterns=patterns, exclude_words=exclude)
    from knic.language.ngram import arpa_from_sentences

    arpa = arpa_from_sentences(texts)
    with contextlib.suppress(OSError):  # no cache: built again next time
        cache.write_text(arpa, encoding="utf-8")
    return arpa


def dictionary_lines(source: Path, words: set[str]) -> list[str]:
    """The lines of a pronunciation dictionary for ``words`` (every pronunciation of each); kept in the
    temporary folder, keyed by the dictionary file and the words (reading the 134k-word dictionary took a
    third of the recogniser's start-up).

    Raises:
        LanguageError: the dictionary cannot be read.
    """
    try:
        stat = source.stat()
    except OSError as exc:
        raise LanguageError(f"{source}: cannot read the pronunciation dictionary: {exc}") from exc
    key = hashlib.sha256(f"{source.resolve()}|{stat.st_size}|{stat.st_mtime_ns}|".encode())
    key.update(" ".join(sorted(words)).encode())
    cache = Path(tempfile.gettempdir()) / f"knic-dict-{key.hexdigest()[:20]}.dict"
    with contextlib.suppress(OSError, UnicodeDecodeError):
        return cache.read_text(encoding="utf-8").splitlines(keepends=True)
    try:
        text = source.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        raise LanguageError(f"{source}: cannot read the pronunciation dictionary: {exc}") from exc
    lines = [
        line + "\n"
        for line in text.splitlines()
        if line.strip() and line.split(maxsplit=1)[0].split("(")[0] in words
    ]
    with contextlib.suppress(OSError):  # no cache: read again next time
        cache.write_text("".join(lines), encoding="utf-8")
    return lines


def binary_model(decoder: Any, arpa: str) -> tuple[Any, Path | None]:
    """The ARPA model as pocketsphinx's ``NGramModel``, read from a binary copy kept in the temporary folder
    by content (reading the binary form takes about 1 ms, parsing the ARPA text about 60), and that copy's
    path (None when it could not be kept).

    Raises:
        RuntimeError, ValueError: pocketsphinx cannot read the model.
    """
    from pocketsphinx import NGramModel

    key = hashlib.sha256(arpa.encode()).hexdigest()[:20]
    cache = Path(tempfile.gettempdir()) / f"knic-ngram-{key}.lm.bin"
    if cache.is_file():
        with contextlib.suppress(RuntimeError, ValueError, OSError):  # unreadable: made again below
            return NGramModel(decoder.config, decoder.logmath, str(cache)), cache
    with tempfile.TemporaryDirectory(prefix="knic-lm-") as tmp:
        path = Path(tmp) / "commands.arpa"
        path.write_text(arpa, encoding="utf-8")
        model = NGramModel(decoder.config, decoder.logmath, str(path))
        with contextlib.suppress(OSError, RuntimeError, ValueError):  # no cache: parsed again next time
            partial = Path(tmp) / "commands.lm.bin"
            model.write(str(partial), NGramModel.str_to_type("bin"))
            shutil.move(str(partial), cache)
    return model, (cache if cache.is_file() else None)


def model_words(arpa: str) -> set[str]:
    """The words of an ARPA model's 1-grams."""
    found: set[str] = set()
    inside = False
    for line in arpa.split("\\2-grams:", 1)[0].splitlines():
        if line.startswith("\\1-grams:"):
            inside = True
        elif line.startswith("\\"):
            if inside:
                break
        elif inside and line.strip():
            found.add(line.split()[1])
    return found
