"""Events of ROS 2 launch that a launch file names (Shutdown)."""
from __future__ import annotations

from typing import Any

__all__ = ["Shutdown"]


class Shutdown:
    """Asks the launch to end."""

    def __init__(self, *, reason: Any = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason = reason
        self.due_to_sigint = due_to_sigint
