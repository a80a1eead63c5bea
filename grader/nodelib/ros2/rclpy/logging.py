"""rclpy.logging: named loggers and their levels."""
from __future__ import annotations

from .impl import rcutils_logger
from .impl.logging_severity import LoggingSeverity  # noqa: F401 - rclpy.logging.LoggingSeverity
from .impl.rcutils_logger import RcutilsLogger

_root_logger = RcutilsLogger()


def get_logger(name: str) -> RcutilsLogger:
    if not name:
        raise ValueError("Logger name must not be empty.")
    return _root_logger.get_child(name)


def initialize() -> None:
    """Nothing to set up: the console handler needs no configuration."""


def shutdown() -> None:
    """Nothing to tear down."""


def clear_config() -> None:
    rcutils_logger._levels.clear()
    rcutils_logger._levels[""] = int(LoggingSeverity.INFO)


def set_logger_level(name: str, level, detailed_error: bool = False) -> None:
    rcutils_logger.set_level(name, LoggingSeverity(level))


def get_logger_effective_level(name: str) -> LoggingSeverity:
    return LoggingSeverity(rcutils_logger.effective_level(name))


def get_logger_level(name: str) -> LoggingSeverity:
    return LoggingSeverity(rcutils_logger._levels.get(name, 0))


def get_logging_severity_from_string(log_severity: str) -> LoggingSeverity:
    return LoggingSeverity[log_severity.upper()]


def get_logging_directory() -> str:
    return "/tmp/.ros/log"
