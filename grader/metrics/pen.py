"""The turtlesim window's picture, redrawn from a recording: what every turtle's pen drew, as the world draws it.

Scoring must depend on the recording alone, so coverage and the report's picture replay the recording instead of
reading the world's canvas. Each turtle's recorded poses (its ``<name>/pose``) are replayed in time order with the pen
state the recorded service calls set, using the world's own ``Turtle`` and ``Canvas`` (``sim.turtlesim``,
``sim.turtle_canvas``) so the lines are drawn exactly as the world draws them:

- a served call takes effect at its time, after the updates published at that time (the session answers a call
  once the world has run up to the caller's time): ``set_pen`` sets colour, width or pen-off; ``/clear`` clears to
  the background; ``/reset`` clears, removes every turtle and puts turtle1 back at the centre with the default pen;
  ``/spawn`` starts a turtle where it asked; ``/kill`` ends one;
- a teleport is kept until the turtle's next pose and drawn then, with the pen of that moment (turtle.cpp applies
  teleports at the start of its next update);
- each pose draws the line from where the turtle was, unless the pose is where the turtle already is;
- the recorded parameter changes are replayed among the calls, so ``/clear`` and ``/reset`` fill the canvas with the
  background the parameters gave then, and the canvas starts with the one they gave at the start (the default
  background in a recording without them); in a ROS 2 run a change of the background shows at once, under the lines
  (Jazzy's turtlesim repaints on its own parameter events).

turtle1 starts at its first recorded pose (the world's moves before that are not in the recording). Its positions
come from ground truth (float64) when asked and recorded; spawned turtles have only their turtlesim/Pose (float32),
so a pixel whose centre lies within about 1e-5 px of the edge of a spawned turtle's line may differ from the world's.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

from grader.metrics.run import TURTLE_POSE_TOPIC, ParamChange, RunData, ServiceCall, Trajectory
from grader.nodelib.common import rosgrade_params
from sim.turtle_canvas import Canvas
from sim.turtlesim import CANVAS_M, CENTRE, DEFAULT_TURTLE, NODE_NAME, Turtle, background

# (topic, x, y, theta) of one recorded pose
Pose = tuple[str, float, float, float]


class _Params:
    """The run's parameter server as the recording replays it (what the world reads its background from)."""

    def __init__(self) -> None:
        self.tree: dict = {}

    def has(self, name: str) -> bool:
        return self.get(name, self) is not self

    def get(self, name: str, default: object = None) -> object:
        try:
            return rosgrade_params.lookup(self.tree, name)
        except KeyError:
            return default

    def set(self, name: str, value: object) -> None:
        rosgrade_params.set_value(self.tree, name, value)

    def change(self, change: ParamChange) -> None:
        """Replay one recorded change (the session recorded only changes the server made)."""
        rosgrade_params.apply(self.tree, [(change.name, change.value)])


@dataclass(frozen=True)
class Drawing:
    """The window at the end of a run: its canvas, and the turtles alive then, at their last recorded pose."""

    canvas: Canvas
    turtles: tuple[Turtle, ...]


def redraw(run: RunData, source: Literal["ground_truth", "odometry"] = "ground_truth",
           node: str = NODE_NAME) -> Drawing:
    """Replay the run's poses and served calls; turtle1's poses are ``run.trajectory(source)``, the background the
    parameters of turtlesim's ``node`` (a further window's: see ``window_run``)."""
    paths = dict(run.poses)
    first = run.trajectory(source)
    if len(first):
        paths[TURTLE_POSE_TOPIC] = first
    canvas = Canvas()
    params = _Params()
    live: dict[str, Turtle] = {}
    if len(first):
        live[DEFAULT_TURTLE] = Turtle.spawned(DEFAULT_TURTLE, float(first.x[0]), float(first.y[0]), float(first.yaw[0]))
    for event in _events(paths, run.service_calls, run.param_changes):
        if isinstance(event, ParamChange):
            params.change(event)
            if event is run.param_changes[0]:  # the tree the world started with: its canvas was filled from it
                canvas.clear(background(params, node))
            elif run.client_library == "rclpy" and event.name.startswith(f"{node}/background_"):  # Jazzy repaints
                canvas.repaint(background(params, node))
        elif isinstance(event, ServiceCall):
            _serve(event, live, canvas, params, node)
        else:
            _move(event, live, canvas)
    return Drawing(canvas, tuple(live[name] for name in sorted(live)))


def window_run(run: RunData, node: str) -> RunData:
    """A further turtlesim window (``node``: ``/turtlesim2/sim``) as a run of its own under turtlesim's own names: its
    turtles' poses and the calls it served with the namespace taken off, for ``redraw(..., node=node)``."""
    namespace = node.rpartition("/")[0]
    poses = {topic[len(namespace):]: path for topic, path in run.window_poses.items()
             if topic.startswith(namespace + "/")}
    calls = tuple(replace(call, service=call.service[len(namespace):]) for call in run.service_calls
                  if call.service.startswith(namespace + "/"))
    first = poses.get(TURTLE_POSE_TOPIC, Trajectory.of([], [], [], []))
    # calls_before counts every served call; the window's own are fewer, so a change keeps its place among them
    params = tuple(replace(change, calls_before=sum(1 for c in run.service_calls[:change.calls_before]
                                                     if c.service.startswith(namespace + "/")))
                   for change in run.param_changes)
    return replace(run, odometry=first, ground_truth=None, poses=poses, service_calls=calls, param_changes=params,
                   windows=(), window_poses={})


Event = Pose | ServiceCall | ParamChange


def _events(paths: dict[str, Trajectory], calls: tuple[ServiceCall, ...],
            params: tuple[ParamChange, ...] = ()) -> list[Event]:
    """Poses, calls and parameter changes in the order the world saw them: by time; at one time the poses first,
    turtle by turtle in topic order (the world updates turtles in name order, the same order for turtleN names), then
    the calls and changes in the order they were made."""
    keyed: list[tuple[float, int, str, Event]] = []
    for topic, path in paths.items():
        keyed += [(t, 0, topic, (topic, x, y, yaw))
                  for t, x, y, yaw in zip(path.t.tolist(), path.x.tolist(), path.y.tolist(), path.yaw.tolist())]
    made: list[ServiceCall | ParamChange] = list(calls)
    for change in reversed(params):  # each before the call that came after it
        made.insert(change.calls_before, change)
    keyed += [(event.t, 1, "", event) for event in made]
    keyed.sort(key=lambda k: k[:3])  # stable: calls at one time keep their order
    return [event for *_, event in keyed]


def _move(pose: Pose, live: dict[str, Turtle], canvas: Canvas) -> None:
    """One update of a turtle: its queued teleports, then the line to its new pose. A turtle no recorded call
    started (a recording without service channels) begins at its first pose."""
    topic, x, y, theta = pose
    turtle = _turtle_serving(live, topic)
    if turtle is None:
        name = topic.removesuffix("/pose").lstrip("/")
        live[name] = Turtle.spawned(name, x, y, theta)
        return
    turtle.apply_teleports(canvas)
    if np.float32(turtle.x) == np.float32(x) and np.float32(turtle.y) == np.float32(y):
        turtle.theta = theta  # not moved, at the precision of turtlesim/Pose: keep the exact position it has
        return
    old = (turtle.x, turtle.y_screen)
    turtle.x, turtle.y_screen, turtle.theta = x, CANVAS_M - y, theta
    turtle.draw(canvas, old)


def _serve(call: ServiceCall, live: dict[str, Turtle], canvas: Canvas, params: _Params,
           node: str = NODE_NAME) -> None:
    """What a call the world answered did to the turtles and the canvas (a failed call did nothing)."""
    if call.response is None:
        return
    request = call.request
    if call.service == "/clear":
        canvas.clear(background(params, node))
    elif call.service == "/reset":
        live.clear()
        live[DEFAULT_TURTLE] = Turtle.spawned(DEFAULT_TURTLE, CENTRE, CENTRE, 0.0)
        canvas.clear(background(params, node))
    elif call.service == "/spawn":
        name = str(call.response["name"])
        if name:  # a ROS 2 /spawn that turtlesim refused still answers, with an empty name
            live[name] = Turtle.spawned(name, float(request["x"]), float(request["y"]), float(request["theta"]))
    elif call.service == "/kill":
        live.pop(str(request["name"]), None)
    else:
        turtle = _turtle_serving(live, call.service)
        if turtle is not None and call.service == turtle.topic("set_pen"):
            turtle.set_pen(request)
        elif turtle is not None:
            turtle.queue_teleport(call.service == turtle.topic("teleport_relative"), request)


def _turtle_serving(live: dict[str, Turtle], name: str) -> Turtle | None:
    """The live turtle whose topic or service ``name`` is (``/turtle2/pose``, ``/turtle2/set_pen``)."""
    namespace = name.rpartition("/")[0]
    return next((t for t in live.values() if t.topic("") == namespace + "/"), None)
