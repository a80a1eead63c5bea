"""Cheap plot rendering: figures reused within a report, legends pasted, lines thinned, the bytes deterministic."""
from __future__ import annotations

import hashlib
import io
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image

from grader.reports.figures import THIN_CELL_PX, Figures, level_changes, png, thin
from grader.reports.legends import PastedLegend, best_place
from grader.reports.plots import _command_figure, task_plots

from . import fakes
from .test_turtle_canvas import TurtlesimRecording

ROOT = Path(__file__).resolve().parents[2]


def circle() -> fakes.FakeRecording:
    return fakes.FakeRecording(Path("circle.mcap"))


def square_from_odometry() -> fakes.FakeRecording:
    return fakes.FakeRecording(Path("square.bag"), ground_truth=False, metadata={})


def pngs(task: str, recording, figures: Figures | None = None) -> list[bytes]:
    return [plot.png for plot in task_plots(task, "nominal", recording, figures=figures)]


def test_plots_are_rgb_pngs_of_the_figure_size():
    path_png = pngs("move_circle", circle())[0]
    image = Image.open(io.BytesIO(path_png))
    assert image.format == "PNG" and image.mode == "RGB" and image.size == (468, 450)  # 5.2 × 5.0 in at 90 dpi


def test_a_plot_is_the_same_bytes_each_time():
    assert pngs("move_circle", circle()) == pngs("move_circle", circle())


def test_a_plot_is_the_same_whatever_the_shared_figures_drew_before():
    alone = pngs("move_circle", circle())
    figures = Figures(90)
    first = pngs("move_circle", circle(), figures)
    pngs("move_square", square_from_odometry(), figures)  # other limits, legend entries and no Ctrl+C mark
    pngs("odom_subscriber", circle(), figures)
    pngs("turtle_circle", TurtlesimRecording(), figures)
    assert pngs("move_circle", circle(), figures) == first == alone


def test_plots_are_the_same_bytes_in_another_process():
    script = ("import hashlib; from pathlib import Path; from tests.cli import fakes; "
              "from grader.reports.plots import task_plots; "
              "print(hashlib.sha256(b''.join(p.png for p in task_plots('odom_subscriber', 'nominal', "
              "fakes.FakeRecording(Path('x.mcap'))))).hexdigest())")
    here = hashlib.sha256(b"".join(pngs("odom_subscriber", circle()))).hexdigest()
    there = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, check=True,
                           env={"PYTHONHASHSEED": "12345", "PATH": "/usr/bin:/bin"})
    assert there.stdout.strip() == here


def test_each_plot_still_gets_its_legend():
    figures = Figures(90)
    task_plots("move_circle", "nominal", circle(), figures=figures)
    figure = _command_figure(circle().commands(), (0.26, 1.82), 30.0, circle().odometry(), figures=figures)
    pasted = [artist for artist in figure.axes[0].artists if isinstance(artist, PastedLegend)]
    assert len(pasted) == 1 and figure.axes[0].get_legend() is None
    assert len(figures.legends._pictures) == 2  # path and commands: drawn once each, pasted again here


@pytest.mark.parametrize("crowded", ["upper right", "upper left", "left half", "everywhere but the bottom"])
def test_the_legend_goes_where_matplotlibs_best_puts_it(crowded):
    x = np.linspace(0, 10, 400)
    y = {"upper right": np.where(x > 5, 9.0, 0.0), "upper left": np.where(x < 5, 9.0, 0.0),
         "left half": np.where(x < 5, np.sin(x * 5) * 5 + 5, 0.0),
         "everywhere but the bottom": 5 + 4 * np.sin(x * 3)}[crowded]
    figure = Figure(figsize=(5, 4), dpi=90)
    axes = figure.add_subplot()
    axes.plot(x, y, label="data")
    axes.axhline(10.0, ls="--", label="limit")
    legend = axes.legend(loc="best", fontsize=8)
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    box = legend.get_window_extent(canvas.get_renderer())
    assert np.allclose(best_place(axes, box.width, box.height, 8 * 90 / 72 * 0.5), box.p0, atol=0.01)


def test_a_legend_matplotlib_cannot_paste_is_matplotlibs_own():
    figures = Figures(90)
    figure = figures.get("bars", lambda f: f.add_subplot(), (4, 3))
    figure.axes[0].bar([1, 2], [3, 4], label="bars")
    figures.legends.add(figure.axes[0], fontsize=8)
    assert figure.axes[0].get_legend() is not None and not figure.axes[0].artists


def polyline_distance(px: np.ndarray, py: np.ndarray, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
    """Distance of each point (px, py) to the polyline through (qx, qy)."""
    ax, ay, bx, by = qx[:-1], qy[:-1], qx[1:], qy[1:]
    dx, dy = bx - ax, by - ay
    length2 = np.where(dx * dx + dy * dy > 0, dx * dx + dy * dy, 1.0)
    t = np.clip(((px[:, None] - ax) * dx + (py[:, None] - ay) * dy) / length2, 0.0, 1.0)
    return np.hypot(ax + t * dx - px[:, None], ay + t * dy - py[:, None]).min(axis=1)


@pytest.mark.parametrize("equal_aspect", [False, True])
def test_thinning_keeps_every_sample_within_a_third_of_a_pixel(equal_aspect):
    rng = np.random.default_rng(7)
    t = np.linspace(0, 100, 10_000)
    # a 100 Hz speed: ramps between plateaus, with the simulator's jitter
    v = 0.2 * np.clip(3 * np.sin(t / 5), 0, 1) + rng.normal(0, 1e-5, len(t))
    axes = Figure(figsize=(7, 4.2), dpi=90).add_subplot()
    kept_t, kept_v = thin(t, v, axes, equal_aspect=equal_aspect)
    assert len(kept_t) < len(t) / 2 and (kept_t[0], kept_t[-1]) == (t[0], t[-1])
    # in pixels of a view that just holds the data (the real view is at least as large, its pixels coarser)
    sx, sy = axes.bbox.width / np.ptp(t), axes.bbox.height / np.ptp(v)
    if equal_aspect:
        sx = sy = min(sx, sy)
    error = polyline_distance(t * sx, v * sy, kept_t * sx, kept_v * sy)
    assert error.max() <= THIN_CELL_PX * np.sqrt(2) + 1e-9


def test_thinning_leaves_short_and_non_finite_lines_alone():
    axes = Figure().add_subplot()
    x = np.array([0.0, 1.0, np.nan, 3.0])
    assert np.array_equal(thin(x, x, axes)[0], x, equal_nan=True)
    assert len(thin(np.array([0.0, 1.0]), np.array([0.0, 0.0]), axes)[0]) == 2


def test_level_changes_draw_the_same_steps():
    t = np.arange(0.0, 10.0, 0.1)
    v = np.repeat([0.0, 0.2, 0.2, 0.0, 0.5], 20)
    kept_t, kept_v = level_changes(t, v)
    assert len(kept_t) == 5 and kept_t[-1] == t[-1]
    probe = np.linspace(0, t[-1], 997)
    def level(times, values):
        return values[np.searchsorted(times, probe, side="right") - 1]
    assert np.array_equal(level(t, v), level(kept_t, kept_v))


def test_a_wide_tick_label_widens_the_margin_for_that_plot_only():
    figures = Figures(90)
    figure = _command_figure(circle().commands(), None, None, None, figures=figures)
    built_left = figure.subplotpars.left
    figure.axes[0].yaxis.set_major_formatter(lambda value, _: f"{value:.9f}")  # wider than the margin
    png(figure, 90)
    renderer = figure.canvas.get_renderer()
    assert figure.subplotpars.left > built_left
    assert min(axes.yaxis.label.get_window_extent(renderer).x0 for axes in figure.axes) >= 0
    assert figures.get("commands", lambda _: None, (7.0, 4.2)).subplotpars.left == built_left
