"""Patches ``time.time/monotonic/perf_counter(_ns)`` and ``time.sleep`` so student timing follows sim time."""
from __future__ import annotations

import operator
import time

from . import runtime

# monotonic/perf_counter = world time plus a constant, so they are never near zero (like a machine's uptime clock).
_MONOTONIC_OFFSET_NS = 1_000 * 1_000_000_000


def _wall_ns() -> int:
    runtime.scheduler.charge()
    return runtime.wall_epoch_ns + runtime.scheduler.world_ns


def _mono_ns() -> int:
    runtime.scheduler.charge()
    return _MONOTONIC_OFFSET_NS + runtime.scheduler.world_ns


def seconds_to_ns(secs) -> int:
    """time.sleep's argument rules: a real number (or an object with __float__/__index__), not negative."""
    if isinstance(secs, int) or hasattr(secs, "__index__") and not hasattr(secs, "__float__"):
        value = float(operator.index(secs))
    elif isinstance(secs, float) or hasattr(secs, "__float__"):
        value = float(secs)
    else:
        raise TypeError(f"'{type(secs).__name__}' object cannot be interpreted as an integer")
    if value != value:
        raise ValueError("Invalid value NaN (not a number)")
    if value < 0:
        raise ValueError("sleep length must be non-negative")
    return round(value * 1e9)


def sleep(secs) -> None:
    """Block for ``secs`` of sim time, waking at the exact nanosecond deadline."""
    try:
        runtime.scheduler.sleep_ns(seconds_to_ns(secs))
    except KeyboardInterrupt as exc:
        if type(exc) is not KeyboardInterrupt:
            raise
        # Ctrl+C without rospy: keep the traceback close to what the C time.sleep gives (no scheduler frames)
        raise exc.with_traceback(None) from None


def install() -> None:
    time.time = lambda: _wall_ns() / 1e9
    time.time_ns = _wall_ns
    time.monotonic = time.perf_counter = lambda: _mono_ns() / 1e9
    time.monotonic_ns = time.perf_counter_ns = _mono_ns
    time.sleep = sleep
