"""rosgrade's ROS 2 ``launch_ros``: Node and the ROS actions and substitutions, for launch files to import."""
from __future__ import annotations

from launch_ros import actions, parameter_descriptions, substitutions

__all__ = ["actions", "parameter_descriptions", "substitutions"]
