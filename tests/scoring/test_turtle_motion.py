"""turtlesim moves: distance and direction driven (turtle_travel), angle and direction turned (turtle_rotation)."""
from __future__ import annotations

import math

import pytest
from scoring_synth import run

from grader.metrics import MetricError
from grader.metrics import turtle_rotation, turtle_travel


def test_a_forward_move_measures_its_distance_and_direction() -> None:
    m = turtle_travel.measure(run([(1.5, 2.0, 0.0), (3.0, 0.0, 0.0)], x0=5.5, y0=5.5),
                              turtle_travel.Params(distance=3.0))
    assert m["travelled"] == pytest.approx(3.0, abs=1e-6) and m["distance_error_rel"] == pytest.approx(0.0, abs=1e-6)
    assert (m["moved_direction"], m["direction_ok"]) == ("forwards", True)


def test_backwards_is_along_the_start_heading_whatever_it_is() -> None:
    m = turtle_travel.measure(run([(2.0, -1.0, 0.0)], yaw0=2.5), turtle_travel.Params(distance=2.5, forward=False))
    assert m["displacement"] == pytest.approx(-2.0, abs=1e-6) and m["direction_ok"] is True
    assert m["distance_error_rel"] == pytest.approx(0.2, abs=1e-6)


def test_the_wrong_direction_and_a_far_overshoot_are_reported() -> None:
    m = turtle_travel.measure(run([(5.0, 2.0, 0.0)]), turtle_travel.Params(distance=2.5, forward=False))
    assert (m["moved_direction"], m["asked_direction"], m["direction_ok"]) == ("forwards", "backwards", False)
    assert m["ratio"] == pytest.approx(4.0, abs=1e-6)


def test_a_turtle_that_never_moved_went_nowhere() -> None:
    m = turtle_travel.measure(run([(3.0, 0.0, 0.0)]), turtle_travel.Params(distance=1.0))
    assert (m["moved_direction"], m["direction_ok"], m["ratio"]) == ("nowhere", False, 0.0)


def test_a_turn_across_plus_minus_pi_counts_continuously() -> None:
    w = math.radians(60)
    m = turtle_rotation.measure(run([(4.5, 0.0, w), (1.0, 0.0, 0.0)], yaw0=2.96706),
                                turtle_rotation.Params(angle_deg=270.0))
    assert m["turned_deg"] == pytest.approx(270.0, abs=0.01) and m["angle_error_deg"] == pytest.approx(0.0, abs=0.01)
    assert m["moved_direction"] == "anticlockwise" and m["direction_ok"] is True


def test_clockwise_turns_are_negative_and_checked_against_the_asked_direction() -> None:
    m = turtle_rotation.measure(run([(2.0, 0.0, -math.radians(45))]),
                                turtle_rotation.Params(angle_deg=90.0, clockwise=False))
    assert m["turned_deg"] == pytest.approx(-90.0, abs=0.01)
    assert (m["moved_direction"], m["direction_ok"]) == ("clockwise", False)


def test_degrees_used_as_radians_turn_57_times_too_far() -> None:
    m = turtle_rotation.measure(run([(3.0, 0.0, 30.0)], t0=0.0), turtle_rotation.Params(angle_deg=90.0))
    assert m["ratio"] == pytest.approx(180 / math.pi, rel=0.01)


def test_no_pose_is_a_metric_error() -> None:
    empty = run([(0.0, 0.0, 0.0)])
    with pytest.raises(MetricError):
        turtle_rotation.measure(empty, turtle_rotation.Params())
