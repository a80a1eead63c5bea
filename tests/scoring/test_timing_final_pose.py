"""Timing (first motion, at rest for good, duration) and final pose (start point, start line, heading) on synthetic runs."""
from __future__ import annotations

import math

import pytest
from scoring_synth import run

from grader.metrics import MetricError
from grader.metrics import final_pose, timing

V, W = 0.1, 0.2
LOOP = 2 * math.pi / W
EIGHT = [(LOOP, V, W), (LOOP, V, -W)]


def test_motion_is_timed_from_the_first_move_to_rest_for_good() -> None:
    m = timing.measure(run([(3.0, 0.0, 0.0)] + EIGHT + [(10.0, 0.0, 0.0)], t0=12.3), timing.Params())
    assert m["first_motion_s"] == pytest.approx(3.0, abs=0.05)
    assert m["motion_s"] == pytest.approx(2 * LOOP, abs=0.05)
    assert m["rest_at_s"] == pytest.approx(3.0 + 2 * LOOP, abs=0.05)
    assert m["moving_at_end"] is False


def test_a_pause_in_the_middle_is_part_of_the_motion() -> None:
    m = timing.measure(run([(10.0, V, 0.0), (5.0, 0.0, 0.0), (10.0, V, 0.0), (10.0, 0.0, 0.0)]), timing.Params())
    assert m["motion_s"] == pytest.approx(25.0, abs=0.05)


def test_a_robot_moving_at_the_end_or_resting_too_briefly_has_no_duration() -> None:
    moving = timing.measure(run(EIGHT), timing.Params())
    assert moving["moving_at_end"] is True and math.isnan(moving["motion_s"])
    brief = timing.measure(run(EIGHT + [(1.0, 0.0, 0.0)]), timing.Params(min_rest_s=2.0))
    assert brief["moving_at_end"] is True


def test_timing_stops_at_ctrl_c() -> None:
    m = timing.measure(run(EIGHT + [(10.0, 0.0, 0.0)], shutdown_at=20.0), timing.Params())
    assert m["interrupted"] is True and m["moving_at_end"] is True and m["observed_s"] == pytest.approx(20.0, abs=0.05)


def test_timing_needs_motion() -> None:
    with pytest.raises(MetricError, match="never moved"):
        timing.measure(run([(10.0, 0.0, 0.0)]), timing.Params())


def test_back_at_the_start_after_a_figure_of_eight() -> None:
    m = final_pose.measure(run(EIGHT + [(5.0, 0.0, 0.0)], x0=-2.0, y0=-0.5, yaw0=math.radians(170)),
                           final_pose.Params(track=0.287))
    assert m["start_distance"] < 0.005 and m["line_distance"] < 0.005 and m["heading_error_deg"] < 0.5


def test_start_line_distance_is_along_the_start_heading_and_counts_each_wheel() -> None:
    # Stop 0.3 m to the left of the start (on the start line) facing 90 degrees away: the wheels sit ahead of and
    # behind the line by half the track.
    segs = [(math.pi / 2 / 0.5, 0.0, 0.5), (3.0, V, 0.0), (5.0, 0.0, 0.0)]
    m = final_pose.measure(run(segs, yaw0=math.radians(30)), final_pose.Params(track=0.3))
    assert m["start_distance"] == pytest.approx(0.3, abs=1e-3)
    assert m["along_start_heading"] == pytest.approx(0.0, abs=1e-3)
    assert m["across_start_heading"] == pytest.approx(0.3, abs=1e-3)
    assert m["line_distance"] == pytest.approx(0.15, abs=1e-3)
    assert m["heading_error_deg"] == pytest.approx(90.0, abs=0.1)


def test_stopping_ahead_of_the_line() -> None:
    m = final_pose.measure(run([(2.0, V, 0.0), (5.0, 0.0, 0.0)]), final_pose.Params(track=0.287))
    assert m["line_distance"] == pytest.approx(0.2, abs=1e-3) and m["heading_error_deg"] < 1e-6


def test_final_pose_needs_the_robot_to_leave_the_start() -> None:
    with pytest.raises(MetricError, match="never left the start"):
        final_pose.measure(run([(5.0, 0.0, 0.0)]), final_pose.Params())
