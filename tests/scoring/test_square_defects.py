"""Issue 9's scoring defects, each pinned on a synthetic run scored with the shipped rubric."""
from __future__ import annotations

import math
from collections.abc import Sequence

import pytest
from scoring_synth import Segment, run, square_segments

from grader.metrics import RunData, RunInfo
from grader.metrics.square import Params, measure
from grader.rubric import Rubric, load_rubrics
from grader.scoring import score_task

RUBRICS = load_rubrics()
QUARTER_TURN: Segment = (math.pi / 2 / 0.5, 0.0, 0.5)


def _runs(rubric: Rubric, segments: Sequence[Segment], ended_s: float | None = None,
          rest_after: bool = True) -> dict[str, RunData]:
    """Every scenario of ``rubric`` driving ``segments`` from its own start; the hook stops the robot at Ctrl+C."""
    out = {}
    for s in rubric.scenarios:
        shutdown = None if s.shutdown_at is None else s.start_time + s.shutdown_at
        segs = list(segments)
        if s.shutdown_at is not None and s.shutdown_at < 10.0:  # "interrupted": Ctrl+C on the first side
            segs = [(s.shutdown_at, 0.2, 0.0)]
        total = sum(d for d, _, _ in segs)
        if s.duration > total and (rest_after or s.shutdown_at is not None):
            segs.append((s.duration - total, 0.0, 0.0))
        end = ended_s if ended_s is not None else (None if shutdown is None else shutdown + 0.5)
        info = RunInfo(shutdown_requested_s=shutdown, exit_code=0, status="exited", ended_s=end)
        p = s.initial_pose
        out[s.name] = run(segs, x0=p.x, y0=p.y, yaw0=p.yaw, t0=s.start_time, info=info, shutdown_at=s.shutdown_at)
    return out


def _criterion(rubric: Rubric, runs: dict[str, RunData], criterion: str):
    return next(c for c in score_task(rubric, runs).criteria if c.id == criterion)


def test_two_sides_then_spinning_earn_only_the_share_of_two_sides_in_four() -> None:
    # The yaw-wrap bug: two good sides, then spinning on the spot at the second corner until the run ends.
    segs = square_segments(loops=1)[:3] + [(140.0, 0.0, 0.5)]
    m = measure(run(segs), Params(side=1.0))
    assert m["n_sides"] == 2 and m["side_worst_error"] == 1.0 and m["side_share"] == 0.5
    side = _criterion(RUBRICS["move_square"], _runs(RUBRICS["move_square"], segs, rest_after=False), "side_length")
    assert side.score == side.max_score / 2
    assert "Only 2 sides were driven" in side.feedback


def test_four_good_sides_still_earn_full_side_credit() -> None:
    m = measure(run(square_segments(loops=1) + [(10.0, 0.0, 0.0)]), Params(side=1.0))
    assert m["n_sides"] == 4 and m["side_worst_error"] < 1e-3


def test_a_turn_on_the_spot_before_the_first_side_is_not_a_corner() -> None:
    segs = [QUARTER_TURN] + square_segments(side=1.0, loops=3, v=0.2, w=0.5)
    m = measure(run(segs), Params())
    assert m["side_min"] > 0.99 and m["corner_min_deg"] > 89.0
    assert m["n_sides"] == m["n_corners"] == 12


def test_timed_square_that_starts_with_a_turn_scores_full_marks() -> None:
    rubric = RUBRICS["mover_timed_square"]
    shape = _criterion(rubric, _runs(rubric, [QUARTER_TURN] + square_segments(loops=4)), "square_shape")
    assert shape.score == shape.max_score, shape.feedback
    assert "Time.now" not in shape.feedback


def test_square_with_good_corners_and_one_short_side_loses_only_that_sides_share() -> None:
    rubric = RUBRICS["mover_timed_square"]
    segs = square_segments(loops=4)
    segs[4] = (0.5 / 0.2, 0.2, 0.0)  # the third side is 0.5 m, the corners are all 90 degrees
    shape = _criterion(rubric, _runs(rubric, segs), "square_shape")
    n = shape.measured["n_sides"]
    assert shape.measured["n_sides_off"] == 1
    assert shape.score == pytest.approx(shape.max_score * (1 + (n - 1) / n) / 2, abs=1e-4)  # scores keep 4 decimals
    assert "Time.now" not in shape.feedback  # the short side is not the first one


def test_a_short_first_side_points_at_the_start_time_read_before_the_clock() -> None:
    rubric = RUBRICS["mover_timed_square"]
    segs = square_segments(loops=4)
    segs[0] = (3.0, 0.2, 0.0)  # 0.6 m: the node's timer had already run 2 s of its first side
    shape = _criterion(rubric, _runs(rubric, segs), "square_shape")
    assert 0 < shape.score < shape.max_score
    assert "rospy.Time.now()" in shape.feedback and "first side (0.60 m)" in shape.feedback


def test_node_that_exited_by_itself_is_not_said_to_have_stopped_after_ctrl_c() -> None:
    rubric = RUBRICS["mover_timed_square"]
    runs = _runs(rubric, square_segments(loops=1), ended_s=40.0)
    stop = _criterion(rubric, runs, "shutdown_stop")
    assert "after Ctrl+C" not in stop.feedback
    assert "had already exited by itself" in stop.feedback and "with the robot at rest" in stop.feedback


def test_node_that_exited_by_itself_leaving_the_robot_moving_is_told_so() -> None:
    rubric = RUBRICS["move_circle"]
    runs = {}
    for s in rubric.scenarios:
        assert s.shutdown_at is not None
        info = RunInfo(shutdown_requested_s=s.start_time + s.shutdown_at, exit_code=0, status="exited",
                       ended_s=s.start_time + 5.0)
        p = s.initial_pose
        runs[s.name] = run([(s.duration, 0.1, 0.2)], x0=p.x, y0=p.y, yaw0=p.yaw, t0=s.start_time,
                           command_segments=[(5.0, 0.1, 0.2)], info=info, shutdown_at=s.shutdown_at)
    stop = _criterion(rubric, runs, "shutdown_stop")
    assert stop.score == 0.0
    assert "had already exited by itself" in stop.feedback and "zero Twist" in stop.feedback
