"""Typed text as the reader reads it: typographic marks a phone or a word processor puts in ("annie’s",
"I’d", "café", "wait… no") as plain ones, and decimal numbers ("dim it to 0.5", "the blinds at 62.5%") read
before a full stop would split them into two numbers ("zero", "five"): levels are whole percentages. Digits
ending a word are set apart, as said ("cup1": "cup 1", a PDDL problem's name; "the 2nd lamp": "the
second lamp"), so that numbered things are named and asked about as the others ("the cup": which cup?).
"""

from __future__ import annotations

import re
import unicodedata

#: a decimal number (not part of a longer run of digits and points: "1.2.3"), and "%" or "percent" after it
DECIMAL = re.compile(r"(?<![\d.])(\d+)\.(\d+)(?!\.?\d)(\s*(?:%|percent\b))?", re.IGNORECASE)
#: typographic marks and their plain forms: curly and other apostrophes, quotes, dashes, the ellipsis and
#: spaces that are not plain ones
_PLAIN = str.maketrans(
    {
        **dict.fromkeys("\u2018\u2019\u201a\u201b\u02bc\u2032\u00b4\u0060", "'"),
        **dict.fromkeys("\u201c\u201d\u201e\u201f\u00ab\u00bb", '"'),
        **dict.fromkeys("\u2013\u2014\u2015\u2212", " - "),
        "\u2026": "...",
        **dict.fromkeys("\u00a0\u2009\u202f\u200b", " "),
    }
)


#: an ordinal written with digits ("2nd", "3rd", "10th") and the words for those up to the twelfth
_ORDINAL = re.compile(r"\b(\d{1,2})(st|nd|rd|th)\b", re.IGNORECASE)
_ORDINALS = (
    *("zeroth", "first", "second", "third", "fourth", "fifth", "sixth"),
    *("seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth"),
)
#: a word of letters ending in digits ("cup1", "sofa2"; not a name with digits inside it: "r2d2")
_RUN = re.compile(r"\b([A-Za-z]+)(\d+)\b")


def digits_apart(text: str) -> str:
    """``text`` with ordinals written in digits as words ("the 2nd lamp": "the second lamp") and the digits
    ending a word set apart ("cup1": "cup 1", "bring me cup2": "bring me cup 2"; "r2d2" stays one word)."""
    text = _ORDINAL.sub(lambda m: _ORDINALS[int(m[1])] if int(m[1]) < len(_ORDINALS) else m[0], text)
    return _RUN.sub(r"\1 \2", text)


def plain_typed(text: str) -> str:
    """``text`` with typographic marks as plain ones ("annie’s": "annie's", "wait…": "wait...") and letters
    without their accents ("café": "cafe", "Zoë": "Zoe"); words in other scripts are left as they are."""
    text = text.translate(_PLAIN)
    if text.isascii():
        return text
    folded = unicodedata.normalize("NFKD", text)
    return "".join(c for c in folded if not unicodedata.combining(c))


def decimals_read(text: str) -> str:
    """``text`` with each decimal number as a whole one: a share of one without a percent sign as a
    percentage ("0.5": "50 percent", "1.0": "100 percent"), any other rounded to the nearest whole number
    ("30.5 percent": "31 percent", "62.5": "63")."""
    return DECIMAL.sub(_whole, text)


def _whole(match: re.Match[str]) -> str:
    value = float(f"{match.group(1)}.{match.group(2)}")
    if match.group(3) is None and value <= 1.0:
        return f"{int(value * 100 + 0.5)} percent"
    return f"{int(value + 0.5)}{match.group(3) or ''}"
