"""A whole run of a node that draws with every service that changes turtlesim's picture (reset, two pen colours and
widths, the pen lifted, both teleports, a spawned turtle with its own pen, clear, kill): the picture redrawn from the
recording alone is the world's own final canvas, pixel for pixel."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from grader.metrics import coverage
from grader.metrics.pen import redraw
from grader.metrics.run import RunData
from grader.recording import Recording
from grader.reports.plots import task_plots
from grader.runtime import NodeSpec, RunSpec
from grader.runtime.session import Session
from sim import Scenario

NODE = Path(__file__).resolve().parent / "nodes" / "turtle_pen_drawing.py"

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def drawn(tmp_path_factory):
    """The world's canvas at the end of the run, and the run's data as scoring reads it from the recording."""
    tmp = tmp_path_factory.mktemp("turtle_pen")
    spec = RunSpec(scenario=Scenario(robot="turtlesim", duration=12.0), nodes=(NodeSpec(script=NODE),))
    session = Session(spec, tmp / "run.mcap", tmp / "run.log")
    result = session.run()
    assert result.nodes[0].status == "exited", result.nodes[0].message
    recording = Recording.open(tmp / "run.mcap")
    return session.world.canvas, RunData.from_recording(recording), recording


def test_the_recording_holds_the_calls_that_drew(drawn) -> None:
    _, run, _ = drawn
    served = [(c.service, c.response is not None) for c in run.service_calls]
    assert [s for s, _ in served] == ["/reset", "/turtle1/set_pen", "/clear", "/turtle1/set_pen",
                                      "/turtle1/teleport_absolute", "/turtle1/set_pen", "/turtle1/teleport_relative",
                                      "/spawn", "/turtle2/set_pen", "/kill"]  # the call to the killed turtle: none
    assert all(ok for _, ok in served) and set(run.poses) == {"/turtle1/pose", "/turtle2/pose"}


def test_the_redraw_from_the_recording_is_the_worlds_canvas(drawn) -> None:
    world, run, _ = drawn
    drawing = redraw(run)
    assert np.array_equal(drawing.canvas.pixels, world.pixels)
    assert np.array_equal(drawing.canvas.inked, world.inked)
    assert [t.name for t in drawing.turtles] == ["turtle1"]
    assert {(255, 0, 0), (30, 200, 60), (20, 20, 240)} <= {tuple(c) for c in drawing.canvas.pixels.reshape(-1, 3)}


def test_coverage_is_what_the_worlds_pens_drew(drawn) -> None:
    world, run, _ = drawn
    assert coverage.measure(run, coverage.Params())["pixel_coverage"] == pytest.approx(world.inked.mean())


def test_the_report_draws_the_recorded_run(drawn) -> None:
    _, _, recording = drawn
    assert [p.name for p in task_plots("turtle_clean", "nominal", recording)][0] == "canvas"
