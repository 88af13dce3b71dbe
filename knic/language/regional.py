"""Words of regional and learners' English read as the standard words they stand for, before chunking.

Two steps, both general English (no world's names):

* :func:`regional_words`, on the words of one sentence, first of all (from
  :func:`knic.language.household.words_tidied`):

  - the Yorkshire and Lancashire article "t'" joined to its noun ("put t'light on", "fetch us t'atlas from
    t'study"): "the";
  - a dropped "g" written with an apostrophe ("fixin'", "watchin'", "nothin'"): the "-ing" word; and "gi'"
    (give), "an'" (and), "o'" (of), "'ere" (here), "'alf" (half);
  - a Japanese honorific after a name ("Kit-kun", "Wilf-san", "Haruka-chan", "Tanaka-sama"), the particles
    and interjections of Singaporean English ("lah", "lor", "aiyo", "alamak") and "sumimasen": left out;
  - "where" straight before a possessive or an article, its verb left out ("where my handbag?", a learner's
    and Singaporean English), or said last ("the remote where ah?"): "where is";
  - "on" before "up", "over", "down", "out" or "back" and then "to" ("tote it on up to the guest room",
    "carry it on over to Huiling", Southern US): left out;
  - a colour of wine after "a bottle of" or "a glass of" ("bring us a bottle of red"): that wine;
  - "on" or "off" said as a verb before "it" or after "help me (to)" ("off it", "help me off it", "please help
    to off the hallway light", Singaporean and Indian English): "switch it off", "switch off ...";
  - "both" said last after two things joined by "and" ("the hall light and the landing light both"), and
    "an' all" said last ("... and the landing light an' all", as well): left out;
  - the Northern "summat", "owt", "nowt": something, anything, nothing;
  - slang for a look after "have a" ("have a butcher's for me gloves", Cockney rhyming slang; "have a
    gander", "a shufti", "a dekko", Australian "a squiz"): "have a look";
  - "I want to drink juice", "I'd like to eat an apple" (a learner's): "I want juice", "I'd like an apple";
  - where a thing or person is said to be, hedged or contracted ("the atlas should be on the dining table",
    "check whether she's in the bedroom"): "is";
  - where the speaker left a thing, hedged ("I seem to have left them on the reading chair", "I must have
    left", a learner's "I forget my glasses in bedroom"): "I left";
  - "where did the biscuit tin get (off) to": where is it; "... where my pen has got to" (a question's order
    inside another): "where has my pen got to".

* :func:`regional_said`, on the sentences of a command with the world's names, before they are put as the
  world says them (from :func:`knic.language.naming.said_named`):

  - "me" for "my" before a thing's name (Yorkshire, Irish, Scouse, Australian: "where's me stick?", "fetch us
    me flat cap", "put me stick back"), except after a verb that takes whom for ("bring me cup", a learner's
    "me" without its article);
  - a question tag said last in Singaporean English ("... can?", "... can or not?", "got ... or not?"): left
    out; a "can" after an article or making a name with the word before ("the watering can") is a can;
  - "got" opening a question ("got oat milk in the fridge or not?", Singaporean and colloquial English):
    "is there";
  - "is it" opening a question before an article ("is it the tablet still on the desk?", Singaporean
    English): "is";
  - "take X come" ("go and take my mug come", Singaporean English: bring it here): "take X to me";
  - "get the light" with no state said ("get the light in the gym, hon", American English): switched off;
  - what a device is set for, said last in words that name nothing of the world ("reading lamp to forty
    percent for the assessment"): left out;
  - a thing said after a question about "it" or "they" ("where is it, the remote?"): what is asked for; an
    aside inside a question ("where, I ask myself, has Haruka got to?"): left out;
  - "them" before a thing's name ("shut them blinds"): "the";
  - what someone did, said after the request ("... Huiling wanted to look at Malaya"): a remark, left out;
  - a learner's singular of a name that is only plural ("my sunglass"): the name;
  - a carry verb with its object left out after a sentence that named a thing ("I forget my sunglasses on
    the terrace table. Please bring to me", a learner's "forget" for "forgot"): "bring it";
  - what the speaker is "fixing to" do, or is "off" to, said beside the request ("fixing to go to bed, get
    the lights", "..., I'm off to the loo"): left out;
  - "step one", "step two" opening a sentence (a nurse's or a manual's numbered steps), and a sentence that
    is only a number ("1. turn on the light. 2. take wilf ...", the "2" read as "to"): left out.
"""

from __future__ import annotations

import re
from functools import lru_cache

from knic.language.kinds import phrases_of
from knic.language.vocabulary import Vocabulary

#: a Yorkshire "t'" before its noun; "gi'", "an'", "o'"; a dropped "g" ("fixin'")
_ARTICLE = re.compile(r"^t'([a-z].*)$")
_CLIPPED = {"gi'": "give", "an'": "and", "o'": "of", "where'd": "where did", "'ere": "here", "'alf": "half"}
#: slang for a look, said after "have a" ("have a butcher's for", "have a gander for", "have a squiz for")
_A_LOOK = frozenset({"butcher's", "butchers", "gander", "shufti", "squiz", "dekko", "butcher", "look-see"})
#: Northern English words for "something", "anything", "nothing"
_NORTHERN = {"summat": "something", "owt": "anything", "nowt": "nothing"}
_DROPPED_G = re.compile(r"^([a-z]+)in'$")
#: wine said by its colour after what it is poured from or into ("a bottle of red")
_WINES = frozenset({"red", "white", "rose", "rosé"})
_POURED = frozenset({"bottle", "glass", "drop", "carafe"})
#: Japanese honorifics said after a name
_HONORIFICS = frozenset({"san", "kun", "chan", "sama"})
#: particles and interjections of Singaporean English, and the Japanese "excuse me", said around a request
#: (read in text only: as fillers they would join the speech model's filler loop)
_PARTICLES = frozenset(
    {"lah", "leh", "lor", "hor", "meh", "ah", "aiyo", "aiyah", "alamak", "wah", "sumimasen"}
)
#: what "where" stands before when its "is" is left out
_POSSESSIVES = frozenset({"my", "the", "your", "his", "her", "our", "their", "me"})
#: what makes "where ... " a question with a verb of its own ("where my pen has got to")
_VERBS_AFTER = frozenset({"is", "are", "was", "were", "has", "have", "had", "did", "do", "does", "'s"})
#: particles of direction after "on" in "carry it on up to ..."
_ON_WHERE = frozenset({"up", "over", "down", "out", "back"})
#: the verbs after which "me" is whom a thing is for ("bring me cup"), not "my"
FOR_WHOM = frozenset(
    {"bring", "fetch", "get", "give", "hand", "pass", "grab", "find", "buy", "chuck", "throw", "toss", "lob"}
    | {"bung", "send", "pour", "make", "fix", "show", "tell", "read", "save", "leave", "order", "help", "let"}
    | {"excuse", "for", "to", "with", "take", "carry"}
)
#: the words of a Singaporean question tag said last ("can?", "can or not?", "or not?")
_TAGS = (("can", "or", "not"), ("can", "anot"), ("or", "not"), ("anot",), ("can",))
_DETERMINERS = frozenset({"the", "a", "an", "my", "your", "this", "that", "his", "her", "our", "their"})
#: where the speaker says they left a thing, hedged: "i left"
_LEFT = (
    ("i", "forget", "my"),  # a learner's present: "i forget my sunglasses on the terrace table"
    ("i", "forgot", "my"),
    ("i", "seem", "to", "have", "left"),
    ("i", "must", "have", "left"),
    ("i", "think", "i", "left"),
    ("i", "have", "left"),
    ("i've", "left"),
)
#: what a person said of after a request did: a remark ("huiling wanted to look at malaya")
_SUBJECTS = frozenset({"he", "she", "they"})
#: what "got" opening a sentence is said before when it asks for nothing ("got it", "got to go")
_NOT_GOT = frozenset({"to", "it", "that", "this", "them", "you", "me", "ya", "him", "her"})
#: what the speaker says they are about to do (Southern US "fixing to"), before or after the request
_ABOUT_TO = (
    ["fixing", "to"],
    ["i'm", "fixing", "to"],
    ["i", "am", "fixing", "to"],
    ["we're", "fixing", "to"],
)
#: a numbered step opening a sentence ("step one: go to the kitchen")
_STEP = frozenset({"step", "stage"})
_NUMBERS = frozenset(
    {"one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "1", "2", "3", "4"}
)
#: words after which a number said alone is a level, not a list's number ("down to, like, five")
_LEVEL_BEFORE = frozenset({"to", "at", "like", "about", "around", "roughly", "maybe", "say"})


def regional_words(tokens: list[str]) -> list[str]:
    """The words of one sentence with the regional and learners' forms of the module docstring read."""
    out: list[str] = []
    for i, token in enumerate(tokens):
        if article := _ARTICLE.match(token):
            out += ["the", article.group(1)]
        elif token in _CLIPPED or token in _NORTHERN:
            out += (_CLIPPED.get(token) or _NORTHERN[token]).split()
        elif dropped := _DROPPED_G.match(token):
            out.append(dropped.group(1) + "ing")
        elif (token in _HONORIFICS and out and out[-1] not in _DETERMINERS) or token in _PARTICLES:
            continue  # "kit kun": Kit; "off the gym light lah"
        elif token == "on" and set(tokens[i + 1 : i + 2]) & _ON_WHERE and "to" in tokens[i + 2 :]:
            continue  # "tote it on up to the guest room"
        elif token in _A_LOOK and out[-2:] == ["have", "a"]:
            out.append("look")  # "have a butcher's for me gloves" (Cockney), "have a squiz for" (Australian)
        else:
            out.append(token)
    for i, token in enumerate(out[:-1]):
        rest = set(out[i + 2 :])
        if token == "where" and out[i + 1] in _POSSESSIVES and not rest & _VERBS_AFTER:
            out.insert(i + 1, "is")  # "where my handbag": where is my handbag
            break
    if len(out) > 2 and out[-1] == "where" and out[0] in _POSSESSIVES and "where" not in out[:-1]:
        out = ["where", "is", *out[:-1]]  # "the remote where ah?": a particle after the question word
    if len(out) > 3 and out[-1] == "both" and "and" in out[:-2]:
        out.pop()  # "the hall light and the landing light both"
    out = _state_said_first(out)
    for i in range(2, len(out)):  # "a bottle of red", "a glass of white": wine
        if (
            out[i] in _WINES
            and out[i - 1] == "of"
            and out[i - 2] in _POURED
            and out[i + 1 : i + 2] != ["wine"]
        ):
            out.insert(i + 1, "wine")
            break
    out = _where_it_is(out)
    for i in range(1, len(out) - 2):  # "i want to drink juice": i want juice
        kind = out[i + 2] in ("something", "anything")  # "i want to drink something": a kind, asked
        if (
            out[i - 1] in ("want", "like", "need")
            and out[i : i + 2] in (["to", "drink"], ["to", "eat"])
            and not kind
        ):
            out[i : i + 2] = []
            break
    if len(out) > 3 and out[-2:] == ["and", "all"]:
        out = out[:-2]  # "... and the landing light an' all": as well
    for said in _LEFT:
        n = len(said)
        at = next((i for i in range(len(out) - n + 1) if tuple(out[i : i + n]) == said), None)
        if at is not None:  # "i seem to have left them on the reading chair"
            out[at : at + n] = ["i", "left", *(["my"] if said[-1] == "my" else [])]
            break
    return _got_to(out)


#: where a thing or person is said to be, hedged ("the atlas should be on the dining table") or contracted
#: after "whether" or "if" ("whether she's in the bedroom"): "is", before a place said with an article
_HEDGED_BE = (["should", "be"], ["ought", "to", "be"], ["must", "be"], ["might", "be"], ["may", "be"])
_CONTRACTED_BE = {"she's": ["she", "is"], "he's": ["he", "is"], "they're": ["they", "are"]}
_PLACE_WORDS = frozenset({"in", "on", "at", "inside", "under", "upstairs", "downstairs"})


def _where_it_is(words: list[str]) -> list[str]:
    """ "the atlas should be on the dining table", "check whether she's in the bedroom": "is"."""
    out: list[str] = []
    i = 0
    while i < len(words):
        hedge = next((h for h in _HEDGED_BE if words[i : i + len(h)] == h), None)
        n = len(hedge) if hedge else 1
        place = words[i + n : i + n + 1]
        said = words[i + n + 1 : i + n + 2]
        if place and place[0] in _PLACE_WORDS and said and said[0] in _DETERMINERS | {"kit's", "our"}:
            if hedge:
                out.append("is")
                i += n
                continue
            if words[i] in _CONTRACTED_BE and out[-1:] in (["whether"], ["if"]):
                out += _CONTRACTED_BE[words[i]]
                i += 1
                continue
        out.append(words[i])
        i += 1
    return out


#: what may stand before "on"/"off" said as a verb ("help me off it", "you off the light")
_BEFORE_STATE = (["help", "me", "to"], ["help", "to"], ["help", "me"], ["please"], ["you"])


def _state_said_first(words: list[str]) -> list[str]:
    """ "off it", "help me off it", "please help to off the hallway light" (Singaporean and Indian English
    say "on" and "off" as verbs): "switch it off", "switch off the hallway light"."""
    rest = words
    lead = 1 if words[:1] == ["please"] else 0
    for before in _BEFORE_STATE:
        after = lead + len(before)
        if words[lead:after] == before and words[after : after + 1] in (["on"], ["off"]):
            rest = words[after:]
            break
    if rest[:1] not in (["on"], ["off"]) or len(rest) < 2:
        return words
    if rest[1] in ("it", "them"):  # "off it": switch it off
        return ["switch", rest[1], rest[0], *rest[2:]]
    return ["switch", *rest] if rest is not words else words


def _got_to(words: list[str]) -> list[str]:
    """ "where did the biscuit tin get (off) to", "where did it go off to": where is it; "... where my pen has
    got to" (a question's order inside another): "where has my pen got to"."""
    for tail in (["get", "off", "to"], ["go", "off", "to"], ["get", "to"]):
        n = len(tail)
        if words[:3] == ["where", "did", "the"] and len(words) > n + 3 and words[-n:] == tail:
            return ["where", "is", *words[2:-n]]
    if "where" in words and words[-3:] in (["has", "got", "to"], ["have", "got", "to"]):
        at = words.index("where")
        if at + 1 < len(words) - 3 and words[at + 1] in _POSSESSIVES:
            return [*words[: at + 1], words[-3], *words[at + 1 : -3], "got", "to"]
    return words


@lru_cache(maxsize=16)
def _names(vocabulary: Vocabulary) -> tuple[frozenset[str], frozenset[str], frozenset[str]]:
    """The world's phrases of things (items, furniture, devices), their first words, and the phrases of its
    lights (read once per vocabulary)."""
    things = frozenset(
        t.phrase
        for t in vocabulary.terms
        if any(vocabulary.is_subtype(t.type, k) for k in ("item", "furniture", "device"))
    )
    lights = frozenset(
        t.phrase
        for t in vocabulary.terms
        if vocabulary.is_subtype(t.type, "light") or vocabulary.is_subtype(t.type, "dimmer")
    )
    return things, frozenset(p.split()[0] for p in things), lights


def _name_at(words: list[str], at: int, phrases: frozenset[str]) -> int:
    """The number of words of the longest phrase of ``phrases`` said from ``at`` on (0: none)."""
    for end in range(len(words), at, -1):
        if " ".join(words[at:end]) in phrases:
            return end - at
    return 0


def regional_said(segments: list[list[str]], vocabulary: Vocabulary) -> list[list[str]]:
    """The sentences with the forms of the module docstring that need the world's names read."""
    things, firsts, lights = _names(vocabulary)
    firsts = firsts | {p.split()[-1] for p in things}
    out: list[list[str]] = []
    segments = (
        [  # a list's number said alone; not a level said after "to" ("down to, like, five")
            s
            for n, s in enumerate(segments)
            if len(s) > 1
            or s[0] not in _NUMBERS | {"to", "for"}
            or (n and set(segments[n - 1][-1:]) & _LEVEL_BEFORE)
        ]
        or segments
    )
    segments = _said_after(_aside_in_question(segments), things | firsts)
    people, items = phrases_of(vocabulary, "person"), phrases_of(vocabulary, "item")
    for n, segment in enumerate(segments):
        words = list(segment)
        if words[:1] and words[0] in _STEP and words[1:2] and words[1] in _NUMBERS:
            words = words[2:]  # "step two, take wilf to the bathroom"
        if n == 0 and words[:1] == ["got"] and words[1:2] and words[1] not in _NOT_GOT:
            words = ["is", "there", *words[1:]]  # "got oat milk in the fridge or not"
        if n == 0 and words[:2] == ["is", "it"] and words[2:3] and words[2] in _DETERMINERS:
            words = ["is", *words[2:]]  # "is it the tablet still on kit's desk"
        words = _my_said_me(_plural_said(words, items, firsts), firsts)
        words = [
            "the" if w == "them" and words[i + 1 : i + 2] and words[i + 1] in firsts else w
            for i, w in enumerate(words)
        ]  # "shut them blinds in the gym"
        if len(segments) > 1 and words[:2] in (["i'm", "off"], ["we're", "off"]) and len(words) > 2:
            continue  # "..., i'm off to the loo": where the speaker is going, no request
        if len(segments) > 1 and any(words[: len(w)] == w for w in _ABOUT_TO):
            continue  # "fixing to go to bed, get the lights": what the speaker is about to do
        if n and len(words) > 2 and (words[0] in _SUBJECTS | people) and words[1].endswith("ed"):
            continue  # "... to the dining table? huiling wanted to look at malaya": what someone did
        if n == len(segments) - 1 or len(words) <= 3:
            words = _tag_dropped(words, things)
        words = _come_here(_purpose_dropped(words, firsts, people), things)
        named = sum(bool(_name_at(s, i, items)) for s in segments[:n] for i in range(len(s)))
        if n and named:  # "the blanket and the teddy, bring to the nursery": them
            words = _object_said(words, "it" if named == 1 else "them")
        words = _light_got(words, lights)
        if words:
            out.append(words)
    return out


#: what says a device's state or level ("to forty percent", "on", "halfway")
_SETTINGS = frozenset({"percent", "on", "off", "open", "closed", "shut", "half", "halfway", "full", "fully"})


def _purpose_dropped(words: list[str], names: frozenset[str], people: frozenset[str]) -> list[str]:
    """ "reading lamp to forty percent for the assessment": what a device is set for, said last with words
    that name nothing of the world, is left out (not a thing the world lacks); "for the half" (a Dutch
    speaker's "voor de helft") is the setting itself, no purpose."""
    if "for" not in words[1:] or not _SETTINGS & set(words):
        return words
    at = len(words) - 1 - words[::-1].index("for")
    said = words[at + 1 :]
    if {"half", "halfway", "full", "fully", "percent"} & set(said):
        return words
    if said[:1] and said[0] in _DETERMINERS and not any(w in names or w in people for w in said):
        return words[:at]
    return words


#: a question about a thing said before the thing itself ("where is it, the remote?")
_WHERE_IT = (["where", "is", "it"], ["where's", "it"], ["where", "are", "they"], ["where", "are", "them"])


def _said_after(segments: list[list[str]], names: frozenset[str]) -> list[list[str]]:
    """ "where is it, the remote?", "where are they, my glasses?": the thing said after "it" or "they" is
    what is asked for."""
    out: list[list[str]] = []
    for segment in segments:
        thing = segment[1:] if segment[:1] and segment[0] in _DETERMINERS else segment
        if (
            out
            and out[-1] in _WHERE_IT
            and thing
            and " ".join(thing) in names | {t.split()[-1] for t in names}
        ):
            out[-1] = ["where", "is", *segment]
        else:
            out.append(list(segment))
    return out


#: carry verbs a learner says without their object, after a sentence that named the thing
_CARRIED = frozenset({"bring", "fetch", "take", "give", "carry"})
#: what may follow such a verb when its object is left out ("please bring to me", "please bring")
_NO_OBJECT = ("to", "here", "over", "please")


def _plural_said(words: list[str], items: frozenset[str], known: frozenset[str]) -> list[str]:
    """ "my sunglass" (a learner's singular of a name that is only plural, "sunglasses"): the name, where no
    thing of the world is called by the word itself; "a glass" stays a glass (glasses may be a pair)."""
    ends = {p.split()[-1] for p in items}
    return [
        w + "es" if w.endswith("ss") and w != "glass" and w + "es" in ends and w not in known else w
        for w in words
    ]


def _object_said(words: list[str], pronoun: str) -> list[str]:
    """ "I forget my sunglass on terrace table. Please bring to me" (a learner leaves the object out, as
    Japanese does): "bring it to me", the thing the sentence before named."""
    at = 1 if words[:1] == ["please"] else 0
    if words[at : at + 1] and words[at] in _CARRIED and (at + 1 == len(words) or words[at + 1] in _NO_OBJECT):
        return [*words[: at + 1], pronoun, *words[at + 1 :]]
    return words


def _aside_in_question(segments: list[list[str]]) -> list[list[str]]:
    """ "where, I ask myself, has Haruka got to?": "where" and the question it opens, without the aside."""
    out: list[list[str]] = []
    skip = 0
    for i, segment in enumerate(segments):
        if skip:
            skip -= 1
            continue
        after = segments[i + 2][:1] if i + 2 < len(segments) else []
        if segment == ["where"] and after and after[0] in _VERBS_AFTER:
            question = segments[i + 2]
            gone = question[-2:] in (["got", "to"], ["gone", "to"]) or question[-1:] == ["gone"]
            if question[0] in ("has", "have") and gone:  # "has haruka got to": where is haruka
                question = ["is", *question[1 : -2 if question[-1] == "to" else -1]]
            out.append(["where", *question])
            skip = 2
        else:
            out.append(segment)
    return out


def _my_said_me(words: list[str], firsts: frozenset[str]) -> list[str]:
    """ "where's me stick", "fetch us me flat cap": "me" before a thing's name (its first or last word), not
    after a verb that takes whom a thing is for, is "my"."""
    out = list(words)
    for i, word in enumerate(words):
        if word != "me" or not words[i + 1 : i + 2] or words[i + 1] not in firsts:
            continue
        if not (i and words[i - 1] in FOR_WHOM):
            out[i] = "my"
    return out


def _tag_dropped(words: list[str], things: frozenset[str]) -> list[str]:
    """A Singaporean question tag said last ("... can?", "... can or not?", "... or not?") left out."""
    for tag in _TAGS:
        n = len(tag)
        if len(words) <= n or tuple(words[-n:]) != tag:
            continue
        before = words[-n - 1]
        if tag[0] == "can" and (
            before in _DETERMINERS or any(f" {p}".endswith(f" {before} can") for p in things)
        ):
            return words  # "bring me the watering can"
        return words[:-n]
    return words


def _come_here(words: list[str], things: frozenset[str]) -> list[str]:
    """ "take my travel mug come" (Singaporean English): take it to the speaker."""
    if len(words) < 3 or words[-1] != "come" or not {"take", "bring", "get", "fetch"} & set(words[:-1]):
        return words
    ends = {p.split()[-1] for p in things}
    return [*words[:-1], "to", "me"] if words[-2] in ends else words


def _light_got(words: list[str], lights: frozenset[str]) -> list[str]:
    """ "get the light in the gym" with no state said: switch it off (American English)."""
    if "get" not in words or {"on", "off", "up", "down", "percent"} & set(words):
        return words
    at = words.index("get")
    if words[at + 1 : at + 2] != ["the"] or not _name_at(words, at + 2, lights | {"light", "lights"}):
        return words
    return [*words[:at], "switch", "off", *words[at + 1 :]]
