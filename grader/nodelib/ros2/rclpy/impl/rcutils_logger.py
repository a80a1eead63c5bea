"""RcutilsLogger: rclpy's logger with its filters (throttle on the system clock, once, skip_first, per call site),
rcutils' console line on stderr and, for a node's logger, one LOG frame per message (the node's /rosout)."""
from __future__ import annotations

import os
import sys

import rosgrade_channel as ch
from rosgrade_node import runtime

from .. import _runtime
from .._rclpy_pybind11 import PUBLISHER_CONTEXT_INVALID
from .logging_severity import LoggingSeverity

# As real rclpy's _internal_callers: only the logging modules' frames are skipped, so rclpy's own calls (an action
# server's warnings) are keyed by their own call sites.
_INTERNAL_CALLERS = (os.path.abspath(__file__),
                     os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "logging.py"))
_SEVERITY_LABEL = {10: "DEBUG", 20: "INFO", 30: "WARN", 40: "ERROR", 50: "FATAL"}
_DEFAULT_FORMAT = "[{severity}] [{time}] [{name}]: {message}"

# Logger levels set by set_level / --log-level ('' is the default for every logger).
_levels: dict[str, int] = {"": int(LoggingSeverity.INFO)}
# Node loggers whose messages go to /rosout: logger name -> node (set by Node, cleared by destroy_node).
rosout_nodes: dict[str, object] = {}


def effective_level(name: str) -> int:
    """The logger's own level, else its nearest dotted ancestor's, else the default."""
    while True:
        level = _levels.get(name)
        if level is not None and level != LoggingSeverity.UNSET:
            return level
        if not name:
            return _levels.get("", 20) or 20
        name = name.rpartition(".")[0]


def set_level(name: str, level: int) -> None:
    _levels[name] = int(level)


def _caller_frame():
    """The first frame outside rclpy's logging modules (whose call site keys the filters)."""
    frame = sys._getframe(1)
    while frame is not None and frame.f_code.co_filename in _INTERNAL_CALLERS:
        frame = frame.f_back
    if frame is None:
        raise ValueError("Cannot get frame info if frame is None")
    return frame


def _rosout_node(name: str):
    node = rosout_nodes.get(name)
    while node is None and "." in name:
        name = name.rpartition(".")[0]
        node = rosout_nodes.get(name)
    return node


def _console_line(severity: int, name: str, message: str, function: str, file: str, line: int) -> str:
    stamp_ns = _runtime.system_ns()
    fmt = os.environ.get("RCUTILS_CONSOLE_OUTPUT_FORMAT") or _DEFAULT_FORMAT
    fields = {"severity": _SEVERITY_LABEL.get(severity, str(severity)), "name": name, "message": message,
              "function_name": function, "file_name": file, "line_number": str(line),
              "time": "%d.%09d" % divmod(stamp_ns, 1_000_000_000), "time_as_nanoseconds": str(stamp_ns)}
    text = fmt
    for key, value in fields.items():
        text = text.replace("{" + key + "}", value)
    return text + "\n"


def rcutils_log(severity: int, name: str, message, function: str, file: str, line: int) -> None:
    """rcutils' output handlers in their order: the console line (stderr), then /rosout for node loggers."""
    if not isinstance(message, str):
        raise TypeError(
            "rclpy_logging_rcutils_log(): incompatible function arguments. The following argument types are "
            "supported:\n    1. (arg0: typing.SupportsInt, arg1: str, arg2: str, arg3: str, arg4: str, "
            "arg5: typing.SupportsInt) -> None\n\n"
            f"Invoked with: {LoggingSeverity(severity)!r}, {name!r}, {message!r}, {function!r}, {file!r}, {line}")
    sys.stderr.write(_console_line(severity, name, message, function, file, line))
    node = _rosout_node(name)
    if node is None or runtime.link is None:
        return
    if not node.context.ok():
        sys.stderr.write("Failed to publish log message to rosout: " + PUBLISHER_CONTEXT_INVALID + "\n")
        return
    runtime.link.send_json(ch.LOG, {"level": int(severity), "msg": message[:ch.MAX_MESSAGE_CHARS * 16],
                                    "name": name, "file": file, "function": function, "line": line})


class _Filter:
    params: dict = {}

    @classmethod
    def initialize_context(cls, context: dict, **kwargs) -> None:
        for name, default in cls.params.items():
            value = kwargs.get(name, default)
            if value is None:
                raise TypeError(f'Required parameter "{name}" was not specified for logging filter "{cls.__name__}"')
            context[name] = value

    @staticmethod
    def should_log(context: dict) -> bool:
        return True


class Once(_Filter):
    """Ignore all log calls except the first one."""

    params = {"once": None}

    @classmethod
    def initialize_context(cls, context: dict, **kwargs) -> None:
        super().initialize_context(context, **kwargs)
        context["has_been_logged_once"] = False

    @staticmethod
    def should_log(context: dict) -> bool:
        if context["has_been_logged_once"]:
            return False
        context["has_been_logged_once"] = True
        return True


class Throttle(_Filter):
    """Log when at least ``throttle_duration_sec`` passed on the throttle clock (default: the SYSTEM clock, not the
    node's sim clock, as measured) since the last logged call."""

    params = {"throttle_duration_sec": None, "throttle_time_source_type": None}

    @classmethod
    def initialize_context(cls, context: dict, **kwargs) -> None:
        from ..clock import Clock
        kwargs.setdefault("throttle_time_source_type", Clock())
        super().initialize_context(context, **kwargs)
        context["throttle_last_logged"] = 0
        if not isinstance(context["throttle_time_source_type"], Clock):
            raise ValueError('Received throttle_time_source_type of "{0}" is not a clock instance'
                             .format(context["throttle_time_source_type"]))

    @staticmethod
    def should_log(context: dict) -> bool:
        now = context["throttle_time_source_type"]._now_ns()
        if now >= context["throttle_last_logged"] + context["throttle_duration_sec"] * 1e9:
            context["throttle_last_logged"] = now
            return True
        return False


class SkipFirst(_Filter):
    """Ignore the first log call but process all subsequent calls."""

    params = {"skip_first": None}

    @classmethod
    def initialize_context(cls, context: dict, **kwargs) -> None:
        super().initialize_context(context, **kwargs)
        context["first_has_been_skipped"] = False

    @staticmethod
    def should_log(context: dict) -> bool:
        if not context["first_has_been_skipped"]:
            context["first_has_been_skipped"] = True
            return False
        return True


supported_filters = {"throttle": Throttle, "skip_first": SkipFirst, "once": Once}
_ALL_PARAMS = ["once", "throttle_duration_sec", "throttle_time_source_type", "skip_first"]


def get_filters_from_kwargs(**kwargs) -> list[str]:
    detected = [key for key, flt in supported_filters.items() if any(kwargs.get(p) for p in flt.params)]
    for key in detected:
        flt = supported_filters[key]
        for param in flt.params:
            if param not in kwargs and flt.params[param] is None and param != "throttle_time_source_type":
                raise TypeError(f'required parameter "{param}" not specified but is required for the the logging '
                                f'filter "{key}"')
    for kwarg in kwargs:
        if kwarg not in _ALL_PARAMS:
            raise TypeError(f'parameter "{kwarg}" is not one of the recognized logging options "{_ALL_PARAMS}"')
    return detected


class RcutilsLogger:
    def __init__(self, name: str = "") -> None:
        self.name = name
        self.contexts: dict[tuple, dict] = {}

    def get_child(self, name: str) -> RcutilsLogger:
        if not name:
            raise ValueError("Child logger name must not be empty.")
        return RcutilsLogger(name=f"{self.name}.{name}" if self.name else name)

    def set_level(self, level) -> None:
        set_level(self.name, LoggingSeverity(level))

    def get_effective_level(self) -> LoggingSeverity:
        return LoggingSeverity(effective_level(self.name))

    def is_enabled_for(self, severity) -> bool:
        return LoggingSeverity(severity) >= effective_level(self.name)

    def log(self, message, severity, name: str | None = None, **kwargs) -> bool:
        """Log ``message``; False when the level or a filter held it back."""
        _runtime.charge()
        if not self.is_enabled_for(severity):
            return False
        severity = LoggingSeverity(severity)
        if name is None:
            name = self.name
        detected = get_filters_from_kwargs(**kwargs)
        frame = _caller_frame()
        caller = (frame.f_code.co_name, os.path.abspath(frame.f_code.co_filename), frame.f_lineno, frame.f_lasti)
        context = self.contexts.get(caller)
        if context is None:
            context = {"name": name, "severity": severity, "filters": detected}
            for key in detected:
                supported_filters[key].initialize_context(context, **kwargs)
            self.contexts[caller] = context
        else:
            if severity != context["severity"]:
                raise ValueError("Logger severity cannot be changed between calls.")
            if name != context["name"]:
                raise ValueError("Logger name cannot be changed between calls.")
            if detected != context["filters"]:
                raise ValueError("Requested logging filters cannot be changed between calls.")
            for key in detected:
                for param in supported_filters[key].params:
                    if param in kwargs and context[param] != kwargs[param]:
                        raise ValueError("Logging filter parameters cannot be changed between calls.")
        for key in context["filters"]:
            if not supported_filters[key].should_log(context):
                return False
        rcutils_log(severity, name, message, caller[0], caller[1], caller[2])
        return True

    def debug(self, message, **kwargs) -> bool:
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message, **kwargs) -> bool:
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message, **kwargs) -> bool:
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    def warn(self, message, **kwargs) -> bool:
        """Alias of warning(): deprecated in Jazzy's docstring only (Kilted's rclpy adds a DeprecationWarning)."""
        return self.warning(message, **kwargs)

    def error(self, message, **kwargs) -> bool:
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message, **kwargs) -> bool:
        return self.log(message, LoggingSeverity.FATAL, **kwargs)
