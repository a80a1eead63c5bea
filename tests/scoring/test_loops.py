"""Loops on synthetic paths: a figure of eight, one direction twice, wobble, unfinished loops, sizes and closure."""
from __future__ import annotations

import math

import pytest
from scoring_synth import path, run

from grader.metrics import MetricError
from grader.metrics.loops import Params, find_loops, measure

V, W = 0.1, 0.2  # 0.5 m radius
LOOP = 2 * math.pi / W
EIGHT = [(LOOP, V, W), (LOOP, V, -W), (10.0, 0.0, 0.0)]
FIGURE = Params(diameter=1.0, order=["anticlockwise", "clockwise"])


def test_figure_of_eight_is_two_loops_anticlockwise_then_clockwise() -> None:
    m = measure(run(EIGHT), FIGURE)
    assert m["n_loops"] == 2 and m["order"] == "anticlockwise, clockwise"
    assert m["order_correct"] is True and m["order_fraction"] == 1.0
    assert m["diameter_worst_error"] == pytest.approx(0.0, abs=2e-3)
    assert m["closure_worst"] < 0.01
    assert m["turned_deg"] == pytest.approx(720.0, abs=1.0)


def test_the_same_direction_twice_gets_half_the_order() -> None:
    m = measure(run([(2 * LOOP, V, W), (10.0, 0.0, 0.0)]), FIGURE)
    assert m["order"] == "anticlockwise, anticlockwise" and m["order_fraction"] == 0.5
    assert (m["n_anticlockwise"], m["n_clockwise"]) == (2, 0)
    assert m["diameter_worst_error"] < 2e-3  # the shape of each loop is still right


def test_loops_are_found_wherever_the_robot_starts_and_faces() -> None:
    m = measure(run(EIGHT, x0=-2.0, y0=-0.5, yaw0=math.radians(170), t0=12.3), FIGURE)
    assert m["order_correct"] is True and m["diameter_worst_error"] < 2e-3


def test_steering_wobble_does_not_split_a_loop() -> None:
    wobbly = [(LOOP / 2, V, W), (1.0, V, -0.3), (LOOP / 2 + 1.5, V, W), (LOOP, V, -W), (5.0, 0.0, 0.0)]
    loops = find_loops(path(wobbly))
    assert [loop.direction for loop in loops] == ["anticlockwise", "clockwise"]


def test_a_nearly_finished_last_loop_counts_and_a_half_loop_does_not() -> None:
    nearly = measure(run([(LOOP, V, W), (LOOP * 0.9, V, -W), (5.0, 0.0, 0.0)]), FIGURE)
    assert nearly["n_loops"] == 2 and nearly["closure_worst"] > 0.2
    half = measure(run([(LOOP, V, W), (LOOP * 0.5, V, -W), (5.0, 0.0, 0.0)]), FIGURE)
    assert half["n_loops"] == 1 and half["order_fraction"] == 0.5
    assert half["diameter_worst_error"] == 1.0  # a missing loop is wholly wrong


def test_loop_size_is_the_fitted_diameter() -> None:
    m = measure(run([(2 * math.pi / 0.1, V, 0.1), (10.0, 0.0, 0.0)]), Params(diameter=1.0))
    assert m["diameter_mean"] == pytest.approx(2.0, abs=5e-3)
    assert m["diameter_worst_error"] == pytest.approx(1.0, abs=5e-3)


def test_loops_after_ctrl_c_are_not_counted() -> None:
    m = measure(run(EIGHT, shutdown_at=LOOP + 2.0), FIGURE)
    assert m["n_loops"] == 1


def test_a_robot_that_never_moved_has_no_loops() -> None:
    with pytest.raises(MetricError, match="hardly moved"):
        measure(run([(10.0, 0.0, 0.0)]), FIGURE)
