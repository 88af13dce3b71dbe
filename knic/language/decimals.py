"""Decimal numbers in commands ("dim it to 0.5", "the blinds at 62.5%"), read before a full stop would split
them into two numbers ("zero", "five"): levels are whole percentages.
"""

from __future__ import annotations

import re

#: a decimal number (not part of a longer run of digits and points: "1.2.3"), and "%" or "percent" after it
DECIMAL = re.compile(r"(?<![\d.])(\d+)\.(\d+)(?!\.?\d)(\s*(?:%|percent\b))?", re.IGNORECASE)


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
