"""Words typed in a hurry or mis-heard by a recogniser, read as the word of the command language or the world
they stand for (text only; the speech model never sees these forms).

A :class:`Speller` is built from the known words (the command language's phrases and the world's names) and
mends the tokens of one command, before they are cut into chunks:

* **Joined names.** A word that is a name of the world written without its spaces ("livingroom",
  "kitchencounter", "teddybear") is that name; two words that make one word of a name ("bath room",
  "bed room") are that word, unless the two are a phrase of their own.
* **Homophones.** A word the recogniser heard for another of the same sound (``homophones`` in
  commands.yaml: "too", "four", "of", "write") is that other word only where that one fits: a state after a
  verb of switching ("switch of the light") or last ("turn the light of"); a preposition before a
  determiner, "me" or a person ("too the kitchen", "the glasses four tracy"; never before a count: "four
  apples"); a determiner before a name ("sum water"); a word that with the next makes a name ("write
  light").
* **Apostrophes left out.** A word nobody knows that is a known word with "s" ("shes", "tracys") is that
  word with "'s".
* **Spellings of an ending.** A word nobody knows ending in "y" where a name has it ending in "ie", or the
  other way round, is that word ("hoody": hoodie).
* **Typos.** A word nobody knows (no known word and no English word) one edit from exactly one known word
  (a letter missing, added, changed or two letters swapped; two edits for words of eight letters or more
  when none is one edit away) is that word: "kitchn", "teh", "brign", "remtoe". A doubled or undoubled
  letter is a slip even where it makes an English word ("dinning", "hamer", "lemmon"). Words of three
  letters never shrink ("dsk", "opn", "teh"; "soa" is no "so"). Of several such words, a lone swap of two
  letters wins outside a noun phrase ("teh": the, not ten); after a determiner or a word of a name
  ("bathroom drawr") only names count, the one keeping most of the word's letters at both ends wins
  ("glases": glasses, not glass), and several names that tie make the word stand for all of them
  (:meth:`Speller.names_for`), so that it is asked about ("the cug": the cup or the mug?); else the one that
  makes a phrase of the language with the next word wins ("wher is": where, not her or when). A real English
  word is never guessed at ("the cake" is no coke, "the basket" no blanket): it is refused naming it; except
  after a word of a name, where one word one edit away ends that name with it ("rubber duk": duck), and
  before the last word of a two-word name whose first word is two edits or fewer away and starts alike
  ("paper mill": the pepper mill; speech mishears a name so).

English words are those of the pronouncing dictionary the speech side ships (pocketsphinx's cmudict),
read once, the first time a word no table knows is near a known word (a command of known words never reads
it); without it no typo is guessed.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from functools import lru_cache

_LETTERS = "abcdefghijklmnopqrstuvwxyz'"
#: shortest word that is mended at all; words of this length only by a letter changed or added or a swap,
#: never by a letter dropped ("teh", "dsk"; "soa" is no "so")
_SHORT = 3
#: words of this length or more may be two edits from the word meant
_LONG = 8


@lru_cache(maxsize=1)
def _dictionary() -> bytes:
    """The speech side's pronouncing dictionary, one word and its sounds a line ("" when not installed)."""
    from knic.language.acoustic import wheel_model_dir

    try:
        path = wheel_model_dir() / "cmudict-en-us.dict"
    except ImportError:
        return b""
    return b"\n" + path.read_bytes() if path.is_file() else b""


def is_english(word: str) -> bool | None:
    """Whether ``word`` is in the pronouncing dictionary; None when there is no dictionary (read once, and
    searched rather than indexed: a set of its words would cost ``knic goal`` a quarter of a second)."""
    text = _dictionary()
    return f"\n{word} ".encode() in text if text else None


def edits(word: str) -> set[str]:
    """The strings one edit from ``word``: a letter deleted, two neighbours swapped, one changed or added."""
    splits = [(word[:i], word[i:]) for i in range(len(word) + 1)]
    out = {a + b[1:] for a, b in splits if b}
    out |= {a + b[1] + b[0] + b[2:] for a, b in splits if len(b) > 1}
    out |= {a + c + b[1:] for a, b in splits if b for c in _LETTERS}
    out |= {a + c + b for a, b in splits for c in _LETTERS}
    out.discard(word)
    return out


def distance(a: str, b: str) -> int:
    """Edit distance with swaps of neighbours (optimal string alignment)."""
    rows = [list(range(len(b) + 1))]
    for i in range(1, len(a) + 1):
        row = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            row[j] = min(rows[-1][j] + 1, row[j - 1] + 1, rows[-1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                row[j] = min(row[j], rows[-2][j - 2] + 1)
        rows = [rows[-1], row]
    return rows[-1][-1]


def swapped(a: str, b: str) -> bool:
    """Whether ``b`` is ``a`` with two neighbouring letters swapped."""
    diff = [i for i in range(len(a)) if len(a) == len(b) and a[i] != b[i]]
    return len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]]


def doubled(a: str, b: str) -> bool:
    """Whether one of the words is the other with one letter doubled ("dinning", "hamer")."""
    short, long_ = sorted((a, b), key=len)
    if len(long_) != len(short) + 1:
        return False
    return any(
        long_[i] == long_[i + 1] and long_[:i] + long_[i + 1 :] == short for i in range(len(long_) - 1)
    )


def _ends_kept(near: list[str], word: str) -> list[str]:
    """Of several names a word may be a typo of, the one that keeps most of its letters at both ends
    ("glases": glasses, not glass); all of them where that ties ("cug": cup or mug, asked about)."""
    if len(near) < 2:
        return near

    def kept(other: str) -> int:
        start = next(
            (i for i, (a, b) in enumerate(zip(word, other, strict=False)) if a != b),
            min(len(word), len(other)),
        )
        pairs = zip(reversed(word), reversed(other), strict=False)
        end = next((i for i, (a, b) in enumerate(pairs) if a != b), min(len(word), len(other)))
        return start + end

    best = max(kept(w) for w in near)
    top = [w for w in near if kept(w) == best]
    return top if len(top) == 1 else near


class Speller:
    """Mends one command's tokens (see the module docstring); build once per chunker.

    Args:
        known: every word of the command language's phrases and of the world's names.
        name_words: the words of the world's names (and their plurals).
        names: the world's names, whole, as said (for joined words).
        kind_of: a phrase's kind in the language tables ("det", "prep", "state", "verb", ...), else None.
        people: the names of people.
        homophones: word heard -> the word meant where it fits.
        english: whether a word is English (None: unknown, no dictionary); read only when needed.
    """

    def __init__(
        self,
        known: Collection[str],
        name_words: Collection[str],
        names: Collection[str],
        kind_of: Callable[[str], str | None],
        people: Collection[str],
        homophones: Mapping[str, str],
        english: Callable[[str], bool | None] = is_english,
    ):
        self._known = frozenset(known)
        self._name_words = frozenset(name_words)
        self._kind_of = kind_of
        self._people = frozenset(people)
        self._homophones = dict(homophones)
        self._english = english
        self._names = frozenset(names)
        self._joined = {n.replace(" ", ""): n for n in self._names if " " in n}
        #: the pairs of words said one after the other in names; the first words of two-word names by the last
        self._pairs = {pair for n in self._names for pair in zip(n.split(), n.split()[1:], strict=False)}
        self._firsts: dict[str, set[str]] = {}
        for first, _, last in (n.partition(" ") for n in self._names):
            self._firsts.setdefault(last, set()).add(first)
        self._by_length: dict[int, list[str]] = {}
        for word in self._known:
            self._by_length.setdefault(len(word), []).append(word)
        self._cache: dict[tuple[str, bool], tuple[str, ...]] = {}

    def mended(self, tokens: Sequence[str]) -> list[str]:
        """The tokens with joined names split, split words joined, homophones and typos mended."""
        out: list[str] = []
        i = 0
        while i < len(tokens):
            token = tokens[i]
            if i + 1 < len(tokens) and self._joins(token, tokens[i + 1]):
                out.append(token + tokens[i + 1])
                i += 2
                continue
            if token in self._joined and token not in self._known:
                out += self._joined[token].split()
                i += 1
                continue
            heard = self._homophone(out, token, tokens[i + 1 :])
            heard = heard or (self._before_name(token, tokens[i + 1]) if i + 1 < len(tokens) else None)
            if heard is not None:
                out.append(heard)
            else:
                noun = bool(out) and (self._kind_of(out[-1]) == "det" or out[-1] in self._name_words)
                meant = self.candidates(token, noun) or self._in_name(out, token)
                if len(meant) > 1 and i + 1 < len(tokens):  # "wher is": where (a phrase with "is"), not her
                    meant = (
                        tuple(w for w in meant if self._kind_of(f"{w} {tokens[i + 1]}") is not None) or meant
                    )
                if len(meant) > 1 and out:  # "can i hav my teddy": have (a phrase with "can i"), not has
                    meant = tuple(w for w in meant if self._ends_phrase(out, w)) or meant
                opening = all(self._polite(w) for w in out)  # "pleas tke the glue": only politeness before
                if len(meant) > 1 and opening and i + 1 < len(tokens):  # "fnd my glasses": find, not and
                    meant = tuple(w for w in meant if self._kind_of(w) == "verb") or meant
                out.append(meant[0] if len(meant) == 1 else token)
            i += 1
        return out

    def _polite(self, word: str) -> bool:
        """Whether a word is one of the language's and of no kind of phrase or name (politeness: "please")."""
        return word in self._known and word not in self._name_words and self._kind_of(word) is None

    def _before_name(self, word: str, after: str) -> str | None:
        """The first word of the one two-word name that ends with ``after`` and begins with a word two edits
        or fewer from ``word`` and with its letter ("paper mill": the pepper mill, not the newspaper and a
        mill), where ``word`` and ``after`` are no part of a name together: the name's last word tells what
        was meant (a recogniser's near miss, or a typo of a known word). Not for a person's name or a short
        word."""
        if len(word) < _SHORT + 1 or word in self._people or after not in self._name_words:
            return None
        if (word, after) in self._pairs:  # "desk lamp" of the attic desk lamp
            return None
        near = {
            first
            for first in self._firsts.get(after, ())
            if first != word and first[:1] == word[:1] and distance(first, word) <= 2
        }
        return near.pop() if len(near) == 1 else None

    def _in_name(self, before: Sequence[str], word: str) -> tuple[str, ...]:
        """The one word, one edit from ``word``, that ends a name of the world with the word said before it
        ("rubber duk": duck), though ``word`` is English: the name's first word tells what was meant."""
        if not before or before[-1] not in self._name_words or word in self._known or not word.isalpha():
            return ()
        if len(word) < _SHORT:
            return ()
        near = sorted(w for w in edits(word) if f"{before[-1]} {w}" in self._names and len(w) >= len(word))
        return tuple(near) if len(near) == 1 else ()

    def _ends_phrase(self, before: Sequence[str], word: str) -> bool:
        """Whether ``word`` ends a phrase of the language begun by the one or two words before it."""
        return any(
            self._kind_of(" ".join([*before[-n:], word])) is not None for n in (1, 2) if len(before) >= n
        )

    def names_for(self, word: str) -> tuple[str, ...]:
        """The names a word after a determiner may be a typo of, when it is one of several ("cug")."""
        meant = self.candidates(word, True)
        return meant if len(meant) > 1 else ()

    def candidates(self, word: str, in_noun: bool) -> tuple[str, ...]:
        """The known words ``word`` may be a typo of (none when it is known, English or no near word)."""
        key = (word, in_noun)
        if key not in self._cache:
            self._cache[key] = self._candidates(word, in_noun)
        return self._cache[key]

    def _candidates(self, word: str, in_noun: bool) -> tuple[str, ...]:
        if word in self._known or not word.isalpha() or len(word) < _SHORT:
            return ()
        if word.endswith("s") and word[:-1] in self._known and self._english(word) is False:
            return (word[:-1] + "'s",)  # "shes", "tracys": the apostrophe left out
        # "hoody" for a hoodie, "nighty" for a nightie: the other spelling of an ending
        variant = word[:-1] + "ie" if word.endswith("y") else word[:-2] + "y" if word.endswith("ie") else ""
        if variant in self._name_words:
            return (variant,)
        near = sorted(w for w in edits(word) if w in self._known)
        if len(word) == _SHORT:  # "dsk", "opn", "teh": grown or swapped, never shrunk
            near = [w for w in near if len(w) >= len(word)]
        if not near and len(word) >= _LONG:
            near = sorted(
                w
                for n in range(len(word) - 2, len(word) + 3)
                for w in self._by_length.get(n, ())
                if distance(word, w) == 2
            )
        if in_noun:
            near = _ends_kept([w for w in near if w in self._name_words], word)
        elif len(near) > 1:
            swaps = [w for w in near if swapped(word, w)]
            near = swaps if len(swaps) == 1 else near
        if not near:
            return ()
        english = self._english(word)
        if english is None:
            return ()  # no dictionary: nothing is guessed
        if english and not (len(near) == 1 and doubled(word, near[0])):
            return ()  # "cake", "basket": a real word, refused as said
        return tuple(near)

    def _joins(self, first: str, second: str) -> bool:
        """Whether two words are one word of a name said apart ("bath room", "bed room")."""
        pair = f"{first} {second}"
        return (
            first + second in self._name_words
            and pair not in self._names
            and self._kind_of(pair) is None
            and first.isalpha()
            and second.isalpha()
        )

    def _homophone(self, before: Sequence[str], word: str, after: Sequence[str]) -> str | None:
        """The word meant for a homophone, where it fits (see the module docstring), else None."""
        meant = self._homophones.get(word)
        if meant is None or (before and (before[-1], word) in self._pairs):  # "bench lamp two": a name's
            return None
        kind = self._kind_of(meant)
        nxt = after[0] if after else ""
        if kind == "state":  # "switch of the light", "turn the light of"
            return meant if (before and self._kind_of(before[-1]) == "verb") or not after else None
        if kind == "prep":  # "too the kitchen", "four tracy", not "four apples"
            fits = self._kind_of(nxt) == "det" or nxt == "me" or nxt in self._people
            return meant if fits and not nxt.isdigit() else None
        if kind == "det":  # "sum water"
            return meant if nxt in self._name_words else None
        if nxt and meant in self._name_words and f"{meant} {nxt}" in self._names:
            return meant  # "write light": the right light
        return None
