"""Partial credit: map a measured value to a credit in [0, 1] with bounds, a margin and a sigmoid (dm_control style).

Full credit inside ``bounds``; outside, credit decays with the distance from the nearest bound, reaching
``value_at_margin`` at ``margin`` away. A margin of 0 makes the criterion all-or-nothing.
"""
from __future__ import annotations

import math
from typing import Literal, get_args

Sigmoid = Literal[
    "gaussian", "linear", "quadratic", "cosine", "hyperbolic", "long_tail", "reciprocal", "tanh_squared"
]
SIGMOIDS: tuple[str, ...] = get_args(Sigmoid)


class ToleranceError(Exception):
    """The tolerance parameters are inconsistent (bounds reversed, negative margin, unknown sigmoid, ...)."""


def _sigmoid(d: float, value_at_margin: float, kind: str) -> float:
    """Credit at normalised distance ``d >= 0`` outside the bounds; equals ``value_at_margin`` at ``d == 1``."""
    v = value_at_margin
    if kind == "gaussian":
        return math.exp(-0.5 * (d * math.sqrt(-2.0 * math.log(v))) ** 2)
    if kind == "hyperbolic":
        s = math.acosh(1.0 / v)
        return 1.0 / math.cosh(d * s)
    if kind == "long_tail":
        s = math.sqrt(1.0 / v - 1.0)
        return 1.0 / ((d * s) ** 2 + 1.0)
    if kind == "reciprocal":
        s = 1.0 / v - 1.0
        return 1.0 / (abs(d) * s + 1.0)
    if kind == "tanh_squared":
        s = math.atanh(math.sqrt(1.0 - v))
        return 1.0 - math.tanh(d * s) ** 2
    if kind == "cosine":
        s = math.acos(2.0 * v - 1.0) / math.pi
        x = d * s
        return (1.0 + math.cos(math.pi * x)) / 2.0 if x < 1.0 else 0.0
    if kind == "linear":
        x = d * (1.0 - v)
        return 1.0 - x if x < 1.0 else 0.0
    if kind == "quadratic":
        x = d * math.sqrt(1.0 - v)
        return 1.0 - x * x if x < 1.0 else 0.0
    raise ToleranceError(f"unknown sigmoid {kind!r}; expected one of {', '.join(SIGMOIDS)}")


def check(bounds: tuple[float, float], margin: float, sigmoid: str, value_at_margin: float) -> None:
    """Raise ToleranceError unless the parameters describe a valid tolerance."""
    lower, upper = bounds
    if math.isnan(lower) or math.isnan(upper) or lower > upper:
        raise ToleranceError(f"bounds must be [lower, upper] with lower <= upper, got [{lower}, {upper}]")
    if not (margin >= 0.0 and math.isfinite(margin)):
        raise ToleranceError(f"margin must be a finite number >= 0, got {margin}")
    if sigmoid not in SIGMOIDS:
        raise ToleranceError(f"unknown sigmoid {sigmoid!r}; expected one of {', '.join(SIGMOIDS)}")
    # Sigmoids with infinite support never reach 0, so their value at the margin must be strictly positive.
    finite_support = sigmoid in ("linear", "quadratic", "cosine")
    if not (0.0 <= value_at_margin < 1.0) or (value_at_margin == 0.0 and not finite_support):
        lowest = "0" if finite_support else "greater than 0"
        raise ToleranceError(
            f"value_at_margin must be {lowest} and less than 1 for sigmoid {sigmoid!r}, got {value_at_margin}"
        )


def tolerance(
    x: float | None,
    bounds: tuple[float, float] = (0.0, 0.0),
    margin: float = 0.0,
    sigmoid: str = "gaussian",
    value_at_margin: float = 0.1,
) -> float:
    """Return the credit in [0, 1] for measured value ``x``; a missing or NaN value earns nothing."""
    check(bounds, margin, sigmoid, value_at_margin)
    if x is None or math.isnan(x):
        return 0.0
    lower, upper = bounds
    if lower <= x <= upper:
        return 1.0
    if margin == 0.0:
        return 0.0
    distance = (lower - x) if x < lower else (x - upper)
    if math.isinf(distance):
        return 0.0
    return min(1.0, max(0.0, _sigmoid(distance / margin, value_at_margin, sigmoid)))
