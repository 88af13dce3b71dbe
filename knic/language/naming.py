"""Names said around their words, put as the world's names before a command is chunked (used by
:mod:`knic.language.reader`):

* a thing said with "of", "for" or "under" before another word ("the blind of the skylight", "a glass of
  water", "the lead for the dog", "the cupboard under the stairs") is the world's name that puts those words
  the other way round ("skylight blind", "water glass", "dog lead", "under stairs cupboard"), where the world
  has such a name; a container the world has no name for, said of what it holds ("a can of coke"), is what
  it holds, so that a refusal names the drink;
* a room named after a person ("rhys_bedroom") is that person's room: "rhys's room", "rhys's bedroom", and
  "his room" or "her bedroom" once the person was named ("find rhys, he'll be in his bedroom");
* a person's first name alone ("mary" for mary_ann) is that person where it begins one person's name; where
  it begins several ("mary ann", "mary beth"), the reader asks which;
* "could rosa have the book" (or "can" or "may", "get" for "have") asks for it for rosa: "rosa would like the
  book";
* of the devices a place narrows a word to ("the light in the attic"), those whose own name ends in that word
  (the attic light, not the attic desk lamp, which is a light only by its kind), where some are
  (:func:`called_so`);
* "there" said of a device ("put the blanket on the sofa and switch the lamp on in there") is the room of the
  place named last, not the piece of furniture (:func:`places_before`).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Sequence
from functools import lru_cache

from core.errors import LanguageError
from knic.language.asides import spoken_to
from knic.language.chains import AmbiguityError
from knic.language.chunks import Chunk
from knic.language.clauses import Arg
from knic.language.frames import CommandFrame
from knic.language.goals import room_of
from knic.language.regional import regional_said
from knic.language.shortnames import containers, contains, english_opposites
from knic.language.signorder import signed_read
from knic.language.vocabulary import Term, Vocabulary, english_synonyms

#: words said between a thing's name and the word its name starts with, and what the name keeps of them
_AROUND = {"of": (), "for": (), "under": ("under",)}
_ARTICLES = ("the", "a", "an")
_OWN = ("his", "her", "their")
#: what holds a helping of a drink or food, beside the containers of ``synonyms.yaml``
_HELPINGS = frozenset({"glass", "cup", "mug", "bowl", "pint", "bag", "slice", "piece"})
#: what a person's room is called after "rhys's", beside the last word of the room's own name
_ROOM_NOUNS = ("room", "bedroom")


def said_named(segments: list[list[str]], vocabulary: Vocabulary, known: Collection[str]) -> list[list[str]]:
    """The sentences with the names of the module docstring put as the world says them; ``known`` are the
    words of the command language, which are never a first name.

    Raises:
        AmbiguityError: a first name begins several people's names.
    """
    segments = spoken_to(segments, vocabulary)  # "Ese, have you seen it? ...", "why is X off?" (asides.py)
    segments = regional_said(segments, vocabulary)  # "fetch us t'atlas", "where's me stick" (regional.py)
    phrases, people, _ = _names(vocabulary)
    for segment in segments:
        _opposite_refused(segment, phrases)
    canon, told = _canonical_names(vocabulary), _told_by_first_word(vocabulary)
    segments = [_one_said(s, phrases, told, known) for s in segments]
    out = [
        _synonyms_said(_contents(_turned_round(s, phrases, canon), phrases), phrases, canon) for s in segments
    ]
    out = [_asked_for(_first_names(s, people, phrases, known), people) for s in out]
    return signed_read(
        _persons_rooms(out, _owned_rooms(vocabulary)), vocabulary
    )  # "freezer take" (signorder.py)


@lru_cache(maxsize=16)
def _names(vocabulary: Vocabulary) -> tuple[frozenset[str], list[list[str]], list[list[str]]]:
    """The world's phrases, and the words of its people's and its rooms' names (read once per vocabulary)."""
    phrases = frozenset(t.phrase for t in vocabulary.terms if t.type != "level")
    people = [t.phrase.split() for t in vocabulary.terms if vocabulary.is_subtype(t.type, "person")]
    rooms = [t.phrase.split() for t in vocabulary.terms if vocabulary.is_subtype(t.type, "room")]
    return phrases, people, rooms


def _opposite_refused(words: list[str], phrases: Collection[str]) -> None:
    """Refuse a name said with the other word of an opposite pair ("the back door" where the world has a
    front door and no back door; "the left lamp" where it has only a right lamp): it names nothing here, not
    the thing the world has (``synonyms.yaml`` opposites).

    Raises:
        LanguageError: the name said, where the world has only its opposite.
    """
    opposite = english_opposites()
    for i, word in enumerate(words):
        others = opposite.get(word, frozenset())
        for n in (2, 1) if others else ():
            rest = words[i + 1 : i + 1 + n]
            tail, said = " ".join(rest), " ".join(words[i : i + 1 + n])
            if len(rest) < n or tail in phrases or any(p == said or p.endswith(" " + said) for p in phrases):
                continue
            if any(p.endswith(" " + tail) and p.split()[-n - 1] in others for p in phrases):
                raise LanguageError(f"there is no '{said}' here: this world has nothing called that")


def _canonical(words: Sequence[str]) -> str:
    """A name with each synonym (``synonyms.yaml``) said as the first word of its set ("telly clicker": "tv
    remote")."""
    sets = _synonym_sets()
    out: list[str] = []
    i = 0
    while i < len(words):
        starting = sets.get(words[i], ())
        found = next(((m, first) for m, first in starting if list(words[i : i + len(m)]) == m), None)
        out += found[1] if found else [words[i]]
        i += len(found[0]) if found else 1
    return " ".join(out)


@lru_cache(maxsize=1)
def _synonym_sets() -> dict[str, tuple[tuple[list[str], list[str]], ...]]:
    """A synonym's first word -> (the synonym's words, the first of its set's words), the longest synonyms
    first."""
    pairs = [(m.split(), group[0].split()) for group in english_synonyms() for m in group]
    by_first: dict[str, list[tuple[list[str], list[str]]]] = {}
    for pair in sorted(pairs, key=lambda pair: -len(pair[0])):
        if pair[0]:
            by_first.setdefault(pair[0][0], []).append(pair)
    return {first: tuple(found) for first, found in by_first.items()}


@lru_cache(maxsize=16)
def _canonical_names(vocabulary: Vocabulary) -> dict[str, str]:
    """A name said with synonyms (:func:`_canonical`) -> the world's name, where it names one thing."""
    longer = [t for t in vocabulary.terms if t.type != "level" and len(t.phrase.split()) > 1]
    return _naming_one((_canonical(t.phrase.split()), t) for t in longer)


@lru_cache(maxsize=16)
def _told_by_first_word(vocabulary: Vocabulary) -> dict[str, str]:
    """The first word of the longer names of the world's things (items) -> the name, where the word (or a
    synonym of it) starts the names of one thing only ("spotty": the spotty mug; "telly": the tv remote; not
    "kitchen", which starts several)."""
    items = [
        t
        for t in vocabulary.terms
        if len(t.phrase.split()) > 1 and not t.given and vocabulary.is_subtype(t.type, "item")
    ]
    return _naming_one((_canonical(t.phrase.split()[:1]), t) for t in items)  # "telly" for a "tv remote" too


def _naming_one(said: Iterable[tuple[str, Term]]) -> dict[str, str]:
    """Of (words said, a term they stand for): the words -> the term's name, where they stand for one thing
    only (the first name given of it)."""
    symbols: dict[str, set[str]] = {}
    named: dict[str, str] = {}
    for words, term in said:
        symbols.setdefault(words, set()).add(term.symbol)
        named.setdefault(words, term.phrase)
    return {words: named[words] for words, found in symbols.items() if len(found) == 1}


def _one_said(
    words: list[str], phrases: Collection[str], told: dict[str, str], known: Collection[str]
) -> list[str]:
    """ "bring me the spotty one", "the thing for the telly": a word that starts the name of one thing only
    (or a synonym of it), said before "one" or "thing" or after "thing for", is that thing ("the spotty mug",
    "the tv remote"); a word of the command language or a name of its own stays as said."""
    out = list(words)
    for i in range(len(out) - 1, 0, -1):
        word = out[i - 1]
        name = told.get(_canonical([word])) if word not in phrases and word not in known else None
        if out[i] in ("one", "thing") and name:
            out[i - 1 : i + 1] = name.split()
    for i in range(len(out) - 2):
        at = i + 2 + (out[i + 2] in _ARTICLES and i + 3 < len(out))
        word = out[at] if at < len(out) else ""
        name = told.get(_canonical([word])) if word not in phrases and word not in known else None
        if out[i : i + 2] == ["thing", "for"] and name:
            out[i : at + 1] = name.split()
            break
    return out


def _synonyms_said(words: list[str], phrases: Collection[str], canon: dict[str, str]) -> list[str]:
    """ "the telly clicker" -> "the tv remote": a name said with more than one synonym of its words, which
    the names the synonyms give (one word replaced at a time) do not reach."""
    out = list(words)
    i = 0
    while i < len(out):
        for n in (4, 3, 2):
            span = out[i : i + n]
            said = " ".join(span)
            name = canon.get(_canonical(span)) if len(span) == n and said not in phrases else None
            if name is not None and name != said:
                out[i : i + n] = name.split()
                break
        i += 1
    return out


def _turned_round(words: list[str], phrases: Collection[str], canon: dict[str, str]) -> list[str]:
    """ "the blind of the skylight" -> "the skylight blind", "the shelf for books" -> "the bookshelf", where
    that is a name (or one said with synonyms: "the clicker for the telly", the tv remote) and the words said
    are none."""
    out = list(words)
    for i in range(len(out) - 2, 0, -1):
        kept = _AROUND.get(out[i])
        if kept is None:
            continue
        after = i + 1 + (out[i + 1] in _ARTICLES)
        for n in range(min(3, i), 0, -1):
            head = out[i - n : i]
            if any(w in _ARTICLES for w in head):
                continue
            found = next(
                (
                    (m, name)
                    for m in range(min(3, len(out) - after), 0, -1)
                    if " ".join(out[i - n : after + m]) not in phrases
                    and not _named_on(out[after:], m, phrases, canon)
                    for said in _the_other_way(list(kept), out[after : after + m], head)
                    if (name := said if said in phrases else canon.get(_canonical(said.split()), ""))
                ),
                None,
            )
            if found:
                out[i - n : after + found[0]] = found[1].split()
                break
    return out


def _named_on(words: list[str], m: int, phrases: Collection[str], canon: dict[str, str]) -> bool:
    """Whether the first ``m`` words begin a longer name said on ("the tv bench for the tv clicker": "tv" is
    the start of "tv clicker", so "bench for the tv" is no "tv bench")."""
    longer = (" ".join(words[:k]) for k in range(m + 1, min(4, len(words)) + 1))
    return any(said in phrases or _canonical(said.split()) in canon for said in longer)


def _the_other_way(kept: list[str], other: list[str], head: list[str]) -> list[str]:
    """The names "head <kept> other" may be said the other way round as: "skylight blind", "under stairs
    cupboard", and with the other word singular ("book shelf") or joined to the head ("bookshelf")."""
    singular = (
        [*other[:-1], other[-1][:-1]] if other[-1].endswith("s") and not other[-1].endswith("ss") else []
    )
    names = [" ".join([*kept, *other, *head]), *([" ".join([*kept, *singular, *head])] if singular else [])]
    if not kept and len(head) == 1:
        names += ["".join([*words, *head]) for words in (other, singular) if len(words) == 1]
    return names


def _contents(words: list[str], phrases: Collection[str]) -> list[str]:
    """ "a can of coke" -> "a coke" where the world has no "can"."""
    held = containers() | _HELPINGS
    return [
        w
        for i, w in enumerate(words)
        if not (w in held and w not in phrases and words[i + 1 : i + 2] == ["of"])
        and not (w == "of" and i and words[i - 1] in held and words[i - 1] not in phrases)
    ]


def _asked_for(words: list[str], people: list[list[str]]) -> list[str]:
    """ "could rosa have the book" -> "rosa would like the book"."""
    if not words or words[0] not in ("can", "could", "may"):
        return words
    for person in people:
        end = 1 + len(person)
        if words[1:end] == person and words[end : end + 1] in (["have"], ["get"]):
            return [*person, "would", "like", *words[end + 1 :]]
    return words


def _first_names(
    words: list[str], people: list[list[str]], phrases: Collection[str], known: Collection[str]
) -> list[str]:
    """A first name alone as the one person's whole name; a question where it begins several."""
    out: list[str] = []
    for i, word in enumerate(words):
        bare = word[:-2] if word.endswith("'s") else word
        named = [p for p in people if len(p) > 1 and p[0] == bare]
        whole = any(
            words[i : i + len(p) - 1] == p[:-1]
            and words[i + len(p) - 1 : i + len(p)] in ([p[-1]], [p[-1] + "'s"])
            for p in named
        )
        if not named or whole or bare in phrases or bare in known:
            out.append(word)
            continue
        if len(named) > 1:
            options = [" ".join(p) for p in named]
            raise AmbiguityError(f"which {bare} do you mean: {', '.join(options[:-1])} or {options[-1]}?")
        out += [*named[0][:-1], named[0][-1] + word[len(bare) :]]
    return out


@lru_cache(maxsize=16)
def _owned_rooms(vocabulary: Vocabulary) -> dict[str, list[str]]:
    """Each person's name and the words of the room named after them ("rhys": "rhys's room")."""
    _, people, rooms = _names(vocabulary)
    return {" ".join(p): r for p in people for r in rooms if len(r) > len(p) and contains(r, p)}


def _persons_rooms(segments: list[list[str]], owned: dict[str, list[str]]) -> list[list[str]]:
    """ "rhys's room" and, once rhys was named, "his bedroom" as the room named after him (``owned``:
    :func:`_owned_rooms`)."""
    if not owned:
        return segments
    last = ""  # the person named latest
    out: list[list[str]] = []
    for segment in segments:
        words = list(segment)
        i = 0
        while i < len(words):
            mentioned = next((p for p in owned if words[i : i + len(p.split())] == p.split()), None)
            owner = next((p for p in owned if _possessive(words, i, p)), None)
            if owner is None and words[i] in _OWN and last:
                owner, end = last, i + 1
            elif owner is not None or mentioned is not None:
                last = owner or mentioned or last
                end = i + len(last.split())
            else:
                i += 1
                continue
            room = owned[owner] if owner is not None else []
            if room and end < len(words) and words[end] in (*_ROOM_NOUNS, room[-1]):
                words[i : end + 1] = room
                end = i + len(room)
            i = end
        out.append(words)
    return out


def _possessive(words: list[str], i: int, person: str) -> bool:
    """Whether ``words[i:]`` starts with ``person`` said as an owner ("rhys's", "mary ann's", "james'")."""
    said = person.split()
    end = i + len(said)
    if words[i : end - 1] != said[:-1] or end > len(words):
        return False
    return words[end - 1] in (said[-1] + "'s", said[-1] + "'")


def called_so(terms: Sequence[Term], said: str, vocabulary: Vocabulary, place: str = "") -> tuple[Term, ...]:
    """Of several devices ``said`` names, those whose own name (not one only given) ends in its last word
    (said as one: in it as one); all of them where none or all do, or where the word is a plural ("the lights
    in the study": its light and its desk lamp); of those, the one named by the ``place`` it was said in and
    the word ("the light in the hallway": the hallway light, not the porch light that hangs there too)."""
    word = said.split()[-1] if said.split() else ""
    devices = {t.symbol for t in terms if vocabulary.is_subtype(t.type, "device")}
    if word.endswith("s") and not word.endswith("ss"):  # "the lights in the study": all of them
        return tuple(terms)
    if len(devices) < 2 or len(devices) < len({t.symbol for t in terms}):
        return tuple(terms)
    own = {
        t.symbol
        for t in vocabulary.terms
        if t.symbol in devices and not t.given and t.phrase.split()[-1] in (word, word + "s", word[:-1])
    }
    # "the light in the kitchen": its kitchen light, not its under-cupboard lights (a plural name is several)
    one = {
        t.symbol for t in vocabulary.terms if t.symbol in own and not t.given and t.phrase.split()[-1] == word
    }
    own = one if not word.endswith("s") and one else own
    named = {t.symbol for t in vocabulary.terms if t.symbol in own and t.phrase == f"{place} {word}"}
    own = named if place and len(own) > 1 and len(named) == 1 and not word.endswith("s") else own
    return tuple(t for t in terms if t.symbol in own) if own and own != devices else tuple(terms)


def named_after(terms: Sequence[Term], landmarks: Sequence[Term], vocabulary: Vocabulary) -> tuple[Term, ...]:
    """Of ``terms`` said near ``landmarks``, the one whose own name opens with the first word of a landmark's
    name of two words or more ("the light over the dining table": the dining light, not the lounge light of
    the same room), or with its last after a room's ("the kitchen island": the island lights); else
    ``terms``."""
    rooms = {w for t in vocabulary.terms if vocabulary.is_subtype(t.type, "room") for w in t.phrase.split()}
    named = [vocabulary.phrase_of(t.symbol).split() for t in landmarks]
    # "the kitchen island" says the room, not which light of it, unless a light is named after the island
    firsts = {w[0] for w in named if len(w) > 1} - rooms
    firsts |= {w[-1] for w in named if len(w) == 2 and w[0] in rooms}
    kept = tuple(t for t in terms if vocabulary.phrase_of(t.symbol).split()[0] in firsts)
    return kept if len({t.symbol for t in kept}) == 1 else tuple(terms)


def places_before(
    previous: Sequence[CommandFrame], args: Sequence[Arg], vocabulary: Vocabulary, verb: Chunk | None = None
) -> list[str]:
    """The places the earlier actions named, latest first (their goal, ground or source), as the rooms they
    are in when ``args`` name a device; a "there" after ``verb`` that carries to it is made where to
    (:func:`carried_there`)."""
    places = [p for f in reversed(previous) for p in _places_of(f, vocabulary)]
    carried_there(verb.text if verb is not None else "", args, previous, places)
    if not names_device(args, vocabulary):
        return places
    rooms = []
    for place in places:
        try:
            rooms.append(room_of(place, vocabulary))
        except LanguageError:
            rooms.append(place)
    return rooms


def _places_of(frame: CommandFrame, vocabulary: Vocabulary) -> list[str]:
    """The places an action names (its goal, ground or source); for a device switched, the one room the world
    puts it in ("switch on the bathroom light, then take me there": the bathroom)."""
    named = [frame.get(r) or "" for r in ("goal", "ground", "source") if frame.get(r)]
    if named or frame.kind != "OPERATING":
        return named
    rooms = [
        p for p in vocabulary.locations.get(frame.get("device") or "", ()) if vocabulary.is_of(p, "room")
    ]
    return rooms if len(rooms) == 1 else []


def carried_there(
    verb: str, args: Sequence[Arg], previous: Sequence[CommandFrame], places: Sequence[str]
) -> None:
    """ "bring the bucket to the kitchen, then take the mop there": "there" after "take" or "carry", where the
    action before carried a thing to that place, is where this thing goes too, not where it is taken from
    ("go to the kitchen and take the mop there" still takes it from the kitchen)."""
    carried = previous[-1:] and previous[-1].kind in ("BRINGING", "PLACING") and previous[-1].get("goal")
    if verb not in ("take", "carry") or not carried or not places or places[0] != previous[-1].get("goal"):
        return
    for arg in args:
        if arg.chunk.kind == "there" and arg.prep == "place" and arg.prep_text == "in":
            arg.prep, arg.prep_text = "goal", "to"


def names_device(args: Sequence[Arg], vocabulary: Vocabulary) -> bool:
    """Whether some argument names a device."""
    return any(vocabulary.is_subtype(t.type, "device") for a in args for t in a.chunk.terms)


def synonym_only(arg: Arg, vocabulary: Vocabulary) -> None:
    """Refuse a thing said by words the world does not know and a last word only a synonym gives ("my hearing
    aid": no "aid" ends a name of the world's own, only the plasters' "band aids"); "the big light" is still a
    light where the world names lights.

    Raises:
        LanguageError: the thing said so, named.
    """
    chunk = arg.chunk
    items = all(vocabulary.is_subtype(t.type, "item") for t in chunk.terms)
    if not arg.modifiers or not chunk.terms or not items:
        return
    if all(t.given and t.phrase != chunk.text for t in chunk.terms):
        ends = {t.phrase.split()[-1] for t in vocabulary.terms if not t.given}
        if not ends & {chunk.text, chunk.text + "s", chunk.text[:-1]}:
            said = " ".join((*arg.modifiers, chunk.text))
            raise LanguageError(f"there is no '{said}' here: this world has nothing called that")
