"""Words a dictation app or a careful speaker writes out or mishears, put back as said plainly (used by
:func:`knic.language.household.words_tidied`, one stretch of a command at a time):

* "it is" opening a stretch, before no article ("switch on the fan, it is very hot"): "it's", a
  remark about the weather or the room, not "it" for a thing said before ("is it on the table" stays);
* "their is", "their are" (a homophone): "there is", "there are"; "were" opening a stretch before "is",
  "are", "did" or "have" ("were are my car keys"): "where"; "no" after "you" ("do you no where ..."):
  "know"; "sea" after "you", "can" or "to" ("can you sea if ..."): "see";
* "were" before a word in "-ing" where no one it could be said of comes before it ("switch the garden lights
  on were having a barbecue", "were going out"), or before what people do ("... in the living room were going
  to bed"): "we're", the speaker's own doing;
* "still" after a thing and before where it is ("is the lasagne still in the oven?"): dropped, the question is
  where the thing is; "the light is still on" keeps it (a complaint);
* what is waited for ("go to the hallway and wait for the postman", "... wait for mark there", "wait in the
  hall for the taxi driver"): dropped up to the next "and" or "then", the robot waits where it went ("wait
  for me" is a verb of its own and stays);
* "over" after a thing and before "the" ("the blind in the kitchen, the one over the sink", "the light over
  the sink"): "above", where it is; after a verb of moving or "it" ("hand it over the fence") it stays, and
  so does "over" before no article ("turn on over lights", a mishearing);
* "hear" for "here" after "over", "in", "back", "up", "down" or "right", or last ("bring the red mug over
  hear"); "can you hear me" stays;
* a term of address said last ("bring me my blanket my boy", "..., boet", "..., my dear"): dropped, unless a
  preposition comes before it ("take it to my boy");
* a level said as a change ("turn the lamp up by 20 percent", "down by 10"): "a bit", a level meant but not
  said (the reader knows no present level: it asks how far); "halfway between off and full": "halfway";
* a thing asked to be done in the passive ("have the lounge curtains opened", "could I get the lights
  switched off", "have the towel sent up to ...", "I'd be grateful if the suitcase could be taken down to
  ...", "arrange for the newspaper to be brought to ..."): the verb said first ("open the lounge curtains"),
  as a hotel guest speaks to staff;
* "is" after a verb of giving and before a thing ("fetch is the hammer off the workbench", "bring is the
  teapot", Geordie and Scots): "me";
* "all the light", "all the lamp", "all the blind" (a learner's singular after "all"): the plural, every one;
* "where'd ... get to", "where did ... get to" (where a thing has gone): "where is ...";
* "on" after the state "off" or "on" before where ("switch the light off on the landing", "all lights off on
  the balcony"): "in", the place, not the state said again;
* "both" after "them" ("the tongs and the sun cream, bring them both to the kitchen"), "all" there before
  where they go ("put them all on the table"), and "both of them": "them";
* a request asked as what the robot is about to do ("are you going to switch off the hall light?", "are you
  gonna bring me the teapot?", "so are you going to put the butter away?"): the verb said first, as "will
  you" already is; "are you going to be long?", "are you going to the kitchen?" stay questions about it;
* where someone is, said out or guessed in a stretch of its own ("find Hugo, he is in the kitchen", "she
  should be in the bedroom", "he is probably in the study"): "he's in ...", as said short;
* "is he in the workshop?" after a question or a request ("where is Lenny? is he in the workshop?"): "check
  if he is in the workshop", a search there;
* "like" said as a filler between a preposition and a thing's name ("put the fork on like the table",
  "bring it to Yuki at like the entrance"): dropped.
"""

from __future__ import annotations

#: what may stand before "were" said for "we're": the end of a request, not a thing it is said of
_BEFORE_WE_RE = frozenset(
    {"on", "off", "up", "down", "open", "closed", "please", "now", "too", "as", "because"}
)
#: what "over" follows when it says where something moves, not where a thing is
_MOVED_OVER = frozenset(
    {
        "it",
        "them",
        "go",
        "come",
        "walk",
        "run",
        "jump",
        "climb",
        "hand",
        "pass",
        "throw",
        "lean",
        "bend",
        "fall",
        "all",
    }
)
#: what says a number is a percentage
_PERCENT = frozenset({"percent", "%", "per", "pc"})
_TENS = frozenset(
    {"five", "ten", "fifteen", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty"}
)


def _waiting(said: list[str]) -> bool:
    """Whether the latest action said is a wait, with where at most ("wait in the hall for ...")."""
    if not said or "wait" not in said:
        return False
    at = len(said) - 1 - said[::-1].index("wait")
    return not any(word in ("and", "then") for word in said[at:])


def _number(word: str) -> bool:
    return word.isdigit() or word in _TENS


#: terms of address said last, after "my" or alone
_ADDRESSED = frozenset({"boy", "girl", "dear", "darling", "friend", "lovely", "love", "angel", "sweetheart"})
_ADDRESSED_ALONE = frozenset({"boet", "bru", "china", "mate", "mein", "lad", "lass", "doll"})
#: what may come before someone spoken of, not to ("take it to my boy")
_SPOKEN_OF = frozenset({"to", "for", "with", "from", "by", "of", "near", "give", "find", "and", "is", "are"})
#: the devices that hang over a thing, said before "over" ("light over dining table": above it)
_HUNG = frozenset({"light", "lights", "lamp", "lamps", "blind", "blinds"})
#: what "over" after such a device comes before that is no place ("the light over there", "over lights")
_NOT_A_PLACE = frozenset({"there", "here", "and", "then", "lights", "light", "lamps", "blinds"})
#: what "here" follows that "hear" does not ("over here", "back here")
_HERE_AFTER = (["over"], ["in"], ["back"], ["up"], ["down"], ["right"])
#: where things go, after "them all"
_GOING = frozenset({"to", "on", "in", "into", "onto", "back", "away", ""})
#: where a thing is said to be, after "still"
_PLACES = frozenset({"in", "on", "at", "inside", "under", "by", "next"})
#: what "still" follows when it says how something is ("is still on"), not where a thing is
_BEING = frozenset({"is", "are", "was", "were", "it's", "they're", "it", "they"})
#: what people do, not things, after "were" ("... in the living room were going to bed")
_OUR_DOING = frozenset({"going", "having", "heading", "leaving", "watching", "eating", "cooking"})
#: articles and determiners: "it is a ..." names what it is
_NAMING = frozenset({"a", "an", "the", "my", "your", "this", "that", "in", "on", "at"})


#: past participles of what is done to a thing, said after it in "have the X opened" -> the verb
_DONE = {
    "opened": "open",
    "closed": "close",
    "shut": "shut",
    "drawn": "draw",
    "dimmed": "dim",
    "lowered": "lower",
    "raised": "raise",
    "switched": "switch",
    "turned": "turn",
    "brought": "bring",
    "sent": "send",
    "taken": "take",
    "carried": "carry",
    "fetched": "fetch",
    "delivered": "deliver",
    "moved": "move",
}
#: what may come before "have" or "get" that asks for a thing done ("could you have ...")
_ASKING_DONE = frozenset(
    {"please", "could", "can", "would", "will", "you", "just", "kindly", "pip", "robot", "may", "i", "we"}
)


def had_done(tokens: list[str]) -> list[str]:
    """A thing asked to be done in the passive ("have the lounge curtains opened, would you", "could I get the
    lights switched off", "please have the bath towel sent up to the bluebell room"): the verb said first
    ("open the lounge curtains", "send the bath towel up to ...")."""
    if (wished := _wished_done(tokens)) is not None:
        return wished
    at = next((i for i, t in enumerate(tokens) if t in ("have", "get")), None)
    if at is None or any(t not in _ASKING_DONE for t in tokens[:at]):
        return tokens
    if tokens[at - 1 : at] in (["i"], ["we"]) and tokens[at - 2 : at - 1] not in (
        ["could"],
        ["can"],
        ["may"],
    ):
        return tokens  # "i have the blinds closed already": said of oneself
    done = next((i for i in range(at + 2, min(len(tokens), at + 7)) if tokens[i] in _DONE), None)
    if done is None or tokens[at + 1] in ("to", "it", "them", "been", "got", "a", "an"):
        return tokens
    if {"and", "then", "n"} & set(tokens[at:done]):
        return tokens  # "get the cup and have it brought to me": two actions
    return [*tokens[:at], _DONE[tokens[done]], *tokens[at + 1 : done], *tokens[done + 1 :]]


def _wished_done(tokens: list[str]) -> list[str] | None:
    """ "I'd be grateful if the suitcase could be taken down to the hall", "please arrange for the newspaper
    to be brought to the breakfast room": the verb, the thing and the rest ("take the suitcase down to the
    hall"); None when the command is not said so."""
    done = next((i for i, t in enumerate(tokens) if t in _DONE and i >= 3 and tokens[i - 1] == "be"), None)
    if done is None or tokens[done - 2] not in ("could", "would", "can", "will", "to", "might"):
        return None
    opens = [i for i in range(done - 2) if tokens[i] in ("if", "for", "that")]
    if not opens or done - 2 - opens[-1] < 2 or tokens[opens[-1] + 1] in ("you", "i", "we", "it", "they"):
        return None
    return [_DONE[tokens[done]], *tokens[opens[-1] + 1 : done - 2], *tokens[done + 1 :]]


#: verbs after which "is" before a thing is the north of England's and Scotland's "me" ("fetch is the hammer")
_GIVING = frozenset({"bring", "fetch", "get", "give", "hand", "pass", "grab", "chuck", "throw", "hoy"})
#: verbs a request opens with, after "are you going to" (not "be", nor a place: "going to the kitchen")
_ASKED_VERBS = frozenset(
    {
        "bring",
        "take",
        "get",
        "fetch",
        "grab",
        "put",
        "place",
        "switch",
        "turn",
        "open",
        "close",
        "shut",
        "dim",
    }
    | {"set", "find", "look", "check", "carry", "move", "go", "give", "hand", "pass", "leave", "draw", "pull"}
)

#: words that make "are you going to ..." a question about the plan itself
_WONDERING = frozenset({"why", "how", "when", "where", "what", "who", "which", "whether", "if"})


def _planned(tokens: list[str]) -> list[str]:
    """``tokens`` from the verb on where "are you going to" comes before a request's verb (see the module
    docstring); else as they are."""
    for i in range(len(tokens) - 4):
        # "why are you going to open it?" asks why
        if (
            tokens[i : i + 4] == ["are", "you", "going", "to"]
            and tokens[i + 4] in _ASKED_VERBS
            and _WONDERING.isdisjoint(tokens[:i])
        ):
            return tokens[:i] + tokens[i + 4 :]
    return tokens


def _got_to(tokens: list[str]) -> list[str]:
    """ "where'd my stetson get to", "where did the keys get to": "where is ...", as "where's ... got to" is
    read; else ``tokens`` as they are."""
    opening = 1 if tokens[:1] == ["where'd"] else 2 if tokens[:2] == ["where", "did"] else 0
    if opening and len(tokens) > opening + 2 and tokens[-2:] == ["get", "to"]:
        return ["where", "is", *tokens[opening:-2]]
    return tokens


def contracted(tokens: list[str]) -> list[str]:
    """``tokens`` (one stretch of a command, lower case) with the statements of the module docstring said as
    contractions."""
    tokens = had_done(_got_to(_planned(_where_said(_asked_if_there(tokens)))))
    out: list[str] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
        after = tokens[i + 2] if i + 2 < len(tokens) else ""
        if not out and token == "it" and nxt == "is" and after and after not in _NAMING:
            out.append("it's")
            i += 2
            continue
        if token == "like" and out[-1:] and out[-1] in _LIKE_AFTER and nxt in _NAMING:
            i += 1  # "put it on like the table", "bring it to like the kitchen": a filler, not a liking
            continue
        if token == "for" and _waiting(out) and nxt not in ("me", "us"):
            while i < len(tokens) and tokens[i] not in ("and", "then", "there"):
                i += 1
            continue
        if out[-1:] in (["them"], ["em"]) and (token == "both" or (token == "all" and nxt in _GOING)):
            i += 1
            continue
        if token == "both" and nxt == "of" and after in ("them", "em"):
            i += 2
            continue
        if token == "by" and _number(nxt) and (after in _PERCENT or out[-1:] in (["up"], ["down"])):
            out += ["a", "bit"]
            i += (3 + (after == "per")) if after in _PERCENT else 2  # "per cent": one word more
            continue
        if token in ("halfway", "midway") and nxt == "between" and "and" in tokens[i:]:
            out.append(token)
            i = tokens.index("and", i) + 2
            continue
        if token == "their" and nxt in ("is", "are"):
            out.append("there")
        elif token == "were" and not out and nxt in ("is", "are", "did", "have", "has", "do"):
            out.append("where")
        elif token == "no" and out[-1:] == ["you"] and nxt in ("where", "if", "whether"):
            out.append("know")
        elif token == "sea" and out[-1:] in (["you"], ["can"], ["to"]):
            out.append("see")
        elif token == "over" and out and out[-1] not in _MOVED_OVER and nxt == "the":
            out.append("above")
        elif token == "over" and out[-1:] and out[-1] in _HUNG and nxt and nxt not in _NOT_A_PLACE:
            out.append("above")  # a learner's "light over dining table": where it hangs, with no article
        elif token == "hear" and (not nxt or out[-1:] in _HERE_AFTER):
            out.append("here")
        elif token in ("light", "lamp", "blind") and out[-2:] in (["all", "the"], ["all", "my"]):
            out.append(token + "s")  # "close all the light in the study" (a learner's singular): every one
        elif token == "is" and out[-1:] and out[-1] in _GIVING and nxt in _NAMING:
            out.append("me")  # "fetch is the hammer", "bring is a cuppa" (Geordie, Scots): "me"
        elif token == "on" and out[-1:] in (["off"], ["on"]) and nxt in ("the", "my", "our"):
            out.append("in")  # "switch the light off on the landing": where, not the state again
        elif (
            token == "still"
            and out
            and out[-1] not in _BEING
            and nxt in _PLACES
            and (after in ("the", "my", "a") or after.startswith("t'") or after.endswith("'s"))
        ):
            pass
        elif (
            token == "were"
            and nxt.endswith("ing")
            and (not out or out[-1] in _BEFORE_WE_RE or nxt in _OUR_DOING)
        ):
            out.append("we're")
        else:
            out.append(token)
        i += 1
    return _unaddressed(out)


#: words after which "like" before a thing's name is a filler ("put it on like the table")
_LIKE_AFTER = frozenset({"on", "in", "at", "to", "into", "onto", "from", "near", "by", "under", "off", "of"})
#: what may stand between "he", "she" or "they" and where they are ("he should be in the kitchen", "she is
#: probably in the bedroom"), and what says where
_MAYBE = frozenset({"should", "must", "might", "may", "could", "will", "be", "probably", "maybe", "perhaps"})
_LIKELY = frozenset({"probably", "maybe", "perhaps", "likely", "still"})
_AT = frozenset({"in", "at", "on", "by", "near", "next"})


def _asked_if_there(tokens: list[str]) -> list[str]:
    """ "where is Lenny? is he in the workshop?", "find the drill. is it in the garage?": a stretch asking
    whether he, she, it or they are somewhere is "check if he is in the workshop", a search there for the one
    said before (a question opening a later sentence opens no command of its own)."""
    asked = len(tokens) > 3 and tokens[0] in ("is", "are") and tokens[1] in ("he", "she", "it", "they")
    if asked and tokens[2] in _AT and tokens[2] != "next":
        return ["check", "if", tokens[1], tokens[0], *tokens[2:]]
    return tokens


def _where_said(tokens: list[str]) -> list[str]:
    """ "find Hugo, he is in the kitchen", "she should be in the bedroom", "he is probably in the study": a
    stretch opening with where someone is, said out or with a guess, is "he's in the kitchen", as "he's in the
    den" already says where he is."""
    if len(tokens) < 3 or tokens[0] not in ("he", "she", "they"):
        return tokens
    at = 1
    while at < len(tokens) and (tokens[at] in _MAYBE or (at == 1 and tokens[at] in ("is", "are"))):
        at += 1
    said = tokens[1:at]
    sure = said[:1] in (["is"], ["are"]) and all(w in _LIKELY for w in said[1:])
    guessed = len(said) >= 2 and said[-1] == "be" and said[0] in _MAYBE
    if at == 1 or at >= len(tokens) or tokens[at] not in _AT or not (sure or guessed):
        return tokens
    return ["they're" if tokens[0] == "they" else tokens[0] + "'s", *tokens[at:]]


def _unaddressed(tokens: list[str]) -> list[str]:
    """``tokens`` without a term of address said last (see the module docstring)."""
    said = 0
    if len(tokens) > 2 and tokens[-2] == "my" and tokens[-1] in _ADDRESSED:
        said = 2
    elif len(tokens) > 1 and tokens[-1] in _ADDRESSED_ALONE:
        said = 1
    if said and tokens[-said - 1] not in _SPOKEN_OF:
        return tokens[:-said]
    return tokens
