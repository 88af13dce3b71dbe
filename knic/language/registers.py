"""Words of the office and of the pulpit, put back as said plainly (used by
:func:`knic.language.household.words_tidied`, one stretch of a command at a time):

* "revert with" (office English for "reply with") and "loop me in on" are "tell me": "kindly revert with the
  location of my car keys" asks where they are; "FYI" and "for your information" opening a stretch are
  dropped ("FYI the study light is on, switch it off");
* a thing that "should be", "must be" or "needs to be" on or in a place, said as a stretch of its own ("per
  my earlier instruction, the calculator should be on the study desk"), is to be put there
  (:func:`to_be_put`, on the command's sentences), unless another sentence acts on it ("the atlas should be
  on the dining table; bring it here" says where it is, hedged); "please see to it" after it asks nothing
  more (a device that "should be on" stays a state: no place follows);
* a purpose said formally after a request, "that the light may enter", "so that we might see": dropped;
* "let there be light" (Genesis, said in jest or from the pulpit) is "turn on the light"; the name a request
  is made in ("..., in Jesus' name", "in the name of Jesus, ...") is dropped.
"""

from __future__ import annotations

import re

#: articles and possessives that open a thing's name
_OPENING = frozenset({"the", "my", "your", "his", "her", "our", "their", "this", "that"})
#: prepositions of a place a thing is put on or in
_ON = frozenset({"on", "in", "into", "onto", "inside"})
#: what a thing "should be" said with
_SHOULD = (["should", "be"], ["must", "be"], ["needs", "to", "be"], ["ought", "to", "be"])
#: words that point back at a thing said before
_POINTING = frozenset({"it", "them", "this", "these", "those"})
#: the stretches of a command's text and what parts them
_STRETCH = re.compile(r"([.?!;,]+\s*)")
#: "see to it" and "see to that", asking nothing more
_SEEN_TO = {("see", "to", "it"), ("see", "to", "that")}
#: what a purpose clause asks with
_PURPOSE = frozenset({"may", "might"})


def register_words(tokens: list[str]) -> list[str]:
    """One stretch of a command with the words of the module docstring said plainly."""
    words = tokens[1:] if tokens[:1] == ["fyi"] else tokens  # "FYI the study light is on, switch it off"
    if words[:4] == ["for", "your", "information", *words[3:4]] and len(words) > 3:
        words = words[3:]
    words = _oath_dropped(words)
    if words[:4] == ["let", "there", "be", "light"]:
        return ["turn", "on", "the", "light", *words[4:]]
    if words[:1] in (["that"], ["so"]) and _PURPOSE & set(words[1:]) and len(words) > 2:
        return []
    if words[-3:] in (["see", "to", "it"], ["see", "to", "that"]) and len(words) <= 4:
        return []
    for i, word in enumerate(words[:-1]):
        if words[i : i + 4] == ["loop", "me", "in", "on"]:  # "please loop me in on where Musa is"
            return [*words[:i], "tell", "me", *words[i + 4 :]]
        if word == "revert" and words[i + 1] in ("with", "back", "on"):
            rest = words[i + 2 :]
            rest = rest[1:] if rest[:1] in (["with"], ["on"]) else rest
            return [*words[:i], "tell", "me", *rest]
    return words


def to_be_put(text: str) -> str:
    """ "the calculator should be on the study desk" -> "put the calculator on the study desk", unless another
    sentence acts on "it" ("the atlas should be on the dining table; bring it here": where it is, hedged)."""
    parts = _STRETCH.split(text)
    put = [" ".join(_to_be_put(part.split())) if i % 2 == 0 else part for i, part in enumerate(parts)]
    changed = [i for i, (a, b) in enumerate(zip(parts, put, strict=True)) if a.split() != b.split()]
    others = {
        w.lower() for i, part in enumerate(parts) if i not in changed and i % 2 == 0 for w in part.split()
    }
    said_to = [p.lower().split()[-3:] for i, p in enumerate(parts) if i % 2 == 0 and p.split()]
    if not changed or (_POINTING & others and not any(w in _SEEN_TO for w in map(tuple, said_to))):
        return text
    return "".join(put)


def _to_be_put(words: list[str]) -> list[str]:
    if not words or words[0].lower() not in _OPENING:
        return words
    for should in _SHOULD:
        n = len(should)
        for i in range(1, len(words) - n - 1):
            after = words[i + n : i + n + 2]
            if (
                words[i : i + n] == should
                and after[:1]
                and after[0] in _ON
                and after[1:]
                and after[1] in _OPENING
            ):
                return ["put", *words[:i], *words[i + n :]]
    return words


def _oath_dropped(words: list[str]) -> list[str]:
    """A stretch without the name it is asked in, said last ("..., in Jesus' name", "in Jesus name", "in God's
    name") or opening it ("in the name of Jesus, bring me ..."): it asks nothing."""
    n = len(words)
    if n > 3 and words[-3] == "in" and words[-1] == "name":
        return words[:-3]
    if words[:4] == ["in", "the", "name", "of"]:
        return [] if n <= 6 else words  # the name is the whole stretch, as it is when said with a comma
    return words
