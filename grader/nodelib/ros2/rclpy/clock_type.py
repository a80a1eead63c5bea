"""rclpy.clock_type.ClockType: rcl's clock types, printed as real rclpy's pybind11 enum prints them."""
from __future__ import annotations

from enum import IntEnum


class ClockType(IntEnum):
    """Which clock a time point comes from (values as rcl's).

    Real rclpy's ClockType is a pybind11 enum: ``str()`` and ``f"{}"`` give ``ClockType.ROS_TIME`` (an IntEnum
    prints ``1`` since Python 3.11) and a format spec is a TypeError."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3

    def __str__(self) -> str:
        return f"ClockType.{self.name}"

    def __format__(self, spec: str) -> str:
        if spec:
            raise TypeError("unsupported format string passed to rclpy._rclpy_pybind11.ClockType.__format__")
        return str(self)
