"""Square criteria by share: one odd side or corner costs its share, never the criterion; a square must have at least
four sides and three corners; a robot that rested after its loops until Ctrl+C stopped by itself."""
from __future__ import annotations

import math

import pytest
from scoring_synth import Segment, run, square_segments

from grader.metrics import RunData, RunInfo
from grader.metrics.square import Params, measure
from grader.rubric import load_rubrics
from grader.scoring import score_task

RUBRICS = load_rubrics()
QUARTER = math.radians(90.0) / 0.5  # s to turn 90 degrees at 0.5 rad/s


def _square(segments: list[Segment], total: float = 150.0, ctrl_c: float | None = None) -> RunData:
    """``segments`` from (0, 0), at rest afterwards until ``total`` s; Ctrl+C at ``ctrl_c`` s if given."""
    rest = total - sum(d for d, _, _ in segments)
    info = RunInfo() if ctrl_c is None else RunInfo(shutdown_requested_s=ctrl_c)
    return run([*segments, (rest, 0.0, 0.0)], info=info, shutdown_at=ctrl_c)


def _criterion(task: str, data: RunData, criterion: str):
    rubric = RUBRICS[task]
    return next(c for c in score_task(rubric, {s.name: data for s in rubric.scenarios}).criteria if c.id == criterion)


def test_eight_good_sides_earn_the_whole_share() -> None:
    m = measure(_square(square_segments()), Params(side=1.0))
    assert (m["n_sides"], m["n_sides_ok"], m["side_share"]) == (8, 8, 1.0)
    assert m["corner_share"] == 1.0


def test_a_first_side_shortened_by_a_lost_command_costs_one_eighth() -> None:
    segs = square_segments()
    segs[0] = (0.7 / 0.2, 0.2, 0.0)  # the first command went nowhere: 0.7 m
    m = measure(_square(segs), Params(side=1.0))
    assert (m["n_sides_off"], m["side_share"]) == (1, 7 / 8)
    side = _criterion("move_square", _square(segs), "side_length")
    assert side.score == pytest.approx(side.max_score * 7 / 8)
    assert "Only the first side (0.70 m) was short" in side.feedback and "get_num_connections" in side.feedback


def test_a_short_side_other_than_the_first_is_not_blamed_on_a_lost_command() -> None:
    segs = square_segments()
    segs[4] = (0.7 / 0.2, 0.2, 0.0)
    side = _criterion("move_square", _square(segs), "side_length")
    assert side.score == pytest.approx(side.max_score * 7 / 8) and "first side" not in side.feedback


def test_one_corner_cannot_pass_for_a_square() -> None:
    m = measure(_square(square_segments(loops=1)[:3]), Params(side=1.0))  # side, corner, side
    assert m["n_corners_ok"] == 1 and m["corner_share"] == pytest.approx(1 / 3)
    assert m["side_share"] == pytest.approx(2 / 4)


def test_a_one_loop_square_has_every_corner_it_needs() -> None:
    m = measure(_square(square_segments(loops=1)[:-1]), Params(side=1.0))  # four sides, three corners between them
    assert (m["n_sides"], m["n_corners"], m["corner_share"], m["side_share"]) == (4, 3, 1.0, 1.0)


def test_one_overshot_corner_costs_its_share() -> None:
    segs = square_segments()
    segs[3] = (math.radians(105.0) / 0.5, 0.0, 0.5)  # the second corner turns 105 degrees
    corner = _criterion("move_square", _square(segs), "corner_angle")
    assert 0.8 * corner.max_score < corner.score < corner.max_score
    assert "turns between sides were within 7.5°" in corner.feedback and "They measured" in corner.feedback


@pytest.mark.parametrize("ctrl_c", [None, 130.0])
def test_resting_after_two_loops_is_stopping_by_itself_with_or_without_ctrl_c(ctrl_c: float | None) -> None:
    data = _square(square_segments(), ctrl_c=ctrl_c)  # the loops end at 65 s: 65 s at rest before Ctrl+C
    assert measure(data.until_ctrl_c(), Params(side=1.0))["loops_at_rest"] == 2.0
    stop = _criterion("move_square", data, "two_loop_stop")
    assert stop.score == stop.max_score, stop.feedback


def test_a_robot_still_driving_when_ctrl_c_comes_did_not_stop_by_itself() -> None:
    data = _square(square_segments(loops=3), total=110.0, ctrl_c=90.0)  # the third loop is under way at 90 s
    stop = _criterion("move_square", data, "two_loop_stop")
    assert stop.score == 0.0 and stop.measured["loops_at_rest"] is None


def test_a_pause_shorter_than_the_rest_needed_before_ctrl_c_is_not_a_stop() -> None:
    data = _square(square_segments(), total=67.0, ctrl_c=66.0)  # at rest 1 s when Ctrl+C comes
    assert math.isnan(measure(data.until_ctrl_c(), Params(side=1.0))["loops_at_rest"])


def test_a_timed_square_with_a_short_first_side_loses_only_that_sides_share() -> None:
    rubric = RUBRICS["mover_timed_square"]
    segs = square_segments(loops=6, v=0.25)
    segs[0] = (2.4, 0.25, 0.0)  # 0.6 m
    runs = {s.name: run(segs + [(20.0, 0.0, 0.0)], info=RunInfo(shutdown_requested_s=s.start_time + 80.0),
                        t0=s.start_time, shutdown_at=80.0) for s in rubric.scenarios}
    shape = next(c for c in score_task(rubric, runs).criteria if c.id == "square_shape")
    n = shape.measured["n_sides"]
    assert shape.score == pytest.approx(shape.max_score * (1 + (n - 1) / n) / 2, abs=1e-4)  # scores keep 4 decimals
    assert "rospy.Time.now()" in shape.feedback
