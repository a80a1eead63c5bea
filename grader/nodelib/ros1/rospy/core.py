"""Node state shared by rospy: initialization, the shutdown sequence and logging (formats and streams as rospy)."""
from __future__ import annotations

import collections.abc
import os
import sys
import traceback
from collections.abc import Callable

import rosgrade_channel as ch
from rosgrade_node import excepthook, runtime

from . import names, rostime
from .exceptions import ROSInterruptException

DEBUG, INFO, WARN, ERROR, FATAL = 1, 2, 4, 8, 16
_LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}

_initialized = False
_initializing = False  # init_node is registering the node (topics created now are announced at once)
_log_level = INFO
_client_hooks: list[Callable[[], object]] = []
# Run with the reason once the client hooks are done and is_shutdown() is True (topics close here).
_internal_hooks: list[Callable[[str], None]] = []
_in_shutdown = False
_shutdown_flag = False


# -- initialization ------------------------------------------------------------------------------------------------
def is_initialized() -> bool:
    return _initialized


def is_initializing() -> bool:
    return _initializing


def set_initializing(log_level: int | None) -> None:
    """init_node has configured logging and is registering the node (rospy's start_node)."""
    global _initializing, _log_level
    _initializing = True
    _log_level = log_level if log_level is not None else INFO


def set_initialized(log_level: int | None) -> None:
    global _initialized, _log_level
    _initialized = True
    _log_level = log_level if log_level is not None else INFO


# -- shutdown --------------------------------------------------------------------------------------------------------
def is_shutdown() -> bool:
    """True once the shutdown sequence has run its hooks (False while they run)."""
    rostime.charge()
    return _shutdown_flag


def is_shutdown_requested() -> bool:
    return _in_shutdown or _shutdown_flag


def on_shutdown(h: Callable[[], object]) -> None:
    """Register a no-argument hook run at shutdown; after shutdown it runs at once."""
    if not callable(h):
        raise TypeError("shutdown hook [%s] must be a function or callable object: %s" % (h, type(h)))
    if _shutdown_flag:
        h()
        return
    _client_hooks.append(h)


def add_internal_shutdown_hook(h: Callable[[str], None]) -> None:
    _internal_hooks.append(h)


def signal_shutdown(reason: str) -> None:
    """rospy's shutdown sequence: client hooks (is_shutdown() still False), then is_shutdown() True, topics closed.

    Runs synchronously in the calling thread; a second call is a no-op. Hook errors are printed and swallowed.
    """
    global _in_shutdown, _shutdown_flag
    if _shutdown_flag or _in_shutdown:
        return
    _in_shutdown = True
    i = 0
    while i < len(_client_hooks):  # a hook may register another one; it runs too
        hook = _client_hooks[i]
        i += 1
        try:
            hook()
        except BaseException:
            traceback.print_exc()
            excepthook.report_current("shutdown hook")
    _client_hooks.clear()
    _shutdown_flag = True
    for internal in _internal_hooks:
        internal(reason)


def raise_if_shutdown(message: str) -> None:
    if _shutdown_flag:
        raise ROSInterruptException(message)


# -- logging ---------------------------------------------------------------------------------------------------------
def format_message(msg: object, args: tuple) -> str:
    """Python logging's rule: ``str(msg) % args`` when there are args (a single non-empty mapping is used as is)."""
    text = str(msg)
    if args:
        if len(args) == 1 and isinstance(args[0], collections.abc.Mapping) and args[0]:
            args = args[0]
        text = text % args
    return text


def format_line(level: int, text: str, wall: float, sim: float | None) -> str:
    """rospy's console line under sim time, ``[INFO] [wall, sim]: text``; ``[INFO] [wall]: text`` while init_node
    has not yet set up the ROS clock (``sim`` None)."""
    if sim is None:
        return "[%s] [%f]: %s\n" % (_LEVEL_NAMES[level], wall, text)
    return "[%s] [%f, %f]: %s\n" % (_LEVEL_NAMES[level], wall, sim, text)


def _emit(level: int, msg: object, args: tuple, frame) -> None:
    if not (_initialized or _initializing):
        # rospy's logger has no handler yet: Python's last resort prints WARN and above bare on stderr
        if level >= WARN:
            sys.stderr.write(format_message(msg, args) + "\n")
        return
    if level < _log_level:
        return
    text = format_message(msg, args)
    # rosgraph's stream handler adds the ROS time only when it is not the wall clock
    sim = runtime.scheduler.clock_ns / 1e9 if rostime.is_initialized() and not rostime.is_wallclock() else None
    (sys.stdout if level <= INFO else sys.stderr).write(format_line(level, text, runtime.wall_time(), sim))
    if runtime.link is not None and _initialized:  # rospy's /rosout publisher comes up once init_node has registered
        runtime.link.send_json(ch.LOG, {"level": level, "msg": text, "name": names.get_name(),
                                        "file": frame.f_code.co_filename, "function": frame.f_code.co_name,
                                        "line": frame.f_lineno})


def _call_site(frame) -> tuple:
    """Throttle/once key: the calling file, line and bytecode offset (so a helper function shares one key).

    The file as inspect.getabsfile names it, without importing inspect (and ast, dis) into every node."""
    return (os.path.normcase(os.path.abspath(frame.f_code.co_filename)), frame.f_lineno, frame.f_lasti)


_once_seen: set[tuple] = set()
_throttle_last: dict[tuple, rostime.Time] = {}
_identical_last: dict[tuple, str] = {}


def _throttle_elapsed(key: tuple, period: float) -> bool:
    """rospy's LoggingThrottle: true when ROS time advanced strictly more than ``period`` since the last print."""
    global _throttle_last
    now = rostime._now()
    last = _throttle_last.get(key)
    if last is None or (now - last) > rostime.Duration(period):
        _throttle_last[key] = now
        return True
    if last > now:
        _throttle_last = {key: now}
    return False


def _log(level: int, msg: object, args: tuple, kwargs: dict, *, throttle: float | None = None,
         identical: bool = False, once: bool = False) -> None:
    """Common body of the public log functions; the student's frame is two levels up."""
    kwargs.pop("logger_name", None)
    rostime.charge()
    frame = sys._getframe(2)
    if once:
        key = _call_site(frame)
        if key in _once_seen:
            return
        _once_seen.add(key)
    elif identical:
        key = _call_site(frame)
        elapsed = _throttle_elapsed(key, throttle) if throttle is not None else False
        text = str(msg)  # rospy compares the texts' MD5 digests: comparing the texts is the same test
        changed = _identical_last.get(key) != text
        _identical_last[key] = text
        if not (changed or elapsed):
            return
    elif throttle:
        if not _throttle_elapsed(_call_site(frame), throttle):
            return
    _emit(level, msg, args, frame)


def logdebug(msg, *args, **kwargs):
    _log(DEBUG, msg, args, kwargs)


def loginfo(msg, *args, **kwargs):
    _log(INFO, msg, args, kwargs)


def logwarn(msg, *args, **kwargs):
    _log(WARN, msg, args, kwargs)


def logerr(msg, *args, **kwargs):
    _log(ERROR, msg, args, kwargs)


def logfatal(msg, *args, **kwargs):
    _log(FATAL, msg, args, kwargs)


def logdebug_throttle(period, msg, *args, **kwargs):
    _log(DEBUG, msg, args, kwargs, throttle=period)


def loginfo_throttle(period, msg, *args, **kwargs):
    _log(INFO, msg, args, kwargs, throttle=period)


def logwarn_throttle(period, msg, *args, **kwargs):
    _log(WARN, msg, args, kwargs, throttle=period)


def logerr_throttle(period, msg, *args, **kwargs):
    _log(ERROR, msg, args, kwargs, throttle=period)


def logfatal_throttle(period, msg, *args, **kwargs):
    _log(FATAL, msg, args, kwargs, throttle=period)


def logdebug_throttle_identical(period, msg, *args, **kwargs):
    _log(DEBUG, msg, args, kwargs, throttle=period, identical=True)


def loginfo_throttle_identical(period, msg, *args, **kwargs):
    _log(INFO, msg, args, kwargs, throttle=period, identical=True)


def logwarn_throttle_identical(period, msg, *args, **kwargs):
    _log(WARN, msg, args, kwargs, throttle=period, identical=True)


def logerr_throttle_identical(period, msg, *args, **kwargs):
    _log(ERROR, msg, args, kwargs, throttle=period, identical=True)


def logfatal_throttle_identical(period, msg, *args, **kwargs):
    _log(FATAL, msg, args, kwargs, throttle=period, identical=True)


def logdebug_once(msg, *args, **kwargs):
    _log(DEBUG, msg, args, kwargs, once=True)


def loginfo_once(msg, *args, **kwargs):
    _log(INFO, msg, args, kwargs, once=True)


def logwarn_once(msg, *args, **kwargs):
    _log(WARN, msg, args, kwargs, once=True)


def logerr_once(msg, *args, **kwargs):
    _log(ERROR, msg, args, kwargs, once=True)


def logfatal_once(msg, *args, **kwargs):
    _log(FATAL, msg, args, kwargs, once=True)


# rospy's deprecated aliases
logout = loginfo
logerror = logerr
