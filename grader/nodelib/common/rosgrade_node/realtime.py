"""The stdlib's other clocks and timed waits follow sim time, as ``time.time``/``time.sleep`` do (timepatch.py).

Patched: ``datetime.datetime.now/today/utcnow`` and ``datetime.date.today``; ``time.localtime/gmtime/ctime/
asctime/strftime`` without a time argument; ``time.clock_gettime(_ns)`` of the wall and monotonic clocks; the
elapsed field of ``os.times()``; the timeouts of ``select.select``, ``select.poll().poll`` and the
``selectors`` classes (so asyncio's event loop sleeps in sim time). A timed wait first polls without blocking; if
nothing is ready it sleeps its timeout in sim time through the scheduler and polls once more, so it burns no wall
time and the recording stays deterministic. A wait without a timeout stays a real wait (only a file descriptor
can end it). Not covered: the C library's clocks through ctypes, ``/proc/uptime``, ``signal.alarm``/``setitimer``.
"""
from __future__ import annotations

import datetime
import os
import select
import selectors
import time

from . import runtime, timepatch

_Datetime = datetime.datetime
_Date = datetime.date


def _sim_seconds() -> float:
    return time.time()  # patched: the node's wall clock at the current sim time


class _RealInstances(type):
    """Instances of the two patched classes are the stdlib's own, so isinstance() holds both ways; a class that
    subclasses them (after the patch) keeps the ordinary rules."""

    def __instancecheck__(cls, obj) -> bool:
        base = _STDLIB.get(cls)
        return isinstance(obj, base) if base is not None else type.__instancecheck__(cls, obj)

    def __subclasscheck__(cls, sub) -> bool:
        base = _STDLIB.get(cls)
        return issubclass(sub, base) if base is not None else type.__subclasscheck__(cls, sub)


class _SimDatetime(_Datetime, metaclass=_RealInstances):
    def __new__(cls, *args, **kwargs):
        return _Datetime(*args, **kwargs) if cls is _SimDatetime else _Datetime.__new__(cls, *args, **kwargs)

    @classmethod
    def now(cls, tz=None):
        return _Datetime.fromtimestamp(_sim_seconds(), tz)

    @classmethod
    def today(cls):
        return _Datetime.fromtimestamp(_sim_seconds())

    @classmethod
    def utcnow(cls):
        return _Datetime.fromtimestamp(_sim_seconds(), datetime.timezone.utc).replace(tzinfo=None)


class _SimDate(_Date, metaclass=_RealInstances):
    def __new__(cls, *args, **kwargs):
        return _Date(*args, **kwargs) if cls is _SimDate else _Date.__new__(cls, *args, **kwargs)

    @classmethod
    def today(cls):
        return _Date.fromtimestamp(_sim_seconds())


_STDLIB = {_SimDatetime: _Datetime, _SimDate: _Date}
for _cls, _name in ((_SimDatetime, "datetime"), (_SimDate, "date")):
    _cls.__name__ = _cls.__qualname__ = _name
    _cls.__module__ = "datetime"


def _with_now(original, position: int):
    """A time.* function whose optional time argument (at ``position``) defaults to sim time."""
    def patched(*args):
        if len(args) <= position or args[position] is None:
            args = (*args[:position], _time_arg(original), *args[position + 1:])
        return original(*args)
    patched.__name__ = original.__name__
    patched.__doc__ = original.__doc__
    return patched


def _time_arg(original):
    seconds = _sim_seconds()
    if original in (_real_strftime, _real_asctime):
        return _real_localtime(seconds)
    return seconds


_real_localtime, _real_gmtime, _real_ctime = time.localtime, time.gmtime, time.ctime
_real_asctime, _real_strftime = time.asctime, time.strftime
_real_select = select.select
_real_poll = select.poll


_real_clock_gettime = time.clock_gettime
_real_clock_gettime_ns = time.clock_gettime_ns
_WALL_CLOCKS = {time.CLOCK_REALTIME}
_MONOTONIC_CLOCKS = {getattr(time, name) for name in ("CLOCK_MONOTONIC", "CLOCK_MONOTONIC_RAW", "CLOCK_BOOTTIME",
                                                         "CLOCK_UPTIME", "CLOCK_HIGHRES") if hasattr(time, name)}


def _clock_gettime_ns(clk_id: int) -> int:
    """The wall and monotonic clocks as time.time_ns/monotonic_ns give them; CPU-time clocks stay real."""
    if clk_id in _WALL_CLOCKS:
        return time.time_ns()
    if clk_id in _MONOTONIC_CLOCKS:
        return time.monotonic_ns()
    return _real_clock_gettime_ns(clk_id)


def _clock_gettime(clk_id: int) -> float:
    if clk_id in _WALL_CLOCKS or clk_id in _MONOTONIC_CLOCKS:
        return _clock_gettime_ns(clk_id) / 1e9
    return _real_clock_gettime(clk_id)


_real_times = os.times


def _times() -> os.times_result:
    """os.times() with its elapsed (real-time) field on the monotonic sim clock; CPU times stay real."""
    real = _real_times()
    return os.times_result((*real[:4], time.monotonic()))


def _managed() -> bool:
    sched = runtime.scheduler
    return sched is not None and sched.holds_token()


def _timed_wait(poll_now, timeout_s: float | None, wait_real):
    """Poll without blocking; if nothing is ready and a timeout is given, sleep it in sim time and poll again."""
    if timeout_s is None or not _managed():
        return wait_real()
    ready = poll_now()
    if _is_empty(ready) and timeout_s > 0:
        runtime.scheduler.sleep_ns(timepatch.seconds_to_ns(timeout_s))
        ready = poll_now()
    return ready


def _is_empty(ready) -> bool:
    return not ready or (isinstance(ready, tuple) and not any(ready))


def _select(rlist, wlist, xlist, timeout=None):
    return _timed_wait(lambda: _real_select(rlist, wlist, xlist, 0), timeout,
                       lambda: _real_select(rlist, wlist, xlist, timeout))


class _SimPoll:
    """select.poll() whose poll(timeout_ms) waits in sim time."""

    def __init__(self) -> None:
        self._poll = _real_poll()

    def register(self, fd, eventmask=select.POLLIN | select.POLLPRI | select.POLLOUT):
        return self._poll.register(fd, eventmask)

    def modify(self, fd, eventmask):
        return self._poll.modify(fd, eventmask)

    def unregister(self, fd):
        return self._poll.unregister(fd)

    def poll(self, timeout=None):
        seconds = None if timeout is None or timeout < 0 else timeout / 1000
        return _timed_wait(lambda: self._poll.poll(0), seconds, lambda: self._poll.poll(timeout))


def _sim_selector(base: type) -> type:
    """A selectors class whose select(timeout) waits in sim time (asyncio's loop uses the default one)."""
    def select_(self, timeout=None):
        seconds = None if timeout is None or timeout < 0 else timeout
        return _timed_wait(lambda: base.select(self, 0), seconds, lambda: base.select(self, timeout))
    return type(base.__name__, (base,), {"select": select_, "__module__": "selectors"})


def install() -> None:
    datetime.datetime = _SimDatetime
    datetime.date = _SimDate
    time.localtime = _with_now(_real_localtime, 0)
    time.gmtime = _with_now(_real_gmtime, 0)
    time.ctime = _with_now(_real_ctime, 0)
    time.asctime = _with_now(_real_asctime, 0)
    time.strftime = _with_now(_real_strftime, 1)
    time.clock_gettime = _clock_gettime
    time.clock_gettime_ns = _clock_gettime_ns
    os.times = _times
    select.select = _select
    select.poll = _SimPoll
    for name in ("SelectSelector", "PollSelector", "EpollSelector", "DevpollSelector", "KqueueSelector"):
        if hasattr(selectors, name):
            setattr(selectors, name, _sim_selector(getattr(selectors, name)))
    selectors.DefaultSelector = getattr(selectors, selectors.DefaultSelector.__name__)
