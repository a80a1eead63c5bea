"""turtlesim shapes: a polygon's sides, turns and closure; the goal reached; the canvas the pen covered; wall hits."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scoring_synth import run

from grader.metrics import MetricError, OutputLine
from grader.metrics import coverage, goal, polygon, wall_hits
from grader.metrics.pen import redraw
from grader.metrics.run import RunData, Trajectory

TURN = math.radians(60)  # rad/s


def triangle(turn_deg: float = 120.0, side: float = 2.0) -> list[tuple[float, float, float]]:
    return [(side, 1.0, 0.0), (math.radians(turn_deg) / TURN, 0.0, TURN)] * 3


def test_an_equilateral_triangle_has_equal_sides_120_degree_turns_and_closes() -> None:
    m = polygon.measure(run(triangle(), x0=5.5, y0=5.5), polygon.Params())
    assert m["n_sides"] == 3 and m["side_spread_rel"] == pytest.approx(0.0, abs=1e-3)
    assert m["turn_worst_error_deg"] == pytest.approx(0.0, abs=0.5) and m["closure_rel"] == pytest.approx(0, abs=0.01)


def test_60_degree_turns_leave_the_shape_open() -> None:
    m = polygon.measure(run(triangle(60.0), x0=5.5, y0=5.5), polygon.Params())
    assert m["turn_mean_deg"] == pytest.approx(60.0, abs=0.5) and m["turn_worst_error_deg"] == pytest.approx(60, abs=0.5)
    assert m["side_spread_rel"] == pytest.approx(0.0, abs=1e-3) and m["closure"] == pytest.approx(4.0, abs=0.05)


def test_unequal_sides_are_measured() -> None:
    segments = [(2.0, 1.0, 0.0), (2.0944 / TURN, 0.0, TURN), (1.0, 1.0, 0.0), (2.0944 / TURN, 0.0, TURN),
                (2.0, 1.0, 0.0)]
    m = polygon.measure(run(segments), polygon.Params())
    assert m["side_min"] == pytest.approx(1.0, abs=0.02) and m["side_spread_rel"] == pytest.approx(0.6, abs=0.02)


def test_driving_and_turning_at_once_is_not_a_polygon() -> None:
    with pytest.raises(MetricError, match="straight sides"):
        polygon.measure(run([(10.0, 1.0, 0.7)]), polygon.Params())


def test_the_goal_is_measured_at_the_end_and_at_the_closest() -> None:
    m = goal.measure(run([(3.0, 1.0, 0.0), (1.0, -1.0, 0.0)], x0=1.0, y0=2.0),
                     goal.Params(goal_x=4.0, goal_y=2.0, within=0.1))
    assert m["final_error"] == pytest.approx(1.0, abs=0.04) and m["closest"] == pytest.approx(0.0, abs=0.04)
    assert m["start_error"] == pytest.approx(3.0) and m["reached_s"] == pytest.approx(2.9, abs=0.05)


def test_redraw_paints_a_3_px_line_along_the_path() -> None:
    line = Trajectory.of([0, 1], [1.0, 3.0], [5.0, 5.0], [0.0, 0.0])
    paint = redraw(RunData(odometry=line)).canvas.inked
    assert paint.sum() == pytest.approx(3 * (2 * 45 + 3), abs=6)  # 90 px long plus the square caps, 3 px wide
    row = int(round((11.088889 - 5.0) * 45))
    assert paint[row, 45 + 10] and not paint[row + 3, 45 + 10]


def test_coverage_counts_cells_the_pen_crossed() -> None:
    # Rows every metre from x, y = 0.2 to 10.9 m: every 45 px cell is crossed but those of the last, 5 px wide, row
    # and column (the canvas is 500 px), while a few percent of the pixels are painted.
    xs, ys = [], []
    for k, y in enumerate(np.arange(0.5, 11.0, 1.0)):
        xs += [0.2, 10.9] if k % 2 == 0 else [10.9, 0.2]
        ys += [y, y]
    lawn = Trajectory.of(np.arange(len(xs)), xs, ys, np.zeros(len(xs)))
    data = run([(1.0, 0.0, 0.0)])
    data = type(data)(odometry=lawn, ground_truth=lawn)
    cells = coverage.measure(data, coverage.Params(cell_px=45))
    pixels = coverage.measure(data, coverage.Params())
    assert cells["cells"] == 12 * 12 and cells["coverage"] == pytest.approx(11 * 11 / 144)
    assert pixels["coverage"] == pixels["pixel_coverage"] < 0.1


def test_wall_hits_count_turtlesims_warnings_only() -> None:
    lines = [OutputLine(3.0, "rosout", "Oh no! I hit the wall! (Clamping from [x=11.100000, y=5.544445])", "WARN"),
             OutputLine(3.016, "rosout", "Oh no! I hit the wall! (Clamping from [x=11.130000, y=5.544445])", "WARN"),
             OutputLine(3.1, "stdout", "Oh no! I hit the wall!")]
    m = wall_hits.measure(run([(1.0, 0.0, 0.0)], t0=2.0, lines=lines), wall_hits.Params())
    assert (m["n_wall_hits"], m["hit_wall"], m["first_hit_x"]) == (2, True, 11.1)
    assert m["first_hit_s"] == pytest.approx(1.0)
    clean = wall_hits.measure(run([(1.0, 0.0, 0.0)]), wall_hits.Params())
    assert (clean["n_wall_hits"], clean["hit_wall"]) == (0, False) and math.isnan(clean["first_hit_s"])
