"""Stop position, distance from the start and whether the robot stays stopped."""
from __future__ import annotations

import math

import pytest
from scoring_synth import run

from grader.metrics.stop import Params, measure


def test_drive_three_metres_and_stop() -> None:
    m = measure(run([(0.5, 0.0, 0.0), (15.1, 0.2, 0.0), (10.0, 0.0, 0.0)]), Params())
    assert m["final_x"] == pytest.approx(3.02, abs=1e-6) and m["travelled"] == pytest.approx(3.02, abs=1e-6)
    assert m["rest_at_end_s"] == pytest.approx(10.0, abs=0.05) and m["moving_at_end"] is False
    assert m["stopped_at_s"] == pytest.approx(15.6, abs=0.05)


def test_global_x_from_an_offset_start() -> None:
    m = measure(run([(25.0, 0.2, 0.0), (5.0, 0.0, 0.0)], x0=-2.0, y0=-0.5, t0=12.3), Params())
    assert (m["final_x"], m["start_x"]) == (pytest.approx(3.0), -2.0)
    assert m["final_distance"] == pytest.approx(5.0)


def test_never_stopping_has_no_rest() -> None:
    m = measure(run([(30.0, 0.2, 0.0)]), Params())
    assert m["moving_at_end"] is True and m["rest_at_end_s"] == 0.0


def test_never_moving_is_not_stopping() -> None:
    m = measure(run([(30.0, 0.0, 0.0)]), Params())
    assert math.isnan(m["rest_at_end_s"]) and m["travelled"] == 0.0


def test_circling_husky_ends_close_to_its_start() -> None:
    # The seed's Husky planner: 1.0 m/s with 0.3 rad/s is a 3.3 m circle, never 10 m from the start.
    m = measure(run([(20.0, 1.0, 0.3)]), Params())
    assert m["travelled"] == pytest.approx(20.0, abs=0.05) and m["final_distance"] < 6.7
