"""turtlesim runs get the picture the turtlesim window would show, redrawn from the recording, beside the usual plots."""
from __future__ import annotations

import io
from pathlib import Path

import numpy as np
from matplotlib.image import imread

from grader.metrics.run import RunData, Trajectory
from grader.reports.canvas import canvas_figure, turtle_outline
from grader.reports.plots import task_plots

from . import fakes

TURTLESIM = {"rosgrade": {"robot": "turtlesim", "scenario": '{"name": "nominal"}'}, "rosgrade.run": {}}


class TurtlesimRecording(fakes.FakeRecording):
    """The fake circle moved to the canvas centre; like turtlesim, it has no nav_msgs/Odometry."""

    def __init__(self) -> None:
        super().__init__(Path("turtle.mcap"), metadata=TURTLESIM)
        self._odom.x, self._odom.y = self._odom.x + 7.5, self._odom.y + 6.0

    def odometry(self):
        raise AssertionError("turtlesim recordings have no odometry to read")


def test_turtlesim_runs_get_the_window_picture_first_and_no_turtlebot_ideal_shape() -> None:
    plots = task_plots("turtle_circle", "nominal", TurtlesimRecording())
    assert [p.name for p in plots] == ["canvas", "path", "commands"]
    assert plots[0].png.startswith(b"\x89PNG") and "turtlesim window" in plots[0].title


def test_turtlebot_runs_get_no_window_picture() -> None:
    plots = task_plots("move_circle", "nominal", fakes.FakeRecording(Path("x.mcap")))
    assert "canvas" not in [p.name for p in plots]


def test_the_picture_shows_the_pen_on_turtlesims_background() -> None:
    path = Trajectory.of([0, 1], [2.0, 9.0], [5.5, 5.5], [0.0, 0.0])
    buffer = io.BytesIO()
    canvas_figure(RunData(odometry=path)).savefig(buffer, format="png", dpi=100)
    pixels = (imread(io.BytesIO(buffer.getvalue()))[..., :3] * 255).round().astype(int)
    colours = {tuple(c) for c in pixels.reshape(-1, 3)}
    assert (69, 86, 255) in colours and (179, 184, 255) in colours  # background and pen


def test_the_turtle_points_along_its_heading_on_screen() -> None:
    up = turtle_outline(100.0, 100.0, np.pi / 2)  # heading +y in the canvas is up on the screen (row decreases)
    assert up[0][1] < 100.0 and abs(up[0][0] - 100.0) < 1e-9
