"""Canvas coverage: the share of the turtlesim window the pen painted, redrawn from the recorded path.

``coverage`` counts square cells of ``cell_px`` pixels the pen touched (``cell_px = 1``: single pixels, which a
3 px pen covers only by passing every few pixels); ``pixel_coverage`` is always the share of pixels painted.
"""
from __future__ import annotations

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricError, TrajectoryParams
from grader.metrics.motion import path_length
from grader.metrics.pen import painted, redraw
from grader.metrics.run import RunData
from sim.turtle_canvas import CANVAS_PX


class Params(TrajectoryParams):
    """Cell size of the coverage grid."""

    cell_px: int = Field(1, ge=1, le=CANVAS_PX)


def measure(run: RunData, params: Params) -> Measurement:
    """Redraw the pen lines and count the painted pixels and touched cells."""
    traj = run.trajectory(params.source)
    if len(traj) < 2:
        raise MetricError("the recording holds no pose of the turtle")
    paint = painted(redraw(traj))
    n = -(-CANVAS_PX // params.cell_px)  # cells per side; the last row and column may be narrower
    padded = np.pad(paint, (0, n * params.cell_px - CANVAS_PX))
    touched = padded.reshape(n, params.cell_px, n, params.cell_px).any(axis=(1, 3))
    return {
        "coverage": float(touched.mean()),
        "pixel_coverage": float(paint.mean()),
        "cells": n * n,
        "path_length": path_length(traj),
    }


METRIC = Metric(
    name="canvas_coverage",
    params=Params,
    quantities=frozenset({"coverage", "pixel_coverage", "cells", "path_length"}),
    measure=measure,
)
