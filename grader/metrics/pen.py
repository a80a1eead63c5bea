"""The turtlesim window's picture, redrawn from a recorded path: what the pen drew, as the world draws it.

Scoring must depend on the recording alone, so coverage and the report's picture redraw the pen lines from the
recorded poses (one line per update, from the previous pose to the next) on ``sim.turtle_canvas.Canvas`` with
turtlesim's default pen, instead of reading the world's canvas. Pen colour changes, pen-off and teleports are not
in the recorded poses, so the picture assumes the default pen throughout.
"""
from __future__ import annotations

import numpy as np

from grader.metrics.run import Trajectory
from sim.turtle_canvas import METER_PX, Canvas
from sim.turtlesim import CANVAS_M, DEFAULT_PEN, DEFAULT_PEN_WIDTH


def screen_px(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Canvas metres (y up) to the window's pixels (y down), as turtle.cpp converts them."""
    return np.asarray(x) * METER_PX, (CANVAS_M - np.asarray(y)) * METER_PX


def redraw(path: Trajectory, pen_width: int = DEFAULT_PEN_WIDTH) -> Canvas:
    """The canvas after the turtle drove ``path`` with its pen down from the first pose on."""
    canvas = Canvas()
    columns, rows = screen_px(path.x, path.y)
    for i in range(1, len(path)):
        start, end = (columns[i - 1], rows[i - 1]), (columns[i], rows[i])
        if start != end:
            canvas.line(start, end, DEFAULT_PEN, pen_width)
    return canvas


def painted(canvas: Canvas) -> np.ndarray:
    """Per pixel [row, column]: the pen drew there (it differs from the background)."""
    return np.any(canvas.pixels != np.asarray(canvas.background, dtype=np.uint8), axis=2)
