"""rclpy.clock: Clock, ROSClock (sim time once a TimeSource activates it) and the jump-callback API."""
from __future__ import annotations

from enum import IntEnum

from . import _runtime
from .clock_type import ClockType
from .duration import Duration
from .time import Time


# Counts sleep_until calls: an executor blocked before a sleep began wakes to include the sleep's target in its
# wake time (real rclpy's executor takes every /clock message; ours wakes only for the ticks something waits on).
_sleep_epoch = 0


def sleep_epoch() -> int:
    return _sleep_epoch


class ClockChange(IntEnum):
    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class JumpThreshold:
    def __init__(self, *, min_forward: Duration | None, min_backward: Duration | None,
                 on_clock_change: bool = True) -> None:
        if min_forward is not None and min_forward.nanoseconds <= 0:
            raise ValueError("min_forward must be a positive non-zero duration")
        if min_backward is not None and min_backward.nanoseconds >= 0:
            raise ValueError("min_backward must be a negative non-zero duration")
        if min_forward is None and min_backward is None and not on_clock_change:
            raise ValueError("At least one jump threshold must be enabled")
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change


class TimeJump:
    def __init__(self, clock_change: ClockChange, delta: Duration) -> None:
        if not isinstance(clock_change, ClockChange):
            raise TypeError("clock_change must be an instance of rclpy.clock.ClockChange")
        self._clock_change = clock_change
        self._delta = delta

    @property
    def clock_change(self) -> ClockChange:
        return self._clock_change

    @property
    def delta(self) -> Duration:
        return self._delta


class JumpHandle:
    """A registered jump callback. Called when ROS time is activated or deactivated (the only jumps sim time makes
    that a node could act on); forward jumps of the /clock are not reported."""

    def __init__(self, *, clock: Clock, threshold: JumpThreshold, pre_callback=None, post_callback=None) -> None:
        if pre_callback is None and post_callback is None:
            raise ValueError("One of pre_callback or post_callback must be callable")
        if pre_callback is not None and not callable(pre_callback):
            raise ValueError("pre_callback must be callable if given")
        if post_callback is not None and not callable(post_callback):
            raise ValueError("post_callback must be callable if given")
        self._clock: Clock | None = clock
        self.threshold = threshold
        self.pre_callback = pre_callback
        self.post_callback = post_callback
        clock._jump_handles.append(self)

    def unregister(self) -> None:
        if self._clock is not None:
            self._clock._jump_handles.remove(self)
            self._clock = None

    def __enter__(self) -> JumpHandle:
        return self

    def __exit__(self, *exc) -> None:
        self.unregister()


class Clock:
    """A clock of one type. ``Clock(clock_type=ClockType.ROS_TIME)`` makes a ROSClock, as real rclpy does."""

    def __new__(cls, *, clock_type: ClockType = ClockType.SYSTEM_TIME):
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        self = super().__new__(ROSClock if clock_type is ClockType.ROS_TIME else cls)
        self._clock_type = clock_type
        self._jump_handles = []
        self._ros_time_active = False
        self._ros_time_ns = 0
        self._sleep_targets: list[int] = []  # ``until`` of each thread in sleep_until
        return self

    @property
    def clock_type(self) -> ClockType:
        return self._clock_type

    def __repr__(self) -> str:
        return f"Clock(clock_type={self.clock_type.name})"

    def _now_ns(self) -> int:
        """The current value without a call charge (for library code)."""
        if self._clock_type is ClockType.STEADY_TIME:
            return _runtime.steady_ns()
        if self._ros_time_active:
            return self._ros_time_ns
        return _runtime.system_ns()

    def now(self) -> Time:
        """Return the current time of this clock."""
        _runtime.charge()
        return Time(nanoseconds=self._now_ns(), clock_type=self._clock_type)

    def create_jump_callback(self, threshold: JumpThreshold, *, pre_callback=None, post_callback=None) -> JumpHandle:
        return JumpHandle(clock=self, threshold=threshold, pre_callback=pre_callback, post_callback=post_callback)

    def sleep_until(self, until: Time, context=None) -> bool:
        """Block until this clock reaches ``until``: True when it did, False when the context shut down or ROS time
        was activated or deactivated first.

        A ROS clock on sim time only moves while an executor spins its node (as in real rclpy: nobody spinning
        means it never wakes); the spinning executor wakes at the /clock tick that reaches ``until``."""
        global _sleep_epoch
        from .exceptions import NotInitializedException
        from .utilities import get_default_context
        context = get_default_context() if context is None else context
        if not context.ok():
            raise NotInitializedException()
        if until.clock_type != self._clock_type:
            raise ValueError("until's clock type does not match this clock's type")
        sched = _runtime.scheduler()
        ros_time_was_active = self._ros_time_active

        def woken() -> bool:
            return (self._now_ns() >= until.nanoseconds or not context.ok()
                    or self._ros_time_active != ros_time_was_active)

        self._sleep_targets.append(until.nanoseconds)
        _sleep_epoch += 1
        try:
            while not woken():
                deadline = None
                if self._clock_type is ClockType.STEADY_TIME:
                    deadline = until.nanoseconds - _runtime.STEADY_OFFSET_NS
                elif not self._ros_time_active:
                    deadline = until.nanoseconds - (_runtime.system_ns() - _runtime.world_ns())
                sched.block(deadline_ns=deadline, ready=woken)
        finally:
            self._sleep_targets.remove(until.nanoseconds)
        if not context.ok() or self._ros_time_active != ros_time_was_active:
            return False
        return self.now() >= until

    def sleep_for(self, rel_time: Duration, context=None) -> bool:
        return self.sleep_until(self.now() + rel_time, context)


class ROSClock(Clock):
    """The ROS clock: system time until a TimeSource activates ROS time (use_sim_time), then the last /clock
    applied by an executor spinning the node."""

    def __new__(cls):
        return super().__new__(Clock, clock_type=ClockType.ROS_TIME)

    @property
    def ros_time_is_active(self) -> bool:
        return self._ros_time_active

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        if enabled == self._ros_time_active:
            return
        self._ros_time_active = enabled
        change = ClockChange.ROS_TIME_ACTIVATED if enabled else ClockChange.ROS_TIME_DEACTIVATED
        for handle in list(self._jump_handles):
            if handle.threshold.on_clock_change:
                if handle.pre_callback is not None:
                    handle.pre_callback()
                if handle.post_callback is not None:
                    handle.post_callback(TimeJump(change, Duration()))

    def set_ros_time_override(self, time: Time) -> None:
        if not isinstance(time, Time):
            raise TypeError("Time must be specified as rclpy.time.Time")
        self._ros_time_ns = time.nanoseconds
