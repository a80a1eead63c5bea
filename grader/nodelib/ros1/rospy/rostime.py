"""rospy.Time / rospy.Duration and the node's ROS clock (always /use_sim_time: the last /clock the node received)."""
from __future__ import annotations

import genpy

from rosgrade_node import runtime

from .exceptions import ROSInitException

_initialized = False
_wallclock = False
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


def set_initialized(wallclock: bool = False) -> None:
    """init_node chose the node's clock: sim time (Time(0) until the first /clock) when /use_sim_time is set, as
    with Gazebo; otherwise the wall clock, as with turtlesim, which publishes no /clock."""
    global _initialized, _wallclock
    _initialized, _wallclock = True, wallclock


def is_initialized() -> bool:
    return _initialized


def is_wallclock() -> bool:
    """Whether the node's ROS time is the wall clock (no /use_sim_time): its patched time.time()."""
    return _wallclock


def _now() -> Time:
    """The cached ROS time (no call charge; for library code)."""
    global _cached, _cached_ns
    if not _initialized:
        raise ROSInitException("time is not initialized. Have you called init_node()?")
    sched = runtime.scheduler
    ns = runtime.wall_epoch_ns + sched.world_ns if _wallclock else sched.clock_ns
    if ns != _cached_ns:
        _cached, _cached_ns = Time(ns // 1000000000, ns % 1000000000), ns
    return _cached


def get_rostime() -> Time:
    charge()
    return _now()


def get_time() -> float:
    """The current ROS time in float seconds (0.0 before the first /clock)."""
    return get_rostime().to_sec()
