"""The robot's sensors besides odometry: IMU, wheel joint states and a planar laser scanner, read from MuJoCo state.

Each runs only on its own tick (200, 30, 5 Hz on a TurtleBot3), so between ticks they cost nothing. The scanner casts
all its beams in one ``mj_multiRay`` call against the obstacles' geom group only (not the robot, not the floor).
"""
from __future__ import annotations

import math

import mujoco
import numpy as np

from sim.model import OBSTACLE_GROUP, RobotModel
from sim.profile import ImuConfig, JointStatesConfig, ScanConfig
from sim.samples import ImuSample, JointStateSample, ScanSample

_OBSTACLES_ONLY = np.array([1 if group == OBSTACLE_GROUP else 0 for group in range(6)], dtype=np.uint8)


class Imu:
    """Orientation, body angular velocity, and proper acceleration from the change of velocity since the last sample.

    The acceleration is the world-frame velocity difference over the sample period plus gravity's reaction, rotated
    into the body frame, so a robot at rest reads +9.81 m/s² on z, as an accelerometer does.
    """

    def __init__(self, config: ImuConfig, model: mujoco.MjModel, t_ns: int, data: mujoco.MjData) -> None:
        self._config = config
        self._gravity = tuple(model.opt.gravity.tolist())
        self._velocity = tuple(data.qvel[:3].tolist())
        self._t_ns = t_ns

    def sample(self, t_ns: int, data: mujoco.MjData) -> ImuSample:
        w, x, y, z = data.qpos[3:7].tolist()
        velocity = tuple(data.qvel[:3].tolist())
        dt = (t_ns - self._t_ns) / 1e9
        change = [(v - u) / dt for v, u in zip(velocity, self._velocity)] if dt > 0 else [0.0, 0.0, 0.0]
        ax, ay, az = (a - g for a, g in zip(change, self._gravity))
        self._velocity, self._t_ns = velocity, t_ns
        # R(q)^T a: the world-frame acceleration in body axes
        body = ((1 - 2 * (y * y + z * z)) * ax + 2 * (x * y + w * z) * ay + 2 * (x * z - w * y) * az,
                2 * (x * y - w * z) * ax + (1 - 2 * (x * x + z * z)) * ay + 2 * (y * z + w * x) * az,
                2 * (x * z + w * y) * ax + 2 * (y * z - w * x) * ay + (1 - 2 * (x * x + y * y)) * az)
        wx, wy, wz = data.qvel[3:6].tolist()
        return ImuSample(t_ns, self._config.topic, self._config.frame_id, (x, y, z, w), (wx, wy, wz), body)


class JointStates:
    """Wheel joint angles (unwrapped, as Gazebo reports a continuous joint) and, if configured, their speeds."""

    def __init__(self, config: JointStatesConfig, robot: RobotModel) -> None:
        self._config = config
        sides = {"left": 0, "right": 1}
        self._qpos = tuple(robot.wheel_qpos[sides[j.wheel]] for j in config.joints)
        self._qvel = tuple(robot.wheel_qvel[sides[j.wheel]] for j in config.joints)
        self._names = tuple(j.name for j in config.joints)

    def sample(self, t_ns: int, data: mujoco.MjData) -> JointStateSample:
        positions = tuple(float(data.qpos[i]) for i in self._qpos)
        velocities = tuple(float(data.qvel[i]) for i in self._qvel) if self._config.velocities else ()
        return JointStateSample(t_ns, self._config.topic, self._config.frame_id, self._names, positions, velocities)


class Scanner:
    """A planar laser scanner mounted on the base; with no obstacles in the scenario every beam reads +inf."""

    def __init__(self, config: ScanConfig, robot: RobotModel) -> None:
        self._config = config
        self._model = robot.model
        self._body = robot.base_body
        self._has_obstacles = bool(robot.obstacle_geoms)
        self._increment = (config.angle_max - config.angle_min) / (config.samples - 1)
        angles = config.angle_min + self._increment * np.arange(config.samples)
        self._beams = np.stack((np.cos(angles), np.sin(angles), np.zeros_like(angles)))  # 3 x n, scanner frame
        self._mount = np.array(config.mount)
        self._directions = np.empty(3 * config.samples)
        self._dist = np.empty(config.samples)
        self._geom = np.empty(config.samples, dtype=np.int32)
        self._empty = (math.inf,) * config.samples

    def sample(self, t_ns: int, data: mujoco.MjData) -> ScanSample:
        c = self._config
        ranges = self._empty
        if self._has_obstacles:
            rotation = data.xmat[self._body].reshape(3, 3)
            origin = data.xpos[self._body] + rotation @ self._mount
            self._directions[:] = (rotation @ self._beams).T.ravel()
            mujoco.mj_multiRay(self._model, data, origin, self._directions, _OBSTACLES_ONLY, 1, -1, self._geom,
                               self._dist, None, c.samples, c.range_max)
            # A beam starts at range_min (Gazebo's ray sensor) and reads inf when it hits nothing before range_max.
            hit = (self._geom >= 0) & (self._dist >= c.range_min) & (self._dist <= c.range_max)
            ranges = tuple(np.where(hit, self._dist, math.inf).tolist())
        return ScanSample(t_ns, c.topic, c.frame_id, c.angle_min, c.angle_max, self._increment, c.range_min,
                          c.range_max, ranges)
