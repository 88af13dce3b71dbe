"""What people say around a command, tidied before it is read: shortenings, false starts, corrections and
talk about things the world lacks (used by :class:`knic.language.reader.Reader`)."""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Mapping

from knic.language.apologies import after_same_preposition
from knic.language.asides import dashed_asides_dropped
from knic.language.chunks import Chunk
from knic.language.decimals import decimals_read, plain_typed
from knic.language.registers import to_be_put
from knic.language.said_loosely import loosely_said

#: "is", "are": after words the world has no name for, what follows is talk, not part of the action
COPULAS = frozenset({"is", "are", "was", "were"})
#: what a correction may say again in place of what was said before
CORRECTED = frozenset({"entity", "me", "number", "level", "state"})
#: what comes right before a thing's name said in a command (besides a determiner)
NAMING = frozenset({"verb", "prep", "me", "owner", "entity", "pronoun", "join"})
#: words the world has no name for that name no thing either
NOT_NAMES = COPULAS | {"not"}
#: where a stretch of a typed command ends (sentences, commas and a colon: "one more thing: the lamp ...", not
#: "4:30"; a dash, typed " - " or as a long dash, "ice pack — freezer take"); recognised speech has none
SEGMENT_END = re.compile(r"[.?!;,]+|:(?!\d)|\s-\s|\s*[—–]\s*")


def unplaced(chunks: list[Chunk]) -> list[Chunk]:
    """The names of things among ``chunks`` that no preposition governs (what an action was about); "on" or
    "off" right after the verb is its particle, not a preposition ("switch on the floor lamp": the lamp)."""
    out: list[Chunk] = []
    previous: Chunk | None = None
    particle = False  # the latest word was "on" or "off" right after a verb
    for chunk in chunks:
        if chunk.kind == "entity" and (previous is None or previous.kind != "prep" or particle):
            out.append(chunk)
        if chunk.kind != "det":
            verb = previous is not None and previous.kind == "verb"
            particle = verb and chunk.kind == "prep" and chunk.state is not None
            previous = chunk
    return out


def unsaid_negated(chunks: list[Chunk]) -> list[Chunk]:
    """A correction without what it takes back ("no sorry, not the tissues, the soap": the soap)."""
    if chunks and chunks[0].kind == "unknown" and chunks[0].text == "not":
        rest = chunks[1:]
        while rest and rest[0].kind == "det":
            rest = rest[1:]
        if rest and rest[0].kind in ("entity", "me", "pronoun"):
            return rest[1:]
    return chunks


def negated_dropped(chunks: list[Chunk], negations: Collection[str]) -> list[Chunk]:
    """Drop the things taken back once something was named ("bring me the glasses, not the mug"; "the water
    instead of the juice"): a negation phrase (:attr:`CommandLanguage.negations`) with the determiners and the
    name after it. A negation before anything is named, or before no name, stays."""
    phrases = sorted((n.split() for n in negations), key=len, reverse=True)
    out: list[Chunk] = []
    i = 0
    while i < len(chunks):
        said = [w for c in chunks[i : i + 3] for w in c.text.split()]
        size = next((len(p) for p in phrases if said[: len(p)] == p), 0)
        end = i + _chunks_over(chunks[i:], size)
        while size and end < len(chunks) and chunks[end].kind == "det":
            end += 1
        named = any(c.kind in ("entity", "me", "pronoun") for c in out)
        if size and named and end < len(chunks) and chunks[end].kind in ("entity", "me", "pronoun"):
            i = end + 1
            continue
        out.append(chunks[i])
        i += 1
    return out


def _chunks_over(chunks: list[Chunk], words: int) -> int:
    """How many chunks from the first hold the first ``words`` words."""
    count = 0
    while words > 0 and count < len(chunks):
        words -= len(chunks[count].text.split())
        count += 1
    return count


def fluent(tokens: list[str], determiners: Collection[str]) -> list[str]:
    """Drop a false start said again right after ("take me to the take me to the kitchen", "the the"):
    a repeated stretch of two or more words, or a repeated determiner ("to half half open" stays)."""
    out = list(tokens)
    changed = True
    while changed:
        changed = False
        for size in range(1, min(6, len(out) // 2) + 1):
            for i in range(len(out) - 2 * size + 1):
                stretch = out[i : i + size]
                if stretch == out[i + size : i + 2 * size] and (size > 1 or stretch[0] in determiners):
                    del out[i : i + size]
                    changed = True
                    break
            if changed:
                break
    return out


def spelled(tokens: list[str], spellings: Mapping[str, str]) -> list[str]:
    """Shortenings as the words they stand for ("gimme": give me; :attr:`CommandLanguage.spellings`)."""
    return [word for token in tokens for word in spellings.get(token, token).split()]


def digits_read(
    text: str,
    digit_words: Mapping[str, str],
    typed: Mapping[str, str],
    units: Collection[str] = (),
    before_numbers: Collection[str] = (),
) -> str:
    """Digits typed for the word they sound like as that word ("bring it 2 tracy": to;
    :attr:`CommandLanguage.digit_words`), before numbers are spelled out, unless they are a number: what
    follows is counted ("2 apples", "2 of them") or one of ``units`` ("2 percent", "4 %"), the word before is
    one of ``before_numbers`` ("to 2", "at 4"), or nothing follows; typed signs as their words ("3/4": three
    quarters; :attr:`CommandLanguage.typed_words`); decimals as whole numbers first
    (:func:`~knic.language.decimals.decimals_read`); a number that numbers a step ("(1) close the blinds
    (2) turn off the light", "1. go to the kitchen 2. ...") as the end of a stretch, not a level. A digit
    before a word "to" or "for" never comes before (:data:`_NUMBERED_BY`) numbers a thing: "bench lamp 2 to
    35 percent", "blind 2 in the conservatory", "lamp 2 on". A form's label typed with its colon opening a
    sentence (:data:`_LABELS`: "Item: tablet. Source: cane sofa. Destination: me") is the preposition it
    stands for, or nothing."""
    tokens = decimals_read(plain_typed(text)).split()
    for i, token in enumerate(tokens):
        if token[-1:] == ":" and token[:-1].lower() in _LABELS and (not i or tokens[i - 1][-1] in ".!?;"):
            tokens[i] = _LABELS[token[:-1].lower()]
            continue
        if _STEP_NUMBER.fullmatch(token) and (token[0] == "(" or not i or tokens[i - 1][-1] in ".!?:;"):
            tokens[i] = ","
            continue
        bare = token.strip(".,;:!?")
        if bare in typed:
            tokens[i] = token.replace(bare, typed[bare])
            continue
        if token not in digit_words or i + 1 == len(tokens):
            continue
        after = tokens[i + 1].lower().strip(".,;:!?")
        before = tokens[i - 1].lower().strip(".,;:!?") if i else ""
        if not (_counted(after) or after in units or before in before_numbers or after in _NUMBERED_BY):
            tokens[i] = digit_words[token]
    return " ".join(tokens)


#: a form's labels typed with a colon ("Item: tablet. Source: cane sofa. Destination: me"): what each says
_LABELS = {"item": "", "object": "", "thing": "", "source": "from", "origin": "from", "destination": "to"}
#: words after a digit that show it numbers a thing ("lamp 2 to 35", "blind 1 up"), as none follows a "to"
_NUMBERED_BY = frozenset(("to", "at", "on", "off", "in", "into", "up", "down", "and", "or", "fully"))
#: a number said as a list's mark: "(1)", "2)", "3." (the dot one only opening a sentence)
_STEP_NUMBER = re.compile(r"\(\d{1,2}\)|\d{1,2}[.)]")


def _counted(word: str) -> bool:
    """Whether a word after a number is what is counted: a plural ("apples", "glasses"; not "us", "his",
    "this") or "of" ("2 of the mugs")."""
    return word == "of" or (word.endswith("s") and not word.endswith(("us", "is", "ss")))


def repaired(chunks: list[Chunk], kind_of: Callable[[Chunk], str]) -> list[Chunk]:
    """Apply the speaker's corrections ("go to the kitchen, no wait, the dining room"; "bring me the cup,
    sorry, I meant the mug"; "switch on the light, no, scratch that, open the blinds").

    What follows a repair phrase up to the next verb or joiner replaces the last thing of the same kind
    said before it (an object, a person, a place, a device, a level or a state), else the last words the
    world has no name for (:func:`unnamed`: "bring me the banana, sorry, I meant the apple"); when it
    starts with a verb, it replaces the last action. A repair with nothing before or after it is dropped.
    """
    while any(c.kind == "repair" for c in chunks):
        at = max(i for i, c in enumerate(chunks) if c.kind == "repair")
        before, after = chunks[:at], unsaid_negated(chunks[at + 1 :])
        words = [c for c in after if c.kind not in ("det", "prep")]
        if not before or not words:
            chunks = before + after
            continue
        if words[0].kind == "verb":
            verbs = [i for i, c in enumerate(before) if c.kind == "verb"]
            start = verbs[-1] if verbs else 0
            while start > 0 and before[start - 1].kind == "join":
                start -= 1
            # the things the dropped action named stay said, for an "it" in the new one ("place the
            # candle on the shelf; correction: place it on the side table")
            chunks = unplaced(before[start:]) + before[:start] + after
            continue
        end = next((i for i, c in enumerate(after) if c.kind in ("verb", "join")), len(after))
        replacement, rest = after[:end], after[end:]
        # what is said again ("actually make it 40": the 40), with its determiners and preposition
        named = [i for i, c in enumerate(replacement) if c.kind in CORRECTED]
        if named:
            first = named[0]
            while first > 0 and replacement[first - 1].kind in ("det", "prep"):
                first -= 1
            replacement = replacement[first : named[0] + 1] + replacement[named[0] + 1 :]
        kind = kind_of(next((c for c in replacement if c.kind not in ("det", "prep")), words[0]))
        target = after_same_preposition(before, replacement)  # "to ottavia? or, no, to the bathroom"
        if target is None:
            target = next((i for i in range(len(before) - 1, -1, -1) if kind_of(before[i]) == kind), None)
        span = (target, target) if target is not None else None
        if target is None or kind == "unknown":
            # what the world lacks, corrected to what it has (or lacks as well): the run in the position
            # the replacement takes ("to the garage, no wait, the kitchen": governed; "the mug": not)
            governed = kind == "place" or bool(replacement and replacement[0].kind == "prep")
            span = unnamed(before, governed) or span
        if span is None:
            chunks = before + after
            continue
        start, target = span
        while target + 2 < len(before) and before[target + 1].kind == "partitive":
            # "a cup of tea, no, a cup": the thing said with what it holds is corrected whole
            nxt = target + 2
            while nxt < len(before) - 1 and before[nxt].kind == "det":
                nxt += 1
            if before[nxt].kind not in ("entity", "unknown"):
                break
            target = nxt
        while start > 0 and before[start - 1].kind == "det":
            start -= 1
        if replacement and replacement[0].kind == "prep" and start > 0 and before[start - 1].kind == "prep":
            start -= 1  # "to the kitchen ... no, to the dining room"
        chunks = before[:start] + replacement + before[target + 1 :] + rest
    return chunks


def unnamed(chunks: list[Chunk], governed: bool) -> tuple[int, int] | None:
    """The first and last index of the last run of words the world has no name for that stands where a
    thing is named (after a determiner, a verb, a preposition, "me" or another name), preferring a run a
    preposition governs (``governed``) or one none does; None when there is no such run."""
    runs: list[tuple[int, int, bool]] = []
    i = 0
    while i < len(chunks):
        if chunks[i].kind != "unknown" or chunks[i].text in NOT_NAMES:
            i += 1
            continue
        end = i
        while end + 1 < len(chunks) and chunks[end + 1].kind == "unknown":
            end += 1
        before = i
        while before > 0 and chunks[before - 1].kind == "det":
            before -= 1
        previous = chunks[before - 1].kind if before > 0 else None
        if before < i or previous in NAMING:
            runs.append((i, end, previous == "prep"))
        i = end + 1
    preferred = [run for run in runs if run[2] == governed]
    if not (preferred or runs):
        return None
    first, last, _ = (preferred or runs)[-1]
    return first, last


def talk_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop what is said about things the world lacks after an action ("close the blinds, the sun's in
    my eyes"): a copula after words the world has no name for, from those words to the next verb or
    joiner. Such talk before the first verb already makes no action."""
    out = list(chunks)
    at = len(out)
    while at > 1:
        at = min(at, len(out)) - 1
        if out[at].kind != "unknown" or out[at].text not in COPULAS:
            continue
        start = at
        while start > 0 and out[start - 1].kind in ("unknown", "det"):
            start -= 1
        subject = out[start:at]
        verbs = [i for i, c in enumerate(out[:start]) if c.kind == "verb"]
        said = verbs and any(c.kind in ("entity", "me", "pronoun") for c in out[verbs[-1] : start])
        if not said or not any(c.kind == "unknown" for c in subject):
            continue  # "check whether the front door is open": what the verb asks about
        end = next((i for i in range(at, len(out)) if out[i].kind in ("verb", "join")), len(out))
        del out[start:end]
    return out


#: the state a device is put in when it is said to be left in the other one
_UNDONE = {"on": "off", "off": "on", "open": "closed", "closed": "open"}
#: words that say a device's state is left as it should not be ("is still on", "has been left on")
_LEFT_SO = frozenset({"still", "left", "been"})


def left_undone(chunks: list[Chunk]) -> list[Chunk]:
    """A device said to be left in a state, with no verb ("the hallway light is still on", "the garage light
    has been left on again", "the blinds are still open", "the lamp has been on all day"): a complaint, so the
    other state is asked for."""
    for i in range(1, len(chunks) - 1):
        marker, state = chunks[i], chunks[i + 1]  # the state may be a verb's ("still open")
        undone = _UNDONE.get(state.state or "") if state.kind in ("state", "prep", "verb") else None
        if marker.kind != "unknown" or marker.text not in _LEFT_SO or undone is None:
            continue
        if any(chunk.kind == "verb" for chunk in chunks[: i + 1]):
            return chunks  # "leave the light on", "is the light still on?"
        after = chunks[i + 2] if i + 2 < len(chunks) else None
        if chunks[i - 1].text not in COPULAS | {"been", "has", "have"} or (
            after and after.kind in ("det", "entity")
        ):
            continue  # "my glasses are still on the table": where they are
        end = i + 2
        if end < len(chunks) and chunks[end].text == "again":
            end += 1
        return [*chunks[:i], Chunk("state", state.text, state=undone), *chunks[end:]]
    return chunks


#: a word broken off as the speaker starts again ("go to the kit- the kitchen"): a word, a hyphen, a space
_CUT_OFF = re.compile(r"(?<![\w'-])[\w']+-(?=\s+\S)")


def cut_off_dropped(text: str) -> str:
    """Drop words the speaker broke off to say again ("go to the kit- the kitchen", "bring me the m- the
    mug"): the determiner said twice is then one (:func:`fluent`); a stammer's starts of a word written
    before it ("I-is Ellis in the k-kitchen?", "sw-sw-switch", "th-thirty": the word; "x-ray", "t-shirt"
    stay); and, said last, a tag urging the request on ("bring me the mug, go on"; :data:`_TAG`) or a pain
    giving the reason ("my tummy hurts"; :data:`_ACHE`)."""
    text = to_be_put(dashed_asides_dropped(loosely_said(text)))  # "bring me the — Tobi, no! — the oil"
    return _CUT_OFF.sub("", _ACHE.sub("", _TAG.sub("", _STAMMER.sub(_stammer_dropped, text))))


#: starts of a word said over before the word ("c-c-can", "I-is"), hyphened as a stammer is written
_STAMMER = re.compile(r"(?<![\w'-])((?:[a-z]{1,4}-)+)([a-z]+)", re.IGNORECASE)


def _stammer_dropped(match: re.Match[str]) -> str:
    word = match.group(2)
    starts = match.group(1).lower().split("-")[:-1]
    return word if all(word.lower().startswith(s) for s in starts) else match.group(0)


#: a pain said last, after a request ("bring me the calpol my tummy hurts", "... my back is killing me"): why
#: it is asked, no request of its own
_ACHE = re.compile(
    r"(?<=\S)[\s,]+(?:because |cos |cause )?(?:my|our) [a-z]+ (?:hurts|aches|is sore|is killing me|"
    r"hurt|ache|are sore|are killing me)[\s.!]*$",
    re.IGNORECASE,
)
#: "go on" said last, after a request ("bring me the mug, go on", "hurry up"): urging, no motion ("the cushion
#: should go on the sofa" has its place after it)
_TAG = re.compile(r"(?<=\S)[\s,]+(?:go on|go on now|go on then|hurry up|chop chop)[\s.!]*$", re.IGNORECASE)


#: words that forbid the action right after them ("don't go to the kitchen")
_FORBIDDING = (("don't",), ("dont",), ("do", "not"), ("never",))


def forbidden_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop an action the speaker forbids before saying what to do instead ("don't go to the kitchen, go to
    the bedroom", "do not bring me the juice, bring me the water"): from the forbidding words to the next
    verb. The things it named stay said, for an "it" later. A forbidden action with none after it is only
    dropped ("don't switch the light off" asks for nothing)."""
    out = list(chunks)
    i = 0
    while i < len(out):
        size = next(
            (
                len(words)
                for words in _FORBIDDING
                if all(
                    i + k < len(out) and out[i + k].kind == "unknown" and out[i + k].text == word
                    for k, word in enumerate(words)
                )
            ),
            0,
        )
        verb = i + size
        if not size or verb >= len(out) or out[verb].kind != "verb":
            i += 1
            continue
        after = next((j for j in range(verb + 1, len(out)) if out[j].kind == "verb"), None)
        if after is None:  # "bring me the mug and don't drop it": nothing is done for it
            return out[:i]
        out = out[:i] + unplaced(out[verb + 1 : after]) + out[after:]
    return out


#: "what" said for "that" after a thing ("the cup what is on the counter"), as many speakers do
_RELATIVE_WHAT = ("what",)
#: who does what a relative clause says ("the glasses that i left in the living room")
_DOERS = frozenset({"i", "you", "we", "they", "he", "she"})


def relative_dropped(chunks: list[Chunk]) -> list[Chunk]:
    """Drop "that i left", "which you put" between a thing and where it is ("find the glasses that i left in
    the living room", "bring me the mug that you put on the table"): the place says where the thing is. "what"
    said for "that" is the same ("the mug what i left on the table", "the cup what is on the counter"). A
    learner's pronoun for the thing again after the clause's verb ("the biscotti which Lyudmila made them",
    Arabic and Persian speakers) is dropped first."""
    out = list(chunks)
    for i in range(1, len(out) - 3):
        that, doer, doing, again = out[i : i + 4]
        if (
            out[i - 1].kind == "entity"
            and that.text in ("that", "which")
            and doer.kind in ("entity", "unknown", "pronoun")
            and doing.kind in ("unknown", "verb")
            and again.kind == "pronoun"
            and again.text in ("it", "them")
        ):
            out = out[: i + 3] + out[i + 4 :]
            break
    for i in range(1, len(out) - 2):
        what, copula, where = out[i : i + 3]
        if (
            out[i - 1].kind == "entity"
            and what.kind == copula.kind == "unknown"
            and what.text in _RELATIVE_WHAT
            and copula.text in COPULAS
            and where.kind == "prep"
        ):
            return out[:i] + out[i + 2 :]
    for i in range(1, len(out) - 3):
        that, doer, doing, where = out[i : i + 4]
        if (
            out[i - 1].kind == "entity"
            and that.text in ("that", "which", *_RELATIVE_WHAT)
            and doer.text in _DOERS
            and doer.kind in ("unknown", "pronoun")
            and doing.kind in ("unknown", "verb")
            and where.kind == "prep"
        ):
            return out[:i] + out[i + 3 :]
    return out


def before_moved(chunks: list[Chunk]) -> list[Chunk]:
    """An action said to come after the next one ("before you go to the bedroom, turn off the hallway
    light"): it is put after that one."""
    if len(chunks) < 3 or chunks[0].kind != "unknown" or chunks[0].text != "before":
        return chunks
    start = 2 if chunks[1].kind in ("unknown", "pronoun") and chunks[1].text in _DOERS else 1
    if chunks[start].kind != "verb":
        return chunks
    nxt = next((j for j in range(start + 1, len(chunks)) if chunks[j].kind == "verb"), None)
    if nxt is None:
        return chunks
    following = next((j for j in range(nxt + 1, len(chunks)) if chunks[j].kind in ("verb", "join")), None)
    end = len(chunks) if following is None else following
    return chunks[nxt:end] + chunks[start:nxt] + chunks[end:]


#: words that put the action after them first, said after another ("bring me the tea once you have switched
#: on the light"), and what may stand between them and that action's verb
_AFTER = frozenset({"after", "once", "when"})
_HAVING = frozenset({"you", "you've", "have", "had", "finished", "done"})


def after_moved(chunks: list[Chunk], verb_of: Callable[[str], Chunk | None]) -> list[Chunk]:
    """An action said to come first after another ("bring me the orange after you switch on the light",
    "... once you've switched on the light", "... when you have turned on the light"): it is put first. A
    verb said in the past there is the verb (``verb_of`` gives the verb chunk of a word, else None). After a
    command that opens with "first", "after you" goes on in order ("first you go in the scullery, after you
    take the gloves": then)."""
    said = next((i for i, c in enumerate(chunks) if c.kind == "verb"), None)
    if chunks[:1] and chunks[0].text == "first":
        return [Chunk("join", "then") if c.text == "after" and c.kind == "unknown" else c for c in chunks]
    for i in range(1, len(chunks) - 2):
        if said is None or i <= said or chunks[i].kind != "unknown" or chunks[i].text not in _AFTER:
            continue
        if not chunks[i + 1].text.startswith("you"):
            continue  # "bring me the tea when it's ready": no action of the robot's
        at = i + 1
        while at < len(chunks) and chunks[at].kind == "unknown" and chunks[at].text in _HAVING:
            at += 1
        if at >= len(chunks):
            continue
        verb = chunks[at] if chunks[at].kind == "verb" else _past(chunks[at], verb_of)
        if verb is None:
            continue
        end = next((j for j in range(at + 1, len(chunks)) if chunks[j].kind in ("verb", "join")), len(chunks))
        return [verb, *chunks[at + 1 : end], Chunk("join", "and"), *chunks[:i], *chunks[end:]]
    return chunks


#: words that ask someone to go somewhere ("ask tracy to come to the kitchen", "tell jack to go to ...")
_ASKING = frozenset({"ask", "tell", "get"})


def asked_to_come(chunks: list[Chunk], lead: Chunk, is_person: Callable[[Chunk], bool]) -> list[Chunk]:
    """Someone asked to come or go somewhere ("ask tracy to come to the kitchen", "tell jack to go to the
    living room", "get tracy to come to the bedroom"): the robot takes them there (``lead``), it does not
    only go there itself."""
    for i in range(len(chunks) - 4):
        asking, person, to, come = chunks[i : i + 4]
        if (
            asking.text in _ASKING
            and (
                (person.kind == "entity" and is_person(person))
                or (person.kind == "pronoun" and person.text in ("her", "him", "them"))  # "ask her to come"
            )
            and to.text == "to"
            and come.kind == "verb"
            and come.frames == ("MOTION",)
            and chunks[i + 4].kind == "prep"
        ):
            return [*chunks[:i], lead, person, *chunks[i + 4 :]]
    return chunks


def _past(chunk: Chunk, verb_of: Callable[[str], Chunk | None]) -> Chunk | None:
    """The verb a word said in the past is ("switched": switch, "closed": close, "dropped": drop), else
    None."""
    word = chunk.text
    if chunk.kind not in ("unknown", "state") or not word.endswith("ed"):
        return None
    doubled = word[:-3] if len(word) > 4 and word[-3] == word[-4] else ""
    return next((v for stem in (word[:-2], word[:-1], doubled) if stem and (v := verb_of(stem))), None)


def restated(chunks: list[Chunk], kind_of: Callable[[Chunk], str]) -> list[Chunk]:
    """A place said again at once as another, the hesitation between dropped ("bring the mug to the kitchen
    uh the dining room"): the speaker corrected the first, so the second is meant. Only for a place a
    preposition governs, the second after a determiner and ending the action (not "the living room sofa")."""
    out = list(chunks)
    for i in range(len(out) - 1, 0, -1):
        if out[i].kind != "entity" or kind_of(out[i]) != "place":
            continue
        after = out[i + 1].kind if i + 1 < len(out) else "join"
        first = i - 1
        while first >= 0 and out[first].kind == "det":
            first -= 1
        if after not in ("verb", "join") or first == i - 1 or first < 0 or kind_of(out[first]) != "place":
            continue
        start = first
        while start > 0 and out[start - 1].kind == "det":
            start -= 1
        if start > 0 and out[start - 1].kind == "prep":
            return out[:start] + out[first + 1 :]
    return out


#: names' last words that are English modal verbs ("watering can", "last will")
_MODALS = frozenset({"can", "could", "will", "would", "may", "might", "must", "shall", "should"})


def modal_unnamed(chunks: list[Chunk]) -> list[Chunk]:
    """A modal verb said without a determiner in a command of no verb ("no can not watching full of old
    photos") is the verb, not the last word of a name ("watering can"): the words are then no request, rather
    than one for the watering can. "the can" and "bring me the can" still name it."""
    if any(c.kind == "verb" for c in chunks):
        return chunks
    return [
        Chunk("unknown", c.text)
        if c.kind == "entity" and c.text in _MODALS and (i == 0 or chunks[i - 1].kind != "det")
        else c
        for i, c in enumerate(chunks)
    ]
