"""Package lookups over the index the evaluator is given (ROSGRADE_LAUNCH_INDEX): the submission's packages, whose
share folder is where their installed files are, and the world's (turtlesim) and external ones (rviz2, gazebo)."""
from __future__ import annotations

import json
import os
from typing import Any

SEARCHED = "/opt/ros/jazzy"  # where `ros2 launch` on a course machine would have looked, for the error text


class PackageNotFoundError(KeyError):
    """No package of that name is installed."""


def index() -> dict[str, dict[str, Any]]:
    """Every package known to the launch: name -> {"share", "prefix", "executables", "external", "world"}."""
    return json.loads(os.environ.get("ROSGRADE_LAUNCH_INDEX", "{}"))


def _entry(package_name: str) -> dict[str, Any]:
    found = index().get(package_name)
    if found is None:
        raise PackageNotFoundError(f"package '{package_name}' not found, searching: ['{SEARCHED}']")
    return found


def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
    return _entry(package_name)["share"]


def get_package_prefix(package_name: str) -> str:
    return _entry(package_name)["prefix"]


def get_packages_with_prefixes() -> dict[str, str]:
    return {name: entry["prefix"] for name, entry in index().items()}
