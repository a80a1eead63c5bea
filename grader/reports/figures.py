"""Report figures made cheaply: each kind built once per report and refilled, fixed margins, PNG drawn by Agg directly.

Building a figure's axes and ticks and laying it out with `tight_layout` cost far more than drawing the data, so a
report reuses one figure per kind: its data artists and legend are removed, new ones are added, and the data limits
are recomputed, which draws the same picture as a new figure would. Margins are fixed (widened and redrawn only
when a y label would fall off the left edge), and the PNG is written as RGB at a low zlib level, which is as small
as matplotlib's RGBA at the default level and about half the encoding time. Output depends only on the data.
"""
from __future__ import annotations

import io
from collections.abc import Callable

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from grader.reports.legends import Legends

THIN_CELL_PX = 0.25  # thinned lines stay within this cell's diagonal (0.35 px) of the samples they stand for
PNG_COMPRESS_LEVEL = 3  # levels 1-3 cost the same here; 4 and up double the time for a few per cent
MARGIN_PX = 4  # kept between a y label that had to move and the figure's edge


class Figures:
    """One reusable figure per kind, and the legends drawn so far, for the plots of one report (not shared
    between threads)."""

    def __init__(self, dpi: int) -> None:
        self.dpi = dpi
        self.legends = Legends(dpi)
        self._made: dict[str, tuple[Figure, float]] = {}  # kind -> (figure, its left margin as built)

    def get(self, kind: str, build: Callable[[Figure], None], size_in: tuple[float, float]) -> Figure:
        """The figure of this kind with no data in it: built by `build` (axes, labels, margins) the first time."""
        if kind not in self._made:
            figure = Figure(figsize=size_in, dpi=self.dpi)
            FigureCanvasAgg(figure)
            build(figure)
            self._made[kind] = (figure, figure.subplotpars.left)
            return figure
        figure, left = self._made[kind]
        for axes in figure.axes:
            _empty(axes)
        if figure.subplotpars.left != left:  # widened for the last plot's labels: each plot starts from the same
            figure.subplots_adjust(left=left)
        return figure


def _empty(axes: Axes) -> None:
    """Remove what a plot added (data artists, legend) and forget its data limits; axes, ticks and labels stay."""
    for artist in [*axes.lines, *axes.patches, *axes.collections, *axes.texts, *axes.images, *axes.artists]:
        artist.remove()
    if axes.legend_ is not None:
        axes.legend_.remove()
    axes.set_prop_cycle(None)  # lines without a colour of their own get the colours a new figure would give them
    axes.relim()  # no artists left: the limits of the next data replace these instead of growing from them


def thin(x: np.ndarray, y: np.ndarray, axes: Axes, equal_aspect: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The samples of a line that its picture needs: where it enters a new THIN_CELL_PX cell of the axes, and the
    last one. A recording's 100 Hz series has several samples per pixel, which cost drawing (and the legend's search
    for a free corner) without changing a pixel."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if len(x) < 3 or not (np.isfinite(x).all() and np.isfinite(y).all()):
        return x, y
    span_x, span_y = float(np.ptp(x)), float(np.ptp(y))
    # The data's span is at most the view's, so these cells are at most THIN_CELL_PX of a drawn pixel.
    cell_x, cell_y = span_x / axes.bbox.width * THIN_CELL_PX, span_y / axes.bbox.height * THIN_CELL_PX
    if equal_aspect:  # one scale for both, set by the longer side (and the view is at least that)
        cell_x = cell_y = max(cell_x, cell_y)
    column = np.floor((x - x.min()) / cell_x) if cell_x > 0 else np.zeros(len(x))
    row = np.floor((y - y.min()) / cell_y) if cell_y > 0 else np.zeros(len(y))
    keep = np.ones(len(x), dtype=bool)
    keep[1:] = (column[1:] != column[:-1]) | (row[1:] != row[:-1])
    keep[-1] = True
    return x[keep], y[keep]


def level_changes(t: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A step series without the samples that repeat the level before them: the same steps, drawn exactly."""
    t, v = np.asarray(t), np.asarray(v)
    keep = np.ones(len(v), dtype=bool)
    keep[1:-1] = v[1:-1] != v[:-2]
    return t[keep], v[keep]


def png(figure: Figure, dpi: int) -> bytes:
    """The figure as PNG bytes at `dpi`: drawn once by Agg (twice when a y label did not fit), written as RGB."""
    figure.set_dpi(dpi)
    canvas = figure.canvas if isinstance(figure.canvas, FigureCanvasAgg) else FigureCanvasAgg(figure)
    canvas.draw()
    if _fit_y_labels(figure, canvas):
        canvas.draw()
    rgb = np.asarray(canvas.buffer_rgba())[:, :, :3]  # the figure is opaque: alpha is always 255
    buffer = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(rgb)).save(buffer, format="png", compress_level=PNG_COMPRESS_LEVEL,
                                                    dpi=(dpi, dpi))
    return buffer.getvalue()


def _fit_y_labels(figure: Figure, canvas: FigureCanvasAgg) -> bool:
    """Widen the left margin when wide tick labels pushed a y label off the figure; True when it was widened."""
    renderer = canvas.get_renderer()
    overflow = max((-axes.yaxis.label.get_window_extent(renderer).x0 for axes in figure.axes
                    if axes.yaxis.label.get_visible() and axes.yaxis.label.get_text()), default=0.0)
    if overflow <= 0:
        return False
    left = figure.subplotpars.left + (overflow + MARGIN_PX) / figure.bbox.width
    figure.subplots_adjust(left=min(left, 0.5))
    return True
