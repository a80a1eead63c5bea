"""rospy.sleep, Rate and Timer under sim time, with rospy's exact algorithms (see rospy-behaviour.md (a))."""
from __future__ import annotations

import itertools

import genpy
import rosgrade_channel as ch
from rosgrade_node import runtime

from . import core, rostime
from .exceptions import ROSInterruptException, ROSTimeMovedBackwardsException

_timer_ids = itertools.count(1)


def _clock_wake_ns(target_ns: int) -> int:
    """World time of the first /clock tick at or after ROS time ``target_ns`` (never now: the clock must move)."""
    sched = runtime.scheduler
    target = max(target_ns, sched.world_ns + 1)
    return -(-target // ch.CLOCK_PERIOD_NS) * ch.CLOCK_PERIOD_NS


def _wall_sleep(duration) -> None:
    """rospy sleeps on the wall clock before init_node and without /use_sim_time: here the patched time.sleep."""
    if isinstance(duration, genpy.Duration):
        duration = duration.to_sec()
    if duration < 0:
        return
    runtime.scheduler.sleep_ns(round(duration * 1e9))


def sleep(duration) -> None:
    """Sleep in ROS time: wait for a non-zero clock, then for the first /clock >= start + duration.

    Raises ROSInterruptException("ROS shutdown request") when the node is (or gets) shut down, even if the deadline
    has passed, and ROSTimeMovedBackwardsException if the clock went back.
    """
    if not rostime.is_initialized() or rostime.is_wallclock():
        _wall_sleep(duration)  # as rospy's wallsleep: no shutdown check, a negative duration returns at once
        return
    sched = runtime.scheduler
    if not isinstance(duration, genpy.Duration):
        duration = rostime.Duration.from_sec(duration)
    start = rostime._now()
    while start.is_zero() and not core._shutdown_flag:
        sched.block(deadline_ns=_clock_wake_ns(1))
        start = rostime._now()
    deadline = start + duration
    deadline_ns = deadline.to_nsec()
    blocked = False
    while sched.clock_ns < deadline_ns and sched.clock_ns >= start.to_nsec() and not core._shutdown_flag:
        blocked = True
        sched.block(deadline_ns=_clock_wake_ns(deadline_ns), ready=lambda: core._shutdown_flag)
    if not blocked:
        sched.charge()
    now = rostime._now()
    if now < start:
        raise ROSTimeMovedBackwardsException((start - now).to_sec())
    core.raise_if_shutdown("ROS shutdown request")


class Rate:
    """Fixed-rate loop helper: the anchor advances by one period per sleep, catches up, and resets when > 2 behind."""

    def __init__(self, hz, reset: bool = False) -> None:
        self.last_time = rostime._now()
        self.sleep_dur = rostime.Duration(0, int(1e9 / hz))
        self._reset = reset

    def _remaining(self, curr_time: rostime.Time) -> rostime.Duration:
        if self.last_time > curr_time:
            self.last_time = curr_time
        return self.sleep_dur - (curr_time - self.last_time)

    def remaining(self) -> rostime.Duration:
        """Time left in the current period (negative when late)."""
        return self._remaining(rostime._now())

    def sleep(self) -> None:
        curr_time = rostime._now()
        try:
            sleep(self._remaining(curr_time))
        except ROSTimeMovedBackwardsException:
            if not self._reset:
                raise
            self.last_time = rostime._now()
            return
        self.last_time = self.last_time + self.sleep_dur
        if curr_time - self.last_time > self.sleep_dur * 2:
            self.last_time = curr_time


class TimerEvent:
    """What a Timer callback receives."""

    def __init__(self, last_expected, last_real, current_expected, current_real, last_duration) -> None:
        self.last_expected = last_expected
        self.last_real = last_real
        self.current_expected = current_expected
        self.current_real = current_real
        self.last_duration = last_duration


class Timer:
    """Calls ``callback(TimerEvent)`` every ``period`` of ROS time in its own (managed) thread."""

    def __init__(self, period: genpy.Duration, callback, oneshot: bool = False, reset: bool = False) -> None:
        self._period = period
        self._callback = callback
        self._oneshot = oneshot
        self._reset = reset
        self._shutdown = False
        self.name = "Timer-%d" % next(_timer_ids)
        runtime.scheduler.spawn(self.name, self.run)

    def shutdown(self) -> None:
        """Stop the timer (takes effect before its next callback)."""
        self._shutdown = True

    def run(self) -> None:
        sched = runtime.scheduler
        rate = Rate(1.0 / self._period.to_sec(), reset=self._reset)
        current_expected = rostime._now() + self._period
        last_expected = last_real = last_duration = None
        while not core._shutdown_flag and not self._shutdown:
            try:
                rate.sleep()
            except ROSInterruptException:
                if core._shutdown_flag:
                    break
                raise
            if self._shutdown:
                break
            current_real = rostime._now()
            started_ns = sched.world_ns
            self._callback(TimerEvent(last_expected, last_real, current_expected, current_real, last_duration))
            if self._oneshot:
                break
            last_duration = (sched.world_ns - started_ns) / 1e9
            last_expected, last_real = current_expected, current_real
            current_expected = current_expected + self._period
