"""What comes into an English request from outside English words, read as the English it stands for before
the request is read (used by :meth:`knic.language.reader.Reader.read`):

* punctuation said aloud to a dictation app that writes it out as words ("turn off the lanai light period",
  "hey comma can you bring me my laptop question mark", "new line bring me ...", "quote bring me the
  sunscreen end quote"): the mark it names (:attr:`CommandLanguage.spoken_marks`); never right after a
  determiner or a preposition ("for a period", "the comma", "in quotes");
* the Spanish words of a bilingual speaker ("bring me mis espejuelos", "prende the light in the cocina",
  "the floor lamp to cincuenta"): the English words they stand for (:attr:`CommandLanguage.spanish_words`),
  accents or none ("azúcar", "azucar"); a Spanish article that is also a word of an English dialect
  (Liverpool's "la", Jamaican "mi") only right before a Spanish word of the table ("la cafetera";
  :attr:`CommandLanguage.spanish_articles`), and a Spanish word that is an English word too only right after
  a Spanish article ("el control": the remote; :attr:`CommandLanguage.spanish_after_articles`);
* a number said as a verb in trade slang, with a thing after it ("86 the kitchen light": a restaurant
  kitchen's "eighty-six", take off; :attr:`CommandLanguage.verb_numbers`);
* "den" for "then" before a verb, as Hawaiian Pidgin and Caribbean English say it ("take da chairs from da
  closet, den put 'em by da table"); after a determiner or a preposition it is the room ("to da den");
* "you'll" or "you will" right before a verb that carries, puts or switches, as New York English says a
  request (Yiddish "du vest mir brengen"; "from the Frigidaire you'll bring me the orange juice"): the verb
  alone, so what is said before it (where from) stays the request's; "you'll be taking ..." is no such;
* "stay" for "is" after a person's name or "you", as Hawaiian Pidgin says it ("Mateo stay in da kitchen?",
  "go check if Lucia stay in the guest room", "Lucia stay sleeping"; "where stay" is a search of its own):
  said of someone, it asks nothing of the robot's staying.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from functools import lru_cache

from knic.language.commands import CommandLanguage
from knic.language.decimals import plain_typed
from knic.language.vocabulary import Vocabulary

#: words after which a mark's name is a word of the sentence ("for a period", "put a comma", "in quotes")
_NOT_AFTER = frozenset(
    {"a", "an", "the", "this", "that", "one", "each", "every", "no", "any", "some", "of", "for", "in", "on"}
)
#: what a Spanish article of the tables stands for ("el": the, "mis": my, "del": of the)
_ARTICLE_MEANINGS = frozenset({"the", "my", "your", "their", "of the"})
#: what may follow a number said as a verb: a thing, not a unit or a count ("86 the light", not "86 percent")
_THING_NEXT = frozenset(
    {"the", "da", "that", "those", "these", "this", "it", "them", "my", "all", "both", "your", "our"}
)


def mixed_said(text: str, language: CommandLanguage, vocabulary: Vocabulary | None = None) -> str:
    """:func:`mixed_read` with the tables of a command language, then "stay" for "is" after the name of a
    person of ``vocabulary`` or "you" (see the module's docstring)."""
    text = mixed_read(
        text,
        language.spoken_marks,
        language.spanish_words,
        language.spanish_articles,
        language.verb_numbers,
        language.spanish_after_articles,
    )
    text = _then_said(text, _verb_starts(language))
    text = _YOU_LL.sub(
        lambda m: "" if m.group(1).lower() in _verb_starts(language, _ASKING) else m.group(0), text
    )
    return _stay(vocabulary).sub(r"\1is", text)


@lru_cache(maxsize=16)
def _stay(vocabulary: Vocabulary | None) -> re.Pattern[str]:
    """The pattern of "stay" said for "is" after a person's name or "you" ("stay put", "stay here" and "stay
    with" are the robot's staying)."""
    people = (
        {t.phrase for t in vocabulary.terms if vocabulary.is_of(t.symbol, "person")} if vocabulary else set()
    )
    names = "|".join(re.escape(p) for p in sorted({*people, "you"}, key=len, reverse=True))
    return re.compile(rf"\b((?:{names})\s+)stay\b(?!\s+(?:put|here|there|with|for)\b)", re.IGNORECASE)


def _verb_starts(language: CommandLanguage, frames: frozenset[str] | None = None) -> frozenset[str]:
    """The first words of the command language's verbs ("put", "bring", "turn", ...), of those that may start
    one of ``frames`` when given."""
    verbs = [v for v in language.verbs if frames is None or frames & set(v.frames)]
    return frozenset(p.split()[0] for verb in verbs for p in verb.phrases)


#: "you'll" said before a verb (the verb kept)
_YOU_LL = re.compile(r"\byou(?:'ll|\s+will)\s+(?=([a-z]+)\b)", re.IGNORECASE)
#: the frames of the verbs a request is said with after "you'll" ("you'll bring me ...", not "you'll find")
_ASKING = frozenset({"BRINGING", "PLACING", "OPERATING", "TAKING"})


def _then_said(text: str, verbs: frozenset[str]) -> str:
    """``text`` with "den" said for "then" before a verb (see the module's docstring)."""
    tokens = text.split()
    for i, token in enumerate(tokens[:-1]):
        word, tail = _split(token)
        before = _split(tokens[i - 1])[0].lower() if i else ""
        after = _split(tokens[i + 1])[0].lower()
        if word.lower() == "den" and not tail and after in verbs and before not in _NOT_AFTER | {"to", "da"}:
            tokens[i] = "then"
    return " ".join(tokens)


def mixed_read(
    text: str,
    marks: Mapping[str, str],
    spanish: Mapping[str, str],
    articles: Mapping[str, str],
    verb_numbers: Mapping[str, str],
    after_articles: Mapping[str, str] | None = None,
) -> str:
    """``text`` with spoken punctuation, Spanish words and numbers said as verbs read as English (see the
    module's docstring): ``mixed_read("Oye, bring me mis espejuelos period", ...)`` is "Oye, bring me my
    glasses."."""
    said_articles = {*articles, *(k for k, v in spanish.items() if v in _ARTICLE_MEANINGS)}
    tokens = text.split()
    longest = max((len(name.split()) for name in marks), default=0)
    out: list[str] = []
    i = 0
    while i < len(tokens):
        said = next(
            (n for n in range(longest, 0, -1) if _mark_of(tokens[i : i + n], marks) is not None),
            0,
        )
        before = _split(out[-1])[0].lower() if out else ""
        if said and before not in _NOT_AFTER:
            mark = _mark_of(tokens[i : i + said], marks) or ""
            if out:
                out[-1] += mark
            i += said
            continue
        word, tail = _split(tokens[i])
        key = plain_typed(word).lower()
        nxt = plain_typed(_split(tokens[i + 1])[0]).lower() if i + 1 < len(tokens) else ""
        previous = plain_typed(_split(tokens[i - 1])[0]).lower() if i else ""
        if key in spanish:
            word = spanish[key]
        elif after_articles and key in after_articles and previous in said_articles:
            word = after_articles[key]
        elif key in articles and not tail and nxt in spanish:
            word = articles[key]
        elif key in verb_numbers and not tail and nxt in _THING_NEXT:
            word = verb_numbers[key]
        out.append(word + tail)
        i += 1
    return " ".join(out)


def _mark_of(words: list[str], marks: Mapping[str, str]) -> str | None:
    """The mark that ``words`` name, with what was typed after the last ("period.": "."), else None."""
    if not words:
        return None
    name, tail = _split(words[-1])
    said = " ".join([*(w.lower() for w in words[:-1]), name.lower()])
    if said not in marks or any(_split(w)[1] for w in words[:-1]):
        return None
    return marks[said] or tail


def _split(token: str) -> tuple[str, str]:
    """A token's word and the punctuation after it ("espejuelos,": "espejuelos", ",")."""
    word = token.rstrip(".,!?;:")
    return word, token[len(word) :]
