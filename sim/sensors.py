"""The robot's sensors besides odometry: IMU, wheel joint states and a planar laser scanner, read from MuJoCo state.

Each runs only on its own tick (200, 30, 5 Hz on a TurtleBot3), so between ticks they cost nothing. The scanner casts
all its beams in one ``mj_multiRay`` call against the obstacles' geom group only (not the robot, not the floor).
"""
from __future__ import annotations

import math
from collections.abc import Sequence

import mujoco
import numpy as np

from sim.model import OBSTACLE_GROUP, RobotModel
from sim.profile import ImuConfig, JointStatesConfig, ScanConfig
from sim.samples import ImuSample, JointStateSample, ScanSample

_OBSTACLES_ONLY = np.array([1 if group == OBSTACLE_GROUP else 0 for group in range(6)], dtype=np.uint8)
_UINT64 = (1 << 64) - 1


class NoiseStream:
    """Standard normal draws that depend on the seed and the time alone: a Philox stream keyed by the seed, at the time
    as its counter, as ``Philox(key=seed, counter=t_ns)`` draws them. One generator is reused and its state set for
    each call (making a new one costs about 60 µs, five times the draws of a sweep)."""

    def __init__(self, seed: int) -> None:
        self._bits = np.random.Philox(key=seed & _UINT64)
        self._normal = np.random.Generator(self._bits).standard_normal
        # The state set before each call, its counter's first word the time: one dict and two arrays, reused.
        self._counter = np.zeros(4, dtype=np.uint64)
        self._state = {"bit_generator": "Philox",
                       "state": {"counter": self._counter, "key": np.array([seed & _UINT64, 0], dtype=np.uint64)},
                       "buffer": np.zeros(4, dtype=np.uint64), "buffer_pos": 4, "has_uint32": 0, "uinteger": 0}

    def draws(self, t_ns: int, samples: int) -> np.ndarray:
        self._counter[0] = t_ns
        self._bits.state = self._state
        return self._normal(samples)


def noise(seed: int, t_ns: int, samples: int) -> np.ndarray:
    """``samples`` standard normal draws for the sweep at ``t_ns`` of a run with ``seed`` (the same on every call)."""
    return NoiseStream(seed).draws(t_ns, samples)


class _Sensor:
    """What every sensor has: the topic it publishes on."""

    _topic: str
    # Whether a sample depends on an earlier one: such a sensor must observe its last sample time even unheard.
    keeps_state = False

    @property
    def topic(self) -> str:
        return self._topic

    def observe(self, t_ns: int, qvel: Sequence[float]) -> None:
        """A sample time passes unheard: keep whatever the next sample depends on (nothing, for most sensors)."""


class Imu(_Sensor):
    """Orientation, body angular velocity, and proper acceleration from the change of velocity since the last sample.

    The acceleration is the world-frame velocity difference over the sample period plus gravity's reaction, rotated
    into the body frame, so a robot at rest reads +9.81 m/s² on z, as an accelerometer does. It samples at 200 Hz on
    a TurtleBot3, so ``sample`` is plain float arithmetic on the lists the world reads once per tick.
    """

    keeps_state = True

    def __init__(self, config: ImuConfig, model: mujoco.MjModel, t_ns: int, qvel: Sequence[float]) -> None:
        self._topic, self._frame_id = config.topic, config.frame_id
        self._gx, self._gy, self._gz = model.opt.gravity.tolist()
        self._vx, self._vy, self._vz = qvel[:3]
        self._t_ns = t_ns

    def sample(self, t_ns: int, qpos: Sequence[float], qvel: Sequence[float]) -> ImuSample:
        _, _, _, w, x, y, z = qpos[:7]
        vx, vy, vz, wx, wy, wz = qvel[:6]
        dt = (t_ns - self._t_ns) / 1e9
        if dt > 0:
            cx, cy, cz = (vx - self._vx) / dt, (vy - self._vy) / dt, (vz - self._vz) / dt
        else:
            cx = cy = cz = 0.0
        ax, ay, az = cx - self._gx, cy - self._gy, cz - self._gz
        self._vx, self._vy, self._vz, self._t_ns = vx, vy, vz, t_ns
        # R(q)^T a: the world-frame acceleration in body axes
        body = ((1 - 2 * (y * y + z * z)) * ax + 2 * (x * y + w * z) * ay + 2 * (x * z - w * y) * az,
                2 * (x * y - w * z) * ax + (1 - 2 * (x * x + z * z)) * ay + 2 * (y * z + w * x) * az,
                2 * (x * z + w * y) * ax + 2 * (y * z - w * x) * ay + (1 - 2 * (x * x + y * y)) * az)
        return ImuSample(t_ns, self._topic, self._frame_id, (x, y, z, w), (wx, wy, wz), body)

    def observe(self, t_ns: int, qvel: Sequence[float]) -> None:
        """The velocity the next sample differentiates against, as ``sample`` would have kept it."""
        self._vx, self._vy, self._vz = qvel[:3]
        self._t_ns = t_ns


class JointStates(_Sensor):
    """Wheel joint angles (unwrapped, as Gazebo reports a continuous joint) and, if configured, their speeds."""

    def __init__(self, config: JointStatesConfig, robot: RobotModel) -> None:
        self._topic, self._frame_id = config.topic, config.frame_id
        sides = {"left": 0, "right": 1}
        self._qpos = tuple(robot.wheel_qpos[sides[j.wheel]] for j in config.joints)
        self._qvel = tuple(robot.wheel_qvel[sides[j.wheel]] for j in config.joints) if config.velocities else ()
        self._names = tuple(j.name for j in config.joints)

    def sample(self, t_ns: int, qpos: Sequence[float], qvel: Sequence[float]) -> JointStateSample:
        positions = tuple([qpos[i] for i in self._qpos])
        velocities = tuple([qvel[i] for i in self._qvel])
        return JointStateSample(t_ns, self._topic, self._frame_id, self._names, positions, velocities)


class Scanner(_Sensor):
    """A planar laser scanner mounted on the base; with no obstacles in the scenario every beam reads +inf.

    Its noise is a function of the scenario's seed and the sweep's time alone (a Philox stream keyed by the seed,
    at the time as counter), so a sweep reads the same whether or not earlier sweeps were taken.
    """

    def __init__(self, config: ScanConfig, robot: RobotModel, data: mujoco.MjData, seed: int = 0) -> None:
        self._config = config
        self._noise = NoiseStream(seed)
        self._topic = config.topic
        self._model, self._data = robot.model, data
        self._body = robot.base_body
        self._has_obstacles = bool(robot.obstacle_geoms)
        self._increment = (config.angle_max - config.angle_min) / (config.samples - 1)
        angles = config.angle_min + self._increment * np.arange(config.samples)
        self._beams = np.stack((np.cos(angles), np.sin(angles), np.zeros_like(angles)))  # 3 x n, scanner frame
        self._mount = np.array(config.mount)
        # Buffers a sweep reuses (a sweep is a dozen small numpy operations: allocating each result costs more
        # than the arithmetic): the beams turned into the world (3 x n) and laid out beam after beam for the cast.
        self._turned = np.empty((3, config.samples))
        self._directions = np.empty(3 * config.samples)
        self._beam_rows = self._directions.reshape(config.samples, 3)
        self._dist = np.empty(config.samples)
        self._geom = np.empty(config.samples, dtype=np.int32)
        self._miss = np.empty(config.samples, dtype=bool)
        self._beyond = np.empty(config.samples, dtype=bool)
        self._empty = (math.inf,) * config.samples

    def sample(self, t_ns: int, qpos: Sequence[float], qvel: Sequence[float]) -> ScanSample:
        """One sweep from the pose after the last step (the base body's frame in ``data``; ``qpos``/``qvel`` unused),
        with the profile's noise on every beam that hit."""
        c = self._config
        ranges = self._empty
        if self._has_obstacles:
            data, dist, miss, beyond = self._data, self._dist, self._miss, self._beyond
            rotation = data.xmat[self._body].reshape(3, 3)
            origin = data.xpos[self._body] + rotation @ self._mount
            np.matmul(rotation, self._beams, out=self._turned)
            np.copyto(self._beam_rows, self._turned.T)
            mujoco.mj_multiRay(self._model, data, origin, self._directions, _OBSTACLES_ONLY, 1, -1, self._geom,
                               dist, None, c.samples, c.range_max)
            # A beam starts at range_min (Gazebo's ray sensor) and reads inf when it hits nothing before range_max.
            np.less(self._geom, 0, out=miss)
            np.less(dist, c.range_min, out=beyond)
            miss |= beyond
            np.greater(dist, c.range_max, out=beyond)
            miss |= beyond
            if c.noise_stddev:
                noise_m = self._noise.draws(t_ns, c.samples)
                np.multiply(noise_m, c.noise_stddev, out=noise_m)
                dist += noise_m
                # clip as min(max()): the same selection without np.clip's Python wrapper
                np.minimum(np.maximum(dist, c.range_min, out=dist), c.range_max, out=dist)
            np.copyto(dist, math.inf, where=miss)
            ranges = tuple(dist.tolist())
        return ScanSample(t_ns, c.topic, c.frame_id, c.angle_min, c.angle_max, self._increment, c.range_min,
                          c.range_max, ranges)
