"""Plots that show a beginner what their robot did: path against the ideal shape, commands against limits, printed pose."""
from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from grader.metrics.collisions import Params as TouchParams
from grader.metrics.collisions import touches
from grader.metrics.pose_print import pose_lines
from grader.metrics.run import (Contact, OutputLine, RunData, Trajectory, by_window, contacts, other_windows,
                                param_changes, service_calls, turtle_poses)
from grader.report import SubmissionReport
from grader.reports.canvas import canvas_figure
from grader.reports.figures import Figures, level_changes, png, thin
from grader.reports.replay import Replay, replay_of, scenario_times
from sim.scenario import TURTLESIM

DPI = 90  # the figures' natural size fits the HTML report's column
IDEAL_RADIUS_M = 0.5
SQUARE_SIDE_M = 1.0
# Course limits from the robots' teleop nodes (linear m/s, angular rad/s); unknown robots get no limit lines.
ROBOT_LIMITS = {
    "turtlebot3_burger": (0.22, 2.84),
    "turtlebot3_waffle": (0.26, 1.82),
    "turtlebot3_waffle_pi": (0.26, 1.82),
}
# Figure sizes (inches) and fixed margins: tight_layout's choice for the usual tick labels, which it cost more to
# compute each time than drawing the plot did (a y label pushed off the edge widens the left margin).
PATH_SIZE_IN, PATH_MARGINS = (5.2, 5.0), {"left": 0.15, "right": 0.96, "bottom": 0.117, "top": 0.965}
SERIES_SIZE_IN, SERIES_MARGINS = (7.0, 4.2), {"left": 0.11, "right": 0.975, "bottom": 0.139, "top": 0.955,
                                              "hspace": 0.2}


@dataclass(frozen=True)
class Plot:
    """One rendered figure of one scenario of one task."""

    task: str
    scenario: str
    name: str
    title: str
    png: bytes

    @property
    def filename(self) -> str:
        """File name of the PNG inside the report's plots folder."""
        return f"{self.task}-{self.scenario}-{self.name}.png"


def shape_for(task_id: str) -> str | None:
    """Which ideal figure a task's path is compared to, judged from the task id."""
    if "circle" in task_id:
        return "circle"
    if "square" in task_id:
        return "square"
    if "odom" in task_id and ("sub" in task_id or "print" in task_id):
        return "printed"
    return None


def report_plots(report: SubmissionReport, dpi: int = DPI, jobs: int = 1) -> tuple[list[Plot], list[str]]:
    """Plots for every recording of a report, and a note for each recording that could not be read."""
    plots, _, notes = report_media(report, dpi, jobs, replays=False)
    return plots, notes


def report_media(report: SubmissionReport, dpi: int = DPI, jobs: int = 1,
                 replays: bool = True) -> tuple[list[Plot], list[Replay], list[str]]:
    """Plots and replays for every recording of a report, and a note for each recording that could not be read;
    ``jobs`` processes draw them (one share of the recordings each), in the same order and to the same bytes."""
    wanted = [(i, path) for i, task in enumerate(report.tasks) for path in task.recordings]
    if not wanted:
        return [], [], []
    from grader.workers import fork_map

    shares = [wanted[i::jobs] for i in range(min(max(1, jobs), len(wanted)))]
    drawn = fork_map(lambda share: _draw(report, share, dpi, replays), shares, jobs)
    by_recording = {item: result for share, results in zip(shares, drawn) for item, result in zip(share, results)}
    plots = [plot for item in wanted for plot in by_recording[item][0]]
    shown = [replay for item in wanted if (replay := by_recording[item][1]) is not None]
    notes = [note for item in wanted if (note := by_recording[item][2])]
    return plots, shown, notes


def _draw(report: SubmissionReport, share: list[tuple[int, str]], dpi: int,
          replays: bool) -> list[tuple[list[Plot], Replay | None, str | None]]:
    """The plots and replay of each (task index, recording path), or why that recording could not be shown. Both
    read one RunData, the series scoring read."""
    from grader.recording import Recording, RecordingError

    figures = Figures(dpi)  # built once, refilled for every recording
    drawn: list[tuple[list[Plot], Replay | None, str | None]] = []
    for index, path in share:
        task, scenario = report.tasks[index], Path(path).stem
        try:
            recording = Recording.open(Path(path))
            run = RunData.from_recording(recording, *scenario_times(recording))
            plots = task_plots(task.id, scenario, recording, dpi=dpi, figures=figures, run=run)
            drawn.append((plots, replay_of(task, scenario, recording, run) if replays else None, None))
        except (RecordingError, ValueError) as exc:
            drawn.append(([], None, f"{task.id}: could not plot {Path(path).name}: {exc}"))
    return drawn


def task_plots(task_id: str, scenario: str, recording: Any, dpi: int = DPI,
               figures: Figures | None = None, run: RunData | None = None) -> list[Plot]:
    """The figures for one recording: the turtlesim window (turtlesim runs), path, commands, and printed pose for
    printing tasks. `figures` lets the recordings of one report share their figures; `run` is the recording as
    RunData when it was read already (the turtlesim window redraws from it)."""
    plots = []
    figures = figures if figures is not None else Figures(dpi)
    metadata = recording.metadata or {}
    turtlesim = _record(metadata, "rosgrade").get("robot") == TURTLESIM
    kind = None if turtlesim else shape_for(task_id)  # the ideal shapes are the TurtleBot tasks'
    truth = recording.ground_truth()
    has_truth = truth is not None and len(truth.t) > 0
    # /odom is read only where it is shown; turtlesim has no nav_msgs/Odometry: its truth is exact
    odom = None if turtlesim or (has_truth and kind != "printed") else recording.odometry()
    path = truth if has_truth else odom
    stop_s = shutdown_s(metadata)
    if turtlesim and path is not None and len(path.t):
        if run is None:
            windows = other_windows(recording)
            poses, window_poses = by_window(turtle_poses(recording), windows)
            run = RunData(odometry=Trajectory.of(path.t, path.x, path.y, path.yaw), poses=poses,
                          service_calls=service_calls(recording), param_changes=param_changes(recording),
                          windows=windows, window_poses=window_poses)
        figure = canvas_figure(run)
        plots.append(Plot(task_id, scenario, "canvas", f"{task_id} ({scenario}): the turtlesim window at the end",
                          png(figure, dpi)))
        for index, window in enumerate(run.windows, start=2):  # the launch tutorials' turtlesim2
            plots.append(Plot(task_id, scenario, f"canvas{index}", f"{task_id} ({scenario}): the turtlesim window of "
                              f"{window} at the end", png(canvas_figure(run, window), dpi)))
    if path is not None and len(path.t):
        touched = touches(run.contacts if run is not None else contacts(recording), TouchParams().gap_s)
        figure = _path_figure(path, kind, has_truth=path is truth, stop_s=stop_s, figures=figures, touched=touched)
        plots.append(Plot(task_id, scenario, "path", f"{task_id} ({scenario}): driven path", png(figure, dpi)))
    commands = recording.commands()
    if commands is not None and len(commands.t):
        shown_path = path if path is not None and len(path.t) else None
        figure = _command_figure(commands, _limits(metadata), stop_s, shown_path, figures=figures)
        plots.append(Plot(task_id, scenario, "commands", f"{task_id} ({scenario}): velocity commands",
                          png(figure, dpi)))
    if kind == "printed" and odom is not None and len(odom.t):
        printed = printed_positions(recording.output_lines())
        if len(printed):
            figure = _printed_figure(printed, odom, figures=figures)
            plots.append(Plot(task_id, scenario, "printed", f"{task_id} ({scenario}): printed vs true pose",
                              png(figure, dpi)))
    return plots


def printed_positions(lines: list[tuple[float, str, str]]) -> np.ndarray:
    """(t, x, y) rows of the poses the node printed, read as the pose_print metric reads them (the stream that
    printed most of them; console prefixes with their wall and sim times are not poses)."""
    poses = pose_lines(tuple(OutputLine(*line) for line in lines))
    return np.array([(p.t, p.x, p.y) for p in poses], dtype=float).reshape(-1, 3)


def fit_circle_centre(x: np.ndarray, y: np.ndarray) -> tuple[float, float] | None:
    """Least-squares (Kåsa) circle centre through the points, or None when they are (nearly) on a line."""
    if len(x) < 3:
        return None
    a = np.column_stack([x, y, np.ones_like(x)])
    b = x**2 + y**2
    solution, _, rank, _ = np.linalg.lstsq(a, b, rcond=None)
    if rank < 3:
        return None
    cx, cy = solution[0] / 2, solution[1] / 2
    if not np.isfinite([cx, cy]).all() or np.hypot(cx - x.mean(), cy - y.mean()) > 100:
        return None
    return float(cx), float(cy)


def _turn_sign(yaw: np.ndarray) -> float:
    """+1 when the robot turned left (counter-clockwise) overall, -1 when right."""
    turned = np.unwrap(yaw)[-1] - yaw[0]
    return -1.0 if turned < 0 else 1.0


def _ideal_outline(kind: str | None, path: Any) -> tuple[np.ndarray, np.ndarray, str] | None:
    """The ideal shape's outline (x, y, label) placed from the start pose or the fitted centre."""
    x0, y0, yaw0 = float(path.x[0]), float(path.y[0]), float(path.yaw[0])
    sign = _turn_sign(np.asarray(path.yaw))
    heading = np.array([np.cos(yaw0), np.sin(yaw0)])
    left = sign * np.array([-np.sin(yaw0), np.cos(yaw0)])
    if kind == "circle":  # through the start, tangent to the start heading, on the side the robot turned to
        fitted = fit_circle_centre(np.asarray(path.x), np.asarray(path.y))
        if fitted is not None:  # the side of the heading the driven circle's centre is on
            cross = heading[0] * (fitted[1] - y0) - heading[1] * (fitted[0] - x0)
            left = (1.0 if cross >= 0 else -1.0) * np.array([-np.sin(yaw0), np.cos(yaw0)])
        centre = tuple(np.array([x0, y0]) + IDEAL_RADIUS_M * left)
        label = "ideal circle (r = 0.5 m) from the start pose"
        angles = np.linspace(0, 2 * np.pi, 200)
        return centre[0] + IDEAL_RADIUS_M * np.cos(angles), centre[1] + IDEAL_RADIUS_M * np.sin(angles), label
    if kind == "square":
        start = np.array([x0, y0])
        corners = [start, start + heading, start + heading + left, start + left, start]
        xs, ys = zip(*(SQUARE_SIDE_M * (c - start) + start for c in corners))
        return np.array(xs), np.array(ys), "ideal 1 × 1 m square from the start pose"
    return None


def _build_path(figure: Figure) -> None:
    axes = figure.add_subplot()
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("x [m]")
    axes.set_ylabel("y [m]")
    axes.grid(True, alpha=0.3)
    figure.subplots_adjust(**PATH_MARGINS)


def _path_figure(path: Any, kind: str | None, has_truth: bool, stop_s: float | None = None,
                 figures: Figures | None = None, touched: Sequence[Contact] = ()) -> Figure:
    """The whole recorded path; what the robot did after Ctrl+C in another colour, from a marked Ctrl+C point; where
    the robot touched a wall or pillar."""
    figures = figures or Figures(DPI)
    figure = figures.get("path", _build_path, PATH_SIZE_IN)
    axes = figure.axes[0]
    source = "true path (simulator)" if has_truth else "path from /odom"
    t = np.asarray(path.t)
    cut = len(t) if stop_s is None else int(np.searchsorted(t, stop_s, side="right"))
    axes.plot(*thin(path.x[:max(cut, 1)], path.y[:max(cut, 1)], axes, equal_aspect=True), color="tab:blue", lw=1.8,
              label=source)
    if 0 < cut < len(t):
        axes.plot(*thin(path.x[cut - 1:], path.y[cut - 1:], axes, equal_aspect=True), color="tab:orange", lw=1.8,
                  label="after Ctrl+C")
        axes.plot(path.x[cut - 1], path.y[cut - 1], "X", color="tab:purple", ms=9, label="Ctrl+C")
    outline = _ideal_outline(kind, path)
    if outline is not None:  # drawn over the path so it stays visible where the two coincide
        axes.plot(outline[0], outline[1], "--", color="tab:green", lw=1.5, label=outline[2])
    if touched:
        axes.plot([c.x for c in touched], [c.y for c in touched], "*", color="tab:red", ms=12,
                  label="touched a wall or pillar")
    axes.plot(path.x[-1], path.y[-1], "s", color="tab:red", ms=7, label="end")
    axes.plot(path.x[0], path.y[0], "o", mfc="none", mec="tab:green", mew=2, ms=12, label="start")
    figures.legends.add(axes, fontsize=8)
    return figure


def _series_builder(y_labels: tuple[str, str]) -> Callable[[Figure], None]:
    """Builds two time-series axes sharing their time axis, with these y labels."""
    def build(figure: Figure) -> None:
        pair = figure.subplots(2, 1, sharex=True)
        for axes, label in zip(pair, y_labels):
            axes.set_ylabel(label)
            axes.grid(True, alpha=0.3)
        pair[1].set_xlabel("time [s]")
        figure.subplots_adjust(**SERIES_MARGINS)
    return build


def _command_figure(commands: Any, limits: tuple[float, float] | None, stop_s: float | None,
                    path: Any = None, figures: Figures | None = None) -> Figure:
    """Commands against the limits and, over the whole recording, the speed the robot really had (so a robot that
    keeps moving after Ctrl+C, when commands have stopped, shows)."""
    figures = figures or Figures(DPI)
    figure = figures.get("commands", _series_builder(("linear.x [m/s]", "angular.z [rad/s]")), SERIES_SIZE_IN)
    linear_axes, angular_axes = figure.axes
    series = (
        (linear_axes, np.asarray(commands.linear)[:, 0], 0, None if path is None else path.vx),
        (angular_axes, np.asarray(commands.angular)[:, 2], 1, None if path is None else path.wz),
    )
    for axes, values, limit_index, actual in series:
        if actual is not None:
            axes.plot(*thin(path.t, actual, axes), color="tab:gray", lw=1.0, label="robot's actual speed")
        axes.step(*level_changes(commands.t, values), where="post", color="tab:blue", lw=1.5, label="commanded")
        if limits is not None:
            limit = limits[limit_index]
            axes.axhline(limit, color="tab:red", ls="--", lw=1, label=f"limit ±{limit:g}")
            axes.axhline(-limit, color="tab:red", ls="--", lw=1)
        if stop_s is not None:
            axes.axvline(stop_s, color="tab:purple", ls=":", lw=1.5, label="Ctrl+C (shutdown)")
    figures.legends.add(linear_axes, fontsize=8)
    return figure


def _printed_figure(printed: np.ndarray, odom: Any, figures: Figures | None = None) -> Figure:
    figures = figures or Figures(DPI)
    figure = figures.get("printed", _series_builder(("x [m]", "y [m]")), SERIES_SIZE_IN)
    for axes, values, column in zip(figure.axes, (odom.x, odom.y), (1, 2)):
        axes.plot(*thin(odom.t, values, axes), color="tab:blue", lw=1.5, label="pose on /odom")
        axes.plot(printed[:, 0], printed[:, column], "o", color="tab:orange", ms=4, label="your printed value")
    figures.legends.add(figure.axes[0], fontsize=8)
    return figure


def _record(metadata: dict[str, Any], name: str) -> dict[str, Any]:
    """A metadata record as a dict (MCAP metadata values are strings; JSON ones are decoded)."""
    record = metadata.get(name) or {}
    return record if isinstance(record, dict) else {}


def _limits(metadata: dict[str, Any]) -> tuple[float, float] | None:
    return ROBOT_LIMITS.get(str(_record(metadata, "rosgrade").get("robot", "")))


def shutdown_s(metadata: dict[str, Any]) -> float | None:
    value = _record(metadata, "rosgrade.run").get("shutdown_requested_s")
    try:
        return None if value in (None, "", "null") else float(json.loads(value) if isinstance(value, str) else value)
    except (TypeError, ValueError):
        return None
