"""Chunks of a command: the longest known phrase at each position, from the command language and the world.

A :class:`Chunker` indexes the phrase tables of :mod:`knic.language.commands` (fillers, determiners, joiners,
states, prepositions, verbs, levels, pronouns) and a vocabulary's names. World names are matched whole first;
when no whole name fits, the last word of a longer name ("table" for every table) or a plural ("cups")
stands for all the names it may mean, which the reader narrows down or asks about. Fillers are dropped;
numbers 0..100 said as words become numbers; anything else is an ``unknown`` chunk.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from knic.language.commands import CommandLanguage
from knic.language.typos import Speller
from knic.language.vocabulary import TENS_WORDS, UNIT_WORDS, Term, Vocabulary, english_synonyms, normalize

#: number words to their values (0..19 and the tens), from the vocabulary's one list of number words
_NUMBERS = {w: i for i, w in enumerate(UNIT_WORDS)}
_TENS = {w: 10 * i for i, w in enumerate(TENS_WORDS) if w != "_"}


@dataclass
class Chunk:
    """One piece of a command: ``kind`` is entity, me, pronoun, verb, prep, state, level, number, join, det,
    percent, partitive, vague (a level not said: "a bit"), unsaid (a destination not said: "away"), quant
    (role: "all" or "both"), everything, repair (the speaker corrects what came before: "no wait"), owner
    (a person said as whose a thing is: "tracy's mug") or unknown."""

    kind: str
    text: str
    terms: tuple[Term, ...] = ()
    role: str = ""  # prep: its role table name; pronoun: the referent type; entity: "plural" ("lamps")
    frames: tuple[str, ...] = ()  # verb: frame kinds it may start
    state: str | None = None  # verb: implied state; state: the state; prep "on"/"off": also a state
    value: int | None = None  # level, number: percent
    beneficiary: str | None = None  # verb: who it is for when unsaid ("i need ...": "me")
    soft: bool = False  # verb said as "-ing" ("getting"): its clause may be talk ("it's getting late")


def singulars(word: str) -> list[str]:
    """The singular of a plural word beyond a dropped "s" ("lollies": lolly, "shelves": shelf, "boxes": box,
    "mangoes": mango); none for a word ending in "sses" ("glasses" may be a pair)."""
    if word.endswith("ies") and len(word) > 4:
        return [word[:-3] + "y"]
    if word.endswith("lves"):
        return [word[:-3] + "f"]
    if word.endswith(("xes", "ches", "shes", "oes")):
        return [word[:-2]]
    return []


def _plural_endings(word: str) -> tuple[str, ...]:
    """What makes a name's last word plural: "es" after a hiss ("boxes"), "s" or "es" after an "o"
    ("radios", "potatoes"), else "s"; no "draweres", whose nearness to typos would hide "drawers"."""
    endings: tuple[str, ...] = ("es",) if word.endswith(("x", "z", "ch", "sh")) else ("s",)
    return endings + (("es",) if word.endswith("o") else ())


def _forms(word: str) -> tuple[str, ...]:
    """A name's last word and its singulars ("shelves": shelves, shelve, shelf)."""
    plural = word.endswith("s") and not word.endswith("ss")
    return (word, *([word[:-1], *singulars(word)] if plural else ()))


def _own_ends(phrase: str) -> tuple[str, ...]:
    """The forms of a name's last word, and its last two words when it has three or more."""
    return (*_forms(phrase.split()[-1]), *([" ".join(phrase.split()[-2:])] if phrase.count(" ") > 1 else []))


def past_determiners(chunks: Sequence[Chunk], at: int) -> int:
    """The index of the first chunk from ``at`` that is no determiner (``len(chunks)`` when none is)."""
    while at < len(chunks) and chunks[at].kind == "det":
        at += 1
    return at


class Chunker:
    """Cuts normalised token lists into chunks (build once per vocabulary; :meth:`chunks` is pure)."""

    def __init__(self, vocabulary: Vocabulary, language: CommandLanguage):
        self.language = language
        lang = language
        self._full: dict[str, list[Term]] = {}
        self._partial: dict[str, list[Term]] = {}
        #: the things a name of another thing would also name by its last word ("desk": the writing desk)
        self._shadowed: dict[str, list[Term]] = {}
        for term in vocabulary.terms:
            if term.type == "level":
                continue
            self._full.setdefault(term.phrase, []).append(term)
        # a name only given (a synonym, a shorter name) that is the last word of another thing's own name
        # is a last word like it: "the chair" is the wicker chair or the gaming chair, not (by "armchair")
        # the armchair alone
        own_last: dict[str, set[str]] = {}
        for t in vocabulary.terms:
            if not t.given and len(t.phrase.split()) > 1:
                for form in _own_ends(t.phrase):  # "lounge light": the annexe lounge light's own end
                    own_last.setdefault(form, set()).add(t.symbol)
        given = {
            p: ts
            for p, ts in self._full.items()
            if all(t.given for t in ts) and own_last.get(p, set()) - {t.symbol for t in ts}
        }
        for phrase in given:
            del self._full[phrase]
            self._partial[phrase] = list(given[phrase])
        for term in vocabulary.terms:
            words = term.phrase.split()
            if term.type == "level" or term.is_group:
                continue
            # plurals of a name, and the singular of a plural name ("a car key" for the car keys, "an ice
            # lolly" for the ice lollies, "the curtain" for the bedroom curtains)
            plural = term.phrase.endswith("s") and not term.phrase.endswith("ss")
            endings = _plural_endings(term.phrase)
            variants = [term.phrase[:-1]] if plural else [term.phrase + e for e in endings]
            variants += [" ".join([*words[:-1], one]) for one in singulars(words[-1])]
            if len(words) > 1:  # "the lamp", and "the desk lamp" for the office desk lamp (not "bedroom
                # light" for the left bedroom light: a name before the last word narrows it as said)
                end = " ".join(words[-2:])  # kept beside a synonym it is the end of ("lounge light")
                ending = [end] if len(words) > 2 and (words[-2] not in self._full or end in given) else []
                variants += [words[-1], *ending]
                plural_last = words[-1].endswith("s") and not words[-1].endswith("ss")
                last_endings = _plural_endings(words[-1])  # "lunchboxes" for the lunchboxes of two people
                variants += (
                    [words[-1][:-1], *singulars(words[-1])]
                    if plural_last
                    else [words[-1] + e for e in last_endings]
                )
            for variant in variants:
                if variant not in self._full:
                    self._partial.setdefault(variant, []).append(term)
                elif term not in self._full[variant]:  # "desk" said of the writing desk where a desk is too
                    self._shadowed.setdefault(variant, []).append(term)
        # a one-word compound name ends in what it is ("armchair": a chair, as a "wicker chair" is)
        compounds = {t.symbol: t.phrase for t in vocabulary.terms if not t.given and " " not in t.phrase}
        for variant, terms in self._partial.items():  # "the table": the dining table, not a "bedside table"
            own = {t.symbol for t in terms if not t.given and variant in _own_ends(t.phrase)}
            own |= {t.symbol for t in terms if own and compounds.get(t.symbol, " ").endswith(variant)}
            if own and any(t.symbol not in own for t in terms):
                self._partial[variant] = [t for t in terms if t.symbol in own]
        named: dict[str, Term] = {}  # one term per single thing, for the nouns of its type
        for term in vocabulary.terms:
            if term.type != "level" and not term.is_group:
                named.setdefault(term.symbol, term)
        for type_name, nouns in lang.type_nouns.items():
            things = [t for t in named.values() if vocabulary.is_subtype(t.type, type_name)]
            things = _told_apart(nouns[0], things, vocabulary) if things else things
            for rank, noun in enumerate(nouns if things else ()):
                for variant in (noun, noun if noun.endswith("s") else noun + "s"):
                    if variant in self._full or (rank and variant in self._partial):
                        continue
                    # the type's own word is any of its things: "the light" is also the "desk lamp" beside
                    # the "garage light"; the others ("lamp") are the things named so, where some are
                    known = self._partial.setdefault(variant, [])
                    known += [t for t in things if t.symbol not in {k.symbol for k in known}]
        #: plurals of a name's last word ("lamps" for the left and the right lamp): all of them are meant
        self._plural = {
            p
            for p, ts in self._partial.items()
            if any(p in (t.phrase.split()[-1] + e for e in _plural_endings(t.phrase)) for t in ts)
        }
        table: dict[str, tuple[int, Chunk | None]] = {}  # phrase -> (priority, chunk); None drops it

        def put(phrase: str, priority: int, chunk: Chunk | None) -> None:
            if phrase and (phrase not in table or table[phrase][0] < priority):
                table[phrase] = (priority, chunk)

        for phrase in (*lang.fillers, *lang.anywhere):  # "search the house for ...": anywhere
            put(phrase, 1, None)
        for phrase in lang.determiners:
            put(phrase, 2, Chunk("det", phrase))
        for phrase in lang.joiners:
            put(phrase, 3, Chunk("join", phrase))
        for phrase in lang.partitive:
            put(phrase, 3, Chunk("partitive", phrase))
        for phrase in lang.percent:
            put(normalize(phrase) or phrase, 3, Chunk("percent", phrase))
        for kind, phrases in (
            ("there", lang.there),
            ("vague", lang.vague_levels),
            ("unsaid", lang.unsaid_goal),
            ("everything", lang.everything),
            ("repair", lang.repairs),
        ):
            for phrase in phrases:
                put(phrase, 3, Chunk(kind, phrase))
        for quantity, phrases in lang.quantifiers.items():
            for phrase in phrases:
                put(phrase, 3, Chunk("quant", phrase, role=quantity))
        for state, phrases in lang.states.items():
            for phrase in phrases:
                put(phrase, 4, Chunk("state", phrase, state=state))
        for role, phrases in lang.prepositions.items():
            for phrase in phrases:
                old = table.get(phrase)
                implied = old[1].state if old and old[1] is not None and old[1].kind == "state" else None
                if role == "level" and old and old[1] is not None and old[1].kind == "prep":
                    continue
                put(phrase, 5, Chunk("prep", phrase, role=role, state=implied))
        for_whom = lang.verb_beneficiaries()
        for phrase, (kinds, verb_state) in lang.verb_frames().items():
            put(
                phrase,
                6,
                Chunk("verb", phrase, frames=kinds, state=verb_state, beneficiary=for_whom.get(phrase)),
            )
        for percent, phrases in lang.levels.items():
            for phrase in phrases:
                put(phrase, 7, Chunk("level", phrase, value=percent))
        for phrase in lang.here:
            put(phrase, 3, Chunk("me", phrase, role="here"))
        for phrase, kind in lang.pronouns.items():
            put(phrase, 8, Chunk("pronoun", phrase, role=kind))
        put("me", 8, Chunk("me", "me"))
        put("us", 8, Chunk("me", "us"))  # "grab us the remote", "take us to the kitchen": the speaker
        self._table = table
        #: the words of the command language's phrases (verbs, fillers, determiners, ...)
        self.language_words = frozenset(w for p in table for w in p.split())
        #: verbs only when they open the command ("is the remote in the living room?")
        self._opening = {
            phrase: Chunk("verb", phrase, frames=v.frames, state=v.state, beneficiary=v.beneficiary)
            for phrase, v in lang.opening_verbs().items()
        }
        #: first words of verb phrases, for "-ing" forms ("would you mind getting me ...": get)
        self._verb_heads = {p.split()[0] for v in lang.verbs for p in v.phrases}
        #: "-ed" forms of the verbs whose past is not so ("bringed", "taked", "putted"): no English word, so
        #: the verb wherever said (a learner's past, read as the command)
        irregular = {v for v in lang.past_forms.values() if v in self._verb_heads}
        self._overregular = {
            form: verb
            for verb in irregular
            for form in ((verb + "d",) if verb.endswith("e") else (verb + "ed", verb + verb[-1] + "ed"))
            if form not in lang.past_forms
        }
        #: verb phrases ending with "if" ("check if"): what follows "if you" there is asked about, not wished
        self._asking_if = [p.split() for v in lang.verbs for p in v.phrases if p.split()[-1] == "if"]
        self._known_words = {
            w for p in list(table) + list(self._full) + list(self._partial) for w in p.split()
        }
        #: the verb a command of noun phrases only is read with ("the remote please": "i want the remote")
        self.bare_verb: Chunk | None = None
        bare = next((v for v in lang.verbs if v.name == lang.bare_request), None)
        if bare is not None:
            self.bare_verb = Chunk(
                "verb", bare.phrases[0], frames=bare.frames, state=bare.state, beneficiary=bare.beneficiary
            )
        self._longest = max((len(p.split()) for p in list(table) + list(self._full)), default=1)
        #: first words of the world's names and of the determiners: after "jack's" they make it a possessive
        self._noun_heads = {p.split()[0] for p in list(self._full) + list(self._partial)} | set(
            lang.determiners
        )
        self._people = {
            p for p, ts in self._full.items() if all(vocabulary.is_subtype(t.type, "person") for t in ts)
        }
        self._pronoun_words = {w for p in lang.pronouns for w in p.split()}
        #: names, and last words of names, on their own ("kitchen", "tv stand", "table")
        self._known_names = set(self._full) | set(self._partial)
        #: typed and mis-heard words mended before chunking (knic.language.typos)
        self._speller = Speller(
            self._known_words,
            {w for p in self._known_names for w in p.split()},
            set(self._full),
            self._kind_of,
            {p.split()[0] for p in self._people},
            lang.homophones,
        )

    # ------------------------------------------------------------------ chunks

    def also_named(self, phrase: str) -> tuple[Term, ...]:
        """The things ``phrase`` names by the last word of their own names where it is the whole name of
        another ("desk" said of the writing desk, where the box room has a desk)."""
        return tuple(self._shadowed.get(phrase, ()))

    def chunks(self, tokens: Sequence[str]) -> list[Chunk]:
        """The chunks of a normalised token list (fillers dropped)."""
        tokens = self._sides(self._apostrophes(self._speller.mended(tokens)))
        said = tokens
        lemmas = [self._lemma(t) for t in tokens]
        inflected = {i for i, (word, lemma) in enumerate(zip(tokens, lemmas, strict=True)) if word != lemma}
        tokens = [self._present(lemmas, i) for i in range(len(lemmas))]
        out: list[Chunk] = []
        i = 0
        while i < len(tokens):
            number = _number(tokens, i)
            best: tuple[int, int, Chunk | None] | None = None  # (length, priority, chunk)
            for length in range(min(self._longest, len(tokens) - i), 0, -1):
                phrase = " ".join(tokens[i : i + length])
                if phrase in self._full:
                    best = (length, 10, Chunk("entity", phrase, tuple(self._full[phrase])))
                elif phrase in self._table and (best is None or best[0] < length):
                    priority, chunk = self._table[phrase]
                    best = (length, priority, chunk)
                elif phrase in self._partial and best is None:
                    plural = "plural" if phrase in self._plural else ""
                    best = (length, 9, Chunk("entity", phrase, tuple(self._partial[phrase]), role=plural))
                if best is not None and best[0] == length:
                    break
            opening = self._opening_at(tokens, i) if not out else None
            if opening is not None and best is not None and best[2] is None:
                # a filler, then a longer verb ("can you see to it that ..." is no "can you see ...")
                after = i + best[0]
                verb = self._longest_verb_at(tokens, after)
                if verb and after + verb > i + len(opening.text.split()):
                    opening = None
            if opening is not None and (best is None or len(opening.text.split()) >= best[0]):
                out.append(opening)  # "is the remote in the living room?"
                i += len(opening.text.split())
                continue
            if number is not None and (best is None or number[0] - i >= best[0]):
                value = number[1]
                if best is not None and best[2] is not None and best[2].kind == "det" and number[0] - i == 1:
                    nxt = tokens[number[0]] if number[0] < len(tokens) else ""
                    if nxt not in self.language.percent and nxt != "percent":
                        out.append(best[2])
                        i += 1
                        continue
                out.append(Chunk("number", " ".join(tokens[i : number[0]]), value=value))
                i = number[0]
                continue
            if best is None:
                guessed = self._guessed(tokens[i]) if out and out[-1].kind == "det" else ()
                out.append(Chunk("entity", tokens[i], guessed) if guessed else Chunk("unknown", tokens[i]))
                i += 1
                continue
            if best[2] is not None and best[2].kind == "verb" and _owned_noun(out, said[i - 1] if i else ""):
                # "my walking stick", "the walking frame": a verb's word after "my"/"the" names a thing, the
                # one whose name ends in it, if any ("my stick": the walking stick)
                phrase = " ".join(tokens[i : i + best[0]])
                ends = self._partial.get(phrase)
                noun = Chunk("unknown", " ".join(said[i : i + best[0]]), role=_NOUN)
                out.append(Chunk("entity", phrase, tuple(ends)) if ends else noun)
            elif best[2] is not None:
                soft = best[2].kind == "verb" and i in inflected
                out.append(replace(best[2], soft=True) if soft else best[2])
            i += best[0]
        out = self._headed(out)
        return _owned(out) if _OWNER in tokens else out

    def _headed(self, chunks: list[Chunk]) -> list[Chunk]:
        """The chunks without a thing said by a shorter name right before another thing said by its whole
        name: the last noun of two is what is meant ("pick up mill alarm clock", heard for "the alarm
        clock": not the pepper mill too). A room or a person so said is kept (it narrows or owns the next)."""
        kept: list[Chunk] = []
        for at, chunk in enumerate(chunks):
            after = chunks[at + 1] if at + 1 < len(chunks) else None
            if (
                after is not None
                and chunk.kind == after.kind == "entity"
                and chunk.terms
                and chunk.text not in self._full
                and after.text in self._full
                and not {t.symbol for t in chunk.terms} & {t.symbol for t in after.terms}
                and all(t.type not in ("room", "person") for t in chunk.terms)
            ):
                continue
            kept.append(chunk)
        return kept

    def _kind_of(self, phrase: str) -> str | None:
        """A phrase's kind in the language tables ("state" for a word that also says a state), else None."""
        entry = self._table.get(phrase)
        if entry is None or entry[1] is None:
            return None
        return "state" if entry[1].state and entry[1].kind in ("state", "prep") else entry[1].kind

    def _guessed(self, word: str) -> tuple[Term, ...]:
        """Every thing a mistyped word after a determiner may name, when it is near several names ("the
        cug": the cup or the mug), else nothing."""
        found = [
            t for w in self._speller.names_for(word) for t in self._full.get(w, self._partial.get(w, []))
        ]
        return tuple(dict.fromkeys(found))  # one thing said two ways ("mugg": mug or mugs) is that thing

    def _apostrophes(self, tokens: Sequence[str]) -> list[str]:
        """Read "'s" after a word the tables do not know as it is: "is" ("the tablet's on the bed", "jack's
        hungry"), or a possessive before a name or a determiner ("tracy's mug": the mug; a person who owns
        it is dropped, "the kitchen's light" stays "kitchen light"). Pronouns and "there", "here", "what"
        ("it's", "there's") are left as said."""
        out: list[str] = []
        for i, token in enumerate(tokens):
            base = token[:-2]
            if (
                not token.endswith("'s")
                or not base
                or token in self._known_words
                or base in self._pronoun_words
                or base in _KEPT_CONTRACTIONS
            ):
                out.append(token)
            elif i + 1 < len(tokens) and (tokens[i + 1] in self._noun_heads or self._whose(out, base)):
                owner = next(  # the words of a person's name ending here ("granny annie's")
                    (
                        n
                        for n in range(min(len(out), 2), -1, -1)
                        if " ".join([*out[len(out) - n :], base]) in self._people
                    ),
                    None,
                )
                out.append(base)
                if owner is not None:
                    out.append(_OWNER)  # "annie's glasses": the glasses; annie is said, for "her"
            else:
                out += [base, "is"]
        return out

    def _whose(self, before: list[str], name: str) -> bool:
        """Whether a person's name with "'s", said right after a verb, a preposition or "me", owns what
        follows ("fetch grandma's medicine": the medicine, which the world may lack) rather than being said
        to be something ("jack's hungry")."""
        if name not in self._people or not before:
            return False
        entry = self._table.get(before[-1])
        said = entry[1] if entry is not None else None
        return before[-1] == "me" or (said is not None and said.kind in ("verb", "prep"))

    def _sides(self, tokens: list[str]) -> list[str]:
        """A thing told from the others by where it is, said after it ("the light on the right", "the table
        on the side") where the world names it with that word first ("right light", "side table"): read as
        that name. A place ("the mug on the left of the sofa") or a word that is itself a name stays."""
        for i in range(1, len(tokens) - 2):
            side = tokens[i + 2]
            if tokens[i : i + 2] != ["on", "the"] or any(
                " ".join(tokens[i + 2 : i + 2 + n]) in self._known_names for n in range(1, 4)
            ):
                continue
            end = i + 3  # past "on the right", and "hand side" or "side" after it
            end += next((len(w) for w in _SIDE_WORDS if tokens[end : end + len(w)] == w), 0)
            if end < len(tokens) and tokens[end] == "of":
                continue
            for length in range(min(3, i), 0, -1):
                if " ".join([side, *tokens[i - length : i]]) in self._full:
                    return [*tokens[: i - length], side, *tokens[i - length : i], *tokens[end:]]
        return tokens

    def _longest_verb_at(self, tokens: Sequence[str], i: int) -> int:
        """The length of the longest verb phrase at ``tokens[i:]`` (0: none)."""
        for length in range(min(self._longest, len(tokens) - i), 0, -1):
            entry = self._table.get(" ".join(tokens[i : i + length]))
            if entry is not None and entry[1] is not None and entry[1].kind == "verb":
                return length
        return 0

    def _opening_at(self, tokens: Sequence[str], i: int) -> Chunk | None:
        """The longest opening verb at ``tokens[i:]``, else None."""
        for length in range(min(4, len(tokens) - i), 0, -1):
            chunk = self._opening.get(" ".join(tokens[i : i + length]))
            if chunk is not None:
                return chunk
        return None

    def _present(self, words: Sequence[str], i: int) -> str:
        """A verb said in the past in a polite wish as the verb ("i'd be grateful if you brought me ...":
        bring; :attr:`CommandLanguage.past_forms`, or a regular "-ed" form), after "if you" but not after a
        verb that asks ("check if you left the light on" stays); any other word as it is."""
        word = words[i]
        if word in self._overregular:  # "robot, bringed me the apple": a learner's past of bring, anywhere
            return self._overregular[word]
        if i < 2 or list(words[i - 2 : i]) != ["if", "you"]:
            return word
        if any(list(words[max(0, i - 1 - len(p)) : i - 1]) == p for p in self._asking_if):
            return word
        if word in self.language.past_forms:
            return self.language.past_forms[word]
        doubled = word[:-3] if len(word) > 4 and word[-3] == word[-4] else ""  # "dropped": drop
        for candidate in (word[:-2], word[:-1], doubled) if word.endswith("ed") else ():
            if candidate in self._verb_heads:
                return candidate
        return word

    def _lemma(self, word: str) -> str:
        """A verb's "-ing" form as the verb ("switching": switch, "getting": get, "closing": close), when the
        word is no phrase of the language or the world; any other word as it is."""
        if not word.endswith("ing") or len(word) < 5 or word in self._known_words:
            return word
        stem = word[:-3]
        for candidate in (stem, stem + "e", stem[:-1] if len(stem) > 2 and stem[-1] == stem[-2] else ""):
            if candidate in self._verb_heads:
                return candidate
        return word


#: what may follow "on the left" before "of" makes it a place beside another ("on the left hand side of")
_SIDE_WORDS = (["hand", "side"], ["side"])
#: the token after a person's name said as an owner ("tracy's mug"): the name becomes an ``owner`` chunk
_OWNER = "'s"
#: words whose "'s" is read as the tables and the reader already read it ("there's a mug on the table")
_KEPT_CONTRACTIONS = frozenset({"there", "here", "what", "who", "where", "that", "let", "how"})


#: the determiners after which a verb's word is a noun ("my walking stick"; not "a": "have a look")
_NOUN_DETERMINERS = frozenset({"my", "your", "our", "their", "the"})
#: the role of an unknown chunk that was a verb's word read as a noun
_NOUN = "noun"


def _told_apart(noun: str, things: list[Term], vocabulary: Vocabulary) -> list[Term]:
    """The things a type's own word names: all of them, unless some are called by it and others only by a
    synonym of it ("office blinds" and "bedroom curtains": the world tells them apart by that word, so "the
    blinds" are the office's)."""
    others = {w for group in english_synonyms() if noun in group for w in group if w != noun}
    ends: dict[str, set[str]] = {}
    for term in vocabulary.terms:
        ends.setdefault(term.symbol, set()).add(term.phrase.split()[-1])
    if not others or not any(noun in ends.get(t.symbol, ()) for t in things):
        return things
    return [t for t in things if not ends.get(t.symbol, set()) <= others]


def _owned_noun(out: list[Chunk], before: str) -> bool:
    """Whether a verb's word said next is a noun: it follows "my", "your", "our", "their" or "the" said just
    before it (``before``, the word said before; "the robot heads to" has a dropped word between), or such a
    word read as a noun ("my walking stick"), or the possessive "'s" ("gopal's stick")."""
    last = out[-1] if out else None
    if last is None or before != last.text.split()[-1]:
        return False
    return (last.kind == "det" and last.text in _NOUN_DETERMINERS) or (
        last.kind == "unknown" and (last.role == _NOUN or last.text == _OWNER)
    )


def _owned(chunks: list[Chunk]) -> list[Chunk]:
    """Mark the people said as owners ("tracy's mug"): the person before the owner mark becomes an
    ``owner`` chunk, which is no argument of the action but is there for a later "her" or "him"."""
    out: list[Chunk] = []
    for chunk in chunks:
        if chunk.kind == "unknown" and chunk.text == _OWNER:
            if out and out[-1].kind == "entity":
                out[-1] = replace(out[-1], kind="owner")
            continue
        out.append(chunk)
    return out


def _number(tokens: Sequence[str], i: int) -> tuple[int, int] | None:
    """A spoken number 0..100 at ``tokens[i:]``: (end index, value), else None."""
    word = tokens[i]
    if word in ("hundred",) or (word in ("a", "one") and i + 1 < len(tokens) and tokens[i + 1] == "hundred"):
        return (i + 1 if word == "hundred" else i + 2), 100
    if word in _TENS:
        value = _TENS[word]
        if i + 1 < len(tokens) and tokens[i + 1] in _NUMBERS and 0 < _NUMBERS[tokens[i + 1]] < 10:
            return i + 2, value + _NUMBERS[tokens[i + 1]]
        return i + 1, value
    if word in _NUMBERS:
        return i + 1, _NUMBERS[word]
    return None
