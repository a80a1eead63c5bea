"""Square analysis on synthetic paths: sides, corners, closure after each loop, loop count, pauses, the final stop."""
from __future__ import annotations

import math

import pytest
from scoring_synth import path, run, square_segments

from grader.metrics.square import Params, analyse_square, measure

REST = [(10.0, 0.0, 0.0)]


def test_two_perfect_loops_then_rest() -> None:
    m = measure(run(square_segments(loops=2) + REST), Params(side=1.0))
    assert m["n_sides"] == 8 and m["n_corners"] == 8
    assert m["side_worst_error"] == pytest.approx(0.0, abs=1e-3)
    assert m["corner_worst_error_deg"] == pytest.approx(0.0, abs=0.1)
    assert m["closure_worst"] == pytest.approx(0.0, abs=1e-3)
    assert m["loops"] == 2.0 and m["heading_loops"] == pytest.approx(2.0, abs=1e-3)
    assert m["loops_at_rest"] == 2.0 and m["moving_at_end"] is False


def test_start_off_origin_facing_170_degrees_is_the_same_square() -> None:
    m = measure(run(square_segments(loops=2) + REST, x0=-2.0, y0=-0.5, yaw0=math.radians(170), t0=12.3),
                Params(side=1.0))
    assert (m["n_sides"], m["loops_at_rest"]) == (8, 2.0)
    assert m["side_worst_error"] < 1e-3 and m["closure_worst"] < 1e-3


def test_long_sides_and_wide_corners_are_measured() -> None:
    m = measure(run(square_segments(side=1.08, loops=1, turn_deg=97.0) + REST), Params(side=1.0))
    assert m["side_max"] == pytest.approx(1.08, abs=2e-3)
    assert m["corner_worst_error_deg"] == pytest.approx(7.0, abs=0.1)
    # Each 7 degree overshoot turns the square; after one loop the robot is well away from its start.
    assert m["closure_first"] > 0.3


def test_closure_is_taken_after_each_loop() -> None:
    # Slightly short fourth side: 0.06 m short of the start after every loop.
    one_loop = square_segments(loops=1)
    one_loop[6] = (0.94 / 0.2, 0.2, 0.0)
    m = measure(run(one_loop * 2 + REST), Params(side=1.0))
    assert m["closure_first"] == pytest.approx(0.06, abs=2e-3)
    assert m["closure_worst"] == pytest.approx(0.12, abs=5e-3)


def test_stopping_after_one_loop() -> None:
    m = measure(run(square_segments(loops=1) + REST), Params(side=1.0))
    assert m["loops_at_rest"] == 1.0


def test_last_side_without_final_turn_counts_when_at_rest() -> None:
    segs = square_segments(loops=2)[:-1] + REST  # eight sides, seven turns, then stop
    m = measure(run(segs), Params(side=1.0))
    assert (m["n_sides"], m["n_corners"], m["loops_at_rest"]) == (8, 7, 2.0)


def test_spinning_past_180_degrees_is_one_huge_corner() -> None:
    # The +-pi bug: the target yaw is never reached, so the robot spins on the spot until the run ends.
    segs = square_segments(loops=1)[:3] + [(40.0, 0.0, 0.5)]
    m = measure(run(segs), Params(side=1.0))
    assert m["corner_max_deg"] > 1000 and m["moving_at_end"] is True
    assert math.isnan(m["loops_at_rest"])


def test_pauses_are_counted() -> None:
    sq = analyse_square(path(square_segments(loops=1, pause=1.0) + REST))
    assert len(sq.pauses) == 7 and all(p == pytest.approx(1.0, abs=0.1) for p in sq.pauses)


def test_timed_square_shape_is_relative_to_the_mean_side() -> None:
    # Ctrl+C in the middle of the ninth turn: the unfinished turn is not a corner.
    m = measure(run(square_segments(side=0.6, loops=3), shutdown_at=8 * (3.0 + math.pi) + 4.5), Params())
    assert m["shape_error"] == pytest.approx(0.0, abs=2e-3)


def test_interrupted_run_ignores_the_partial_side() -> None:
    m = measure(run(square_segments(loops=1) + [(2.0, 0.2, 0.0)], shutdown_at=34.0), Params(side=1.0))
    assert m["n_sides"] == 4 and math.isnan(m["loops_at_rest"])


def test_the_square_is_decided_where_its_last_corner_was_turned() -> None:
    """The report's moment: the middle of the eighth turn, in seconds after the run's start (t0 = 12.3 s)."""
    segs = square_segments(loops=2)
    m = measure(run(segs + REST, t0=12.3), Params(side=1.0))
    last_turn_middle = sum(d for d, _, _ in segs) - segs[-1][0] / 2
    assert m["decided_at_s"] == pytest.approx(last_turn_middle, abs=0.05)


def test_a_square_ending_on_a_side_is_decided_where_the_robot_came_to_rest() -> None:
    segs = square_segments(loops=1)[:-1]  # no turn after the fourth side
    m = measure(run(segs + REST), Params(side=1.0))
    assert m["n_sides"] == 4 and m["decided_at_s"] == pytest.approx(sum(d for d, _, _ in segs), abs=0.05)
