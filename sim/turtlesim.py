"""turtlesim as a rosgrade world: ROS 1 noetic ``turtlesim_node`` re-done as an exact kinematic integrator.

The same contract as ``sim.world.World`` (DEVELOPERS.md), so the session routes and records it without knowing which
world runs. Semantics follow ``ros_tutorials`` noetic ``turtle.cpp`` / ``turtle_frame.cpp``: a 16 ms update with a
fixed dt of 0.016 s; teleports queued by services are applied first, then a command older than 1 s is zeroed, then
θ += ω·dt (wrapped to [−π, π)), then x, y move along the new θ, then the turtle is clamped to the canvas. Positions
are kept in the window's screen coordinates (y down) as turtle.cpp does, so the published y is ``height - y``
computed the same way. The one deliberate difference: the 1 s timeout counts sim time, not wall time.

Services (``services``, ``call``) are turtle_frame.cpp's ``/clear``, ``/reset``, ``/spawn``, ``/kill`` and each
turtle's ``set_pen``, ``teleport_absolute`` and ``teleport_relative``, handled at once at the current time; turtlesim
answers them in its next update's ``spinOnce``, before moving the turtles, which has the same effect on the turtles.
The background is turtle_frame.cpp's: its private ``background_r/g/b`` parameters on the run's parameter server
(``use_parameters``), given their defaults at start when unset, and read again by every ``/clear`` and ``/reset``.

A ROS 2 run (``flavour`` "ros2") has Jazzy's turtlesim (ros/ros_tutorials rolling 1.8.2, the version Jazzy ships),
which moves, times out and clamps a turtle as noetic's does, with these differences: a command's ``linear.y`` is taken
only while the node's ``holonomic`` parameter is true (turtle.cpp velocityCallback), the colour sensor reads the
transparent path image, white where no pen painted since the last clear (turtle.cpp update, turtle_frame.cpp clear),
and a taken name is refused as "A turtle named [...]" (noetic: "A turtled named"). The background parameters are
Jazzy's declared integers; a change made through the world (``set_parameter``) shows at once, as Jazzy repaints on
every parameter event of its own node, where noetic waits for /clear.

A run may have further windows (``TurtlesimWindows``): a launch file that starts turtlesim_node twice, as the
launch tutorials' turtlesim_mimic does. The first window has turtlesim's own names; each other (``TurtlesimWindow``)
is a world of its own under its node's name and namespace (``/turtlesim2/sim``: ``/turtlesim2/turtle1/cmd_vel``,
``/turtlesim2/spawn``, ``/turtlesim2/sim/background_r``), with no scripted commands, start pose or ground truth.
"""
from __future__ import annotations

import math
import string
import struct
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field
from functools import cached_property, partial
from typing import Protocol

from sim.samples import (DEFAULT_QOS, ColorSample, CommandSample, GroundTruthSample, LogSample, Sample, ServiceResult,
                         TurtlePoseSample, WorldService, WorldTopic)
from sim.scenario import Scenario, ScenarioTimes, TurtlesimWindow
from sim import turtlesim_params
from sim.turtle_canvas import CANVAS_PX, DEFAULT_BACKGROUND, METER_PX, Canvas, Rgb

UPDATE_NS = 16_000_000  # the Qt update timer's interval
DT = 0.001 * 16  # turtle_frame.cpp passes 0.001 * interval as dt
COMMAND_TIMEOUT_NS = 1_000_000_000
CANVAS_M = (CANVAS_PX - 1) / METER_PX  # 11.0889 m: the window's width in metres
CANVAS_M32 = struct.unpack("<f", struct.pack("<f", CANVAS_M))[0]  # turtle_frame.hpp keeps it as a float
CENTRE = CANVAS_M / 2.0  # where turtle1 starts, and starts again after /reset
# turtle.cpp wraps θ with its own PI macro, not M_PI.
TURTLE_PI = 3.14159265
DEFAULT_PEN = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3
DEFAULT_TURTLE = "turtle1"
DEFAULT_COMMAND_TOPIC = f"/{DEFAULT_TURTLE}/cmd_vel"  # where a scripted command without a topic goes
GROUND_TRUTH_TOPIC = "/ground_truth/odom"
ROSOUT = "/rosout"
NODE_NAME = "/turtlesim"
WARN = 4
INFO = 2
ERROR = 8
# turtlesim's private parameters for the background colour (turtle_frame.cpp); DEFAULT_BACKGROUND holds their defaults.
BACKGROUND_PARAMS = tuple(f"{NODE_NAME}/background_{c}" for c in "rgb")
ROS2 = "ros2"
# What a C++ double-to-int conversion gives on x86 for NaN and values out of int's range.
_INT_INDEFINITE = -(1 << 31)
# Characters roscpp's names::validate accepts after the first one of a graph resource name.
_NAME_CHARS = frozenset(string.ascii_letters + string.digits + "/_")

Request = Mapping[str, object]


class Parameters(Protocol):
    """The run's parameter server as turtlesim uses it (absolute names)."""

    def has(self, name: str) -> bool: ...

    def get(self, name: str, default: object = None) -> object: ...

    def set(self, name: str, value: object) -> None: ...


def roscpp_int(value: object, default: int) -> int:
    """What roscpp's ``param(name, int&, default)`` gives for a stored value: an int as it is, a double rounded half
    up (``fmod(d, 1) < 0.5`` floors, else ceils), anything else (bool, string, list, missing) the default."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return default
    if isinstance(value, int):
        return value
    if not math.isfinite(value):
        return _INT_INDEFINITE
    rounded = math.floor(value) if math.fmod(value, 1.0) < 0.5 else math.ceil(value)
    return rounded if -(1 << 31) <= rounded < (1 << 31) else _INT_INDEFINITE


def background(params: Parameters | None, node: str = NODE_NAME) -> Rgb:
    """turtle_frame.cpp's ``clear()`` colour: each channel from its parameter of ``node`` (default when unusable),
    then ``qRgb``, which keeps the low 8 bits."""
    if params is None:
        return DEFAULT_BACKGROUND
    return tuple(roscpp_int(params.get(f"{node}/background_{channel}"), default) & 0xFF
                 for channel, default in zip("rgb", DEFAULT_BACKGROUND))


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
    node: str = NODE_NAME  # the turtlesim node it lives in, whose namespace its names resolve in

    @classmethod
    def spawned(cls, name: str, x: float, y: float, theta: float, node: str = NODE_NAME) -> Turtle:
        """A new turtle where ``spawnTurtle`` puts it: canvas (x, y up) to screen (x, height − y), not clamped."""
        return cls(name, x, CANVAS_M - y, theta, node=node)

    @property
    def y(self) -> float:
        """Canvas y, up (what turtlesim/Pose says)."""
        return CANVAS_M - self.y_screen

    def set_pen(self, request: Request) -> None:
        """turtle.cpp's set_pen: ``off`` lifts the pen and keeps its colour; otherwise a new pen (width 0 keeps Qt's
        default cosmetic pen, 1 px wide)."""
        self.pen_on = not request["off"]
        if not request["off"]:
            self.pen = (int(request["r"]), int(request["g"]), int(request["b"]))
            self.pen_width = int(request["width"]) or 1

    def queue_teleport(self, relative: bool, request: Request) -> None:
        """teleport_relative (``linear``, ``angular``) or teleport_absolute (``x``, ``y``, ``theta``) request: kept
        until the turtle's next update, as turtle.cpp does."""
        if relative:
            self.teleports.append((True, float(request["linear"]), 0.0, float(request["angular"])))
        else:
            self.teleports.append((False, float(request["x"]), float(request["y"]), float(request["theta"])))

    def apply_teleports(self, canvas: Canvas) -> None:
        """The queued teleports, in order, each drawn with the pen (start of turtle.cpp's ``update``)."""
        for relative, a, b, theta in self.teleports:
            old = (self.x, self.y_screen)
            if relative:  # a = linear: rotate first, then move along the new heading
                self.theta += theta
                self.x += math.cos(self.theta) * a
                self.y_screen += -math.sin(self.theta) * a
            else:
                self.x, self.y_screen, self.theta = a, max(0.0, CANVAS_M - b), theta
            self.draw(canvas, old)
        self.teleports.clear()

    def draw(self, canvas: Canvas, old: tuple[float, float]) -> None:
        """The pen line from ``old`` (screen metres) to where the turtle is now (nothing when the pen is off, it did
        not move, or an end is not a finite point: Qt draws nothing there either)."""
        ends = (*old, self.x, self.y_screen)
        if self.pen_on and (self.x, self.y_screen) != old and all(math.isfinite(v) for v in ends):
            canvas.line((old[0] * METER_PX, old[1] * METER_PX), (self.x * METER_PX, self.y_screen * METER_PX),
                        self.pen, self.pen_width)

    @cached_property
    def namespace(self) -> str:
        """Where its topics and services live: its name resolved in turtlesim's namespace, as ros::NodeHandle does
        (``turtle2`` → ``/turtle2``, ``~t`` → ``/turtlesim/t``; in window ``/turtlesim2/sim``, ``/turtlesim2/turtle2``)."""
        if self.name.startswith("~"):
            resolved = f"{self.node}/{self.name[1:]}"
        else:
            namespace = self.node.rpartition("/")[0]
            resolved = self.name if self.name.startswith("/") else f"{namespace}/{self.name}"
        while "//" in resolved:
            resolved = resolved.replace("//", "/")
        return resolved.rstrip("/") or "/"

    def topic(self, leaf: str) -> str:
        """The full name of one of its topics or services (``pose``, ``set_pen``)."""
        return f"{self.namespace.rstrip('/')}/{leaf}"


class TurtlesimWorld(ScenarioTimes):
    """One run of turtlesim: ``command`` a turtle, ``advance_to`` a time, collect what it published on the way."""

    def __init__(self, scenario: Scenario, flavour: str = "ros1", window: TurtlesimWindow | None = None) -> None:
        self.scenario = scenario
        self.flavour = flavour  # "ros1" (Noetic's turtlesim) or "ros2" (Jazzy's)
        self.window = window  # None: the run's first window, with turtlesim's own names
        self.node = window.node if window is not None else NODE_NAME
        self._namespace = self.node.rpartition("/")[0]
        self.mode_name = "kinematic"
        self.canvas = Canvas(DEFAULT_BACKGROUND)
        self.params: Parameters | None = None  # the run's parameter server, once given
        self.turtles: dict[str, Turtle] = {}
        self._id_counter = 0  # turtle_frame.cpp's id_counter_: the N of the last turtleN it named
        self._time_ns = 0
        self._spawn_default()
        if window is None and "initial_pose" in scenario.model_fields_set:  # turtle1 moved before the run
            pose = scenario.initial_pose
            turtle = self.turtles[DEFAULT_TURTLE]
            turtle.x, turtle.y_screen, turtle.theta = pose.x, CANVAS_M - pose.y, pose.yaw
        for i, command in enumerate(scenario.script if window is None else ()):
            if command.topic is not None and command.topic not in self.command_topics:
                raise TurtlesimError(f"script[{i}].topic {command.topic!r} is not a turtle's cmd_vel; expected one of "
                                     f"{self.command_topics}")
        self._script = [(scenario.start_ns + command.t_ns, command) for command in scenario.script if window is None]
        self._next_script = 0
        self._updates = 0  # updates happen at every multiple of UPDATE_NS after 0
        self._pending: list[Sample] = []
        self._run(scenario.start_ns, self._pending, emit=False)

    # -- the contract (DEVELOPERS.md) ------------------------------------------------------------------------------

    @property
    def publications(self) -> tuple[WorldTopic, ...]:
        """Each turtle's pose and colour sensor, turtle1's ground truth, and the /rosout warnings."""
        rate = 1e9 / UPDATE_NS
        declared = []
        node = self.node if self.window is not None else ""  # a further window's topics are its node's
        for turtle in self.turtles.values():
            declared.append(WorldTopic(turtle.topic("pose"), "turtlesim/Pose", rate, node=node))
            declared.append(WorldTopic(turtle.topic("color_sensor"), "turtlesim/Color", rate, node=node))
        if self.window is None:
            declared.append(WorldTopic(GROUND_TRUTH_TOPIC, "nav_msgs/Odometry", rate, to_nodes=False))
        # Jazzy's rclcpp publishes its log on /rosout for any node to hear (the probes read the warnings there).
        declared.append(WorldTopic(ROSOUT, "rosgraph_msgs/Log", 0, to_nodes=self.flavour == ROS2, shared=True))
        return tuple(declared)

    @property
    def odometry_topic(self) -> str:
        """Where the turtle says where it is."""
        return f"/{DEFAULT_TURTLE}/pose"

    @property
    def command_topics(self) -> tuple[str, ...]:
        """Each live turtle's cmd_vel (scripted commands without a topic go to turtle1's)."""
        return tuple(turtle.topic("cmd_vel") for turtle in self.turtles.values())

    @property
    def command_qos(self) -> tuple[str, str]:
        """(reliability, durability) a turtle's ROS 2 cmd_vel subscription requests: Jazzy's turtle.cpp subscribes
        with rclcpp::QoS(KeepLast(7)), RELIABLE and VOLATILE."""
        return DEFAULT_QOS

    @property
    def known_as(self) -> str:
        """What feedback calls this world (a robot world is "this robot")."""
        return "turtlesim"

    @property
    def node_name(self) -> str:
        """The ROS node that publishes this world's topics (the callerid recordings name)."""
        return self.node

    @property
    def sim_clock(self) -> bool:
        """turtlesim publishes no /clock and nothing sets /use_sim_time: nodes read the wall clock (here it runs with
        world time from a fixed epoch, so rospy.Time.now() is never 0, as on a real turtlesim)."""
        return False

    @property
    def services(self) -> tuple[WorldService, ...]:
        """turtle_frame.cpp's four, then each live turtle's three (turtle.cpp)."""
        ns = self._namespace
        declared = [WorldService(f"{ns}/clear", "std_srvs/Empty"), WorldService(f"{ns}/reset", "std_srvs/Empty"),
                    WorldService(f"{ns}/spawn", "turtlesim/Spawn"), WorldService(f"{ns}/kill", "turtlesim/Kill")]
        if self.flavour == ROS2:  # the node's own parameter services, as every rclcpp node serves them
            declared += [WorldService(f"{self.node}/get_parameters", "rcl_interfaces/GetParameters"),
                         WorldService(f"{self.node}/set_parameters", "rcl_interfaces/SetParameters"),
                         WorldService(f"{self.node}/describe_parameters", "rcl_interfaces/DescribeParameters")]
        for turtle in self.turtles.values():
            declared += [WorldService(turtle.topic("set_pen"), "turtlesim/SetPen"),
                         WorldService(turtle.topic("teleport_absolute"), "turtlesim/TeleportAbsolute"),
                         WorldService(turtle.topic("teleport_relative"), "turtlesim/TeleportRelative")]
        return tuple(declared)

    def call(self, name: str, request: Request) -> ServiceResult:
        """Handle one request to the service ``name`` now, as turtlesim's callback does; ``request`` holds the
        request's fields by name. TurtlesimError for a service turtlesim does not serve."""
        handler = self._handlers().get(name)
        if handler is None:
            raise TurtlesimError(f"turtlesim serves no service {name!r}")
        return handler(request)

    def use_parameters(self, params: Parameters) -> None:
        """Start on the run's parameter server as turtle_frame.cpp's constructor does: each background parameter
        not set yet gets its default, then the canvas is filled with the colour they give."""
        own = self.scenario.world_params if self.window is None else self.window.params
        for name, value in own.items():  # the node's own parameters, from its launch
            if self.flavour != ROS2 or name in turtlesim_params.DECLARED:  # Jazzy ignores overrides it never declares
                params.set(f"{self.node}/{name}", value)
        for channel, default in zip("rgb", DEFAULT_BACKGROUND):
            if not params.has(f"{self.node}/background_{channel}"):
                params.set(f"{self.node}/background_{channel}", default)
        if self.flavour == ROS2 and not params.has(f"{self.node}/holonomic"):
            params.set(f"{self.node}/holonomic", False)
        self.params = params
        self.canvas.clear(self._background())

    def command(self, topic: str, linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
                angular: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> bool:
        """A Twist received now on ``topic``; the next update uses it. False if no turtle listens there."""
        turtle = self._turtle_of(topic)
        if turtle is None:
            return False
        self._receive(turtle, self._time_ns, linear, angular)
        return True

    def listen(self, topics: Collection[str] | None) -> None:
        """turtlesim publishes every topic whoever listens (its pose and colour sensor are all it has)."""

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
            topic = command.topic or DEFAULT_COMMAND_TOPIC
            turtle = self._turtle_of(topic)
            if turtle is not None:
                self._receive(turtle, due_ns, command.linear, command.angular)
            out.append(CommandSample(due_ns, topic, command.linear, command.angular))

    def _update(self, t_ns: int, out: list[Sample] | None) -> None:
        """One tick of turtle_frame.cpp: every turtle moves, publishes its pose and colour, and draws, in the order
        of their names (turtle_frame.cpp keeps them in a std::map)."""
        for name in sorted(self.turtles):
            self._move(self.turtles[name], t_ns, out)

    def _move(self, turtle: Turtle, t_ns: int, out: list[Sample] | None) -> None:
        """turtle.cpp's ``Turtle::update`` for one turtle."""
        turtle.apply_teleports(self.canvas)
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
                out.append(LogSample(t_ns, ROSOUT, WARN, self._log_name,
                                     f"Oh no! I hit the wall! (Clamping from [x={turtle.x:f}, y={turtle.y_screen:f}])"))
        turtle.x = min(max(turtle.x, 0.0), CANVAS_M)
        turtle.y_screen = min(max(turtle.y_screen, 0.0), CANVAS_M)

        speed = math.sqrt(turtle.linear_x ** 2 + turtle.linear_y ** 2)
        # The colour is read before this update's line is drawn, as turtle.cpp does.
        color = self._color_under(turtle)
        if out is not None:
            out.append(TurtlePoseSample(t_ns, turtle.topic("pose"), turtle.x, turtle.y, theta, speed,
                                        turtle.angular))
            out.append(ColorSample(t_ns, turtle.topic("color_sensor"), *color))
            if turtle.name == DEFAULT_TURTLE:
                half = theta / 2
                out.append(GroundTruthSample(
                    t_ns, GROUND_TRUTH_TOPIC, "world", turtle.name, (turtle.x, turtle.y, 0.0),
                    (0.0, 0.0, math.sin(half), math.cos(half)), (turtle.linear_x, turtle.linear_y, 0.0),
                    (0.0, 0.0, turtle.angular)))
        turtle.draw(self.canvas, old)

    def _color_under(self, turtle: Turtle) -> Rgb:
        """The canvas pixel under the turtle; a position that is not a number (a NaN command or teleport) reads what
        Qt's ``QImage::pixel`` returns off the image, 12345 as an RGB value."""
        if not (math.isfinite(turtle.x) and math.isfinite(turtle.y_screen)):
            return (0, 12345 >> 8 & 0xFF, 12345 & 0xFF)
        if self.flavour == ROS2:  # Jazzy reads its transparent path image, not the window
            return self.canvas.path_color_at(turtle.x * METER_PX, turtle.y_screen * METER_PX)
        return self.canvas.color_at(turtle.x * METER_PX, turtle.y_screen * METER_PX)

    # -- turtles -------------------------------------------------------------------------------------------------

    def _turtle_of(self, topic: str) -> Turtle | None:
        """The live turtle whose cmd_vel ``topic`` is, if any."""
        return next((t for t in self.turtles.values() if t.topic("cmd_vel") == topic), None)

    def _receive(self, turtle: Turtle, t_ns: int, linear: tuple[float, float, float],
                 angular: tuple[float, float, float]) -> None:
        """turtle.cpp's velocityCallback: Jazzy's keeps the last ``linear.y`` unless ``holonomic`` is true now."""
        turtle.last_command_ns = t_ns
        turtle.linear_x, turtle.angular = float(linear[0]), float(angular[2])
        if self.flavour != ROS2 or (self.params is not None and self.params.get(f"{self.node}/holonomic") is True):
            turtle.linear_y = float(linear[1])

    def _spawn_default(self) -> LogSample:
        """turtle1 at the centre, heading east (turtlesim's start and /reset)."""
        return self._spawn("", CENTRE, CENTRE, 0.0)[1]

    def _spawn(self, name: str, x: float, y: float, theta: float) -> tuple[str, LogSample]:
        """turtle_frame.cpp's ``spawnTurtle`` for a free or empty name: an empty one becomes the next free turtleN."""
        if not name:
            self._id_counter += 1
            while f"turtle{self._id_counter}" in self.turtles:
                self._id_counter += 1
            name = f"turtle{self._id_counter}"
        # spawnTurtle takes floats: its log line prints them rounded to float32.
        x32, y32, theta32 = struct.unpack("<3f", struct.pack("<3f", x, y, theta))
        if self.flavour == ROS2:
            # Jazzy's turtle starts from the floats, its screen y the float difference (height_in_meters_ is a float):
            # turtle1's y is 5.544445 in the wall warning, not 5.544444 (measured with real_turtlesim2.py).
            y_screen = struct.unpack("<f", struct.pack("<f", CANVAS_M32 - y32))[0]
            self.turtles[name] = Turtle(name, x32, y_screen, theta32, node=self.node)
        else:
            self.turtles[name] = Turtle.spawned(name, x, y, theta, self.node)
        return name, self._log(INFO, f"Spawning turtle [{name}] at x=[{x32:f}], y=[{y32:f}], theta=[{theta32:f}]")

    def _log(self, level: int, msg: str) -> LogSample:
        """A line turtlesim logs on /rosout now."""
        return LogSample(self._time_ns, ROSOUT, level, self._log_name, msg)

    @property
    def _log_name(self) -> str:
        """Who /rosout says logged: roscpp gives the node's name, rclcpp its logger's (``turtlesim2.sim``)."""
        return self.node if self.flavour != ROS2 else self.node[1:].replace("/", ".")

    # -- services (turtle_frame.cpp, turtle.cpp) ---------------------------------------------------------------

    def _handlers(self) -> dict[str, Callable[[Request], ServiceResult]]:
        """Each served service's handler, by resolved name."""
        ns = self._namespace
        handlers: dict[str, Callable[[Request], ServiceResult]] = {
            f"{ns}/clear": self._clear, f"{ns}/reset": self._reset, f"{ns}/spawn": self._spawn_service,
            f"{ns}/kill": self._kill}
        if self.flavour == ROS2:
            handlers[f"{self.node}/get_parameters"] = self._get_parameters
            handlers[f"{self.node}/set_parameters"] = self._set_parameters
            handlers[f"{self.node}/describe_parameters"] = self._describe_parameters
        for turtle in self.turtles.values():
            handlers[turtle.topic("set_pen")] = partial(self._set_pen, turtle)
            handlers[turtle.topic("teleport_absolute")] = partial(self._teleport, turtle, False)
            handlers[turtle.topic("teleport_relative")] = partial(self._teleport, turtle, True)
        return handlers

    def _clear(self, request: Request) -> ServiceResult:  # noqa: ARG002 -- std_srvs/Empty
        """/clear: the canvas filled with the background the parameters give now."""
        self.canvas.clear(self._background())
        return ServiceResult(True, {}, (self._log(INFO, "Clearing turtlesim."),))

    def _reset(self, request: Request) -> ServiceResult:  # noqa: ARG002 -- std_srvs/Empty
        """/reset: every turtle gone, names counted from 1 again, turtle1 back at the centre, the canvas cleared."""
        said = self._log(INFO, "Resetting turtlesim.")
        self.turtles.clear()
        self._id_counter = 0
        spawned = self._spawn_default()
        self.canvas.clear(self._background())
        return ServiceResult(True, {}, (said, spawned))

    def _spawn_service(self, request: Request) -> ServiceResult:
        """/spawn: a new turtle with its own topics and services; a taken name fails, as does one roscpp refuses (the
        response is left empty, which is what a ROS 2 caller gets back)."""
        name = str(request["name"])
        if name in self.turtles:
            taken = "A turtle named" if self.flavour == ROS2 else "A turtled named"  # Jazzy fixed noetic's typo
            return ServiceResult(False, {"name": ""}, (self._log(ERROR, f"{taken} [{name}] already exists"),))
        problem = _name_problem(name)
        if problem:
            said = self._log(ERROR, f"Exception thrown while processing service call: {problem}")
            return ServiceResult(False, {"name": ""}, (said,), error=problem)
        name, said = self._spawn(name, float(request["x"]), float(request["y"]), float(request["theta"]))
        return ServiceResult(True, {"name": name}, (said,))

    def _kill(self, request: Request) -> ServiceResult:
        """/kill: the turtle, its topics and its services are gone; an unknown name fails."""
        name = str(request["name"])
        if self.turtles.pop(name, None) is None:
            said = self._log(ERROR, f"Tried to kill turtle [{name}], which does not exist")
            return ServiceResult(False, {}, (said,))
        return ServiceResult(True, {})

    def _get_parameters(self, request: Request) -> ServiceResult:
        """Jazzy's get_parameters: each named parameter's value (none when one is not declared)."""
        names = [str(name) for name in request["names"]]  # type: ignore[attr-defined]
        return ServiceResult(True, {"values": turtlesim_params.get_parameters(self.node, self._tree(), names)})

    def _describe_parameters(self, request: Request) -> ServiceResult:
        """Jazzy's describe_parameters (`ros2 param describe /turtlesim background_r`), measured by probe p24."""
        names = [str(name) for name in request["names"]]  # type: ignore[attr-defined]
        return ServiceResult(True, {"descriptors": turtlesim_params.describe_parameters(names)})

    def _set_parameters(self, request: Request) -> ServiceResult:
        """Jazzy's set_parameters, one parameter at a time; a new background colour shows at once (turtle_frame.cpp
        repaints on its own node's parameter events, and paintEvent reads the parameters)."""
        parameters: list = request["parameters"]  # type: ignore[assignment]
        results, changed = turtlesim_params.set_parameters(self.node, self._tree(), parameters)
        if any(name.startswith("background_") for name in changed):
            self.canvas.repaint(self._background())
        return ServiceResult(True, {"results": results})

    def _background(self) -> Rgb:
        return background(self.params, self.node)

    def _tree(self) -> Parameters:
        """The run's parameter tree (the world's start hands it over; TurtlesimError before that)."""
        if self.params is None:
            raise TurtlesimError("turtlesim's parameters are served once the run's parameter server is given")
        return self.params

    @staticmethod
    def _set_pen(turtle: Turtle, request: Request) -> ServiceResult:
        """set_pen: see ``Turtle.set_pen``."""
        turtle.set_pen(request)
        return ServiceResult(True, {})

    @staticmethod
    def _teleport(turtle: Turtle, relative: bool, request: Request) -> ServiceResult:
        """teleport_absolute / teleport_relative: queued, applied at the start of the turtle's next update."""
        turtle.queue_teleport(relative, request)
        return ServiceResult(True, {})


def _name_problem(name: str) -> str:
    """roscpp's ``names::validate`` message for a name a NodeHandle refuses ('' when it is valid or empty)."""
    if not name:
        return ""
    first = name[0]
    if not (first.isascii() and first.isalpha()) and first not in "/~":
        return (f"Character [{first}] is not valid as the first character in Graph Resource Name [{name}].  "
                "Valid characters are a-z, A-Z, / and in some cases ~.")
    for i, c in enumerate(name[1:], start=1):
        if c not in _NAME_CHARS:
            return (f"Character [{c}] at element [{i}] is not valid in Graph Resource Name [{name}].  "
                    "Valid characters are a-z, A-Z, 0-9, / and _.")
    return ""

