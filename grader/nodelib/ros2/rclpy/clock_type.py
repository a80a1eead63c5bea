"""rclpy.clock_type.ClockType: rcl's clock types, as Jazzy's rclpy defines them (an IntEnum in Python)."""
from __future__ import annotations

from enum import IntEnum


class ClockType(IntEnum):
    """Which clock a time point comes from (values as rcl's).

    Jazzy's ClockType is an IntEnum, so ``str()`` and ``f"{}"`` give ``1`` (Python 3.11) and a format spec is an int's
    (Kilted's is the pybind11 enum itself, which prints ``ClockType.ROS_TIME``)."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3
