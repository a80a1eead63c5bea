"""rospy.Time / rospy.Duration and the node's ROS clock (always /use_sim_time: the last /clock the node received)."""
from __future__ import annotations

import genpy

from rosgrade_node import runtime

from .exceptions import ROSInitException

_initialized = False
_cached: Time | None = None
_cached_ns = -1


class Duration(genpy.Duration):
    """A genpy.Duration whose repr says rospy."""

    __slots__: list[str] = []

    def __repr__(self) -> str:
        return "rospy.Duration[%d]" % self.to_nsec()


class Time(genpy.Time):
    """A genpy.Time with ``now()``; ``Time - Time`` stays a genpy.Duration, as in rospy."""

    __slots__: list[str] = []

    def __repr__(self) -> str:
        return "rospy.Time[%d]" % self.to_nsec()

    @staticmethod
    def now() -> Time:
        """The current ROS time: the same object until the next /clock arrives."""
        charge()
        return _now()


def charge() -> None:
    """Account a non-blocking library call (see rosgrade_node.scheduler; no-op without a grader)."""
    if runtime.scheduler is not None:
        runtime.scheduler.charge()


def set_initialized() -> None:
    """init_node switched the node to sim time: Time(0) until the first /clock."""
    global _initialized
    _initialized = True


def is_initialized() -> bool:
    return _initialized


def is_wallclock() -> bool:
    """rosgrade nodes always run under /use_sim_time."""
    return False


def _now() -> Time:
    """The cached ROS time (no call charge; for library code)."""
    global _cached, _cached_ns
    if not _initialized:
        raise ROSInitException("time is not initialized. Have you called init_node()?")
    ns = runtime.scheduler.clock_ns
    if ns != _cached_ns:
        _cached, _cached_ns = Time(ns // 1000000000, ns % 1000000000), ns
    return _cached


def get_rostime() -> Time:
    charge()
    return _now()


def get_time() -> float:
    """The current ROS time in float seconds (0.0 before the first /clock)."""
    return get_rostime().to_sec()
