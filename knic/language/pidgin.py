"""Words of Nigerian (West African) Pidgin and the particles of Nigerian English, put back as said plainly
(used by :func:`knic.language.household.words_tidied`, one stretch of a command at a time, before
:mod:`knic.language.dialects`, which reads the serial verbs Pidgin shares with Jamaican English: "carry X go
Y", "bring come X"):

* "am" for "it" (and for "him" or "her"): "bring am come", "put am for the car"; "I am" stays;
* "wetin" for "what"; "dey" for "is" ("visitor dey for gate"), and "where X dey" is "where is X";
* "make you" before a verb ("make you carry the umbrella ...") is "please": a request put politely;
* "for" is Pidgin's one preposition of place: after a verb of putting it is "on" ("put the umbrella for the
  shoe rack"), after "it" or "them" carried "to" ("bring am for study"; "for me" and "for him" stay), after
  "dey" "at"; where a place is said already "for" is English's ("put the candle on the shelf for books");
* "give" after a thing carried, before the one given it, is "to" ("carry the football from the bench give
  Tobi", "carry the umbrella go give Oga"; "... and give it to tracy" stays), as "go" before where to is
  (:mod:`knic.language.dialects`); "come" before "the" after a thing carried is "to" ("bring am come the
  compound");
* "go the X" opening a stretch is "go to the X" ("go the store, ..."); "on it" and "off it" opening one are
  "switch it on" and "switch it off" ("is the security light off? please on it"), and "help me on the fan"
  is "help me switch on the fan";
* the particles of Nigerian English and Pidgin that ask nothing ("oya", "o", "sha", "jare", "abi", "ehen",
  "shey", Yoruba "e jo" for "please", "omo mi", "my child" said to the listener) are dropped;
* "small" said last after a device is "a bit" ("open the curtain small": how far?);
* "light" for the mains power, said bare after taking or bringing it or opening a remark ("NEPA has taken
  light again", "light don go", "there is no light"): "power", no device to ask about.
"""

from __future__ import annotations

#: particles that ask nothing: Pidgin "oya" (come on), Yoruba-English "o", "sha", "jare", "abi", "ehen"
_PARTICLES = frozenset({"oya", "o", "sha", "jare", "abi", "ehen", "shey", "ehn"})
#: verbs of putting after which Pidgin "for" is "on"
_PUTTING = frozenset({"put", "keep", "drop", "leave", "place", "hang", "set"})
#: verbs of carrying after which Pidgin "for" is "to" and "give" or "come" says to whom or where
_CARRYING = frozenset({"carry", "bring", "take", "fetch", "send", "move"})
#: verbs of working a device, after which "small" said last is "a bit"
_WORKING = frozenset({"open", "close", "on", "off", "switch", "turn", "dim", "shut", "raise", "lower"})
#: verbs after which "for" is English's ("look for", "wait for", "ask for")
_OTHER_VERBS = frozenset({"look", "search", "hunt", "wait", "ask", "asking", "check", "find", "call"})
#: words before "give" that make it a verb of its own ("... and give it to tracy")
_JOINED = (["and"], ["then"], ["to"], ["please"], ["also"], ["or"], ["i"], ["you"], ["can"], ["and", "then"])
#: what "give" as a verb of its own is said with
_GIVEN = frozenset({"it", "them", "back", "you", "the", "a", "an", "this", "that", ""})
#: prepositions of place that leave "for" as it is ("put the candle on the shelf for books")
_PLACED = frozenset({"on", "in", "into", "onto", "at", "under", "by", "to", "inside", "beside", "next"})
#: words after "for" that keep it: who a thing is for
_FOR_WHOM = frozenset({"me", "us", "you", "him", "her", "them", "my", "your", "our"})


def pidgin_words(tokens: list[str]) -> list[str]:
    """One stretch of a command with the Pidgin words of the module docstring said plainly."""
    if not tokens:
        return tokens
    words = _yoruba_dropped(tokens)
    words = [w for w in words if w not in _PARTICLES] or words
    if words[:2] == ["make", "you"] and len(words) > 2:  # "make you carry the umbrella go give oga"
        words = ["please", *words[2:]]
    lead = 1 if words[:1] in (["please"], ["abeg"]) else 0
    if words[lead : lead + 1] in (["on"], ["off"]) and words[lead + 1 : lead + 2] in (
        ["it"],
        ["them"],
        ["am"],
    ):
        it = "them" if words[lead + 1] == "them" else "it"
        words = [*words[:lead], "switch", it, words[lead], *words[lead + 2 :]]  # "please on it"
    for i in range(len(words) - 2):
        if (
            words[i : i + 2] == ["help", "me"]
            and words[i + 2] in ("on", "off")
            and words[i + 3 : i + 4] == ["the"]
        ):
            words = [*words[: i + 2], "switch", *words[i + 2 :]]  # "help me on the fan"
            break
    if words[:2] == ["go", "the"]:  # "go the store"
        words = ["go", "to", *words[1:]]
    if words[:1] == ["where"] and "dey" in words[1:]:  # "where my sunglasses dey": where is
        words = ["where", "is", *[w for w in words[1:] if w != "dey"]]
    words = _power_said(words)
    out: list[str] = []
    verb = ""  # the last verb of carrying, putting or working said
    for i, word in enumerate(words):
        nxt = words[i + 1] if i + 1 < len(words) else ""
        if word in _CARRYING | _PUTTING | _WORKING and not verb:
            verb = word
        elif word in _OTHER_VERBS or word in ("and", "then"):  # "... and also look for the remote"
            verb = ""
        if word == "am" and out[-1:] != ["i"]:
            word = "it"
        elif word == "wetin":
            word = "what"
        elif word == "dey":
            word = "is"
        elif word == "for" and nxt not in _FOR_WHOM and nxt:
            word = _for(verb, out)
        elif word == "give" and verb in _CARRYING and out[-1:] not in ([], *_JOINED) and nxt not in _GIVEN:
            if out[-1] == "go":  # "carry the umbrella go give oga"
                out.pop()
            word = "to"
        elif word == "come" and verb in _CARRYING and nxt in ("the", "to") and len(out) > 1:
            if nxt == "to":
                continue
            word = "to"
        elif word == "small" and not nxt and verb in _WORKING and out[-1:] != ["a"]:
            out += ["a", "bit"]
            continue
        out.append(word)
    return out


def _for(verb: str, said: list[str]) -> str:
    """What Pidgin "for" stands for after ``said``, the stretch's first verb being ``verb``: only where
    English would not say "for" so ("put the umbrella for the shoe rack", "bring am for study")."""
    if said[-1:] == ["is"] and said[:1] != ["is"]:  # "visitor dey for gate"
        return "at"
    if verb in _PUTTING and not _PLACED & set(said):
        return "on"
    if verb in _CARRYING and said[-1:] in (["it"], ["them"]) and not _PLACED & set(said):
        return "to"
    return "for"


def _yoruba_dropped(tokens: list[str]) -> list[str]:
    """Yoruba "e jo" (please) and "omo mi" (my child, said to the listener) dropped."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        pair = tokens[i : i + 2]
        if pair in (["e", "jo"], ["omo", "mi"]):
            i += 2
            continue
        out.append(tokens[i])
        i += 1
    return out


#: verbs after which a bare "light" is the mains power ("NEPA has taken light", "they have brought light")
_POWER_VERBS = frozenset(
    {"take", "takes", "took", "taken", "bring", "brings", "brought", "restore", "restored"}
)
#: what may follow that "light": the stretch ends, or says when
_AFTER_POWER = frozenset(
    {"", "again", "since", "now", "today", "yesterday", "o", "for", "this", "at", "finally"}
)
#: what follows "light" opening a stretch when it is the power ("light don go", "light has gone")
_POWER_GONE = frozenset({"don", "has", "is", "came", "come", "went", "just"})


def _power_said(words: list[str]) -> list[str]:
    """Nigerian English "light" for the mains power, said bare after taking or bringing it ("NEPA has taken
    light again") or opening a remark ("light don go", "light has come back"): "power", no device."""
    out = list(words)
    for i, word in enumerate(words):
        if word != "light":
            continue
        nxt = words[i + 1] if i + 1 < len(words) else ""
        taken = i > 0 and words[i - 1] in _POWER_VERBS and nxt in _AFTER_POWER
        gone = i == 0 and nxt in _POWER_GONE and len(words) > 2
        if taken or gone or (i > 0 and words[i - 1] == "no" and nxt in _AFTER_POWER):
            out[i] = "power"
    return out
