"""rclpy.timer: Timer with rcl's schedule (next call advances by whole periods, skipping missed ones) and Rate."""
from __future__ import annotations

import threading

from . import _runtime
from ._rclpy_pybind11 import CONTEXT_INVALID, DESTROYED, InvalidHandle, RCLError
from .clock import Clock
from .clock_type import ClockType
from .exceptions import ROSInterruptException


class Timer:
    """Calls ``callback`` every ``timer_period_ns`` of ``clock`` time, when an executor spins its node."""

    def __init__(self, callback, callback_group, timer_period_ns: int, clock: Clock, *, context=None,
                 autostart: bool = True) -> None:
        from .utilities import get_default_context
        self._context = get_default_context() if context is None else context
        if not self._context.ok():
            raise RCLError("failed to create timer: " + CONTEXT_INVALID)
        self.callback = callback
        self.callback_group = callback_group
        self._clock = clock
        self._period_ns = int(timer_period_ns)
        now = clock._now_ns()
        self._last_call_ns = now
        self._next_call_ns = now + self._period_ns
        self._canceled = not autostart
        self._destroyed = False

    @property
    def handle(self):
        return self

    @property
    def clock(self) -> Clock:
        return self._clock

    @property
    def timer_period_ns(self) -> int:
        return self._period_ns

    @timer_period_ns.setter
    def timer_period_ns(self, value: int) -> None:
        self._check()
        self._period_ns = int(value)
        self._next_call_ns = self._last_call_ns + self._period_ns

    def _check(self) -> None:
        if self._destroyed:
            raise InvalidHandle(DESTROYED)

    def is_ready(self) -> bool:
        self._check()
        return not self._canceled and self._clock._now_ns() >= self._next_call_ns

    def is_canceled(self) -> bool:
        self._check()
        return self._canceled

    def cancel(self) -> None:
        self._check()
        self._canceled = True

    def reset(self) -> None:
        self._check()
        now = self._clock._now_ns()
        self._next_call_ns = now + self._period_ns
        self._canceled = False

    def time_since_last_call(self) -> int:
        self._check()
        return self._clock._now_ns() - self._last_call_ns

    def time_until_next_call(self) -> int | None:
        self._check()
        return None if self._canceled else self._next_call_ns - self._clock._now_ns()

    def wake_world_ns(self) -> int | None:
        """The world time at which this timer becomes ready (None: canceled)."""
        if self._canceled or self._destroyed:
            return None
        if self._clock.clock_type is ClockType.STEADY_TIME:
            return self._next_call_ns - _runtime.STEADY_OFFSET_NS
        if self._clock._ros_time_active:
            return _runtime.clock_wake_ns(self._next_call_ns)
        return self._next_call_ns - (_runtime.system_ns() - _runtime.world_ns())

    def call(self) -> None:
        """rcl_timer_call: advance the schedule by one period, or by as many as were missed."""
        now = self._clock._now_ns()
        self._last_call_ns = now
        self._next_call_ns += self._period_ns
        if self._next_call_ns < now:
            if self._period_ns == 0:
                self._next_call_ns = now
            else:
                ahead = now - self._next_call_ns
                self._next_call_ns += (1 + (ahead - 1) // self._period_ns) * self._period_ns

    def run_callback(self) -> None:
        """The callback, with no argument (Jazzy's rclpy has no TimerInfo; Kilted passes one to an annotated one)."""
        if self.callback is not None:
            self.callback()

    def destroy(self) -> None:
        self._destroyed = True


class Rate:
    """Sleeps until its timer fires; the timer only fires while an executor spins the node (in another thread)."""

    def __init__(self, timer: Timer, *, context) -> None:
        self._timer = timer
        self._is_shutdown = False
        self._is_destroyed = False
        self._event = threading.Event()
        self._num_sleepers = 0
        self._timer.callback = self._event.set
        context.on_shutdown(self._on_shutdown)

    def _on_shutdown(self) -> None:
        self._is_shutdown = True
        self.destroy()

    def destroy(self) -> None:
        self._is_destroyed = True
        self._event.set()

    def _presleep(self) -> None:
        if self._is_shutdown:
            raise ROSInterruptException()
        if self._is_destroyed:
            raise RuntimeError("Rate cannot sleep because it has been destroyed")
        if self._timer._destroyed:
            self.destroy()
            raise InvalidHandle("Rate cannot sleep because the timer has been destroyed")
        self._num_sleepers += 1

    def _postsleep(self) -> None:
        self._num_sleepers -= 1
        if self._num_sleepers == 0:
            self._event.clear()
        if self._is_shutdown:
            self.destroy()
            raise ROSInterruptException()

    def sleep(self) -> None:
        """Block until the timer triggers (forever when nothing spins the node, as in real rclpy)."""
        self._presleep()
        try:
            self._event.wait()
        finally:
            self._postsleep()
