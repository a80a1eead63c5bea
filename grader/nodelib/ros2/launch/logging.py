"""launch.logging: the loggers a launch file may ask for (what they print goes to the launch's output)."""
from __future__ import annotations

import logging as _logging

__all__ = ["get_logger"]


def get_logger(name: str | None = None) -> _logging.Logger:
    return _logging.getLogger(f"launch.{name}" if name else "launch")
