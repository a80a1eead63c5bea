"""Scenarios: what one run of the world is (robot, base mode, spawn pose, timing, imperfections, scripted commands).

Times are written in seconds (readable in TOML/JSON) and read by the world as integer nanoseconds (``*_ns``).
"""
from __future__ import annotations

from typing import Annotated, Literal, Union

from pydantic import (BaseModel, ConfigDict, Field, JsonValue, SerializerFunctionWrapHandler, StrictBool,
                      StrictFloat, StrictInt, StrictStr, field_validator, model_serializer, model_validator)

from sim.clock import seconds_to_ns
from sim.profile import ProfileError, load_robot
from sim.samples import Vec3

# Worlds that are not a robot profile: exact kinematic worlds with their own module (sim/turtlesim.py).
TURTLESIM = "turtlesim"

NonNegative = Annotated[float, Field(ge=0)]
Positive = Annotated[float, Field(gt=0)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class Pose2D(_Model):
    """A planar pose in the world frame (metres, radians)."""

    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0


class Box(_Model):
    """A fixed box (a wall, a crate) standing on the floor: centre, heading, and full length x width x height in metres."""

    kind: Literal["box"]
    name: str = Field("", description="what feedback calls it (empty: 'box' and its number)")
    x: float
    y: float
    yaw: float = 0.0
    length: Positive
    width: Positive
    height: Positive = 0.5


class Cylinder(_Model):
    """A fixed upright cylinder (a pillar) standing on the floor."""

    kind: Literal["cylinder"]
    name: str = Field("", description="what feedback calls it (empty: 'cylinder' and its number)")
    x: float
    y: float
    radius: Positive
    height: Positive = 0.5


Obstacle = Annotated[Union[Box, Cylinder], Field(discriminator="kind")]


class Imperfections(_Model):
    """Deliberate differences between the physical robot and what its driver and odometry believe.

    ``wheel_radius_error`` e: the wheels' real radius is nominal·(1+e); the driver and odometry keep the nominal
    radius, so with e > 0 the robot goes farther than commanded and encoder odometry under-reports.
    ``slip`` s: constant longitudinal slip; the ground moves by only 1/(1+s) of the wheels' rim travel, so encoder
    odometry over-counts the true motion by the fraction s (and the robot covers less than commanded). It is
    modelled as a smaller effective rolling radius, nominal·(1+e)/(1+s).
    """

    wheel_radius_error: float = Field(0.0, gt=-0.5, lt=0.5)
    slip: float = Field(0.0, ge=0.0, le=1.0)

    @property
    def wheel_radius_scale(self) -> float:
        """Physical rolling radius over nominal radius."""
        return (1.0 + self.wheel_radius_error) / (1.0 + self.slip)


class ScriptedCommand(_Model):
    """A velocity command the scripted driver sends at ``t`` seconds after the start (no node needed).

    ``linear``/``angular`` take a vector or a number (read as linear.x / angular.z); ``topic`` defaults to the
    robot's first command topic.
    """

    t: NonNegative
    linear: Vec3 = (0.0, 0.0, 0.0)
    angular: Vec3 = (0.0, 0.0, 0.0)
    topic: str | None = None

    @field_validator("linear", mode="before")
    @classmethod
    def _linear_x(cls, value: object) -> object:
        return (value, 0.0, 0.0) if isinstance(value, (int, float)) else value

    @field_validator("angular", mode="before")
    @classmethod
    def _angular_z(cls, value: object) -> object:
        return (0.0, 0.0, value) if isinstance(value, (int, float)) else value

    @property
    def t_ns(self) -> int:
        """``t`` in integer nanoseconds (relative to the start)."""
        return seconds_to_ns(self.t)


class ServiceCallSpec(_Model):
    """A service call the grader makes at ``t`` seconds after the start, as ``ros2 service call <service> <type>
    <request>`` (or ``rosservice call``) would: it waits for the service to be offered, then for the answer, before
    its next call. ``type`` is spelled as the run's client library spells it (``example_interfaces/srv/AddTwoInts``
    for rclpy, ``rospy_tutorials/AddTwoInts`` for rospy); ``request`` gives every field of the request."""

    t: NonNegative
    service: Annotated[str, Field(pattern=r"^/[A-Za-z0-9_/]+$")]
    type: str
    request: dict[str, JsonValue] = Field(default_factory=dict)

    @property
    def t_ns(self) -> int:
        """``t`` in integer nanoseconds (relative to the start)."""
        return seconds_to_ns(self.t)


class ParamSetSpec(_Model):
    """A parameter the grader sets on a ROS 2 node at ``t`` seconds after the start, as ``ros2 param set <node> <name>
    <value>`` would: one call to the node's ``<node>/set_parameters`` (rcl_interfaces/srv/SetParameters), in the
    script of ``service_calls``. ``value``'s type is the parameter's, as the command line's YAML reads it: ``1.2`` a
    double, ``1`` an integer (which a double parameter refuses), ``true`` a bool, ``"x"`` a string, or a list of one
    of them."""

    t: NonNegative
    node: Annotated[str, Field(pattern=r"^/[A-Za-z0-9_/]+$")]
    name: Annotated[str, Field(pattern=r"^[A-Za-z_][A-Za-z0-9_./]*$")]
    value: Union[StrictBool, StrictInt, StrictFloat, StrictStr,
                 Annotated[list[StrictBool], Field(min_length=1)], Annotated[list[StrictInt], Field(min_length=1)],
                 Annotated[list[StrictFloat], Field(min_length=1)], Annotated[list[StrictStr], Field(min_length=1)]]

    @property
    def t_ns(self) -> int:
        """``t`` in integer nanoseconds (relative to the start)."""
        return seconds_to_ns(self.t)


class ActionGoalSpec(_Model):
    """An action goal the grader sends at ``t`` seconds after the start, as ``ros2 action send_goal <action> <type>
    <goal>`` would: it waits for the action's server, sends the goal and, once accepted, waits for its result; with
    ``cancel_at``, Ctrl+C then cancels the goal if it has not ended (``ros2 action send_goal``'s own cancel). ``type``
    is ``pkg/action/Name`` (a rubric's ``*/action/Name``: the submission's own action of that name, else the built-in
    one); ``goal`` gives the fields of its Goal. Goals run side by side, each as its own command. For rospy nodes the
    goal goes out on ``<action>/goal`` as actionlib's client sends it, and its cancel on ``<action>/cancel``."""

    t: NonNegative
    action: Annotated[str, Field(pattern=r"^/[A-Za-z0-9_/]+$")]
    type: Annotated[str, Field(pattern=r"^(\*|[A-Za-z0-9_]+)/action/[A-Za-z0-9_]+$")]
    goal: dict[str, JsonValue] = Field(default_factory=dict)
    cancel_at: NonNegative | None = None

    @property
    def t_ns(self) -> int:
        """``t`` in integer nanoseconds (relative to the start)."""
        return seconds_to_ns(self.t)

    @property
    def cancel_ns(self) -> int | None:
        return None if self.cancel_at is None else seconds_to_ns(self.cancel_at)


class PublicationSpec(_Model):
    """A message the grader publishes from ``t`` seconds after the start, as ``rostopic pub <topic> <type> <values>``
    (rospy runs) or ``ros2 topic pub`` (rclpy runs) would. ``values`` gives the message's fields as YAML would (a
    mapping; fields not given are zero or empty). ``once``: ``-1``/``--once``. ``rate``: ``-r`` in Hz (rostopic:
    none by default, one latched message; ros2: 1 Hz by default). ``times``: ros2's ``-t``. ``latch``: rostopic's
    ``-l`` (with a rate; without one it always latches)."""

    t: NonNegative
    topic: Annotated[str, Field(pattern=r"^/[A-Za-z0-9_/]+$")]
    type: str
    values: dict[str, JsonValue] = Field(default_factory=dict)
    once: bool = False
    rate: Annotated[float, Field(gt=0, le=1000)] | None = None
    times: Annotated[int, Field(ge=1)] | None = None
    latch: bool | None = None

    @model_validator(mode="after")
    def _one_mode(self) -> PublicationSpec:
        if self.once and (self.rate is not None or self.times is not None):
            raise ValueError("publications: once publishes one message; give once, or a rate and times, not both")
        return self

    @property
    def t_ns(self) -> int:
        """``t`` in integer nanoseconds (relative to the start)."""
        return seconds_to_ns(self.t)


class TurtlesimWindow(_Model):
    """A further turtlesim window in the run: a launch file's second turtlesim_node (the launch tutorials' two
    turtlesims and mimic). Its topics and services live in its node's namespace, its parameters under its node."""

    node: str = Field(pattern=r"^(/[A-Za-z_]\w*)+$", description="the node's full name, e.g. /turtlesim2/sim")
    params: dict[str, JsonValue] = Field(default_factory=dict,
                                         description="the parameters the node starts with, by name")

    @property
    def namespace(self) -> str:
        """The node's namespace, where its names resolve ('' for the root)."""
        return self.node.rpartition("/")[0]


class Scenario(_Model):
    """One run: the world starts at ``start_time`` (it has been running since 0) and lasts ``duration`` seconds after it."""

    robot: str = "turtlebot3_waffle"
    world: str | None = Field(None, description="a course world in sim/course_worlds/ (None: an open floor)")
    start: str | None = Field(None, description="a start pose of the course world, by name; sets initial_pose")
    base_mode: str | None = Field(None, description="a mode of the robot profile; None: the profile's default_mode")
    initial_pose: Pose2D = Pose2D()
    start_time: NonNegative = Field(2.0, description="sim seconds at which the node starts")
    duration: float = Field(60.0, gt=0, description="sim seconds after start_time that the run lasts")
    shutdown_at: NonNegative | None = Field(
        None, description="seconds after start_time when the operator presses Ctrl+C (used by the grader, not the world)"
    )
    seed: int = Field(0, description="recorded with the run; keys the LiDAR's noise (a function of the seed and the sweep's time)")
    imperfections: Imperfections = Imperfections()
    script: list[ScriptedCommand] = Field(default_factory=list, description="commands sent by the scripted driver")
    obstacles: list[Obstacle] = Field(default_factory=list, description="fixed walls and pillars (empty: an open floor)")
    service_calls: list[ServiceCallSpec] = Field(default_factory=list,
                                                 description="service calls the grader makes, in time order")
    param_sets: list[ParamSetSpec] = Field(default_factory=list,
                                           description="ROS 2 parameters the grader sets, in time order")
    action_goals: list[ActionGoalSpec] = Field(default_factory=list,
                                               description="action goals the grader sends (ROS 2, or actionlib's for rospy), in time order")
    publications: list[PublicationSpec] = Field(
        default_factory=list, description="messages the grader publishes (rostopic pub / ros2 topic pub), in time order")
    world_params: dict[str, JsonValue] = Field(
        default_factory=dict, description="parameters the world's node starts with, by name, as a launch file's "
        "parameters for turtlesim_node give them (e.g. {background_r = 255}); a name it does not declare is ignored")
    turtlesim_windows: list[TurtlesimWindow] = Field(
        default_factory=list, description="turtlesim windows besides the first (whose names are turtlesim's own, "
        "/turtle1/cmd_vel...), each in its node's namespace; a robot world has none")
    command_types: list[str] | None = Field(
        None, description="velocity command types the robot's base takes, e.g. ['geometry_msgs/Twist', "
        "'geometry_msgs/TwistStamped']; None: what the robot takes from the run's client library (turtlesim: "
        "Twist; a ROS 1 robot: Twist; a ROS 2 Jazzy robot: TwistStamped)")

    @model_validator(mode="before")
    @classmethod
    def _start_pose(cls, data: object) -> object:
        """A named start sets ``initial_pose`` (given both, they must agree: a recorded scenario holds both)."""
        if isinstance(data, dict) and data.get("start") is not None and data.get("world") is not None:
            from sim.course import CourseWorldError, load_course_world  # sim.course builds on this module's shapes
            try:
                starts = load_course_world(data["world"]).starts
            except CourseWorldError as exc:
                raise ValueError(f"world: {exc}") from None
            if data["start"] not in starts:
                raise ValueError(f"start {data['start']!r} is not a start of {data['world']}; expected one of "
                                 f"{sorted(starts)}")
            pose = starts[data["start"]]
            given = data.get("initial_pose")
            if given is not None and Pose2D.model_validate(given) != pose:
                raise ValueError(f"initial_pose differs from start {data['start']!r} of {data['world']}; give one")
            data = {**data, "initial_pose": pose}
        return data

    @model_serializer(mode="wrap")
    def _dump(self, handler: SerializerFunctionWrapHandler) -> dict:
        """Without an unset world or start (or no publications, other turtlesim windows or node parameters), so a
        scenario without them is recorded as it always was."""
        dumped = handler(self)
        for key in ("world", "start"):
            if dumped.get(key, "") is None:
                del dumped[key]
        for key in ("publications", "turtlesim_windows", "node_params"):  # likewise without those that came later
            if key in dumped and not dumped[key]:
                del dumped[key]
        return dumped

    @property
    def all_obstacles(self) -> tuple[Box | Cylinder, ...]:
        """The course world's walls and pillars, then the scenario's own obstacles."""
        if self.world is None:
            return tuple(self.obstacles)
        from sim.course import load_course_world
        return (*load_course_world(self.world).obstacles, *self.obstacles)

    @model_validator(mode="after")
    def _check(self) -> Scenario:
        if self.world is not None:
            from sim.course import CourseWorldError, load_course_world
            try:
                load_course_world(self.world)
            except CourseWorldError as exc:
                raise ValueError(f"world: {exc}") from None
        if self.start is not None and self.world is None:
            raise ValueError("start names a start pose of a course world; name the world too")
        if self.robot == TURTLESIM:
            if self.base_mode is not None or self.obstacles or self.world or self.imperfections != Imperfections():
                raise ValueError("turtlesim has no base modes, worlds, obstacles or imperfections; remove them from "
                                 "the scenario")
        else:
            if self.turtlesim_windows:
                raise ValueError("turtlesim_windows: only a turtlesim run has windows; remove them or set robot = "
                                 f"{TURTLESIM!r}")
            try:
                profile = load_robot(self.robot)
            except ProfileError as exc:
                raise ValueError(f"robot: {exc} (or {TURTLESIM!r})") from None
            if self.base_mode is not None and self.base_mode not in profile.modes:
                raise ValueError(f"base_mode {self.base_mode!r} is not a mode of {self.robot}; expected one of {sorted(profile.modes)}")
        if self.shutdown_at is not None and self.shutdown_at > self.duration:
            raise ValueError(f"shutdown_at {self.shutdown_at} s is after the end of the run (duration {self.duration} s)")
        times = [command.t for command in self.script]
        for i, (earlier, later) in enumerate(zip(times, times[1:]), start=1):
            if later < earlier:
                raise ValueError(f"script[{i}].t = {later} s comes before script[{i - 1}].t = {earlier} s; expected times in order")
        for goal in self.action_goals:
            if goal.cancel_at is not None and not goal.t < goal.cancel_at <= self.duration:
                raise ValueError(f"action_goals: a goal sent at {goal.t} s is cancelled at {goal.cancel_at} s; "
                                 "expected a later time within the run's duration")
        for field_name in ("service_calls", "param_sets", "action_goals", "publications"):
            calls = [call.t for call in getattr(self, field_name)]
            if calls != sorted(calls) or (calls and calls[-1] > self.duration):
                raise ValueError(f"{field_name} must come in time order, within the run's duration")
        if times and times[-1] > self.duration:
            raise ValueError(f"script[{len(times) - 1}].t = {times[-1]} s is after the end of the run (duration {self.duration} s)")
        return self

    @property
    def start_ns(self) -> int:
        """World time when the run (and the node) starts."""
        return seconds_to_ns(self.start_time)

    @property
    def end_ns(self) -> int:
        """World time when the run ends."""
        return self.start_ns + seconds_to_ns(self.duration)

    @property
    def shutdown_ns(self) -> int | None:
        """World time of the Ctrl+C, if any."""
        return None if self.shutdown_at is None else self.start_ns + seconds_to_ns(self.shutdown_at)


class ScenarioTimes:
    """What every world says about time: now, and the run's start and end as its scenario sets them."""

    scenario: Scenario
    _time_ns: int

    @property
    def time_ns(self) -> int:
        """Current sim time."""
        return self._time_ns

    @property
    def start_ns(self) -> int:
        """Sim time at which the run starts (the world was created already advanced to it)."""
        return self.scenario.start_ns

    @property
    def end_ns(self) -> int:
        """Sim time at which the run ends."""
        return self.scenario.end_ns
