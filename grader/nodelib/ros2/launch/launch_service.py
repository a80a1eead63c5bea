"""launch.LaunchService: a launch file's own `__main__` block may build one; rosgrade reads the file as
`ros2 launch` does, through generate_launch_description(), and never runs a service."""
from __future__ import annotations

from typing import Any

__all__ = ["LaunchService"]


class LaunchServiceError(Exception):
    """A launch file tried to run a launch service itself."""


class LaunchService:
    """Holds what would be launched; running it is refused with what to do instead."""

    def __init__(self, *, argv: Any = None, noninteractive: bool = False, debug: bool = False) -> None:
        self.argv = list(argv or [])
        self.descriptions: list[Any] = []

    def include_launch_description(self, launch_description: Any) -> None:
        self.descriptions.append(launch_description)

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        raise LaunchServiceError("rosgrade reads a launch file as `ros2 launch` does, through its "
                                 "generate_launch_description(); it does not run a LaunchService")
