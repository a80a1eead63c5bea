"""rosgrade's ROS 2 ``launch``: what a launch file imports, evaluated into the processes real launch would start."""
from __future__ import annotations

from launch import (
    actions, conditions, event_handlers, events, launch_description_sources, logging, substitutions, utilities,
)
from launch.core import (
    Action, Condition, InvalidLaunchFileError, LaunchContext, LaunchDescription, LaunchDescriptionEntity,
    SomeSubstitutionsType, Substitution,
)
from launch.launch_description_sources import LaunchDescriptionSource
from launch.launch_service import LaunchService

__all__ = ["Action", "Condition", "InvalidLaunchFileError", "LaunchContext", "LaunchDescription",
           "LaunchDescriptionEntity", "LaunchDescriptionSource", "LaunchService", "SomeSubstitutionsType", "Substitution", "actions",
           "conditions", "event_handlers", "events", "launch_description_sources", "logging", "substitutions",
           "utilities"]
