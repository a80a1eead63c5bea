"""ROS substitutions: FindPackageShare, FindPackagePrefix, ExecutableInPackage."""
from __future__ import annotations

from typing import Any

from ament_index_python.packages import _entry
from launch.core import LaunchContext, Substitution, SubstitutionFailure, normalize_to_list_of_substitutions, \
    perform_substitutions

__all__ = ["ExecutableInPackage", "FindPackage", "FindPackagePrefix", "FindPackageShare"]


class FindPackagePrefix(Substitution):
    """The install prefix of a package."""

    def __init__(self, package: Any) -> None:
        self.package = normalize_to_list_of_substitutions(package)

    def perform(self, context: LaunchContext) -> str:
        return _entry(perform_substitutions(context, self.package))["prefix"]

    def describe(self) -> str:
        return f"{type(self).__name__}(pkg={' + '.join(s.describe() for s in self.package)})"


class FindPackageShare(FindPackagePrefix):
    """The share folder of a package (where its launch and config files are installed)."""

    def perform(self, context: LaunchContext) -> str:
        return _entry(perform_substitutions(context, self.package))["share"]


FindPackage = FindPackagePrefix


class ExecutableInPackage(Substitution):
    """The path of an executable the package installs (what `ros2 run` finds)."""

    def __init__(self, executable: Any, package: Any) -> None:
        self.executable = normalize_to_list_of_substitutions(executable)
        self.package = normalize_to_list_of_substitutions(package)

    def perform(self, context: LaunchContext) -> str:
        package = perform_substitutions(context, self.package)
        executable = perform_substitutions(context, self.executable)
        entry = _entry(package)
        if entry.get("external") or executable in entry.get("executables", []):
            return f"{entry['prefix']}/lib/{package}/{executable}"
        raise SubstitutionFailure(f"executable '{executable}' not found on the libexec directory "
                                  f"'{entry['prefix']}/lib/{package}' ")
