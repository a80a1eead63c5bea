"""Two turtles drawing a figure each: whether a turtle was spawned, whether each turtle's pen got the colour asked
for, and whether each colour on the final picture (redrawn from the recording, ``pen.redraw``) is a square outline of
the side asked for.

The figure is judged on the picture, as a student sees the window: the pixels of one asked colour must span a square
of ``side`` metres (their bounding box, less the pen's width) and hold about as much ink as its outline does
(``ink_ratio``, the colour furthest from 1: a filled square has far more, a single line far less; where a line falls
between pixels it is drawn a pixel wider). A colour that is not on the picture counts as a figure 100 % wrong.
"""
from __future__ import annotations

import numpy as np
from pydantic import Field

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.pen import redraw
from grader.metrics.run import RunData, ServiceCall
from sim.turtle_canvas import METER_PX

Rgb = tuple[int, int, int]
WORST = 1.0  # the relative error of a figure that is not there


class Params(MetricParams):
    """The pens asked for (turtle name → [r, g, b]), their width and the square's side."""

    pens: dict[str, tuple[int, int, int]]
    width: int = Field(3, ge=1, le=255)  # px
    side: float = Field(2.0, gt=0.0)  # m


def _spawned(calls: tuple[ServiceCall, ...]) -> list[str]:
    """The names of the turtles /spawn created (a refused or failed call names none)."""
    return [str(c.response["name"]) for c in calls
            if c.service == "/spawn" and c.response is not None and c.response.get("name")]


def _pen_of(calls: tuple[ServiceCall, ...], turtle: str) -> Rgb | None:
    """The colour the turtle's last answered set_pen call gave it with the pen down (None: never set, or lifted)."""
    served = [c.request for c in calls if c.service == f"/{turtle}/set_pen" and c.response is not None]
    if not served or served[-1].get("off"):
        return None
    last = served[-1]
    return (int(last["r"]), int(last["g"]), int(last["b"]))


def _figure(pixels: np.ndarray, rgb: Rgb, side: float, width: int) -> tuple[float, float]:
    """How far one colour's pixels span from a square of ``side`` m drawn ``width`` px wide (relative), and their
    ink against that square's outline (1: as much as the outline; a filled square has far more, a line far less)."""
    mask = np.all(pixels == np.array(rgb, dtype=np.uint8), axis=2)
    if not mask.any():
        return WORST, 0.0
    rows, cols = np.nonzero(mask)
    span_m = np.array([rows.max() - rows.min() + 1, cols.max() - cols.min() + 1], dtype=float) - width
    size_error = float(np.max(np.abs(span_m / METER_PX - side))) / side
    return min(WORST, size_error), float(mask.sum()) / (4.0 * side * METER_PX * width)


def measure(run: RunData, params: Params) -> Measurement:
    """Spawned turtles, pens set as asked (and which not), and each asked colour's figure on the final picture."""
    calls = run.service_calls
    spawned = _spawned(calls)
    wrong = [name for name, rgb in params.pens.items() if _pen_of(calls, name) != tuple(rgb)]
    pixels = redraw(run).canvas.pixels
    figures = {name: _figure(pixels, tuple(rgb), params.side, params.width) for name, rgb in params.pens.items()}
    worst = max(figures, key=lambda name: figures[name][0])
    odd = max(figures, key=lambda name: abs(figures[name][1] - 1.0))
    return {
        "n_spawned": len(spawned),
        "spawned_names": ", ".join(spawned),
        "pens_wrong": len(wrong),
        "pens_wrong_names": ", ".join(wrong),
        "figure_error_rel": figures[worst][0],
        "figure_worst_turtle": worst,
        "figures_missing": sum(1 for error, _ in figures.values() if error == WORST),
        "ink_ratio": figures[odd][1],
        "side": params.side,
    }


METRIC = Metric(
    name="spawn_draw",
    params=Params,
    quantities=frozenset({"n_spawned", "spawned_names", "pens_wrong", "pens_wrong_names", "figure_error_rel",
                          "figure_worst_turtle", "figures_missing", "ink_ratio", "side"}),
    measure=measure,
)
