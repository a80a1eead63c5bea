"""Base drivers: what sits between a robot's velocity command topic and its wheels, one small class per real behaviour.

Every driver runs on the robot's control tick. ``CommandLatch`` holds the last command and applies the base's timeout
(the same rule in every stack: older than the timeout → zero); each ``BaseDriver`` then shapes the (v, ω) it is given
into left/right wheel rim speeds the way its upstream code does.
"""
from __future__ import annotations

import math
from abc import ABC, abstractmethod

from sim.clock import seconds_to_ns
from sim.profile import (
    BaseMode,
    DiffDriveControllerConfig,
    DirectConfig,
    GazeboDiffDriveConfig,
    Geometry,
    OpenCrConfig,
)

WheelSpeeds = tuple[float, float]  # left, right rim speeds in m/s


class CommandLatch:
    """The last velocity command the base received and when; read as zero before the first one and after a timeout."""

    def __init__(self, timeout_ns: int | None) -> None:
        self._timeout_ns = timeout_ns
        self._command = (0.0, 0.0)
        self._received_ns: int | None = None

    def receive(self, t_ns: int, linear: float, angular: float) -> None:
        """Keep (linear.x, angular.z); non-finite values read as 0 (MuJoCo cannot integrate NaN)."""
        self._command = (linear if math.isfinite(linear) else 0.0, angular if math.isfinite(angular) else 0.0)
        self._received_ns = t_ns

    def renew(self, t_ns: int) -> None:
        """The command in force was received again at ``t_ns``, unchanged: only its timeout starts again."""
        self._received_ns = t_ns

    def holds_until_ns(self) -> int | None:
        """The last time the command in force holds without another (None: it never times out)."""
        if self._timeout_ns is None or self._received_ns is None:
            return None
        return self._received_ns + self._timeout_ns

    def command_at(self, t_ns: int) -> tuple[float, float]:
        """The (v, ω) in force at ``t_ns``: the upstream drivers all zero it once ``now - received > timeout``."""
        if self._received_ns is None:
            return (0.0, 0.0)
        if self._timeout_ns is not None and t_ns - self._received_ns > self._timeout_ns:
            return (0.0, 0.0)
        return self._command


def unicycle_to_wheels(linear: float, angular: float, separation: float) -> WheelSpeeds:
    """Rim speeds of the left and right wheel for body twist (v, ω)."""
    return (linear - angular * separation / 2, linear + angular * separation / 2)


class BaseDriver(ABC):
    """Turns the latched (v, ω) into wheel rim speed targets once per control tick of ``dt`` seconds."""

    def __init__(self, geometry: Geometry, dt: float) -> None:
        self.geometry = geometry
        self.dt = dt

    @abstractmethod
    def tick(self, linear: float, angular: float) -> WheelSpeeds:
        """Rim speed targets (m/s) for the next control period."""


class GazeboDiffDrive(BaseDriver):
    """gazebo_ros_diff_drive (ROS 1): no clamp; each wheel's rim speed ramps toward its target at ``wheelAcceleration``.

    The plugin skips the ramp whenever either wheel's *measured* speed is within 0.01 m/s of its target; that quirk is
    not reproduced (the ramp always applies), which makes runs independent of servo noise.
    """

    def __init__(self, geometry: Geometry, dt: float, config: GazeboDiffDriveConfig) -> None:
        super().__init__(geometry, dt)
        self._step = config.wheel_acceleration * dt
        self._rims = (0.0, 0.0)

    def tick(self, linear: float, angular: float) -> WheelSpeeds:
        left, right = unicycle_to_wheels(linear, angular, self.geometry.wheel_separation)
        rim_left, rim_right = self._rims
        step = self._step
        self._rims = (rim_left + min(max(left - rim_left, -step), step),
                      rim_right + min(max(right - rim_right, -step), step))
        return self._rims


class OpenCrFirmware(BaseDriver):
    """TurtleBot3 OpenCR ROS 1 firmware: clamp the twist, clamp each wheel in Dynamixel units, truncate to whole units.

    The truncation is what makes a real Waffle drive a 0.50225 m circle for (0.1, 0.2) instead of 0.5 m.
    The firmware computes in 32-bit floats; doubles are used here (only values within ~1e-7 of a unit boundary differ).
    """

    def __init__(self, geometry: Geometry, dt: float, config: OpenCrConfig) -> None:
        super().__init__(geometry, dt)
        self._config = config
        # VELOCITY_CONSTANT_VALUE / WHEEL_RADIUS: Dynamixel velocity units per m/s at the rim
        self._units_per_mps = 60.0 / (2 * math.pi * geometry.wheel_radius * config.rpm_per_unit)

    def tick(self, linear: float, angular: float) -> WheelSpeeds:
        c = self._config
        linear = min(max(linear, -c.max_linear), c.max_linear)
        angular = min(max(angular, -c.max_angular), c.max_angular)
        limit = c.wheel_limit_units
        rims = unicycle_to_wheels(linear, angular, self.geometry.wheel_separation)
        units = [int(min(max(rim * self._units_per_mps, -limit), limit)) for rim in rims]  # int(): C's (int64_t) cast
        return (units[0] / self._units_per_mps, units[1] / self._units_per_mps)


class DiffDriveController(BaseDriver):
    """ros_controllers diff_drive_controller: speed limiter on v and ω separately (acceleration, then velocity clamp)."""

    def __init__(self, geometry: Geometry, dt: float, config: DiffDriveControllerConfig) -> None:
        super().__init__(geometry, dt)
        self._config = config
        self._last = (0.0, 0.0)

    def tick(self, linear: float, angular: float) -> WheelSpeeds:
        c = self._config
        linear = _limit(linear, self._last[0], c.max_linear_acceleration * self.dt, c.max_linear)
        angular = _limit(angular, self._last[1], c.max_angular_acceleration * self.dt, c.max_angular)
        self._last = (linear, angular)
        return unicycle_to_wheels(linear, angular, self.geometry.wheel_separation)


def _limit(value: float, last: float, max_change: float, max_value: float) -> float:
    """SpeedLimiter::limit without jerk: bound the change from ``last``, then the magnitude."""
    value = last + min(max(value - last, -max_change), max_change)
    return min(max(value, -max_value), max_value)


class DirectDrive(BaseDriver):
    """A base that sets wheel speeds straight from the command, with no clamp or ramp (kobuki_node)."""

    def tick(self, linear: float, angular: float) -> WheelSpeeds:
        return unicycle_to_wheels(linear, angular, self.geometry.wheel_separation)


def make_driver(mode: BaseMode, geometry: Geometry) -> tuple[CommandLatch, BaseDriver]:
    """The latch and driver for ``mode``."""
    dt = 1.0 / mode.control_rate_hz
    config = mode.driver
    driver: BaseDriver
    if isinstance(config, GazeboDiffDriveConfig):
        driver = GazeboDiffDrive(geometry, dt, config)
    elif isinstance(config, OpenCrConfig):
        driver = OpenCrFirmware(geometry, dt, config)
    elif isinstance(config, DiffDriveControllerConfig):
        driver = DiffDriveController(geometry, dt, config)
    else:
        assert isinstance(config, DirectConfig)
        driver = DirectDrive(geometry, dt)
    timeout = None if mode.command_timeout is None else seconds_to_ns(mode.command_timeout)
    return CommandLatch(timeout), driver
