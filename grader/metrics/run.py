"""One recorded run as plain arrays: the only input metrics see, so they can be tested on synthetic data."""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from grader.metrics.action_record import ActionGoal, action_goals
from sim.scenario import Box, Cylinder, Scenario

DRIVER_CALLERID = "/rosgrade_driver"  # the grader's scripted driver; its commands are not the student's
TURTLE_POSE_TOPIC = "/turtle1/pose"  # turtlesim's pose of turtle1 (turtlesim/Pose), its only odometry
TURTLE_POSE_TYPE = "turtlesim/Pose"
SERVICE_PREFIX = "/rosgrade/service"  # <service>/request, then <service>/response or <service>/error (the session's)
PARAM_TOPIC = "/rosgrade/param"  # the run's parameter server: the tree it started with, then each change (JSON)
CONTACT_TOPIC = "/rosgrade/contacts"  # the world's: the robot touching an obstacle, once per 50 Hz tick (JSON)
RUN_KEYS = ("shutdown_requested_s", "exit_code", "exit_signal", "status", "ended_s")


class RunDataError(Exception):
    """A recording does not provide the arrays a run needs."""


@dataclass(frozen=True)
class Trajectory:
    """Planar poses in time order: t (s, sim time), x, y (m), yaw (rad); ``source`` says where they came from."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray
    source: str = "odometry"

    @classmethod
    def of(cls, t: Any, x: Any, y: Any, yaw: Any, source: str = "odometry") -> Trajectory:
        """Build from sequences, sorted by time, keeping one sample per stamp (repeated stamps add nothing)."""
        arrays = [np.asarray(a, dtype=float).reshape(-1) for a in (t, x, y, yaw)]
        if len({len(a) for a in arrays}) != 1:
            raise RunDataError("trajectory arrays t, x, y, yaw differ in length")
        order = np.argsort(arrays[0], kind="stable")
        t_sorted = arrays[0][order]
        keep = np.concatenate(([True], np.diff(t_sorted) > 0)) if len(t_sorted) else np.zeros(0, bool)
        return cls(*(a[order][keep] for a in arrays), source=source)

    def __len__(self) -> int:
        return len(self.t)

    def between(self, start: float = -math.inf, end: float = math.inf) -> Trajectory:
        """The samples with start <= t <= end."""
        m = (self.t >= start) & (self.t <= end)
        return Trajectory(self.t[m], self.x[m], self.y[m], self.yaw[m], self.source)


@dataclass(frozen=True)
class Commands:
    """Velocity commands the student's node published: t (s), linear and angular (N x 3), topic of each."""

    t: np.ndarray
    linear: np.ndarray
    angular: np.ndarray
    topic: tuple[str, ...] = ()

    @classmethod
    def of(cls, t: Any, linear: Any, angular: Any, topic: Any = ()) -> Commands:
        """Build from sequences; ``linear``/``angular`` are (N, 3) or a bare x / z column for 2-D commands."""
        t_arr = np.asarray(t, dtype=float).reshape(-1)
        n = len(t_arr)
        lin, ang = np.asarray(linear, dtype=float), np.asarray(angular, dtype=float)
        if lin.ndim == 1:
            lin = np.column_stack([lin, np.zeros(n), np.zeros(n)]) if n else np.zeros((0, 3))
        if ang.ndim == 1:
            ang = np.column_stack([np.zeros(n), np.zeros(n), ang]) if n else np.zeros((0, 3))
        topics = (topic,) * n if isinstance(topic, str) else tuple(topic)
        return cls(t_arr, lin.reshape(n, 3), ang.reshape(n, 3), topics)

    @classmethod
    def empty(cls) -> Commands:
        return cls.of([], [], [])

    def __len__(self) -> int:
        return len(self.t)

    def is_zero(self) -> np.ndarray:
        """Per message: every one of the six components is exactly zero (a full stop)."""
        return np.all(np.hstack([self.linear, self.angular]) == 0.0, axis=1)


@dataclass(frozen=True)
class ServiceCall:
    """One call that reached a server (the world's or a node's): sim time (s), the service's name, the request's
    fields by name, and the response's (None when the server failed the call or never answered it)."""

    t: float
    service: str
    request: dict[str, Any]
    response: dict[str, Any] | None


@dataclass(frozen=True)
class ParamChange:
    """A change to the run's parameter server: sim time (s), the name ("/" with the whole tree in the first one, the
    tree the run started with), the value (None: deleted), and how many served calls came before it."""

    t: float
    name: str
    value: Any
    calls_before: int


@dataclass(frozen=True)
class Contact:
    """The robot touching an obstacle at sim time ``t`` (s): which one, as feedback names it, and where (m)."""

    t: float
    obstacle: str
    x: float
    y: float


# rospy's console prefix: "[INFO] [1795250908.523113, 21.060000]: " (wall and sim time) before the message.
LOG_PREFIX = re.compile(
    r"^\s*\[\s*(?P<level>DEBUG|INFO|WARN|WARNING|ERROR|FATAL)\s*\]\s*(?:\[[^\]]*\]\s*:?)?\s?", re.I)
ROSOUT_LEVELS = {1: "DEBUG", 2: "INFO", 4: "WARN", 8: "ERROR", 16: "FATAL"}  # rosgraph_msgs/Log level values


@dataclass(frozen=True)
class OutputLine:
    """One line the node wrote: sim time (s), stream (stdout, stderr, rosout, ...), text, and its log level if any."""

    t: float
    stream: str
    text: str
    level: str | None = None  # DEBUG, INFO, WARN, ERROR, FATAL for /rosout; None for what the node printed

    def message(self) -> tuple[str | None, str]:
        """The log level and the message itself, without the console prefix rospy adds on stdout."""
        prefix = LOG_PREFIX.match(self.text)
        if prefix is None:
            return self.level, self.text
        level = prefix.group("level").upper()
        return self.level or ("WARN" if level == "WARNING" else level), self.text[prefix.end():]


@dataclass(frozen=True)
class RunInfo:
    """How the node's process went: from the recording's ``rosgrade.run`` metadata (sim-time seconds)."""

    shutdown_requested_s: float | None = None
    exit_code: int | None = None
    exit_signal: int | str | None = None
    status: str | None = None
    ended_s: float | None = None

    @classmethod
    def from_metadata(cls, metadata: dict[str, Any] | None) -> RunInfo:
        """Read the run record, whose values may be JSON text (MCAP metadata holds strings only)."""
        record = _decode((metadata or {}).get("rosgrade.run") or {})
        if not isinstance(record, dict):
            return cls()
        record = {k: _decode(v) for k, v in record.items()}
        if len(record) == 1 and isinstance(next(iter(record.values())), dict):
            record = next(iter(record.values()))  # a record that nests everything under one key
        values = {k: _decode(record.get(k)) for k in RUN_KEYS}
        for k in ("shutdown_requested_s", "ended_s"):
            values[k] = None if values[k] is None else float(values[k])
        if values["exit_code"] is not None:
            values["exit_code"] = int(values["exit_code"])
        return cls(**values)


@dataclass(frozen=True)
class RunData:
    """Everything a metric may read about one scenario run."""

    odometry: Trajectory
    ground_truth: Trajectory | None = None
    commands: Commands = field(default_factory=Commands.empty)
    lines: tuple[OutputLine, ...] = ()
    run: RunInfo = field(default_factory=RunInfo)
    start_time: float = 0.0  # sim time (s) when the node was started
    shutdown_at: float | None = None  # scenario's Ctrl+C time, seconds after start
    poses: dict[str, Trajectory] = field(default_factory=dict)  # turtlesim: each turtle's pose topic → its poses
    # turtlesim's further windows (the launch tutorials' turtlesim2): their nodes; their turtles' pose topics → poses
    windows: tuple[str, ...] = ()
    window_poses: dict[str, Trajectory] = field(default_factory=dict)
    service_calls: tuple[ServiceCall, ...] = ()  # in the order they were served
    param_changes: tuple[ParamChange, ...] = ()  # in the order they were made (none: a recording without them)
    action_goals: tuple[ActionGoal, ...] = ()  # the grader's, in the order sent (grader/metrics/action_record.py)
    contacts: tuple[Contact, ...] = ()  # in time order; none on an open floor
    obstacles: tuple[Box | Cylinder, ...] = ()  # the course world's walls and pillars, then the scenario's own
    robot: str = ""  # the robot profile the run simulated ("" when the recording does not say)
    client_library: str = "rospy"  # the node's, as the recording says: "rospy" or "rclpy"
    # Velocity command types nodes published on the robot's command topics that its base does not take
    # (a Twist to the Jazzy TurtleBot3, which drives on TwistStamped), comma-separated.
    ignored_command_types: str = ""
    command_type: str = "Twist"  # what the robot's base takes, as feedback names it ("Twist or TwistStamped")

    def trajectory(self, source: Literal["ground_truth", "odometry"]) -> Trajectory:
        """The requested path; ground truth falls back to odometry when the recording has none."""
        if source == "ground_truth" and self.ground_truth is not None and len(self.ground_truth):
            return self.ground_truth
        return self.odometry

    def until_shutdown(self, source: Literal["ground_truth", "odometry"]) -> Trajectory:
        """The requested path up to the Ctrl+C, or all of it when the scenario sends none."""
        shutdown = self.shutdown_time()
        return self.trajectory(source).between(end=math.inf if shutdown is None else shutdown)

    def until_ctrl_c(self) -> RunData:
        """What happened until the Ctrl+C, the run a metric judges (the shutdown criteria alone judge what came after):
        poses up to it, what the node did (commands, lines, calls, parameter changes) before it. All of it when the
        scenario sends none."""
        end = self.shutdown_time()
        if end is None:
            return self
        cut = self.commands.t < end
        return replace(
            self,
            odometry=self.odometry.between(end=end),
            ground_truth=None if self.ground_truth is None else self.ground_truth.between(end=end),
            commands=Commands(self.commands.t[cut], self.commands.linear[cut], self.commands.angular[cut],
                              tuple(tp for tp, k in zip(self.commands.topic, cut) if k)),
            lines=tuple(line for line in self.lines if line.t < end),
            poses={topic: path.between(end=end) for topic, path in self.poses.items()},
            window_poses={topic: path.between(end=end) for topic, path in self.window_poses.items()},
            service_calls=tuple(call for call in self.service_calls if call.t < end),
            # The first change is the tree the run started with, whenever it was recorded.
            param_changes=tuple(c for c in self.param_changes if c.t < end or c is self.param_changes[0]),
            action_goals=tuple(goal for goal in self.action_goals if goal.t < end),
            contacts=tuple(contact for contact in self.contacts if contact.t < end),
        )

    def shutdown_time(self) -> float | None:
        """Sim time (s) of the Ctrl+C: as the run recorded it, else as the scenario planned it."""
        if self.run.shutdown_requested_s is not None:
            return self.run.shutdown_requested_s
        return None if self.shutdown_at is None else self.start_time + self.shutdown_at

    @classmethod
    def from_recording(cls, recording: Any, start_time: float = 0.0, shutdown_at: float | None = None) -> RunData:
        """Adapt a ``grader.recording.Recording`` (documented API in DEVELOPERS.md) into arrays."""
        truth = recording.ground_truth()
        calls, params = _calls_and_params(recording)
        windows = other_windows(recording)
        poses, window_poses = by_window(turtle_poses(recording), windows)
        return cls(
            odometry=_odometry(recording),
            ground_truth=None if truth is None else _trajectory(truth, "ground_truth"),
            commands=_student_commands(recording.commands()),
            lines=_lines(recording),
            run=RunInfo.from_metadata(getattr(recording, "metadata", None)),
            start_time=start_time,
            shutdown_at=shutdown_at,
            poses=poses,
            windows=windows,
            window_poses=window_poses,
            service_calls=calls,
            param_changes=params,
            action_goals=action_goals(recording),
            contacts=contacts(recording),
            obstacles=obstacles(recording),
            robot=str(_world_info(recording).get("robot", "")),
            client_library=_client_library(recording),
            ignored_command_types=_ignored_command_types(recording),
            command_type=_command_type(recording),
        )


def _world_info(recording: Any) -> dict:
    info = _decode((getattr(recording, "metadata", None) or {}).get("rosgrade") or {})
    return info if isinstance(info, dict) else {}


def other_windows(recording: Any) -> tuple[str, ...]:
    """The nodes of the run's further turtlesim windows (``/turtlesim2/sim``), as its recorded scenario names them."""
    scenario = _decode(_world_info(recording).get("scenario"))
    windows = scenario.get("turtlesim_windows", []) if isinstance(scenario, dict) else []
    return tuple(str(w.get("node", "")) for w in windows if isinstance(w, dict))


def by_window(poses: dict[str, Trajectory], others: tuple[str, ...]) -> tuple[dict[str, Trajectory],
                                                                            dict[str, Trajectory]]:
    """The first window's turtles' poses, and the further windows' (``others``: their nodes, in whose namespaces
    their topics are)."""
    namespaces = [node.rpartition("/")[0] for node in others]
    theirs = {topic for topic in poses if any(topic.startswith(namespace + "/") for namespace in namespaces)}
    return ({t: p for t, p in poses.items() if t not in theirs}, {t: p for t, p in poses.items() if t in theirs})


def _client_library(recording: Any) -> str:
    return "rclpy" if _world_info(recording).get("client_library") == "rclpy" else "rospy"


def _command_type(recording: Any) -> str:
    taken = _decode(_world_info(recording).get("command_types"))
    names = sorted({t.rsplit("/", 1)[-1] for t in taken if isinstance(t, str)}) if isinstance(taken, list) else []
    return " or ".join(names) or "Twist"


def _ignored_command_types(recording: Any) -> str:
    """Types nodes published on command topics that the base does not take (from the recording's declarations)."""
    info = _world_info(recording)
    topics, taken = _decode(info.get("command_topics")), _decode(info.get("command_types"))
    if not isinstance(topics, list) or not isinstance(taken, list) or not hasattr(recording, "topics"):
        return ""
    taken_short = {t.replace("/msg/", "/") for t in taken if isinstance(t, str)}
    sent = {t.type for t in recording.topics() if t.topic in topics and t.origin == "node" and t.count}
    return ", ".join(sorted(t for t in sent if t not in taken_short))


def _decode(value: Any) -> Any:
    """JSON-decode a string that holds JSON; anything else is returned as it is."""
    if isinstance(value, str):
        try:
            return json.loads(value)
        except json.JSONDecodeError:
            return value
    return value


def _lines(recording: Any) -> tuple[OutputLine, ...]:
    """The output lines, with each /rosout line's level (both lists hold /rosout in the same time order)."""
    rosout = iter(getattr(recording, "rosout", list)())
    lines = []
    for t, stream, text in recording.output_lines():
        entry = next(rosout, None) if stream == "rosout" else None
        level = None if entry is None else ROSOUT_LEVELS.get(int(entry.level))
        lines.append(OutputLine(float(t), str(stream), str(text), level))
    return tuple(lines)


def _odometry(recording: Any) -> Trajectory:
    """What the node could see of its pose: nav_msgs/Odometry, or in turtlesim (which has none) turtle1/pose."""
    if getattr(recording, "odometry_topic", lambda: "")() is None:
        poses = [(t_ns / 1e9, m.x, m.y, m.theta) for t_ns, m in recording.world_messages(TURTLE_POSE_TOPIC)]
        return Trajectory.of(*(zip(*poses) if poses else ([], [], [], [])), source="odometry")
    return _trajectory(recording.odometry(), "odometry")


def turtle_poses(recording: Any) -> dict[str, Trajectory]:
    """Every turtle's turtlesim/Pose topic the world published (spawned turtles have their own), by topic."""
    poses = {}
    for topic in getattr(recording, "world_topics", lambda _: [])(TURTLE_POSE_TYPE):
        rows = [(t_ns / 1e9, m.x, m.y, m.theta) for t_ns, m in recording.world_messages(topic)]
        if rows:
            poses[topic] = Trajectory.of(*zip(*rows), source="odometry")
    return poses


def obstacles(recording: Any) -> tuple[Box | Cylinder, ...]:
    """The walls and pillars of the recorded scenario (none when it holds no scenario this version can read)."""
    recorded = _decode(_world_info(recording).get("scenario"))
    if not isinstance(recorded, dict):
        return ()
    try:  # a rubric's scenario records its name, description and such besides the world's fields
        return Scenario.model_validate({k: v for k, v in recorded.items() if k in Scenario.model_fields}).all_obstacles
    except ValueError:
        return ()


def contacts(recording: Any) -> tuple[Contact, ...]:
    """The world's record of the robot touching obstacles."""
    if CONTACT_TOPIC not in {i.topic for i in getattr(recording, "topics", list)()}:
        return ()
    found = []
    for t_ns, message in recording.world_messages(CONTACT_TOPIC):
        record = _decode(getattr(message, "data", None))
        if isinstance(record, dict):
            found.append(Contact(t_ns / 1e9, str(record.get("obstacle", "")), float(record["x"]), float(record["y"])))
    return tuple(found)


def service_calls(recording: Any) -> tuple[ServiceCall, ...]:
    """The calls that reached a server, each request paired with the response or error recorded after it (a call is
    answered before the next one is made), or with None if it was never answered; an error with no request is a call
    no server took (not served)."""
    return _calls_and_params(recording)[0]


def param_changes(recording: Any) -> tuple[ParamChange, ...]:
    """The changes to the run's parameter server, each placed among the served calls."""
    return _calls_and_params(recording)[1]


def _calls_and_params(recording: Any) -> tuple[tuple[ServiceCall, ...], tuple[ParamChange, ...]]:
    """The served calls and the parameter changes, read in one pass so that their order is the run's."""
    topics = {i.topic for i in getattr(recording, "topics", list)()
              if i.topic.startswith(SERVICE_PREFIX + "/") or i.topic == PARAM_TOPIC}
    if not topics:
        return (), ()
    calls, params, open_requests = [], [], {}
    for topic, t_ns, message in recording.messages_on(topics):
        if topic == PARAM_TOPIC:
            change = _param_change(t_ns, message, len(calls))
            if change is not None:
                params.append(change)
            continue
        service, _, part = topic[len(SERVICE_PREFIX):].rpartition("/")
        if part == "request":
            open_requests[service] = (t_ns, _fields(message))
        elif service in open_requests:
            t_req, request = open_requests.pop(service)
            calls.append(ServiceCall(t_req / 1e9, service, request, _fields(message) if part == "response" else None))
    # a request a node's server never answered before the run ended
    calls += [ServiceCall(t_ns / 1e9, service, request, None) for service, (t_ns, request) in open_requests.items()]
    calls.sort(key=lambda call: call.t)
    return tuple(calls), tuple(params)


def _param_change(t_ns: int, message: Any, calls_before: int) -> ParamChange | None:
    """A recorded ``{"op": "set", "name", "value"}`` or ``{"op": "delete", "name"}``; None when it is neither."""
    change = _decode(getattr(message, "data", None))
    if not isinstance(change, dict) or not isinstance(change.get("name"), str):
        return None
    root, value = not change["name"].strip("/"), change.get("value")
    if change.get("op") == "set" and value is not None and (not root or isinstance(value, dict)):
        return ParamChange(t_ns / 1e9, change["name"], value, calls_before)
    if change.get("op") == "delete" and not root:
        return ParamChange(t_ns / 1e9, change["name"], None, calls_before)
    return None


def _fields(message: Any) -> dict[str, Any]:
    """A decoded message's fields by name."""
    return {name: getattr(message, name) for name in message.__dataclass_fields__ if not name.startswith("__")}


def _trajectory(series: Any, source: str) -> Trajectory:
    return Trajectory.of(series.t, series.x, series.y, series.yaw, source)


def _column(series: Any, name: str) -> np.ndarray:
    """An (N, 3) vector column, whether the series stores ``name`` as one array or as ``name_x/_y/_z``."""
    if hasattr(series, name):
        return np.asarray(getattr(series, name), dtype=float).reshape(-1, 3)
    return np.column_stack([np.asarray(getattr(series, f"{name}_{a}"), dtype=float) for a in "xyz"])


def _strings(value: Any, n: int) -> list[str]:
    if value is None:
        return [""] * n
    return [value] * n if isinstance(value, str) else [str(v) for v in value]


def _student_commands(series: Any) -> Commands:
    """The node's commands only: the scripted driver's are the grader's, not the student's.

    The recording's origin marks say which channels the grader wrote; a callerid is a name a node can choose, so
    it is only the fallback for recordings without marks (bags recorded elsewhere, older rosgrade files)."""
    t = np.asarray(series.t, dtype=float).reshape(-1)
    n = len(t)
    origin = getattr(series, "origin", None)
    if origin is not None:
        keep = np.array([o != "grader" for o in _strings(origin, n)], dtype=bool)
    else:
        keep = np.array([c != DRIVER_CALLERID for c in _strings(getattr(series, "callerid", None), n)], dtype=bool)
    topics = _strings(getattr(series, "topic", None), n)
    return Commands.of(
        t[keep], _column(series, "linear")[keep], _column(series, "angular")[keep],
        tuple(tp for tp, k in zip(topics, keep) if k),
    )
