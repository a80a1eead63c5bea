"""The tolerance function: full credit inside the bounds, the promised value at the margin, monotone decay."""
from __future__ import annotations

import math

import pytest

from grader.tolerance import SIGMOIDS, ToleranceError, tolerance


@pytest.mark.parametrize("x", [0.45, 0.5, 0.55])
def test_inside_bounds_is_full_credit(x: float) -> None:
    assert tolerance(x, (0.45, 0.55), margin=0.1, sigmoid="linear") == 1.0


@pytest.mark.parametrize("sigmoid", SIGMOIDS)
def test_value_at_margin_is_reached_exactly_one_margin_out(sigmoid: str) -> None:
    for x in (0.65, 0.35):
        assert tolerance(x, (0.45, 0.55), 0.1, sigmoid, value_at_margin=0.1) == pytest.approx(0.1, abs=1e-9)


@pytest.mark.parametrize("sigmoid", SIGMOIDS)
def test_credit_decreases_with_distance(sigmoid: str) -> None:
    credits = [tolerance(1.0 + d, (0.0, 1.0), 0.5, sigmoid, 0.1) for d in (0.0, 0.1, 0.3, 0.5, 0.8, 2.0)]
    assert all(a >= b for a, b in zip(credits, credits[1:]))
    assert credits[0] == 1.0 and credits[-1] < 0.1


def test_linear_with_zero_floor_reaches_nothing_at_the_margin() -> None:
    # The move_circle radius: full within 0.05 m, nothing beyond 0.15 m, halfway at 0.10 m.
    assert tolerance(0.60, (0.45, 0.55), 0.10, "linear", 0.0) == pytest.approx(0.5)
    assert tolerance(0.65, (0.45, 0.55), 0.10, "linear", 0.0) == pytest.approx(0.0, abs=1e-12)
    assert tolerance(1.00, (0.45, 0.55), 0.10, "linear", 0.0) == 0.0


def test_zero_margin_is_all_or_nothing() -> None:
    assert tolerance(0.0, (0.0, 0.0)) == 1.0
    assert tolerance(1e-6, (0.0, 0.0)) == 0.0


@pytest.mark.parametrize("x", [None, math.nan])
def test_missing_measurement_earns_nothing(x: float | None) -> None:
    assert tolerance(x, (0.0, 1.0), 1.0, "gaussian") == 0.0


def test_open_upper_bound_and_infinite_distance() -> None:
    assert tolerance(1e12, (5.0, math.inf), 5.0, "linear", 0.0) == 1.0
    assert tolerance(-math.inf, (5.0, math.inf), 5.0, "gaussian") == 0.0


@pytest.mark.parametrize(
    "bounds, margin, sigmoid, value",
    [((1.0, 0.0), 0.1, "linear", 0.0), ((0.0, 1.0), -1.0, "linear", 0.0), ((0.0, 1.0), 0.1, "cubic", 0.1),
     ((0.0, 1.0), 0.1, "gaussian", 0.0), ((0.0, 1.0), 0.1, "linear", 1.0)],
)
def test_inconsistent_parameters_raise(bounds: tuple[float, float], margin: float, sigmoid: str, value: float) -> None:
    with pytest.raises(ToleranceError):
        tolerance(0.5, bounds, margin, sigmoid, value)
