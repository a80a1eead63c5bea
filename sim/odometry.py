"""Odometry as each robot computes it (Gazebo's world pose, or wheel-encoder dead reckoning), and the ground truth.

Everything here reads MuJoCo state directly (qpos/qvel after ``mj_step``), in plain Python floats: it runs on every
odometry tick, and a few small-array numpy calls would cost more than the arithmetic.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco

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


def ground_truth(data: mujoco.MjData) -> Estimate:
    """World pose of the base frame and its body-frame twist, from the free joint (qpos 0–6, qvel 0–5)."""
    px, py, pz, w, x, y, z = data.qpos[:7].tolist()
    vx, vy, vz, wx, wy, wz = data.qvel[:6].tolist()  # linear in world axes, angular in body axes
    # rotate the world-frame velocity into the body frame: R(q)^T v
    bx = (1 - 2 * (y * y + z * z)) * vx + 2 * (x * y + w * z) * vy + 2 * (x * z - w * y) * vz
    by = 2 * (x * y - w * z) * vx + (1 - 2 * (x * x + z * z)) * vy + 2 * (y * z + w * x) * vz
    bz = 2 * (x * z + w * y) * vx + 2 * (y * z - w * x) * vy + (1 - 2 * (x * x + y * y)) * vz
    return Estimate((px, py, pz), (x, y, z, w), (bx, by, bz), (wx, wy, wz))


class WorldPoseOdometry:
    """Gazebo's ``odometrySource world``: the pose is the true world pose, so /odom starts at the spawn pose."""

    def update(self, t_ns: int, data: mujoco.MjData) -> Estimate:
        truth = ground_truth(data)
        # gazebo_ros_diff_drive publishes the planar twist only: body-frame vx, vy and world ω_z
        return Estimate(truth.position, truth.orientation, (truth.linear[0], truth.linear[1], 0.0), (0.0, 0.0, truth.angular[2]))


class WheelOdometry:
    """Dead reckoning from wheel joint angles with the *nominal* radius and separation, starting at (0, 0, 0).

    Second-order Runge–Kutta on the heading (as turtlebot3_fake and diff_drive_controller for small turns); the
    twist is the last tick's displacement over its duration. A wheel-radius error or slip therefore shows up as
    odometry drift against the ground truth, as on a real robot.
    """

    def __init__(self, radius: float, separation: float, wheel_qpos: tuple[int, int], t_ns: int, data: mujoco.MjData) -> None:
        self._radius = radius
        self._separation = separation
        self._qpos = wheel_qpos
        self._angles = (float(data.qpos[wheel_qpos[0]]), float(data.qpos[wheel_qpos[1]]))
        self._t_ns = t_ns
        self._x = self._y = self._yaw = 0.0

    def update(self, t_ns: int, data: mujoco.MjData) -> Estimate:
        left, right = float(data.qpos[self._qpos[0]]), float(data.qpos[self._qpos[1]])
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
