"""One run's replay for report.html: the recording cut down to what a page can animate (poses, pen lines, commands,
output lines, events and the moments criteria were decided), as compact JSON that is the same for the same recording.

It reads the series scoring read (the recording memo shares them) and turtlesim's pen through the picture's own
replay (``grader.metrics.pen``), so the page shows what was scored.
"""
from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

# The turtlesim picture's replay, step by step: the strokes are the picture's, only kept with their times.
from grader.metrics.collisions import Params as TouchParams
from grader.metrics.collisions import touches
from grader.metrics.pen import _events, _move, _Params, _serve
from grader.metrics.run import TURTLE_POSE_TOPIC, ParamChange, RunData, RunInfo, Trajectory
from grader.metrics.run import obstacles as recorded_obstacles
from grader.metrics.wall_hits import WARNING as WALL_WARNING
from grader.report import TaskReport
from grader.reports.cause import criterion_measured
from grader.reports.escape import plain
from sim.scenario import TURTLESIM
from sim.turtle_canvas import METER_PX, Canvas
from sim.turtlesim import CANVAS_M, DEFAULT_BACKGROUND, DEFAULT_TURTLE, Turtle, background

MAX_BYTES = 250_000  # one run's data at most: with its share of the page, a run stays under 300 KB
COARSER = (1, 2, 4, 8, 16, 32, 64)  # how much coarser than a pixel the data may get to fit in MAX_BYTES
VIEW_PX = 480  # the replay's width on a wide screen: thinning keeps what differs by a pixel there
STRAIGHT_SPAN = 100  # points looked back at when leaving out straight stretches (bounds the work per point)
MAX_LINES = 300  # output lines kept per run (the first ones: a loop printing forever repeats itself)
MAX_TEXT = 160  # characters kept of one line
COMMAND_BIN_S = 0.1  # commands shown at most this often
MAX_GAP_S = 0.5  # a pose is kept at least this often, so the robot moves smoothly while it turns slowly
TURN_RAD = 0.05  # and whenever it turned this much
# Footprints (length, width in metres) of the robots, to draw them to scale; others get a 0.3 m square.
FOOTPRINTS = {
    "turtlebot3_burger": (0.138, 0.178),
    "turtlebot3_waffle": (0.281, 0.306),
    "turtlebot3_waffle_pi": (0.281, 0.306),
    "turtlebot2": (0.354, 0.354),
    "husky_a200": (0.990, 0.670),
}
VIEW_MARGIN_M = 0.5  # around what the robot world shows
MIN_ASPECT = 0.6  # its height to width at least (and width to height)
TURTLE_M = 0.45  # the turtle image's size in the window
MAX_HITS = 20  # wall hits (and touches of obstacles) marked on the timeline
# Quantities that say when a criterion was decided, in seconds after the start: a metric that knows reports
# decided_at_s; the others are older metrics' own times (the first wall hit, when the robot stopped).
FROM_START = ("decided_at_s", "first_hit_s", "stopped_at_s", "judged_until_s")
# Those counted from the Ctrl+C: the moment only when they are what the criterion judges (a NaN: never, so the end).
AFTER_CTRL_C = ("rest_time", "zero_command_delay", "exit_delay")


@dataclass(frozen=True)
class Replay:
    """One scenario run of one task, ready for the page: ``data`` is its JSON."""

    task: str
    scenario: str
    data: str
    moments: tuple[tuple[str, float], ...] = ()  # (criterion id, seconds after the start) decided in this run

    @property
    def anchor(self) -> str:
        """The element id of its replay on the page (what a criterion's link points to)."""
        return "replay-" + "".join(c if c.isalnum() or c in "-_" else "-" for c in f"{self.task}-{self.scenario}")


def _decode(value: Any) -> Any:
    if isinstance(value, str):
        try:
            return json.loads(value)
        except json.JSONDecodeError:
            return value
    return value


def _record(recording: Any, name: str) -> dict[str, Any]:
    record = _decode((recording.metadata or {}).get(name) or {})
    return {k: _decode(v) for k, v in record.items()} if isinstance(record, dict) else {}


def _r(value: float, digits: int = 3) -> float:
    """A number as the page needs it (rounded, so that the JSON is short and the same on every machine)."""
    rounded = round(float(value), digits)
    return 0.0 if rounded == 0 else rounded


def _hex(rgb: tuple[int, int, int]) -> str:
    return "#%02x%02x%02x" % tuple(int(c) for c in rgb)


def _deltas(values: Any, scale: float) -> list[int]:
    """Values as integers in 1/scale units, each but the first as the change from the one before: a short JSON
    array (the page adds them up again)."""
    ints = [int(v) for v in np.round(np.asarray(values, dtype=float) * scale)]
    return ints[:1] + [b - a for a, b in zip(ints, ints[1:])]


def _thin_poses(path: Trajectory, start: float, tolerance: float, coarse: float = 1) -> dict[str, list[int]]:
    """Poses kept where the path bends by ``tolerance`` metres, the heading turned TURN_RAD, or every MAX_GAP_S
    (those two times ``coarse``), first and last always; times in 1/100 s after the start, positions in mm,
    headings in 1/100 rad."""
    t, x, y, yaw = (np.asarray(a, dtype=float) for a in (path.t, path.x, path.y, path.yaw))

    def due(i: int, since: int) -> bool:
        return (t[i] - t[since] >= MAX_GAP_S * coarse
                or abs(math.remainder(yaw[i] - yaw[since], math.tau)) >= TURN_RAD * coarse)

    keep = _straightened(x, y, tolerance, due) if len(t) else []
    return {"t": _deltas(t[keep] - start, 100), "x": _deltas(x[keep], 1000), "y": _deltas(y[keep], 1000),
            "a": _deltas(np.unwrap(yaw[keep]), 100)}


class _PenCanvas(Canvas):
    """A canvas that keeps the pen's lines as polylines with the time each point was drawn, instead of pixels."""

    def __init__(self) -> None:
        super().__init__()
        self.now = 0.0
        self.strokes: list[dict[str, Any]] = []
        self.clears: list[tuple[float, str]] = [(-math.inf, _hex(DEFAULT_BACKGROUND))]

    def line(self, a: tuple[float, float], b: tuple[float, float], rgb: tuple[int, int, int], width: int) -> None:
        colour = _hex(rgb)
        last = self.strokes[-1] if self.strokes else None
        if last is None or last["c"] != colour or last["w"] != width or last["end"] != a:
            last = {"c": colour, "w": width, "p": [(self.now, *a)]}
            self.strokes.append(last)
        last["p"].append((self.now, *b))
        last["end"] = b

    def clear(self, rgb: tuple[int, int, int] = DEFAULT_BACKGROUND) -> None:
        if hasattr(self, "clears"):  # Canvas() clears once while it is made: that is the initial background
            self.clears.append((self.now, _hex(rgb)))
            if self.strokes:  # a stroke never spans a clear: the page shows whole strokes drawn since the last one
                self.strokes[-1]["end"] = None


def _straightened(x: np.ndarray, y: np.ndarray, tolerance: float,
                  due: Callable[[int, int], bool] = lambda i, since: False) -> list[int]:
    """The indices of the points a polyline needs: one is left out while every point since the last one kept lies
    within ``tolerance`` of the straight line from there to the next (looking back at most STRAIGHT_SPAN points),
    unless ``due(index, index of the last one kept)``."""
    kept = [0]
    for i in range(1, len(x) - 1):
        since = kept[-1]
        dx, dy = x[i + 1] - x[since], y[i + 1] - y[since]
        rx, ry = x[since + 1:i + 1] - x[since], y[since + 1:i + 1] - y[since]
        length = math.hypot(dx, dy)
        off = np.abs(dx * ry - dy * rx) / length if length > 0 else np.hypot(rx, ry)
        if i - since >= STRAIGHT_SPAN or off.max() > tolerance or due(i, since):
            kept.append(i)
    return kept + [len(x) - 1] if len(x) > 1 else kept


def _pen_canvas(run: RunData) -> _PenCanvas:
    """The pen's strokes and the clears, replayed as the turtlesim picture replays them."""
    canvas = _PenCanvas()
    params = _Params()
    live: dict[str, Turtle] = {}
    first = run.trajectory("ground_truth")
    if len(first):
        live[DEFAULT_TURTLE] = Turtle.spawned(DEFAULT_TURTLE, float(first.x[0]), float(first.y[0]), float(first.yaw[0]))
    paths = {**run.poses, TURTLE_POSE_TOPIC: first} if len(first) else dict(run.poses)
    seen = dict.fromkeys(paths, 0)  # each topic's poses come in time order: the k-th is at its t[k]
    for event in _events(paths, run.service_calls, run.param_changes):
        if isinstance(event, tuple):
            topic = event[0]
            canvas.now = float(paths[topic].t[seen[topic]])
            seen[topic] += 1
            _move(event, live, canvas)
            continue
        canvas.now = event.t
        if not isinstance(event, ParamChange):
            _serve(event, live, canvas, params)
            continue
        params.change(event)
        if event is run.param_changes[0]:  # the tree the world started with: its canvas was filled from it
            canvas.clears[0] = (-math.inf, _hex(background(params)))
    return canvas


def _strokes(canvas: _PenCanvas, start: float, tolerance_px: float) -> dict[str, Any]:
    """Each stroke's points, those on a straight stretch left out (the page draws the line to where the pen is
    at any time between two points); times in 1/100 s, positions in 1/10 px."""
    strokes = []
    for stroke in canvas.strokes:
        t, x, y = np.array(stroke["p"], dtype=float).T
        keep = _straightened(x, y, tolerance_px)
        t, x, y = t[keep], x[keep], y[keep]
        strokes.append({"c": stroke["c"], "w": stroke["w"], "t": _deltas(np.subtract(t, start), 100),
                        "x": _deltas(x, 10), "y": _deltas(y, 10)})
    clears = [[None if math.isinf(t) else _r(t - start, 2), colour] for t, colour in canvas.clears]
    return {"strokes": strokes, "clears": clears}

def _goal(task: TaskReport, scenario: str) -> list[float] | None:
    """Where the rubric puts this scenario's goal (a metric with goal_x and goal_y), read from the task's rubric."""
    if task.rubric is None:
        return None
    from grader.rubric import RubricError, load_rubric

    try:
        rubric = load_rubric(task.rubric.file)
    except (RubricError, OSError):
        return None
    for s in (s for s in rubric.scenarios if s.name == scenario):
        for criterion in rubric.criteria:
            params = criterion.params_for(s)
            if hasattr(params, "goal_x") and hasattr(params, "goal_y"):
                return [_r(params.goal_x), _r(params.goal_y)]
    return None


def _moment(measured: dict[str, Any], start: float, ctrl_c: float | None, end: float) -> float:
    """When the criterion was decided, in seconds after the start (``end``: when the run ended)."""
    def number(name: str) -> float | None:
        value = measured.get(name)
        finite = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
        return float(value) if finite else None

    own = next(iter(measured), None)  # scoring puts the criterion's own quantity first
    if own in AFTER_CTRL_C and ctrl_c is not None:
        after = number(own)
        return end if after is None else ctrl_c - start + after
    return next((at for name in FROM_START if (at := number(name)) is not None), end)


def _events_of(task: TaskReport, scenario: str, run: RunData, start: float, end: float) -> list[list[Any]]:
    """[t, kind, text, criterion id] for Ctrl+C, the node's exit, wall hits, the robot's touches of walls and pillars
    and the criteria decided in this run."""
    events: list[list[Any]] = []
    ctrl_c = run.shutdown_time()
    if ctrl_c is not None:
        events.append([_r(ctrl_c - start, 2), "ctrl_c", "Ctrl+C: the grader asked your node to shut down", ""])
    hits = [line for line in run.lines if line.stream == "rosout" and WALL_WARNING in line.text]
    for line in hits[:MAX_HITS]:
        events.append([_r(line.t - start, 2), "hit", "the turtle hit the wall", ""])
    for touch in touches(run.contacts, TouchParams().gap_s)[:MAX_HITS]:  # touches as the collisions metric counts
        events.append([_r(touch.t - start, 2), "hit", f"the robot touched the {touch.obstacle}", ""])
    info = run.run
    if info.ended_s is not None:
        events.append([_r(info.ended_s - start, 2), "exit", _ending(info), ""])
    for c in task.criteria:
        if c.scenario != scenario:
            continue
        measured = criterion_measured(task, c)
        text = f"{'✔' if c.passed else '✘'} {c.title or c.id}" + (f": {measured}" if measured else "")
        events.append([_r(_moment(c.measured, start, ctrl_c, end), 2), "pass" if c.passed else "fail", text, c.id])
    return sorted(events, key=lambda e: (e[0], e[1], e[2]))


def _ending(info: RunInfo) -> str:
    """How the node's process ended, in a student's words."""
    if info.status == "stopped_at_end":
        return "the scenario ended, so the grader stopped your node"
    if info.exit_code is not None:
        return f"your node exited with code {info.exit_code}"
    if info.exit_signal not in (None, ""):
        return f"your node was ended by signal {info.exit_signal}"
    return f"your node ended ({info.status or 'unknown'})"


def _finite_or_text(value: float) -> float | str:
    """A command's value for the page: inf and nan as text ("inf"), which JSON can carry and the page shows as is (a
    node that divides by a beam that hit nothing commands inf)."""
    return _r(value, 2) if math.isfinite(value) else str(value)


def _commands(run: RunData, start: float, every_s: float) -> list[list[float | str]]:
    """[t, linear.x, angular.z] when the command in force changed, at most once per ``every_s`` (the last one of
    each bin: a controller that changes its command every cycle reads the same on a page)."""
    rows: list[list[float]] = []
    commands = run.commands
    for t, linear, angular in zip(commands.t.tolist(), commands.linear[:, 0].tolist(), commands.angular[:, 2].tolist()):
        row = [_r(t - start, 2), _finite_or_text(linear), _finite_or_text(angular)]
        if rows and rows[-1][1:] == row[1:]:
            continue
        if rows and math.floor(rows[-1][0] / every_s) == math.floor(row[0] / every_s):
            if len(rows) > 1 and rows[-2][1:] == row[1:]:
                rows.pop()  # back to the command before, within one bin: as if it had not changed
            else:
                rows[-1] = row
            continue
        rows.append(row)
    return rows

def _lines(run: RunData, start: float) -> tuple[list[list[Any]], int]:
    """[t, level, stream, text] of the first MAX_LINES output lines, and how many lines came after them."""
    kept, seen = [], set()
    for line in run.lines[:MAX_LINES]:
        level, text = line.message()
        if (line.t, text) in seen:  # rospy logs a line on /rosout and prints it on stdout: show it once
            continue
        seen.add((line.t, text))
        text = plain(text)
        text = text if len(text) <= MAX_TEXT else text[:MAX_TEXT - 1] + "…"
        kept.append([_r(line.t - start, 2), level or "", line.stream, text])
    return kept, max(0, len(run.lines) - MAX_LINES)


def scenario_times(recording: Any) -> tuple[float, float | None]:
    """The node's start (sim s) and the planned Ctrl+C (s after it), as the recorded scenario says."""
    world = _record(recording, "rosgrade").get("scenario")
    world = world if isinstance(world, dict) else {}
    shutdown = world.get("shutdown_at")
    return float(world.get("start_time", 0.0)), None if shutdown is None else float(shutdown)


def replay_of(task: TaskReport, scenario: str, recording: Any, run: RunData | None = None) -> Replay:
    """The replay of one recording of ``task`` (``run``: the recording as RunData, when it was read already)."""
    from grader.reports.plots import _ideal_outline, shape_for

    start, shutdown_at = scenario_times(recording)
    run = run if run is not None else RunData.from_recording(recording, start, shutdown_at)
    robot = str(_record(recording, "rosgrade").get("robot", ""))
    path = run.trajectory("ground_truth")
    data: dict[str, Any] = {"task": task.id, "scenario": scenario, "robot": robot}
    canvas = None
    if robot == TURTLESIM:
        tolerance = CANVAS_M / VIEW_PX
        bodies = {DEFAULT_TURTLE: path} if len(path) else {}
        bodies.update({topic.removesuffix("/pose").lstrip("/"): p for topic, p in run.poses.items()
                       if topic != TURTLE_POSE_TOPIC})
        data["world"] = {"bounds": [0.0, 0.0, _r(CANVAS_M, 4), _r(CANVAS_M, 4)], "size": [TURTLE_M, TURTLE_M],
                         "px_per_m": METER_PX}
        canvas = _pen_canvas(run)
    else:
        obstacles = [o.model_dump() for o in recorded_obstacles(recording)]
        xs = [*np.asarray(path.x).tolist(), *(o["x"] for o in obstacles)] or [0.0]
        ys = [*np.asarray(path.y).tolist(), *(o["y"] for o in obstacles)] or [0.0]
        outline = _ideal_outline(shape_for(task.id), path) if len(path) else None
        if outline is not None:
            xs += outline[0].tolist()
            ys += outline[1].tolist()
            data["ideal"] = {"label": outline[2], "x": [_r(v) for v in outline[0][::4]],
                             "y": [_r(v) for v in outline[1][::4]]}
        bounds = _view(min(xs), min(ys), max(xs), max(ys))
        tolerance = max(bounds[2] - bounds[0], bounds[3] - bounds[1]) / VIEW_PX
        bodies = {"robot": path} if len(path) else {}
        data["world"] = {"bounds": [_r(b, 2) for b in bounds], "size": list(FOOTPRINTS.get(robot, (0.3, 0.3))),
                         "obstacles": [_obstacle(o) for o in obstacles]}
    goal = _goal(task, scenario)
    if goal is not None:
        data["goal"] = goal
    data["lines"], data["more_lines"] = _lines(run, start)
    times = [float(p.t[i]) - start for p in bodies.values() for i in (0, -1)]
    data["events"] = _events_of(task, scenario, run, start, end=max([0.0, *times]))
    times += [e[0] for e in data["events"]]
    data["span"] = [_r(min([0.0, *times]), 2), _r(max([0.0, *times]), 2)]
    for coarse in COARSER:  # finer than a pixel where it fits, coarser where a long run would not
        data["bodies"] = {name: _thin_poses(p, start, tolerance * coarse, coarse) for name, p in bodies.items()}
        if canvas is not None:
            data["pen"] = _strokes(canvas, start, tolerance_px=coarse)
        data["commands"] = _commands(run, start, COMMAND_BIN_S * coarse)
        text = json.dumps(data, separators=(",", ":"), ensure_ascii=False, sort_keys=True)
        if len(text.encode()) <= MAX_BYTES:
            break
    moments = tuple((e[3], e[0]) for e in data["events"] if e[3])
    return Replay(task.id, scenario, text, moments)


def _view(x0: float, y0: float, x1: float, y1: float) -> list[float]:
    """The area shown: what was there with a margin, at least MIN_ASPECT as tall as wide and the other way round
    (a straight drive would otherwise be a thin strip)."""
    x0, y0, x1, y1 = x0 - VIEW_MARGIN_M, y0 - VIEW_MARGIN_M, x1 + VIEW_MARGIN_M, y1 + VIEW_MARGIN_M
    grow_x = max(0.0, MIN_ASPECT * (y1 - y0) - (x1 - x0)) / 2
    grow_y = max(0.0, MIN_ASPECT * (x1 - x0) - (y1 - y0)) / 2
    return [x0 - grow_x, y0 - grow_y, x1 + grow_x, y1 + grow_y]


def _obstacle(o: dict[str, Any]) -> dict[str, Any]:
    """A wall or pillar as the page draws it (metres, radians)."""
    if o.get("kind") == "cylinder":
        return {"kind": "cylinder", "x": _r(o["x"]), "y": _r(o["y"]), "r": _r(o["radius"])}
    return {"kind": "box", "x": _r(o["x"]), "y": _r(o["y"]), "a": _r(o.get("yaw", 0.0)),
            "l": _r(o["length"]), "w": _r(o["width"])}
