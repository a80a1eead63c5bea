"""Where an included launch description comes from: a Python, XML or YAML launch file."""
from __future__ import annotations

import importlib.util
import os
from typing import Any

from launch.core import (
    EvaluationError, InvalidLaunchFileError, LaunchContext, LaunchDescription, normalize_to_list_of_substitutions,
    perform_substitutions,
)

__all__ = ["AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource", "LaunchDescriptionSource",
           "PythonLaunchDescriptionSource", "load_python_launch_file_as_module"]


def load_python_launch_file_as_module(path: str) -> Any:
    """The launch file run as a module (its top level runs, as real launch runs it)."""
    name = os.path.basename(path).replace(".", "_")
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise InvalidLaunchFileError(f"could not load launch file '{path}'")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class LaunchDescriptionSource:
    """A launch file's path (substitutions allowed), read when the include is executed."""

    kind = "any"

    def __init__(self, launch_file_path: Any) -> None:
        self.path_subs = normalize_to_list_of_substitutions(launch_file_path)
        self.location = ""

    def get_launch_description(self, context: LaunchContext) -> LaunchDescription:
        self.location = perform_substitutions(context, self.path_subs)
        return context.recorder.load(self.location, self.kind, context)

    def try_get_launch_description_without_context(self) -> LaunchDescription | None:
        """The included description when its path needs no launch configuration (for finding its arguments)."""
        context = LaunchContext()
        try:
            path = perform_substitutions(context, self.path_subs)
        except Exception:
            return None
        try:
            return context.recorder.load(path, self.kind, context, record=False)
        except EvaluationError:
            raise
        except Exception:
            return None


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """A .launch.py file."""

    kind = "python"


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    """An XML or YAML launch file."""

    kind = "frontend"


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """A launch file of any format, told by its extension (Python, else XML, else YAML)."""

    kind = "any"
