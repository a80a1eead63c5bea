"""Feedback that reads as a person would write it, whatever numbers fill the rubric's templates: no "All 1 velocity
commands", no "between 1.02 m and 1.02 m", no "n/a m"."""
from __future__ import annotations

import re

_UNIT = r"(?:m/s|rad/s|m|s|°|Hz|%|rad)"
# "between 1.02 m and 1.02 m" / "between 89.9° and 89.9°": both ends print the same.
_SAME_ENDS = re.compile(rf"\bbetween (-?[\d.]+)( ?{_UNIT})? and \1\2(?![\w])")
# "loops of 1.00–1.00 m" / "89.9°–89.9°": a range written with an en dash whose ends print the same.
_SAME_DASH_ENDS = re.compile(rf"(?<![\w.])(-?\d[\d.]*)((?: ?{_UNIT})?)–\1\2(?!\w|\.\d)")
# "All 1 velocity commands were ..." → "The only velocity command was ..."
_ALL_ONE = re.compile(r"\bAll 1 ((?:[\w-]+ )*?[\w-]+?)s\b( were)?")
# A value that could not be measured, with the unit its template put after it ("n/a m").
_NOT_MEASURED = re.compile(rf"\bn/a ?{_UNIT}(?![\w/])")


def tidy(text: str) -> str:
    """Rendered feedback with the phrasings that numbers can make awkward rewritten."""
    text = _SAME_ENDS.sub(lambda m: f"{m.group(1)}{m.group(2) or ''}", text)
    text = _SAME_DASH_ENDS.sub(lambda m: f"{m.group(1)}{m.group(2)}", text)
    text = _ALL_ONE.sub(lambda m: f"The only {m.group(1)}" + (" was" if m.group(2) else ""), text)
    return _NOT_MEASURED.sub("not measured", text)
