"""Plain records the world emits while it advances; the grader turns them into ROS messages.

They carry no ROS types so that `sim/` stays independent of the messaging layer.
"""
from __future__ import annotations

from dataclasses import dataclass

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]  # x, y, z, w (ROS order)


@dataclass(frozen=True, slots=True)
class OdometrySample:
    """What the robot publishes on its odometry topic at ``t_ns`` (nav_msgs/Odometry fields)."""

    t_ns: int
    topic: str
    frame_id: str
    child_frame_id: str
    position: Vec3
    orientation: Quat
    linear: Vec3  # body-frame twist
    angular: Vec3
    pose_covariance: tuple[float, ...]  # 36 values
    twist_covariance: tuple[float, ...]  # 36 values


@dataclass(frozen=True, slots=True)
class TransformSample:
    """One transform the robot stack broadcasts on /tf at ``t_ns``."""

    t_ns: int
    topic: str
    frame_id: str
    child_frame_id: str
    translation: Vec3
    rotation: Quat


@dataclass(frozen=True, slots=True)
class GroundTruthSample:
    """The true world pose and body twist of the robot base at ``t_ns`` (recorded, never shown to the node)."""

    t_ns: int
    topic: str
    frame_id: str
    child_frame_id: str
    position: Vec3
    orientation: Quat
    linear: Vec3
    angular: Vec3


@dataclass(frozen=True, slots=True)
class CommandSample:
    """A velocity command the scripted driver gave the robot at ``t_ns`` on ``topic``."""

    t_ns: int
    topic: str
    linear: Vec3
    angular: Vec3


@dataclass(frozen=True, slots=True)
class ImuSample:
    """What the IMU publishes at ``t_ns`` (sensor_msgs/Imu fields; covariances are zero: a noise-free sensor)."""

    t_ns: int
    topic: str
    frame_id: str
    orientation: Quat
    angular_velocity: Vec3  # body frame
    linear_acceleration: Vec3  # body frame, proper acceleration (+g up at rest)


@dataclass(frozen=True, slots=True)
class JointStateSample:
    """Wheel joint angles (and speeds, if the robot publishes them) at ``t_ns`` (sensor_msgs/JointState)."""

    t_ns: int
    topic: str
    frame_id: str
    names: tuple[str, ...]
    positions: tuple[float, ...]
    velocities: tuple[float, ...]  # empty when the publisher leaves them out


@dataclass(frozen=True, slots=True)
class ScanSample:
    """One sweep of a planar laser scanner at ``t_ns`` (sensor_msgs/LaserScan; inf where a beam hits nothing)."""

    t_ns: int
    topic: str
    frame_id: str
    angle_min: float
    angle_max: float
    angle_increment: float
    range_min: float
    range_max: float
    ranges: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class ContactSample:
    """The robot touching one obstacle at ``t_ns``: which (its name, or kind and number), the deepest contact point in
    the world frame and how far the two overlap there (m). Recorded for the grader only, never sent to a node."""

    t_ns: int
    topic: str
    obstacle: str
    position: Vec3
    depth: float


@dataclass(frozen=True, slots=True)
class TurtlePoseSample:
    """Where a turtlesim turtle is at ``t_ns`` (turtlesim/Pose: canvas metres, y up, radians)."""

    t_ns: int
    topic: str
    x: float
    y: float
    theta: float
    linear_velocity: float
    angular_velocity: float


@dataclass(frozen=True, slots=True)
class ColorSample:
    """The canvas colour under a turtlesim turtle at ``t_ns`` (turtlesim/Color)."""

    t_ns: int
    topic: str
    r: int
    g: int
    b: int


@dataclass(frozen=True, slots=True)
class LogSample:
    """A line the world itself logs on /rosout at ``t_ns`` (level as in rosgraph_msgs/Log: 4 is WARN)."""

    t_ns: int
    topic: str
    level: int
    name: str
    msg: str


# rclcpp::QoS(KeepLast(n)): the (reliability, durability) of a world's ROS 2 endpoint unless it declares another.
DEFAULT_QOS = ("RELIABLE", "VOLATILE")


@dataclass(frozen=True, slots=True)
class WorldTopic:
    """A topic the world publishes: its message type, rate, and who may see it.

    ``to_nodes``: delivered to subscribing nodes (False: recorded for the grader only, like the ground truth).
    ``shared``: nodes may publish there too (``/tf``); on any other world topic a node's messages are ignored.
    ``qos``: what a ROS 2 node's subscription must be compatible with (rosgrade_qos names).
    ``node``: the world's node that publishes it, when the world stands for several ('': its ``node_name``).
    """

    topic: str
    type: str
    rate_hz: float
    to_nodes: bool = True
    shared: bool = False
    qos: tuple[str, str] = DEFAULT_QOS  # ROS 2: (reliability, durability) the world's publisher offers
    node: str = ""


@dataclass(frozen=True, slots=True)
class WorldService:
    """A service the world serves: its resolved name and its srv type (``turtlesim/Spawn``)."""

    name: str
    type: str


@dataclass(frozen=True, slots=True)
class ServiceResult:
    """What a world's service handler returned: success and the response's field values (plain Python values),
    plus what the world logged while handling it (``LogSample`` on /rosout, at the call's time).

    ``ok`` False is a handler that failed: a roscpp callback returning false (``error`` empty, as roscpp sends no
    text then) or throwing (``error`` is the exception's text, which roscpp sends to the caller).
    """

    ok: bool
    response: dict[str, object]
    samples: tuple[LogSample, ...] = ()
    error: str = ""


Sample = (OdometrySample | TransformSample | GroundTruthSample | CommandSample | ImuSample | JointStateSample
          | ScanSample | ContactSample | TurtlePoseSample | ColorSample | LogSample)
