"""turtlesim as a rosgrade world: ROS 1 noetic ``turtlesim_node`` re-done as an exact kinematic integrator.

The same contract as ``sim.world.World`` (DEVELOPERS.md), so the session routes and records it without knowing which
world runs. Semantics follow ``ros_tutorials`` noetic ``turtle.cpp`` / ``turtle_frame.cpp``: a 16 ms update with a
fixed dt of 0.016 s; teleports queued by services are applied first, then a command older than 1 s is zeroed, then
θ += ω·dt (wrapped to [−π, π)), then x, y move along the new θ, then the turtle is clamped to the canvas. Positions
are kept in the window's screen coordinates (y down) as turtle.cpp does, so the published y is ``height - y``
computed the same way. The one deliberate difference: the 1 s timeout counts sim time, not wall time.
"""
from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass, field

from sim.samples import (ColorSample, CommandSample, GroundTruthSample, LogSample, Sample, TurtlePoseSample,
                         WorldTopic)
from sim.scenario import Scenario, ScenarioTimes
from sim.turtle_canvas import CANVAS_PX, DEFAULT_BACKGROUND, METER_PX, Canvas, Rgb

UPDATE_NS = 16_000_000  # the Qt update timer's interval
DT = 0.001 * 16  # turtle_frame.cpp passes 0.001 * interval as dt
COMMAND_TIMEOUT_NS = 1_000_000_000
CANVAS_M = (CANVAS_PX - 1) / METER_PX  # 11.0889 m: the window's width in metres
# turtle.cpp wraps θ with its own PI macro, not M_PI.
TURTLE_PI = 3.14159265
DEFAULT_PEN = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3
DEFAULT_TURTLE = "turtle1"
GROUND_TRUTH_TOPIC = "/ground_truth/odom"
ROSOUT = "/rosout"
NODE_NAME = "/turtlesim"
WARN = 4
INFO = 2
ERROR = 8


class TurtlesimError(Exception):
    """A call that breaks the world's contract (going back in time) or a service request turtlesim would refuse."""


@dataclass
class Turtle:
    """One turtle: pose in screen coordinates (x right, y down, metres), the command in force, its pen."""

    name: str
    x: float
    y_screen: float
    theta: float
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0
    last_command_ns: int = 0
    pen: Rgb = DEFAULT_PEN
    pen_width: int = DEFAULT_PEN_WIDTH
    pen_on: bool = True
    teleports: list[tuple[bool, float, float, float]] = field(default_factory=list)  # (relative, a, b, θ)

    @property
    def y(self) -> float:
        """Canvas y, up (what turtlesim/Pose says)."""
        return CANVAS_M - self.y_screen


class TurtlesimWorld(ScenarioTimes):
    """One run of turtlesim: ``command`` a turtle, ``advance_to`` a time, collect what it published on the way."""

    def __init__(self, scenario: Scenario) -> None:
        self.scenario = scenario
        self.mode_name = "kinematic"
        self.canvas = Canvas(DEFAULT_BACKGROUND)
        self.turtles: dict[str, Turtle] = {}
        self._spawned = 0
        self._spawn_default()
        if "initial_pose" in scenario.model_fields_set:  # a turtle moved away from the centre before the run
            pose = scenario.initial_pose
            turtle = self.turtles[DEFAULT_TURTLE]
            turtle.x, turtle.y_screen, turtle.theta = pose.x, CANVAS_M - pose.y, pose.yaw
        for i, command in enumerate(scenario.script):
            if command.topic is not None and command.topic not in self.command_topics:
                raise TurtlesimError(f"script[{i}].topic {command.topic!r} is not a turtle's cmd_vel; expected one of "
                                     f"{self.command_topics}")
        self._script = [(scenario.start_ns + command.t_ns, command) for command in scenario.script]
        self._next_script = 0
        self._updates = 0  # updates happen at every multiple of UPDATE_NS after 0
        self._time_ns = 0
        self._pending: list[Sample] = []
        self._run(scenario.start_ns, self._pending, emit=False)

    # -- the contract (DEVELOPERS.md) ------------------------------------------------------------------------------

    @property
    def publications(self) -> tuple[WorldTopic, ...]:
        """Each turtle's pose and colour sensor, turtle1's ground truth, and the /rosout warnings."""
        rate = 1e9 / UPDATE_NS
        declared = []
        for name in self.turtles:
            declared.append(WorldTopic(f"/{name}/pose", "turtlesim/Pose", rate))
            declared.append(WorldTopic(f"/{name}/color_sensor", "turtlesim/Color", rate))
        declared.append(WorldTopic(GROUND_TRUTH_TOPIC, "nav_msgs/Odometry", rate, to_nodes=False))
        declared.append(WorldTopic(ROSOUT, "rosgraph_msgs/Log", 0, to_nodes=False, shared=True))
        return tuple(declared)

    @property
    def odometry_topic(self) -> str:
        """Where the turtle says where it is."""
        return f"/{DEFAULT_TURTLE}/pose"

    @property
    def command_topics(self) -> tuple[str, ...]:
        """Each live turtle's cmd_vel (the first is turtle1's, where scripted commands go by default)."""
        return tuple(f"/{name}/cmd_vel" for name in self.turtles)

    def command(self, topic: str, linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
                angular: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> bool:
        """A Twist received now on ``topic``; the next update uses it. False if no turtle listens there."""
        turtle = self._turtle_of(topic)
        if turtle is None:
            return False
        self._receive(turtle, self._time_ns, linear, angular)
        return True

    def advance_to(self, t_ns: int) -> list[Sample]:
        """Run the updates up to ``t_ns``; return the samples due in (previous time, ``t_ns``], in time order."""
        if t_ns < self._time_ns:
            raise TurtlesimError(f"cannot advance back in time: now {self._time_ns} ns, asked for {t_ns} ns")
        out, self._pending = self._pending, []
        self._run(t_ns, out, emit=True)
        return out

    def next_output_ns(self, topics: Collection[str] | None = None) -> int | None:
        """When the next update (every publication happens on one) or scripted command is due.

        With ``topics``, the next update counts only if it publishes on one of them.
        """
        if self._pending:
            return self._pending[0].t_ns
        due = []
        declared = {p.topic for p in self.publications if p.rate_hz > 0}
        if topics is None or declared.intersection(topics):
            due.append((self._updates + 1) * UPDATE_NS)
        if self._next_script < len(self._script):
            due.append(max(self._script[self._next_script][0], self._time_ns))
        return min(due, default=None)

    def state(self) -> dict[str, float]:
        """turtle1's pose (canvas frame, y up) and the command in force."""
        turtle = self.turtles.get(DEFAULT_TURTLE)
        if turtle is None:
            return {}
        return {"x": turtle.x, "y": turtle.y, "yaw": turtle.theta, "vx": turtle.linear_x, "vy": turtle.linear_y,
                "wz": turtle.angular, "command_linear": turtle.linear_x, "command_angular": turtle.angular}

    # -- the loop ------------------------------------------------------------------------------------------------

    def _run(self, t_ns: int, out: list[Sample], emit: bool) -> None:
        """Every update up to ``t_ns``, each after the scripted commands due by then."""
        while (self._updates + 1) * UPDATE_NS <= t_ns:
            self._updates += 1
            now = self._updates * UPDATE_NS
            self._apply_script(now, out)
            self._update(now, out if emit else None)
        self._apply_script(t_ns, out)
        self._time_ns = t_ns

    def _apply_script(self, t_ns: int, out: list[Sample]) -> None:
        """Deliver the scripted commands due by ``t_ns`` (as if a node had published them then)."""
        while self._next_script < len(self._script) and self._script[self._next_script][0] <= t_ns:
            due_ns, command = self._script[self._next_script]
            self._next_script += 1
            topic = command.topic or self.command_topics[0]
            turtle = self._turtle_of(topic)
            if turtle is not None:
                self._receive(turtle, due_ns, command.linear, command.angular)
            out.append(CommandSample(due_ns, topic, command.linear, command.angular))

    def _update(self, t_ns: int, out: list[Sample] | None) -> None:
        """One tick of turtle_frame.cpp: every turtle moves, publishes its pose and colour, and draws."""
        for turtle in list(self.turtles.values()):
            self._move(turtle, t_ns, out)

    def _move(self, turtle: Turtle, t_ns: int, out: list[Sample] | None) -> None:
        """turtle.cpp's ``Turtle::update`` for one turtle."""
        for relative, a, b, theta in turtle.teleports:
            old = (turtle.x, turtle.y_screen)
            if relative:  # a = linear: rotate first, then move along the new heading
                turtle.theta += theta
                turtle.x += math.cos(turtle.theta) * a
                turtle.y_screen += -math.sin(turtle.theta) * a
            else:
                turtle.x, turtle.y_screen, turtle.theta = a, max(0.0, CANVAS_M - b), theta
            self._draw(turtle, old)
        turtle.teleports.clear()

        if t_ns - turtle.last_command_ns > COMMAND_TIMEOUT_NS:
            turtle.linear_x = turtle.linear_y = turtle.angular = 0.0
        old = (turtle.x, turtle.y_screen)
        theta = turtle.theta + turtle.angular * DT
        theta -= 2 * TURTLE_PI * math.floor((theta + TURTLE_PI) / (2 * TURTLE_PI))
        turtle.theta = theta
        turtle.x += math.cos(theta) * turtle.linear_x * DT - math.sin(theta) * turtle.linear_y * DT
        turtle.y_screen -= math.cos(theta) * turtle.linear_y * DT + math.sin(theta) * turtle.linear_x * DT
        if not (0.0 <= turtle.x <= CANVAS_M and 0.0 <= turtle.y_screen <= CANVAS_M):
            if out is not None:
                out.append(LogSample(t_ns, ROSOUT, WARN, NODE_NAME,
                                     f"Oh no! I hit the wall! (Clamping from [x={turtle.x:f}, y={turtle.y_screen:f}])"))
        turtle.x = min(max(turtle.x, 0.0), CANVAS_M)
        turtle.y_screen = min(max(turtle.y_screen, 0.0), CANVAS_M)

        speed = math.sqrt(turtle.linear_x ** 2 + turtle.linear_y ** 2)
        # The colour is read before this update's line is drawn, as turtle.cpp does.
        color = self.canvas.color_at(turtle.x * METER_PX, turtle.y_screen * METER_PX)
        if out is not None:
            out.append(TurtlePoseSample(t_ns, f"/{turtle.name}/pose", turtle.x, turtle.y, theta, speed,
                                        turtle.angular))
            out.append(ColorSample(t_ns, f"/{turtle.name}/color_sensor", *color))
            if turtle.name == DEFAULT_TURTLE:
                half = theta / 2
                out.append(GroundTruthSample(
                    t_ns, GROUND_TRUTH_TOPIC, "world", turtle.name, (turtle.x, turtle.y, 0.0),
                    (0.0, 0.0, math.sin(half), math.cos(half)), (turtle.linear_x, turtle.linear_y, 0.0),
                    (0.0, 0.0, turtle.angular)))
        self._draw(turtle, old)

    def _draw(self, turtle: Turtle, old: tuple[float, float]) -> None:
        """The pen line from ``old`` to where the turtle is now (nothing when the pen is off or it did not move)."""
        if turtle.pen_on and (turtle.x, turtle.y_screen) != old:
            self.canvas.line((old[0] * METER_PX, old[1] * METER_PX),
                             (turtle.x * METER_PX, turtle.y_screen * METER_PX), turtle.pen, turtle.pen_width)

    # -- turtles -------------------------------------------------------------------------------------------------

    def _turtle_of(self, topic: str) -> Turtle | None:
        name = topic[1:].rsplit("/", 1)[0] if topic.endswith("/cmd_vel") else ""
        return self.turtles.get(name)

    @staticmethod
    def _receive(turtle: Turtle, t_ns: int, linear: tuple[float, float, float],
                 angular: tuple[float, float, float]) -> None:
        turtle.last_command_ns = t_ns
        turtle.linear_x, turtle.linear_y, turtle.angular = float(linear[0]), float(linear[1]), float(angular[2])

    def _spawn_default(self) -> None:
        """turtle1 at the centre, heading east (turtlesim's start and /reset)."""
        self._spawned = 1
        centre = CANVAS_M / 2.0
        self.turtles[DEFAULT_TURTLE] = Turtle(DEFAULT_TURTLE, centre, CANVAS_M - centre, 0.0)

