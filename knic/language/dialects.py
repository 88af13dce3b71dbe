"""Words of regional and world Englishes that stand for plain English words only in context, put back as said
plainly (used by :func:`knic.language.household.words_tidied`, one stretch of a command at a time, before
:mod:`knic.language.regional` reads the forms that need the world's names; the words that always stand for
one plain word, such as Jamaican "di" for "the", are ``spellings`` in ``commands.yaml``):

* Jamaican English: "mi" for "I" opening a stretch ("mi cyaan find ..."), for "me" before where to, after
  "give" or before no thing ("carry mi go a di bedroom", "bring mi di sheets"), else for "my" ("bring mi
  slippers"); "him" for "he" opening a stretch, and for "his" before a thing after a preposition, after
  "him" or after a verb of the past ("give him him comic", "inna him tea", "Tobias cut him finger"); "dem"
  after a thing is its plural said again, dropped ("open di blinds dem"), elsewhere "them"; "where X deh"
  is "where is X"; "go a" is "go to"; "go" said after the thing carried, before where to ("carry di teapot
  go a di kitchen", and in Nigerian English "carry the cup go kitchen"), is "to"; "come" straight after a
  verb of carrying ("bring come di sugar bowl"), as after the thing, is where to: left out (a thing brought
  is brought to the speaker);
* Northern English "tha" for "you" after a verb of asking ("has tha seen ...": "have you seen"); elsewhere
  "tha" is a typed "the" ("turn on tha light"); "it" or "them" with the person straight after, said last
  ("take it him", "give them her"): "to" that person;
* Tagalog "paki-" (please) before a verb ("pakibring the sheets", "paki-close the curtains"): the verb; "po"
  (politeness, "where po is the vacuum?"), Filipino English "for a while" (just a moment) and "already"
  before the thing acted on ("turn off already the light"): dropped;
* "wait on me" (American South, Scotland): "wait for me";
* "come" or "go" before a state after "make" ("mek di bedside lamp come on", "make the lights go off"): the
  device made so;
* "me" opening a stretch before "want", "need" or "go" ("me want the apple!", a child's or a learner's; "me
  go wet room", a signer's): "I"; "dem" after a verb that acts on things ("close dem"): "them";
* "for me" said between a thing and where it is ("switch on di light fi mi inna di kitchen"): left out, the
  place says which light;
* "like" before a number ("likkle bit, like twenty", "to like 40"): "to", a level said roughly;
* "up the stairs", "down the stairs" before where to ("help me up the stairs to the heather room"): the way
  there, not a place;
* Caribbean "she" after a preposition ("Wanjiru in she room?", "give it to she"): "her";
* "by" for where to after "carry", "take" or "bring" with no one and nowhere else said (Caribbean English
  "carry dis mug by de sink", "carry de bible by Kieran": to the sink, to Kieran); "bring me the cup by the
  sink" stays the cup that is by the sink.
"""

from __future__ import annotations

import itertools

#: verbs of asking after which "tha" is "you" ("has tha seen", "can tha fetch")
_ASKING = frozenset({"has", "have", "can", "could", "will", "would", "did", "do", "wilt", "hast"})
#: words after which "mi" or "him" is no possessive (what follows is no thing of theirs)
_NOT_A_THING = frozenset(
    {"the", "a", "an", "to", "in", "on", "at", "for", "from", "and", "then", "please", "here", "there", "go"}
    | {"come", "some", "your", "his", "her", "up", "down", "back", "into", "with", "one", "off", "out", "now"}
    | {"today", "tonight", "again", "too", "as", "so", "because", "when", "if", "or", ""}
)
#: people said straight after "it" or "them", given the thing ("take it him")
_GIVEN = frozenset({"him", "her", "me", "us"})
#: verbs of carrying after whose object "go" is "to" (Jamaican serial verbs: "carry it go a di kitchen")
_CARRYING = frozenset({"carry", "take", "bring", "fetch", "send", "move", "put"})
#: prepositions after which Jamaican "him" is "his"
_PREPOSITIONS = frozenset({"in", "on", "to", "from", "into", "at", "off", "with", "for"})
#: past verbs after which "him" before a thing is "his" ("tobias cut him finger")
_PAST = frozenset({"cut", "hurt", "broke", "lost", "left", "dropped", "burnt", "burned", "forgot", "bumped"})
#: where "mi" stands for "me": before where to or a verb of going
_MI_ME = frozenset({"go", "come", "to", "a", "in", "up", "down", "back", "over", "out"})
#: what joins actions: "go" after one starts a new action
_JOINING = frozenset({"and", "then", "to", "please", "", "n"})
#: what says a new action comes next ("put it in the bin and after that go to the hallway")
_NEXT_ACTION = frozenset({"and", "then", "after", "afterwards", "next", "finally", "also", "n"})
#: what "go a" is "go to" before
_ARTICLES = frozenset({"the", "my", "your", "his", "her", "our", "me", "mi"})
#: what "for me" may stand before and be left out ("the light for me in the kitchen")
_PLACE_AFTER = frozenset({"in", "on", "at", "inside", "by", "near"})
#: states a device is made to come or go to ("make the lamp come on", "make the lights go off")
_STATES = frozenset({"on", "off", "out"})
#: number words a level may be said with after "like" ("like twenty")
_NUMBERS = frozenset(
    {"five", "ten", "fifteen", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"}
    | {"hundred", "half", "halfway"}
)
#: what "like" follows when it is the verb ("i'd like twenty")
_LIKING = frozenset({"i", "i'd", "would", "you", "we", "they", "he", "she", "don't", "really", "we'd"})
#: what "me" opening a stretch is the subject of ("me want the apple", "me need my glasses")
_WISHING = frozenset({"want", "need", "like", "wanna", "needs", "wants"})
#: verbs of carrying after which Caribbean "by" says where to; and what says whom or where to already
_CARRY_BY = frozenset({"carry", "take", "bring"})
_TO_SAID = frozenset({"me", "us", "here", "to", "into", "onto", "for", "him", "her"})
#: verbs after which "dem" is "them", the thing acted on ("close dem"), not a plural said again
_ACTING = frozenset(
    {"close", "open", "shut", "switch", "turn", "leave", "find", "check", "move", "get", "pass"}
)
#: the Jamaican plural said after a thing ("di blinds dem")
_PLURAL_MARK = "dem"


def dialect_words(tokens: list[str]) -> list[str]:
    """``tokens`` (one stretch of a command, lower case, after ``spellings``) with the words of the module
    docstring said in plain English."""
    out: list[str] = []
    carried = False  # a verb of carrying was said in this action
    i = 0
    while i < len(tokens):
        token, nxt = tokens[i], tokens[i + 1] if i + 1 < len(tokens) else ""
        before = out[-1] if out else ""
        i += 1
        if token == "tha":
            if before in _ASKING:
                out[-1:] = ["have" if before == "has" else before, "you"]
            else:
                out.append("the")
            continue
        if token == "po" or (token == "for" and tokens[i : i + 2] == ["a", "while"]):
            i += 0 if token == "po" else 2  # Tagalog "po", politeness; "for a while": just a moment
            continue
        if token.startswith("paki") and token[4:].isalpha() and len(token) > 5:
            token = token[4:]  # "pakibring"
        elif token == "paki":
            continue  # "paki-close"
        if token in ("up", "down") and tokens[i : i + 3] in (["the", "stairs", "to"], ["the", "stair", "to"]):
            i += 2  # "help me up the stairs to ...": the way, not a place
            continue
        if carried and token == "go" and nxt and before not in _JOINING | _NEXT_ACTION:
            out.append("to")  # "carry di teapot go a di kitchen", "carry the cup go kitchen"
            i += nxt in ("a", "to")
            continue
        if token in ("come", "go") and nxt in _STATES and _making(out):
            continue  # "mek di lamp come on": turn it on
        if token == "come" and before in _CARRYING and nxt in _ARTICLES | {"a", "some"}:
            continue  # "bring come di sugar bowl": bring it here
        if (
            token == "for"
            and nxt in ("me", "mi")
            and tokens[i + 1 : i + 2]
            and tokens[i + 1] in _PLACE_AFTER
            and out
        ):
            i += 1  # "switch on the light for me in the kitchen": the place narrows the light
            continue
        if token == "already" and nxt in _ARTICLES | {"a", "all"}:
            continue  # "turn off already the light": already said before the thing
        if token == "a" and before == "go" and nxt in _ARTICLES:
            token = "to"
        elif token == "like" and (nxt.isdigit() or nxt in _NUMBERS) and before not in _LIKING:
            if before in ("to", "at"):
                continue  # "to like twenty": to twenty
            token = "to"  # "likkle bit, like twenty": to twenty
        elif token == "on" and before == "wait" and nxt in ("me", "us"):
            token = "for"
        elif token == "mi":
            token = _mi(before, nxt, bool(out))
        elif token == "me" and not out and (nxt in _WISHING or nxt in ("go", "going")):
            token = "i"  # "me want the apple!", "me go wet room" (a child's, a learner's or a signer's "I")
        elif token == "him":
            if not out:
                token = "he"
            elif nxt not in _NOT_A_THING and (before in _PREPOSITIONS | _PAST or before == "him"):
                token = "his"
        elif token == _PLURAL_MARK:
            if before and before not in _CARRYING | _NOT_A_THING | _JOINING | _ACTING:
                continue  # "di blinds dem": the plural said again
            token = "them"
        if token == "she" and before in _PREPOSITIONS | {"into", "by", "inna"}:
            token = "her"  # "in she room"
        if token == "by" and _carried_to(out, tokens[i:]):
            token = "to"  # "carry dis mug by de sink"
        if token in _GIVEN and before in ("it", "them") and nxt in ("", "and", "then", "please"):
            out.append("to")  # "take it him"
        listed = token == "and" and nxt in _ARTICLES | {"a", "an", "some"}  # "the cornflakes and the jam"
        carried = (carried or token in _CARRYING) and (token not in _NEXT_ACTION or listed)
        out.append(token)
    if len(out) > 2 and out[0] == "where" and out[-1] == "deh":  # "where keith deh?": where is keith
        out = ["where", "is", *out[1:-1]]
    return out


def _mi(before: str, nxt: str, said: bool) -> str:
    """Jamaican "mi": "i" opening a stretch; "me" before where to, after "give" or before no thing; else
    "my"."""
    if not said:
        return "i"
    if nxt in _MI_ME or nxt in _NOT_A_THING or before in ("give", "gimme"):
        return "me"
    return "my"


def _making(said: list[str]) -> bool:
    """Whether the latest action said so far is "make" ("make the lamp come on"), no "and" or "then" since."""
    for word in reversed(said):
        if word in ("and", "then"):
            return False
        if word == "make":
            return True
    return False


def _carried_to(said: list[str], rest: list[str]) -> bool:
    """Whether the latest action said so far carries a thing ("carry", "take", "bring") and says, before or
    after, no one and nowhere it goes to ("bring me", "take it to", "for tracy"); "and" before an article
    lists things ("the bible and the book by the recliner")."""
    ahead = list(itertools.takewhile(lambda w: w not in ("and", "then"), rest))
    for i in range(len(said) - 1, -1, -1):
        if said[i] in _CARRY_BY:
            return not _TO_SAID & set(said[i + 1 :] + ahead)
        if said[i] == "then" or (
            said[i] == "and" and said[i + 1 : i + 2] and said[i + 1] not in _ARTICLES | {"a"}
        ):
            return False
    return False
