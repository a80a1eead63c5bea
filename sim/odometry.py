"""Odometry as each robot computes it (Gazebo's world pose, or wheel-encoder dead reckoning), and the ground truth.

Everything here reads the MuJoCo state as plain Python lists (``qpos``/``qvel`` after ``mj_step``, read once per tick
by the world): it runs on every odometry tick, and a few small-array numpy calls would cost more than the arithmetic.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from sim.samples import Quat, Vec3


@dataclass(frozen=True, slots=True)
class Estimate:
    """A pose and body twist (ROS conventions: quaternion x, y, z, w; twist in the child frame)."""

    position: Vec3
    orientation: Quat
    linear: Vec3
    angular: Vec3


def yaw_quaternion(yaw: float) -> Quat:
    """The ROS-order quaternion of a rotation by ``yaw`` about z."""
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def quaternion_yaw(q: Quat) -> float:
    """Heading of a ROS-order quaternion."""
    x, y, z, w = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def ground_truth(qpos: Sequence[float], qvel: Sequence[float]) -> Estimate:
    """World pose of the base frame and its body-frame twist, from the free joint (qpos 0–6, qvel 0–5)."""
    px, py, pz, w, x, y, z = qpos[:7]
    vx, vy, vz, wx, wy, wz = qvel[:6]  # linear in world axes, angular in body axes
    # rotate the world-frame velocity into the body frame: R(q)^T v
    bx = (1 - 2 * (y * y + z * z)) * vx + 2 * (x * y + w * z) * vy + 2 * (x * z - w * y) * vz
    by = 2 * (x * y - w * z) * vx + (1 - 2 * (x * x + z * z)) * vy + 2 * (y * z + w * x) * vz
    bz = 2 * (x * z + w * y) * vx + 2 * (y * z - w * x) * vy + (1 - 2 * (x * x + y * y)) * vz
    return Estimate((px, py, pz), (x, y, z, w), (bx, by, bz), (wx, wy, wz))


class WorldPoseOdometry:
    """Gazebo's ``odometrySource world``: the pose is the true world pose, so /odom starts at the spawn pose."""

    def update(self, t_ns: int, qpos: Sequence[float], qvel: Sequence[float]) -> Estimate:
        truth = ground_truth(qpos, qvel)
        # gazebo_ros_diff_drive publishes the planar twist only: body-frame vx, vy and world ω_z
        return Estimate(truth.position, truth.orientation, (truth.linear[0], truth.linear[1], 0.0), (0.0, 0.0, truth.angular[2]))


class WheelOdometry:
    """Dead reckoning from wheel joint angles with the *nominal* radius and separation, starting at (0, 0, 0).

    Second-order Runge–Kutta on the heading (as turtlebot3_fake and diff_drive_controller for small turns); the
    twist is the last tick's displacement over its duration. A wheel-radius error or slip therefore shows up as
    odometry drift against the ground truth, as on a real robot.
    """

    def __init__(self, radius: float, separation: float, wheel_qpos: tuple[int, int], t_ns: int,
                 qpos: Sequence[float]) -> None:
        self._radius = radius
        self._separation = separation
        self._left, self._right = wheel_qpos
        self._angles = (qpos[self._left], qpos[self._right])
        self._t_ns = t_ns
        self._x = self._y = self._yaw = 0.0

    def update(self, t_ns: int, qpos: Sequence[float], qvel: Sequence[float]) -> Estimate:
        left, right = qpos[self._left], qpos[self._right]
        d_left = (left - self._angles[0]) * self._radius
        d_right = (right - self._angles[1]) * self._radius
        self._angles = (left, right)
        ds = (d_left + d_right) / 2
        dyaw = (d_right - d_left) / self._separation
        heading = self._yaw + dyaw / 2
        self._x += ds * math.cos(heading)
        self._y += ds * math.sin(heading)
        self._yaw += dyaw
        dt = (t_ns - self._t_ns) / 1e9
        self._t_ns = t_ns
        v, w = (ds / dt, dyaw / dt) if dt > 0 else (0.0, 0.0)
        return Estimate((self._x, self._y, 0.0), yaw_quaternion(self._yaw), (v, 0.0, 0.0), (0.0, 0.0, w))
