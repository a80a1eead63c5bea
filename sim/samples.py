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
    frame_id: str
    child_frame_id: str
    translation: Vec3
    rotation: Quat


@dataclass(frozen=True, slots=True)
class GroundTruthSample:
    """The true world pose and body twist of the robot base at ``t_ns`` (recorded, never shown to the node)."""

    t_ns: int
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


Sample = OdometrySample | TransformSample | GroundTruthSample | CommandSample
