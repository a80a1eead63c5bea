"""Velocity compliance on every command message: limits per component, NaN/inf, components a 2-D base cannot use."""
from __future__ import annotations

import math

import pytest

from grader.metrics import Commands, RunData, Trajectory
from grader.metrics.velocity import Params, measure

LIMITS = Params(max_linear=0.26, max_angular=1.82)
ODOM = Trajectory.of([0.0, 1.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0])


def _measure(linear: list[list[float]], angular: list[list[float]]) -> dict:
    cmds = Commands.of([0.1 * i for i in range(len(linear))], linear, angular)
    return measure(RunData(odometry=ODOM, commands=cmds), LIMITS)


def test_commands_within_limits_including_exactly_at_the_limit() -> None:
    m = _measure([[0.26, 0, 0], [-0.26, 0, 0], [0.1, 0, 0]], [[0, 0, 1.82], [0, 0, -1.82], [0, 0, 0]])
    assert (m["n_messages"], m["n_violations"], m["violating_fraction"]) == (3, 0, 0.0)


def test_too_fast_linear_and_angular_are_counted_separately() -> None:
    m = _measure([[0.3, 0, 0], [0.1, 0, 0], [0.1, 0, 0], [0.1, 0, 0]], [[0, 0, 0], [0, 0, -2.0], [0, 0, 0], [0, 0, 0]])
    assert (m["n_over_linear"], m["n_over_angular"], m["n_violations"]) == (1, 1, 2)
    assert m["violating_fraction"] == 0.5
    assert m["max_linear"] == pytest.approx(0.3) and m["max_angular"] == pytest.approx(2.0)
    assert m["first_violation_s"] == pytest.approx(0.0)


def test_nan_and_infinity_are_violations() -> None:
    m = _measure([[math.nan, 0, 0], [0.1, 0, 0], [0.2, 0, 0]], [[0, 0, 0.5], [0, 0, math.inf], [0, 0, 0]])
    assert (m["n_nonfinite"], m["n_violations"]) == (2, 2)
    assert m["max_linear"] == pytest.approx(0.2)  # from the finite messages only


def test_components_a_differential_drive_cannot_use() -> None:
    m = _measure([[0.1, 0.05, 0], [0.1, 0, 0.01], [0.1, 0, 0]], [[0, 0, 0], [0.2, 0, 0], [0, 0, 0.3]])
    assert (m["n_off_axis"], m["n_violations"]) == (2, 2)


def test_no_commands_means_no_fraction() -> None:
    m = measure(RunData(odometry=ODOM), LIMITS)
    assert m["n_messages"] == 0 and math.isnan(m["violating_fraction"])
    assert all(math.isnan(m[q]) for q in ("n_violations", "max_linear", "max_angular"))  # nothing to count
