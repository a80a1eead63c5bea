"""What a run is asked to do (nodes, limits) and what it reports back (statuses, exit codes, diagnostics)."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Literal

if TYPE_CHECKING:
    from grader.interfaces import InterfaceSet
    from grader.runtime.client_library import EntryPoint
    from sim import Scenario

# Statuses a node ends a run in; each comes with a plain explanation in NodeOutcome.message.
NodeStatus = Literal[
    "exited",             # the process ended by itself (any exit code)
    "stopped_at_end",     # still running when the scenario's time was up; stopped by the grader
    "killed_after_shutdown",  # ignored Ctrl+C and SIGTERM; killed after the grace period
    "timeout",            # exceeded its wall-clock budget or stopped answering (hung outside the client library)
    "crashed",            # died from a signal it did not ask for (segfault, abort)
    "killed_by_limit",    # exceeded a CPU, memory, process, file-size or output limit
    "protocol_violation",  # sent something that is not a valid frame
    "not_started",        # launch would start it later (a TimerAction, an event handler) and the run ended first
]


@dataclass(frozen=True)
class Limits:
    """Resource limits for one node process; enforced with rlimits and the grader's own watchdogs."""

    wall_s: float = 120.0         # whole run, wall clock
    silent_wall_s: float = 10.0   # longest a node may run without yielding to the grader
    cpu_s: float = 120.0
    memory_mb: int = 1024
    processes: int = 64
    file_mb: int = 64
    output_bytes: int = 4 * 1024 * 1024

    def __post_init__(self) -> None:
        for name, value in vars(self).items():
            if not value > 0:
                raise ValueError(f"limit {name} must be positive (got {value!r})")


# An argument that stands for one of NodeSpec.files until the node starts, then becomes that file's path. A NUL is in
# no real argument, so nothing a student passes is taken for one.
FILE_ARG = "\0file:"


def file_arg(name: str) -> str:
    """The argument that becomes the path of the node's file ``name`` (NodeSpec.files): ``--params-file`` takes it."""
    return FILE_ARG + name


@dataclass(frozen=True)
class Start:
    """When a node starts, as `ros2 launch` starts it: with the run, ``delay_s`` after it (a TimerAction), or when the
    run's node ``after`` (its index) starts or exits (an OnProcessStart / OnProcessExit handler), plus ``delay_s``."""

    delay_s: float = 0.0
    after: int | None = None
    on: Literal["start", "exit"] = "exit"
    said: str = ""  # how the launch file says it, for the report ("when move_square.py exits")

    def __post_init__(self) -> None:
        if not self.delay_s >= 0:
            raise ValueError(f"a node's start delay must not be negative (got {self.delay_s!r})")


@dataclass(frozen=True)
class NodeSpec:
    """One node to run: a script, its arguments (remaps included, e.g. ``cmd_vel:=/x``), stdin and namespace."""

    script: Path
    args: tuple[str, ...] = ()
    stdin: str | None = None
    ros_namespace: str | None = None
    params: dict[str, object] = field(default_factory=dict)
    # As roslaunch's node attributes: a required node that ends stops the others (Ctrl+C to each); a node with
    # output "log" prints to its own log file instead of the run's log (the recording holds its text either way).
    required: bool = False
    output: Literal["screen", "log"] = "screen"
    # Which client library the script imports (rospy: "ros1", rclpy: "ros2"): its import root and wire format.
    flavour: Literal["ros1", "ros2"] = "ros1"
    # When it starts (launch's TimerAction and event handlers); by default with the run.
    start: Start = Start()
    # A node the grader provides (a server the student's client calls, teleop): confined like the student's, but
    # its traffic and findings are not the student's to act on.
    provided: bool = False
    # An ament_python node is started through this console_scripts entry point, as `ros2 run` would.
    entry: EntryPoint | None = None
    # Folders holding the Python packages its workspace's build installs (ament_python_install_package, setup.py's
    # packages): on the node's import path after the client library, shown read-only in its sandbox.
    import_roots: tuple[Path, ...] = ()
    # Files handed to the node by content, (name, bytes): the parameter files launch_ros writes for a launch file's
    # node. They are written read-only into a folder of the node's own (/tmp/rosgrade-files inside its sandbox, the
    # same path every run), and each argument file_arg(name) becomes that file's path.
    files: tuple[tuple[str, bytes], ...] = ()

    def __post_init__(self) -> None:
        names = [name for name, _content in self.files]
        for name in names:
            if not name or name in (".", "..") or "/" in name or "\0" in name:
                raise ValueError(f"a node's file needs a plain file name, not {name!r}")
        if len(set(names)) != len(names):
            raise ValueError(f"a node's files need different names: {names}")
        unknown = sorted({a[len(FILE_ARG):] for a in self.args if a.startswith(FILE_ARG)} - set(names))
        if unknown:
            raise ValueError(f"the node's arguments name files it is not given: {unknown}")


@dataclass(frozen=True)
class RunSpec:
    """A scenario and the nodes that run in it."""

    scenario: Scenario
    nodes: tuple[NodeSpec, ...]
    limits: Limits = Limits()
    name: str = "nominal"
    # Sim seconds a node gets after Ctrl+C before SIGTERM, then before SIGKILL.
    shutdown_grace_s: float = 5.0
    # The submission's own .msg/.srv/.action types: the run's catalog and what its nodes import (None: none).
    interfaces: InterfaceSet | None = None

    def __post_init__(self) -> None:
        for index, node in enumerate(self.nodes):
            after = node.start.after
            if after is not None and not (0 <= after < len(self.nodes) and after != index):
                raise ValueError(f"node {index} starts after node {after}, which is not another node of the run")

    @property
    def flavour(self) -> str:
        """The client library flavour of the run's nodes ("ros1" when it has none): one wire format per run."""
        flavours = {node.flavour for node in self.nodes}
        if len(flavours) > 1:
            raise ValueError("a run cannot mix rospy and rclpy nodes: ROS 1 and ROS 2 nodes do not talk to each other")
        return flavours.pop() if flavours else "ros1"


@dataclass
class NodeOutcome:
    """How one node's run ended."""

    script: str
    name: str | None = None
    status: NodeStatus = "exited"
    message: str = ""
    exit_code: int | None = None
    exit_signal: int | None = None
    ended_s: float | None = None
    exception: dict | None = None
    findings: list[str] = field(default_factory=list)


@dataclass
class RunResult:
    """What the grader observed in one run, besides the recording itself."""

    recording: Path
    log: Path
    started_s: float
    ended_s: float
    shutdown_requested_s: float | None
    nodes: list[NodeOutcome]
    diagnostics: list[str]
    topics: list[str] = field(default_factory=list)  # what each node published and received, with counts
    wall_s: float = 0.0
    isolation: str = ""  # how the nodes were confined (confine.ISOLATION)

    @property
    def status(self) -> str:
        """The worst node status, for one-word summaries."""
        order = ["protocol_violation", "killed_by_limit", "crashed", "timeout", "killed_after_shutdown",
                 "stopped_at_end", "exited", "not_started"]
        statuses = [n.status for n in self.nodes] or ["exited"]
        return min(statuses, key=order.index)

