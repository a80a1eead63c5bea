"""Array views of a recording that the metrics score: pose/twist series, commands, transforms, output lines."""
from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from grader import exact


@dataclass(frozen=True)
class TimeSeries:
    """A planar pose and body twist over time: t in seconds, yaw in (-pi, pi]."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    yaw: np.ndarray
    vx: np.ndarray
    wz: np.ndarray
    topic: str = ""

    def __len__(self) -> int:
        return len(self.t)


@dataclass(frozen=True)
class CommandSeries:
    """Every velocity command received: t in seconds, linear and angular as (N, 3), with topic and callerid."""

    t: np.ndarray
    linear: np.ndarray
    angular: np.ndarray
    topic: np.ndarray  # str objects
    callerid: np.ndarray  # str objects ("" when the format has none)
    origin: np.ndarray | None = None  # str objects: 'world' | 'grader' | 'node'; None when the recording does not say

    def __len__(self) -> int:
        return len(self.t)

    @property
    def vx(self) -> np.ndarray:
        """Forward speed commands."""
        return self.linear[:, 0]

    @property
    def wz(self) -> np.ndarray:
        """Yaw rate commands."""
        return self.angular[:, 2]


@dataclass(frozen=True)
class TransformSeries:
    """Every transform in /tf messages: header stamp t (s), frames, translation (N, 3), rotation xyzw (N, 4)."""

    t: np.ndarray
    frame_id: np.ndarray
    child_frame_id: np.ndarray
    translation: np.ndarray
    rotation: np.ndarray

    def __len__(self) -> int:
        return len(self.t)


class OutputLine(NamedTuple):
    """One line the node printed or logged (the documented ``(t, stream, text)`` contract)."""

    t: float
    stream: str  # 'stdout' | 'stderr' | 'rosout'
    text: str


class LogLine(NamedTuple):
    """One rosgraph_msgs/Log message on /rosout: level is 1 DEBUG, 2 INFO, 4 WARN, 8 ERROR, 16 FATAL."""

    t: float
    level: int
    name: str
    msg: str
    file: str
    function: str
    line: int


class TopicInfo(NamedTuple):
    """One (topic, callerid) of a recording and how many messages it holds."""

    topic: str
    type: str  # ROS 1 spelling, e.g. geometry_msgs/Twist
    callerid: str
    count: int
    origin: str = ""  # 'world' | 'grader' | 'node' in rosgrade's recordings; "" when the file does not say


def yaw_from_quaternion(qx: np.ndarray, qy: np.ndarray, qz: np.ndarray, qw: np.ndarray) -> np.ndarray:
    """Heading (rotation about z) of x y z w quaternions, in (-pi, pi]."""
    yaw = exact.atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))
    return np.where(yaw == -np.pi, np.pi, yaw)


def seconds(t_ns: np.ndarray | list[int]) -> np.ndarray:
    """Integer nanoseconds to float64 seconds."""
    return np.asarray(t_ns, dtype=np.int64) / 1e9
