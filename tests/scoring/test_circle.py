"""Circle fit on synthetic arcs: radius, centre, residual, revolutions and the radius implied by the commands."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scoring_synth import run

from grader.metrics import MetricError
from grader.metrics.circle import Params, fit_circle, measure


def _arc(radius: float, sweep: float, n: int, noise: float, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    a = np.linspace(0.3, 0.3 + sweep, n)
    return (1.2 + radius * np.cos(a) + rng.normal(0, noise, n), -0.7 + radius * np.sin(a) + rng.normal(0, noise, n))


def test_noisy_half_metre_arc_radius_within_a_millimetre() -> None:
    x, y = _arc(0.5, math.radians(270), 600, noise=0.005)
    fit = fit_circle(x, y)
    assert fit.radius == pytest.approx(0.5, abs=1e-3)
    assert (fit.cx, fit.cy) == pytest.approx((1.2, -0.7), abs=2e-3)
    assert fit.rms == pytest.approx(0.005, abs=1e-3)
    assert fit.revolutions == pytest.approx(0.75, abs=0.01)


def test_outliers_do_not_drag_the_fit() -> None:
    x, y = _arc(0.5, math.radians(200), 400, noise=0.003, seed=1)
    x[::40] += 0.3  # ten wild samples (e.g. a wheel slip or a teleport)
    assert fit_circle(x, y).radius == pytest.approx(0.5, abs=1e-3)


def test_short_arc_far_from_origin() -> None:
    x, y = _arc(0.5, math.radians(60), 200, noise=0.001, seed=2)
    fit = fit_circle(x + 100.0, y - 50.0)
    assert fit.radius == pytest.approx(0.5, abs=2e-3)


def test_revolutions_count_several_turns() -> None:
    x, y = _arc(0.5, 2.5 * 2 * math.pi, 2000, noise=0.0)
    assert fit_circle(x, y).revolutions == pytest.approx(2.5, abs=1e-3)


def test_measure_reads_radius_and_commanded_ratio() -> None:
    m = measure(run([(25.0, 0.1, 0.2)]), Params(target_radius=0.5))
    assert m["radius"] == pytest.approx(0.5, abs=1e-6)
    assert m["cmd_radius"] == pytest.approx(0.5) and m["swapped_radius"] == pytest.approx(2.0)


def test_measure_equal_speeds_give_one_metre_and_the_needed_omega() -> None:
    m = measure(run([(20.0, 0.2, 0.2)]), Params(target_radius=0.5))
    assert m["radius"] == pytest.approx(1.0, abs=1e-6)
    assert m["needed_angular"] == pytest.approx(0.4)


def test_measure_stops_at_ctrl_c() -> None:
    # A circle for 10 s, then (after Ctrl+C) a straight run that must not distort the fit.
    r = run([(10.0, 0.1, 0.2), (5.0, 0.1, 0.0)], shutdown_at=10.0)
    assert measure(r, Params())["radius"] == pytest.approx(0.5, abs=1e-3)


def test_robot_that_never_moves_cannot_be_measured() -> None:
    with pytest.raises(MetricError, match="drove only 0.00 m"):
        measure(run([(10.0, 0.0, 0.0)]), Params())
