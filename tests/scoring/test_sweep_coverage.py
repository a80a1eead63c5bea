"""turtlesim cleaning: what the turtle sweeps (a band as wide as the turtle) is cleaned, and gaps inside its path show."""
from __future__ import annotations

import math

import numpy as np
import pytest

from grader.metrics import RunData, Trajectory
from grader.metrics.coverage import Params, measure
from grader.metrics.run import ServiceCall
from grader.rubric import load_rubrics
from grader.scoring import score_task

CENTRE = 5.544445
SWEEP = Params(cell_px=22, sweep_px=45)  # turtle_clean's
RUBRIC = load_rubrics()["turtle_clean"]


def _run(xs: list[float], ys: list[float], calls: tuple[ServiceCall, ...] = ()) -> RunData:
    """A turtle driving through the points (one pose each 16 ms, turtlesim's update, 2 m/s between them)."""
    px, py = [xs[0]], [ys[0]]
    for (x0, y0), (x1, y1) in zip(zip(xs, ys), zip(xs[1:], ys[1:])):
        n = max(1, math.ceil(math.hypot(x1 - x0, y1 - y0) / 0.032))
        px += np.linspace(x0, x1, n + 1)[1:].tolist()
        py += np.linspace(y0, y1, n + 1)[1:].tolist()
    t = np.arange(len(px)) * 0.016
    yaw = np.arctan2(np.diff(py, prepend=py[0]), np.diff(px, prepend=px[0]))
    path = Trajectory.of(t, px, py, yaw, "ground_truth")
    return RunData(odometry=path, ground_truth=path, service_calls=calls)


def _rows(spacing: float) -> RunData:
    """A lawnmower from (0.5, 0.5): rows ``spacing`` m apart up to 10.5 m."""
    xs, ys, k = [], [], 0
    for y in np.arange(0.5, 10.5 + 1e-9, spacing):
        xs += [0.5, 10.5] if k % 2 == 0 else [10.5, 0.5]
        ys += [float(y), float(y)]
        k += 1
    return _run(xs, ys)


def _spiral(spacing: float, radius: float = 5.0) -> RunData:
    phi = np.linspace(0.01, radius / spacing * 2.0 * math.pi, 4000)
    r = spacing * phi / (2.0 * math.pi)
    return _run((CENTRE + r * np.cos(phi)).tolist(), (CENTRE + r * np.sin(phi)).tolist())


def test_rows_as_far_apart_as_the_turtle_is_wide_clean_everything() -> None:
    m = measure(_rows(1.0), SWEEP)
    assert m["coverage"] == 1.0 and m["outline_coverage"] > 0.97
    assert measure(_rows(1.0), Params(cell_px=22))["coverage"] < 0.6  # the pen's 3 px alone: about half


def test_rows_twice_the_turtles_width_apart_leave_stripes() -> None:
    m = measure(_rows(2.0), SWEEP)
    assert m["coverage"] > 0.75  # most cells are touched...
    assert m["outline_coverage"] < 0.65  # ...but a metre in every two is never swept


def test_a_tight_spiral_cleans_the_disc_it_means_to_without_gaps() -> None:
    m = measure(_spiral(1.0), SWEEP)
    assert 0.6 < m["coverage"] < 0.8 and m["outline_coverage"] > 0.97


def test_a_loose_spiral_leaves_gaps() -> None:
    assert measure(_spiral(2.0), SWEEP)["outline_coverage"] < 0.7


def test_a_teleport_sweeps_nothing() -> None:
    # 1 s at (2, 2), teleported to (9, 9) at 1 s, where it stays: nothing is swept between them
    t = np.arange(125) * 0.016
    at_start = t < 1.0
    path = Trajectory.of(t, np.where(at_start, 2.0, 9.0), np.where(at_start, 2.0, 9.0), np.zeros(125), "ground_truth")
    jump = (ServiceCall(1.0, "/turtle1/teleport_absolute", {"x": 9.0, "y": 9.0, "theta": 0.0}, {}),)
    swept = measure(RunData(odometry=path, ground_truth=path, service_calls=jump), Params(sweep_px=45))
    unannounced = measure(RunData(odometry=path, ground_truth=path), Params(sweep_px=45))
    assert swept["pixel_coverage"] < 0.03 < unannounced["pixel_coverage"]


@pytest.mark.parametrize("spacing, full", [(0.5, True), (1.0, True), (2.0, False)])
def test_turtle_clean_coverage_by_row_spacing(spacing: float, full: bool) -> None:
    coverage = next(c for c in score_task(RUBRIC, {s.name: _rows(spacing) for s in RUBRIC.scenarios}).criteria
                    if c.id == "coverage")
    assert (coverage.score == coverage.max_score) is full, coverage.feedback
    assert full or "closer together" in coverage.feedback


def test_turtle_clean_gives_a_tight_spiral_full_coverage() -> None:
    coverage = score_task(RUBRIC, {s.name: _spiral(1.0) for s in RUBRIC.scenarios}).criteria[0]
    assert coverage.id == "coverage" and coverage.score == coverage.max_score, coverage.feedback
