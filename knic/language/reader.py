"""Reading commands as people say them: chunks, clauses, roles and frames from normalised text.

Driven by the phrase tables of :mod:`knic.language.commands` (general English) and a world's :class:`~knic.
language.vocabulary.Vocabulary` (its names), it is more forgiving than the templates and reads all they admit.

Steps for one command:

1. **Chunks.** Left to right, the longest phrase at each position becomes one chunk: a world name (full
   phrase, else the last word of a longer name, else a plural: "table" may be any table, "cups" is "cup"),
   a verb, a preposition, a state, a level or number, a joiner, a determiner, a pronoun, "me"; fillers and
   politeness are dropped; anything else is an unknown word.
2. **Clauses.** A new action starts at every verb (with or without "and" / "then" before it); "and" before a
   noun joins several objects in one action. A clause without a verb is a device command when it names a
   device and a state ("lights off"), otherwise words before the first verb are taken as address
   (:mod:`knic.language.clauses`).
3. **Frames.** The verb lists the frame kinds it may start; the first kind whose arguments fit by type wins
   ("take Tracy to the bedroom" is ACCOMPANYING, "take the cup to the kitchen" BRINGING). Prepositions give
   roles; a place right after a piece of furniture or a device narrows it down ("the table in the kitchen").
   One interpreter per frame kind (:mod:`knic.language.roles`).
4. **Chains.** Pronouns take the previous action's referent; a TAKING followed by an action on the same
   object hands it its source; a MOTION followed by an action gives it its source or ground
   (:mod:`knic.language.chains`).

Errors are :class:`~core.errors.LanguageError` with one line for the user; an ambiguous name raises
:class:`AmbiguityError` whose message is the question to ask back.
"""

from __future__ import annotations

import contextlib
import copy
from collections.abc import Sequence

from core.errors import LanguageError
from knic.language.chains import AmbiguityError, Reading, chain, referent, settled
from knic.language.chunkmemo import Chunk, RememberedChunker
from knic.language.clauses import Arg, Clause, split_clauses
from knic.language.commands import CommandLanguage, command_language
from knic.language.excepting import read_excepting
from knic.language.frames import KIND_PLURALS, SPEAKER, CommandFrame, not_of_kinds
from knic.language.household import gathered_up, ones_named, other_one, said_around, where_last, words_tidied
from knic.language.learners import learners_read
from knic.language.naming import names_device, places_before, said_named, synonym_only
from knic.language.owned import own_pairs
from knic.language.places import Places
from knic.language.quantified import every_one
from knic.language.remarks import NoSuchAction, plain_words, refused, tagged, unknown_action
from knic.language.roles import INTERPRETERS
from knic.language.segments import (
    cut,
    doings_dropped,
    late_repairs,
    operates_it,
    pointed,
    sayings_dropped,
    sorry_repairs,
    statements_dropped,
)
from knic.language.selecting import described
from knic.language.sentences import sentences_read
from knic.language.terse import for_asker, room_alone, told_read, wished_first
from knic.language.tidy import (
    SEGMENT_END,
    after_moved,
    asked_to_come,
    before_moved,
    cut_off_dropped,
    digits_read,
    fluent,
    forbidden_dropped,
    left_undone,
    modal_unnamed,
    negated_dropped,
    relative_dropped,
    repaired,
    restated,
    spelled,
    talk_dropped,
)
from knic.language.vocabulary import Vocabulary, level_percent, normalize

MAX_ACTIONS = 3


class Reader(Places):
    """Reads normalised commands against one vocabulary (build once per vocabulary; :meth:`read` is pure)."""

    def __init__(self, vocabulary: Vocabulary, language: CommandLanguage | None = None):
        self.vocabulary = vocabulary
        self.language = language or command_language()
        self.chunker = RememberedChunker(vocabulary, self.language)
        # what makes a typed digit a number, not a word it sounds like ("to 2 percent", not "to to percent")
        self._units = frozenset(p.split()[0] for p in self.language.percent)
        level_words = self.language.prepositions.get("level", ())
        self._before_numbers = frozenset(p.split()[-1] for p in level_words) | {"to", "at"}
        #: what the speaker says they want ("i need the duvet, bring it to the bedroom": terse.wished_first)
        wishes = (p for v in self.language.verbs if v.name in ("want", "need") for p in v.phrases)
        self._wishes = frozenset(p for p in wishes if p != "i'll have")  # an order, as "can i have" is

    def chunks(self, tokens: Sequence[str]) -> list[Chunk]:
        """The chunks of a normalised token list (see :class:`~knic.language.chunks.Chunker`)."""
        return self.chunker.chunks(tokens)

    def clauses(self, chunks: list[Chunk], context: list[Arg] | None = None) -> list[Clause]:
        """Chunks split at verbs (:mod:`knic.language.clauses`); ``context``: noun phrases before the 1st."""
        return split_clauses(
            chunks,
            lambda chunk: any(self.is_a(t, "device") for t in chunk.terms),
            lambda chunk: any(self.is_a(t, "item") for t in chunk.terms),
            self.chunker.bare_verb,
            context,
            lambda chunk: any(self.is_a(t, "person") for t in chunk.terms),
        )

    # ------------------------------------------------------------------ reading

    def read(self, text: str) -> Reading:
        """The frames of a command.

        Raises:
            AmbiguityError: a name fits several things (the message asks which).
            LanguageError: the command is not understood (the message says what is missing or unknown).
        """
        language = self.language
        if (excepting := read_excepting(text, self, self._verb_of)) is not None:  # "all the lights but ..."
            return excepting
        text = digits_read(
            where_last(cut_off_dropped(text)),
            language.digit_words,
            language.typed_words,
            self._units,
            self._before_numbers,
        )
        segments = [
            plain_words(words_tidied(spelled(normalize(part).split(), self.language.spellings)))
            for part in SEGMENT_END.split(text)
        ]
        segments = gathered_up(segments)  # the empty ones dropped
        if not segments:
            raise LanguageError("nothing to understand: the command is empty")
        opening = not_request(
            tagged(segments, self.chunks), language.not_requests, language.not_requests_unless
        )
        if opening:
            what = "asks about something or says what you do or will do: no request, no action for me"
            raise LanguageError(f"'{opening} ...' {what}")
        if refusal := refused(segments, self.chunks):  # "the landing light has been flickering all week"
            raise LanguageError(refusal)
        segments = said_named(segments, self.vocabulary, self.chunker.language_words)  # naming.py
        segments = described(ones_named(segments, self.vocabulary), self.vocabulary)  # selecting.py
        segments = late_repairs(sorry_repairs(segments, self.chunks), self.chunks)
        segments = sentences_read(segments, self.chunks, self.is_a)  # "jas borrowed them", "..., light off"
        # pointing first ("see that candle? put it on the nightstand"), else as said; unpunctuated ("close the
        # blinds it's too bright"): by the sentences the words start, then without statements (segments.py)
        pointing = pointed(segments, self.chunks)
        if pointing is not None:
            with contextlib.suppress(LanguageError):
                return self._read_segments(pointing)
        try:
            return self._read_segments(segments)
        except NoSuchAction:  # "... and wash it": read otherwise, the washing would be dropped (remarks.py)
            raise
        except LanguageError as exc:
            first = exc
        tries = [cut(s, self.chunks) for s in (segments, *([pointing] if pointing else []))]
        tries += [said for s in tries if (said := statements_dropped(s, self.chunks)) is not None]
        last: LanguageError | None = None
        for segmented in tries:
            if segmented in (segments, pointing):
                continue
            try:
                return self._read_segments(segmented)
            except LanguageError as exc:
                last = last or exc
        # a command said without punctuation is refused as its sentences would be
        raise last if last is not None and len(segments) == 1 else first

    def _read_segments(self, segments: list[list[str]]) -> Reading:
        """:meth:`read` of the command's stretches (sentences and what commas set apart): the whole, else
        without the stretches that name nothing of the world (talk around the request)."""
        try:
            return self._read_tokens(self._fluent([t for segment in segments for t in segment]))
        except LanguageError as exc:
            whole = exc
        # "... bring me the sponge, love, I want to wipe up a little spill": what names nothing of the world
        # around the request is talk; read without it before giving up
        kept = [segment for segment in segments if self._names_things(segment)]
        corrected = any(chunk.kind == "repair" for segment in segments for chunk in self.chunks(segment))
        if not kept and len(segments) > 1 and not corrected:  # name what the request lacks, not the talk
            for segment in segments:
                if any(chunk.kind == "verb" for chunk in self.chunks(segment)):
                    self._read_tokens(self._fluent(segment))
                    break
        if any(operates_it(s, self.chunks) for s in segments):  # "the radio, turn it off": the switching
            kept = [segment for segment in segments if self._names_things(segment, it=True)]  # is no talk
        if not kept or len(kept) == len(segments):
            raise whole
        try:
            return self._read_tokens(self._fluent([t for segment in kept for t in segment]))
        except LanguageError as exc:
            wider = [segment for segment in segments if self._names_things(segment, it=True)]
            if len(kept) < len(wider) < len(segments):  # "are the blinds shut? open them, i want some light"
                with contextlib.suppress(LanguageError):
                    return self._read_tokens(self._fluent([t for segment in wider for t in segment]))
            acts = any(chunk.kind == "verb" for segment in kept for chunk in self.chunks(segment))
            # a question beats a complaint ("light on please, I can't see": which light?; "i'm going to bed,
            # turn everything off": which devices?, not the talk's "no action")
            acts = acts and not isinstance(whole, AmbiguityError)
            raise (exc if acts or isinstance(exc, AmbiguityError) else whole) from None

    def _fluent(self, tokens: list[str]) -> list[str]:
        return fluent(tokens, self.language.determiners)

    def _names_things(self, tokens: list[str], it: bool = False) -> bool:
        """Whether a stretch of a command names an object, a place, a device or a person of the world; with
        ``it``, also whether it asks for an action on "it" or "them" ("open them please"; not "i need it")."""
        kinds = ("item", "room", "furniture", "device", "person")
        said = self.chunks(tokens)
        said = said[next((i for i, c in enumerate(said) if c.kind != "join"), 0) :]  # "then open them"
        verb = said[0] if said[:1] and said[0].kind == "verb" else None
        back = any(c.kind == "me" for c in said) or (verb is not None and verb.text.endswith(" back"))
        if verb is not None and "MOTION" in verb.frames and back:  # "..., then come back (to me)": no talk
            return True
        acts = it and verb is not None and verb.beneficiary is None
        if acts and any(c.kind == "pronoun" and c.role != "person" for c in said):
            return True
        return any(self.is_a(t, k) for c in said for t in c.terms for k in kinds)

    def _read_tokens(self, tokens: list[str]) -> Reading:
        """:meth:`read` of normalised tokens."""
        said, asker = told_read(tokens, self.chunker, self.vocabulary)  # knic.language.terse
        chunks = learners_read(said, self.vocabulary)
        chunks = after_moved(before_moved(relative_dropped(forbidden_dropped(chunks))), self._verb_of)
        chunks = asked_to_come(chunks, self.chunks(["lead"])[0], lambda c: self._kind_of(c) == "person")
        chunks = said_around(other_one(chunks, self.vocabulary), self.vocabulary, self.chunker)
        chunks = restated(negated_dropped(chunks, self.language.negations), self._kind_of)
        chunks = sayings_dropped(doings_dropped(talk_dropped(repaired(left_undone(chunks), self._kind_of))))
        chunks = modal_unnamed(room_alone(chunks, self.vocabulary, self.chunker))  # "ok robot, dining room"
        verbless = not any(c.kind == "verb" for c in chunks)
        if not chunks or (verbless and [c.kind for c in chunks[:3]] == ["entity", "det", "entity"]):
            # "light the candle", as "water the plant": a name said as a verb the robot has not
            raise LanguageError(f"no action in '{' '.join(tokens)}': say what to do, e.g. 'bring me ...'")
        if verb := unknown_action(chunks, self._kind_of):
            raise NoSuchAction(f"I cannot {verb} things: '{verb}' is no action of mine")
        context: list[Arg] = []
        clauses = self.clauses(chunks, context)
        if not clauses:
            unknown = [c.text for c in chunks if c.kind == "unknown"]
            if unknown:
                raise LanguageError(f"I do not know what to do: no action I know in '{' '.join(tokens)}'")
            raise LanguageError(f"no action in '{' '.join(tokens)}': say what to do, e.g. 'bring me ...'")
        if len(clauses) > MAX_ACTIONS:
            raise LanguageError(f"{len(clauses)} actions in one command; I take up to {MAX_ACTIONS} at once")
        frames: list[CommandFrame] = []
        mentioned, located, unsettled = self._mentions(context)
        for chunk in chunks:  # "annie's glasses are on the shelf, take them to her": annie is said
            symbols = {t.symbol for t in chunk.terms}
            if chunk.kind == "owner" and len(symbols) == 1:
                mentioned.insert(0, CommandFrame("SEARCHING", {"theme": symbols.pop()}))
        groups: list[list[CommandFrame]] = [mentioned]
        ask_where: set[int] = set()  # "take the cup away": where to, unless a later action says so
        held: set[int] = set()  # TAKING frames of verbs that only take: nothing carries them on, it holds
        skipped: LanguageError | None = None  # why the first clause taken as talk was no action
        for clause in clauses:
            try:
                group = self._frames_of(clause, frames, groups)
            except AmbiguityError:
                raise
            except LanguageError as exc:
                if unsettled and ("does not refer" in str(exc) or " what? " in str(exc)):  # "milk bring me"
                    raise AmbiguityError(unsettled) from None
                talk = clause.verb is not None and (clause.verb.soft or clause.names_nothing())
                lone = len(clauses) == 1 and clause.verb is not None and clause.verb.soft
                if talk and lone and not clause.args:
                    # "what's the weather going to be like": "going" asks nothing of the robot
                    raise LanguageError(
                        f"I do not know what to do: no action I know in '{' '.join(tokens)}'"
                    ) from None
                if not talk or len(clauses) == 1:
                    raise
                # "it's getting late, close the blinds", "look, bring me the mug": talk, not an action
                skipped = skipped or exc
                continue
            indices = range(len(frames), len(frames) + len(group))
            takes_only = clause.verb is not None and clause.verb.frames[0] == "TAKING"
            if clause.unsaid_goal and takes_only:
                ask_where.update(indices)
            if takes_only and not clause.mine:  # "pick up the box": held; "grab my glasses": for me
                held.update(indices)
            groups.append(group)
            frames.extend(group)
        if not frames:  # every clause was talk
            raise skipped or LanguageError(f"no action in '{' '.join(tokens)}'")
        # "is there a parcel on the hall table? bring it to me", "i need the duvet from the cupboard, bring it
        # to the back bedroom": the first only says what and where the thing is
        n = (
            1
            if self._asked_first(clauses[0], frames)
            else wished_first(clauses[0], groups[1:2], frames, self._wishes)
        )
        for frame in frames[:n]:
            if frame.get("ground") or frame.get("source"):
                located.setdefault(frame.args["theme"], frame.get("ground") or frame.args["source"])
        frames = frames[n:]
        ask_where, held = {i - n for i in ask_where if i >= n}, {i - n for i in held if i >= n}
        frames = own_pairs(self._placed(frames, located))  # "give tyler and maisie their lunchboxes"
        reading = chain(frames, self.vocabulary, ask_where=ask_where, held=held)
        reading = settled(reading, self.vocabulary)  # "open the blinds and set them to 40": at 40
        return for_asker(reading, asker)  # "tracy asks the robot to fetch her glasses": for tracy

    def _asked_first(self, clause: Clause, frames: list[CommandFrame]) -> bool:
        """Whether the command opens by asking whether a thing is somewhere ("is there a parcel on the hall
        table?") and then acts on that thing: the question only says where it is, no search of its own."""
        asked = clause.verb is not None and clause.verb.text in self.language.opening_verbs()
        theme = frames[0].get("theme") if asked and frames[0].kind == "SEARCHING" else None
        carried = ("BRINGING", "TAKING", "PLACING")
        return theme is not None and any(f.kind in carried and f.get("theme") == theme for f in frames[1:])

    def _verb_of(self, word: str) -> Chunk | None:
        said = self.chunker.chunks([word])
        return said[0] if len(said) == 1 and said[0].kind == "verb" else None

    def _kind_of(self, chunk: Chunk) -> str:
        """What a chunk names, for corrections: object, person, place, device, level, state or its kind."""
        if chunk.kind == "me":
            return "person"
        if chunk.kind in ("level", "number"):
            return "level"
        if chunk.kind != "entity" or not chunk.terms:
            return chunk.kind
        for kind, categories in (
            ("person", ("person",)),
            ("object", ("item",)),
            ("device", ("device",)),
            ("place", ("room", "furniture")),
        ):
            if any(self.is_a(t, c) for t in chunk.terms for c in categories):
                return kind
        return "entity"

    def _frames_of(
        self, clause: Clause, previous: list[CommandFrame], groups: list[list[CommandFrame]]
    ) -> list[CommandFrame]:
        if clause.missing:
            word = clause.missing[0]
            raise LanguageError(f"there is no '{word}' here: this world has nothing called that")
        self._there(clause, previous)
        kinds = clause.verb.frames if clause.verb is not None else ("OPERATING",)
        first_error: LanguageError | None = None
        question: AmbiguityError | None = None
        # every kind as said first; then with an object left unsaid taken from before ("the cup on the
        # table, bring to me"), so that "move next to the counter" stays a motion
        for implicit in (False, True):
            for kind in kinds:
                heard = copy.deepcopy(clause)  # each reading starts from the clause as heard
                heard.implicit = implicit
                try:
                    found = INTERPRETERS[kind](self, heard, previous, groups)
                except AmbiguityError as exc:
                    if implicit:
                        raise
                    question = question or exc
                    break  # asked as said: the unsaid object may still settle it
                except LanguageError as exc:
                    first_error = first_error or exc
                    continue
                if found:
                    return found
        if question is not None:
            raise question
        verb = clause.verb.text if clause.verb is not None else "the command"
        raise first_error or LanguageError(f"I do not know how to '{verb}' that")

    def _mentions(self, context: list[Arg]) -> tuple[list[CommandFrame], dict[str, str], str]:
        """Things named before the first verb without making an action ("my glasses are in the bedroom,
        bring them to me"), as frames for pronouns to refer to (the earliest group; never goals), where
        the command says each of them is ("there's a mug on the table in the kitchen": the kitchen table),
        and the question a thing said so asks when it fits several and nothing tells which ("there's a mug
        on the coffee table, take it ...": which mug, where the robot knows the table, not what is on it).
        """
        mentioned: list[CommandFrame] = []
        located: dict[str, str] = {}
        unsettled = ""
        args = copy.deepcopy(context)
        with contextlib.suppress(LanguageError):  # a place that fits nothing leaves the things unplaced
            self.narrow(args)
        last: str | None = None
        for arg in args:
            symbols = {t.symbol for t in arg.chunk.terms}
            items = sorted(s for s in symbols if self.vocabulary.is_of(s, "item"))
            if not arg.consumed and arg.prep is None and len(items) > 1 and len(items) == len(symbols):
                unsettled = unsettled or f"which {arg.chunk.text} do you mean: {self._listed(items)}?"
            if arg.consumed or arg.chunk.kind != "entity" or len(symbols) != 1:
                continue
            synonym_only(arg, self.vocabulary)  # "my hearing aid, where is it": no plasters
            symbol = symbols.pop()
            place = any(self.is_a(t, "room") or self.is_a(t, "furniture") for t in arg.chunk.terms)
            if arg.prep == "place" and not place and last is not None:
                continue  # "the toaster near the kettle, bring it ...": the kettle only says where
            if not place or (arg.prep is None and last is None):  # "i seem to have misplaced my glasses"
                mentioned.append(CommandFrame("SEARCHING", {"theme": symbol}))
                last = symbol
            elif last is not None and arg.prep in ("place", "source", None):  # "care folder from the desk"
                # where all said before is: "calpol, bathroom cabinet, ...", "kimchi and milk, from fridge"
                located.update({f.args["theme"]: symbol for f in mentioned if f.args["theme"] not in located})
        return mentioned, located, unsettled

    @staticmethod
    def _placed(frames: list[CommandFrame], located: dict[str, str]) -> list[CommandFrame]:
        """Give each action on a thing said to be somewhere that place as its source or ground, if none."""
        out = []
        for frame in frames:
            role = "ground" if frame.kind == "SEARCHING" else "source"
            where = located.get(frame.get("theme") or "")
            carry = frame.kind in ("BRINGING", "TAKING", "SEARCHING")
            if where and carry and frame.get(role) is None and where != frame.get("goal"):
                frame = CommandFrame(frame.kind, {**frame.args, role: where})
            out.append(frame)
        return out

    def _there(self, clause: Clause, previous: list[CommandFrame]) -> None:
        """'there': the place the latest earlier action named (its goal, ground or source). With no place
        named before, "there" points at what the robot cannot see ("the cup over there") and is left out."""
        places = places_before(previous, clause.args, self.vocabulary, clause.verb)  # naming.py
        for arg in list(clause.args):
            if arg.chunk.kind != "there":
                continue
            if not places:
                clause.args.remove(arg)
                continue
            terms = tuple(t for t in self.vocabulary.terms if t.symbol == places[0])[:1]
            arg.chunk = Chunk("entity", arg.chunk.text, terms)
            if arg.prep == "source" and names_device(clause.args, self.vocabulary):
                # "switch the light off there": "off" says the state; the room is where the light must be
                arg.prep, arg.prep_text = "place", "in"

    # ------------------------------------------------------------------ arguments

    def resolve(
        self,
        arg: Arg,
        categories: Sequence[str],
        previous: list[CommandFrame],
        groups: list[list[CommandFrame]],
    ) -> list[str]:
        """The symbols an argument names (several for "them"), of one of ``categories``.

        Raises:
            LanguageError: the argument names nothing of those categories.
            AmbiguityError: it names several things.
        """
        chunk = arg.chunk
        if chunk.kind == "me":
            if "person" not in categories and "room" in categories:  # "come to me"
                raise AmbiguityError("where are you: in which room?")
            if "person" not in categories:
                raise LanguageError(not_of_kinds("me", categories, False))  # "grab me a pop": no object
            return [SPEAKER]
        if chunk.kind == "pronoun":
            return referent(chunk, categories, groups, self.vocabulary)
        if chunk.kind == "everything":  # "bring me everything": which things is not said
            things = " or ".join(KIND_PLURALS.get(c, c) for c in categories)
            raise AmbiguityError(f"which {things} do you mean by '{chunk.text}'? Name them, please")
        terms = [t for t in chunk.terms if any(self.is_a(t, c) for c in categories)]
        if terms:
            synonym_only(arg, self.vocabulary)  # "my hearing aid" is no "band aid" (naming.py)
        if not terms:
            device = any(self.is_a(t, "device") for t in chunk.terms)  # "is the hallway light on?"
            raise LanguageError(not_of_kinds(chunk.text, categories, device))
        symbols = list(dict.fromkeys(t.symbol for t in terms))
        if arg.modifiers and (arg.quantity == "all" or any(t.is_group for t in terms)):  # "the garden lights"
            raise LanguageError(
                f"there is no '{' '.join((*arg.modifiers, chunk.text))}' here: this world has none"
            )
        if arg.quantity == "all" and not ({"room", "furniture"} & set(categories)):
            group = self.vocabulary.group_of(symbols) if len(symbols) > 1 else None
            return [group] if group is not None else every_one(arg, symbols, self.vocabulary)
        if arg.quantity == "both":
            return self._both(chunk, symbols)
        # "I fancy a sherry, bring me the bottle": of several things, the one said earlier in the command
        said_before = [s for s in symbols if any(s in f.args.values() for f in previous)]
        symbols = said_before if len(symbols) > 1 and len(said_before) == 1 else symbols
        # "go to the wet room, then take the shampoo from the cabinet": the one in the room gone to
        gone = [f.get("goal") for f in previous if f.kind == "MOTION"][-1:]
        there = [s for s in symbols if gone and gone[0] in self.vocabulary.locations.get(s, ())]
        symbols = there if len(symbols) > 1 and len(there) == 1 else symbols
        symbols = self._said_otherwise(arg, categories) or symbols
        if len(symbols) > 1:
            question = f"which {chunk.text} do you mean: {self._listed(symbols)}?"
            if arg.modifiers:  # words the world does not know before the name are said back ("kitchen light")
                said = " ".join((*arg.modifiers, chunk.text))
                question = f"I know no '{said}' here. {question[:1].upper()}{question[1:]}"
            raise AmbiguityError(question)
        return symbols

    def _said_otherwise(self, arg: Arg, categories: Sequence[str]) -> list[str]:
        """The one thing named by the words said before a type's noun with another noun of the type ("the
        bedside light" for a bedside lamp, "the reading light" for a reading lamp), else none."""
        if not arg.modifiers:
            return []
        for nouns in self.language.type_nouns.values():
            forms = [(n, n + "s") for n in nouns]
            for one, many in forms:
                if arg.chunk.text not in (one, many):
                    continue
                said = {" ".join((*arg.modifiers, n if arg.chunk.text == one else m)) for n, m in forms}
                named = {
                    t.symbol
                    for t in self.vocabulary.terms
                    if t.phrase in said and any(self.is_a(t, c) for c in categories)
                }
                if len(named) == 1:
                    return list(named)
        return []

    def _both(self, chunk: Chunk, symbols: list[str]) -> list[str]:
        """The two things "both ..." names: two names, or one group of two; else a question."""
        if len(symbols) == 1 and len(self.vocabulary.members(symbols[0])) == 2:
            return symbols
        if len(symbols) == 2:
            group = self.vocabulary.group_of(symbols)
            return [group] if group is not None else symbols
        options = symbols if len(symbols) > 1 else list(self.vocabulary.members(symbols[0]))
        if len(options) < 2:
            raise LanguageError(f"there is only one {chunk.text} here, not two")
        raise AmbiguityError(f"which two {chunk.text} do you mean: {self._listed(options, 'and')}?")

    def _listed(self, symbols: Sequence[str], last: str = "or") -> str:
        options = [f"the {self.vocabulary.phrase_of(s)}" for s in symbols]
        return ", ".join(options[:-1]) + f" {last} {options[-1]}"


__all__ = ["AmbiguityError", "Reader", "Reading", "chain", "level_percent"]


def not_request(segments: list[list[str]], openings: Sequence[str], unless: Sequence[str]) -> str | None:
    """The opening of a command of one sentence that asks about something or says what the speaker means to
    do ("how do you spell kitchen", "i should water the plants later"), when no word of ``unless`` follows it
    ("i should like you to ..."); else None."""
    if len(segments) != 1:
        return None
    said = " ".join(segments[0])
    for opening in openings:
        if said == opening or said.startswith(opening + " "):
            rest = said[len(opening) :].strip()
            if not any(rest == word or rest.startswith(word + " ") for word in unless):
                return opening
    return None
