"""What a launch file starts, as plain data: the nodes, the parameters and the simulated world it asks for."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path


class LaunchError(Exception):
    """A launch file cannot be used as it is; the message names the file and line and says what to change."""

    def __init__(self, message: str, located: bool = False) -> None:
        super().__init__(message)
        self.located = located  # the message already starts with the file and line


@dataclass(frozen=True)
class Where:
    """A place in a launch file, for messages."""

    file: Path
    line: int

    def __str__(self) -> str:
        return f"{self.file.name} line {self.line}"


@dataclass(frozen=True)
class LaunchNode:
    """One ``<node>``, with every substitution done: what roslaunch would start."""

    pkg: str
    type: str
    name: str
    namespace: str  # global, with a trailing slash: "/" or "/robot1/"
    args: tuple[str, ...]
    remaps: tuple[tuple[str, str], ...]
    output: str  # "log" or "screen"
    required: bool
    respawn: bool
    where: Where

    @property
    def full_name(self) -> str:
        """The node's resolved name, e.g. ``/robot1/mover``."""
        return self.namespace + self.name


@dataclass(frozen=True)
class WorldLaunch:
    """A known simulator launch file (``turtlebot3_gazebo``, ``husky_gazebo``) mapped onto a rosgrade robot."""

    package: str
    file: str
    robot: str
    x: float
    y: float
    yaw: float
    where: Where


@dataclass
class Launch:
    """Everything one launch file (and what it includes) asks for."""

    file: Path
    args: dict[str, str | None] = field(default_factory=dict)  # the top-level file's args and their values
    nodes: list[LaunchNode] = field(default_factory=list)
    params: dict[str, object] = field(default_factory=dict)
    worlds: list[WorldLaunch] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # things the grader ignores or models loosely, with the place
