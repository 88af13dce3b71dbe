"""A back-off trigram language model of command sentences, written in the ARPA format pocketsphinx reads.

The sentences are sampled from the command templates with a world's names (:mod:`knic.language.sampling`),
so the model knows the same phrasings as the reader and the grammar, but lets the recogniser leave them: any
word sequence over the vocabulary has some probability, which suits commands that are phrased a little
differently from every template. Estimation: absolute discounting (D = 0.5) with Katz-style back-off weights,
computed exactly so that each context's probabilities sum to one. Deterministic for a given sentence list.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterable
from itertools import pairwise

DISCOUNT = 0.5
BOS, EOS = "<s>", "</s>"


def arpa_from_sentences(sentences: Iterable[str], discount: float = DISCOUNT) -> str:
    """The ARPA text of a trigram model of ``sentences`` (lowercase words separated by spaces).

    Raises:
        ValueError: no sentence has a word.
    """
    uni: Counter[str] = Counter()
    bi: Counter[tuple[str, str]] = Counter()
    tri: Counter[tuple[str, str, str]] = Counter()
    for sentence in sentences:
        words = [BOS, *sentence.split(), EOS]
        if len(words) == 2:
            continue
        uni.update(words[1:])
        bi.update(pairwise(words))
        tri.update(zip(words, words[1:], words[2:], strict=False))
    if not uni:
        raise ValueError("no sentences to build a language model from")
    total = sum(uni.values())
    vocabulary = sorted(set(uni) | {BOS})
    p1 = {w: uni[w] / total for w in vocabulary}
    p1[BOS] = 0.0
    # bigrams
    context1: Counter[str] = Counter()
    for (u, _), c in bi.items():
        context1[u] += c
    p2 = {(u, w): (c - discount) / context1[u] for (u, w), c in bi.items()}
    bow1: dict[str, float] = {}
    seen1: dict[str, list[str]] = {}
    for u, w in bi:
        seen1.setdefault(u, []).append(w)
    for u, ws in seen1.items():
        left = 1.0 - sum(p2[(u, w)] for w in ws)
        below = 1.0 - sum(p1[w] for w in ws)
        bow1[u] = left / below if below > 1e-12 else 1.0

    def p2_full(u: str, w: str) -> float:
        return p2.get((u, w), bow1.get(u, 1.0) * p1[w])

    context2: Counter[tuple[str, str]] = Counter()
    for (u, v, _), c in tri.items():
        context2[(u, v)] += c
    p3 = {(u, v, w): (c - discount) / context2[(u, v)] for (u, v, w), c in tri.items()}
    seen2: dict[tuple[str, str], list[str]] = {}
    for u, v, w in tri:
        seen2.setdefault((u, v), []).append(w)
    bow2: dict[tuple[str, str], float] = {}
    for (u, v), ws in seen2.items():
        left = 1.0 - sum(p3[(u, v, w)] for w in ws)
        below = 1.0 - sum(p2_full(v, w) for w in ws)
        bow2[(u, v)] = left / below if below > 1e-12 else 1.0

    def log10(p: float) -> float:
        return math.log10(p) if p > 0 else -99.0

    lines = [
        "\\data\\",
        f"ngram 1={len(vocabulary)}",
        f"ngram 2={len(p2)}",
        f"ngram 3={len(p3)}",
        "",
        "\\1-grams:",
    ]
    for w in vocabulary:
        lines.append(f"{log10(p1[w]):.6f}\t{w}\t{log10(bow1.get(w, 1.0)):.6f}")
    lines += ["", "\\2-grams:"]
    for (u, w), p in sorted(p2.items()):
        lines.append(f"{log10(p):.6f}\t{u} {w}\t{log10(bow2.get((u, w), 1.0)):.6f}")
    lines += ["", "\\3-grams:"]
    for (u, v, w), p in sorted(p3.items()):
        lines.append(f"{log10(p):.6f}\t{u} {v} {w}")
    lines += ["", "\\end\\", ""]
    return "\n".join(lines)
