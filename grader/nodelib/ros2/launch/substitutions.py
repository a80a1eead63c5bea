"""The substitutions of ROS 2 launch (LaunchConfiguration, PathJoinSubstitution, PythonExpression, ...)."""
from __future__ import annotations

import importlib
import os
from typing import Any

from launch.core import (
    LaunchContext, Substitution, SubstitutionFailure, TextSubstitution, normalize_to_list_of_substitutions,
    perform_substitutions,
)

__all__ = ["AndSubstitution", "AnonName", "Command", "EnvironmentVariable", "EqualsSubstitution", "FileContent",
           "FindExecutable", "IfElseSubstitution", "LaunchConfiguration", "NotEqualsSubstitution", "LocalSubstitution", "NotSubstitution", "OrSubstitution", "PathJoinSubstitution",
           "PythonExpression", "Substitution", "SubstitutionFailure", "TextSubstitution", "ThisLaunchFile",
           "ThisLaunchFileDir"]


class LaunchConfiguration(Substitution):
    """The value of a launch configuration (an argument, or one set by SetLaunchConfiguration/let)."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        if default is None:
            self.default = None
        else:
            items = [default] if isinstance(default, (str, Substitution)) else list(default)
            self.default = normalize_to_list_of_substitutions(
                [i if isinstance(i, (str, Substitution)) else str(i) for i in items])

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.variable_name)
        if name not in context.launch_configurations:
            if self.default is None:
                raise SubstitutionFailure(f"launch configuration '{name}' does not exist")
            return perform_substitutions(context, self.default)
        return context.launch_configurations[name]

    def describe(self) -> str:
        return f"LaunchConfig({' + '.join(s.describe() for s in self.variable_name)})"


class PathJoinSubstitution(Substitution):
    """Its parts joined with the path separator."""

    def __init__(self, substitutions: Any) -> None:
        self.substitutions = [normalize_to_list_of_substitutions(item) for item in substitutions]

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*[perform_substitutions(context, item) for item in self.substitutions])

    def describe(self) -> str:
        return f"PathJoin('{' + '.join(s.describe() for item in self.substitutions for s in item)}')"


class PythonExpression(Substitution):
    """A Python expression, evaluated with the math module's names (as real launch allows)."""

    def __init__(self, expression: Any, python_modules: Any = ("math",)) -> None:
        self.expression = normalize_to_list_of_substitutions(expression)
        self.python_modules = normalize_to_list_of_substitutions(python_modules)

    def perform(self, context: LaunchContext) -> str:
        names = [context.perform_substitution(sub) for sub in self.python_modules]
        scope: dict[str, Any] = {}
        for name in names:
            module = importlib.import_module(name)
            if module.__name__ == "math":
                scope.update(vars(module))
            scope[module.__name__] = module
        return str(eval(perform_substitutions(context, self.expression), {}, scope))

    def describe(self) -> str:
        return (f"PythonExpr({' + '.join(s.describe() for s in self.expression)}, "
                f"[{', '.join(s.describe() for s in self.python_modules)}])")


class EnvironmentVariable(Substitution):
    """An environment variable of the launch (default_value when unset; without one, an error)."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)

    def perform(self, context: LaunchContext) -> str:
        default = None if self.default_value is None else perform_substitutions(context, self.default_value)
        name = perform_substitutions(context, self.name)
        value = context.environment.get(name, default)
        if value is None:
            raise SubstitutionFailure(f"environment variable '{name}' does not exist")
        return value

    def describe(self) -> str:
        return f"EnvVar({' + '.join(s.describe() for s in self.name)})"


class LocalSubstitution(Substitution):
    """A value of the context's locals, by a Python expression on them."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        self.expression = expression

    def perform(self, context: LaunchContext) -> str:
        try:
            return str(eval(self.expression, {}, context.get_locals_as_dict()))
        except Exception as exc:
            raise SubstitutionFailure(f"Local substitution '{self.expression}' failed: {exc}") from None


class ThisLaunchFileDir(Substitution):
    """The folder of the launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        value = context.locals.get("current_launch_file_directory")
        if value is None:
            raise SubstitutionFailure("ThisLaunchFileDir used outside of a launch file (in a script)")
        return value

    def describe(self) -> str:
        return "ThisLaunchFileDir()"


class ThisLaunchFile(Substitution):
    """The launch file being read."""

    def perform(self, context: LaunchContext) -> str:
        value = context.locals.get("current_launch_file_path")
        if value is None:
            raise SubstitutionFailure("ThisLaunchFile used outside of a launch file (in a script)")
        return value


def _boolean(context: LaunchContext, subs: list[Substitution]) -> bool:
    from launch.conditions import evaluate_condition_expression
    try:
        return evaluate_condition_expression(context, subs)
    except ValueError as exc:
        raise SubstitutionFailure(exc) from None


class NotSubstitution(Substitution):
    """'true' when its value is false."""

    def __init__(self, value: Any) -> None:
        self.value = normalize_to_list_of_substitutions(value)

    def perform(self, context: LaunchContext) -> str:
        return str(not _boolean(context, self.value)).lower()


class AndSubstitution(Substitution):
    """'true' when both values are true."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize_to_list_of_substitutions(left), normalize_to_list_of_substitutions(right)

    def perform(self, context: LaunchContext) -> str:
        return str(_boolean(context, self.left) and _boolean(context, self.right)).lower()


class OrSubstitution(AndSubstitution):
    """'true' when either value is true."""

    def perform(self, context: LaunchContext) -> str:
        return str(_boolean(context, self.left) or _boolean(context, self.right)).lower()


class EqualsSubstitution(Substitution):
    """'true' when both sides are the same text."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize_to_list_of_substitutions(left), normalize_to_list_of_substitutions(right)

    def perform(self, context: LaunchContext) -> str:
        return str(perform_substitutions(context, self.left) == perform_substitutions(context, self.right)).lower()


class NotEqualsSubstitution(EqualsSubstitution):
    """'true' when the sides differ."""

    def perform(self, context: LaunchContext) -> str:
        return str(super().perform(context) == "false").lower()


class IfElseSubstitution(Substitution):
    """One text when the condition is true, another when false."""

    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        self.condition = normalize_to_list_of_substitutions(condition)
        self.if_value = normalize_to_list_of_substitutions(if_value)
        self.else_value = normalize_to_list_of_substitutions(else_value)

    def perform(self, context: LaunchContext) -> str:
        chosen = self.if_value if _boolean(context, self.condition) else self.else_value
        return perform_substitutions(context, chosen)


class FileContent(Substitution):
    """A file's text (an error if it cannot be read)."""

    def __init__(self, path: Any) -> None:
        self.path = normalize_to_list_of_substitutions(path)

    def perform(self, context: LaunchContext) -> str:
        path = perform_substitutions(context, self.path)
        try:
            with open(path, encoding="utf-8", errors="replace") as handle:
                return handle.read()
        except OSError:
            raise SubstitutionFailure(f"File not found: {path}") from None


class AnonName(Substitution):
    """A name made unique per launch (deterministic here: the name and a counter)."""

    def __init__(self, name: Any) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        names = context.locals.setdefault("anon", {})
        return names.setdefault(name, f"{name}_{len(names) + 1}")


class _NotRun(Substitution):
    """A substitution that would run a program on the grading machine: refused with what to do instead."""

    what = ""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        self.args = args

    def perform(self, context: LaunchContext) -> str:
        raise SubstitutionFailure(f"{type(self).__name__} {self.what}")


class Command(Substitution):
    """A command's output: `cat FILE` is read as cat would; rosgrade runs no other program while reading a launch
    file (xacro included)."""

    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        self.command = normalize_to_list_of_substitutions(command)

    def perform(self, context: LaunchContext) -> str:
        words = perform_substitutions(context, self.command).split()
        if len(words) == 2 and words[0] == "cat":
            try:
                with open(words[1], encoding="utf-8", errors="replace") as handle:
                    return handle.read()
            except OSError as exc:
                raise SubstitutionFailure(f"executed command failed. Command: {' '.join(words)}\n"
                                          f"Captured stderr output: cat: {words[1]}: {exc.strerror}") from None
        raise SubstitutionFailure(f"Command {' '.join(words[:1])!r} would run a program while the launch file is "
                                  "read; rosgrade does not run programs then (only `cat FILE` is read): pass the "
                                  "file's path or its content read in Python instead")


class FindExecutable(Substitution):
    """The path ``which NAME`` gives on a ROS 2 Jazzy machine (the grading machine's PATH is not shown to a launch
    file): ROS's programs under /opt/ros/jazzy/bin, the others under /usr/bin. The substitutions tutorial starts its
    `ros2 service call` this way, and the grader carries that call out."""

    ROS_PROGRAMS = frozenset({"ros2", "rviz2", "rqt", "xacro", "gzserver", "gzclient"})

    def __init__(self, *, name: Any) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        if not name or "/" in name:
            raise SubstitutionFailure(f"executable '{name}' not found on the PATH")
        return f"/opt/ros/jazzy/bin/{name}" if name in self.ROS_PROGRAMS else f"/usr/bin/{name}"

    def describe(self) -> str:
        return f"FindExec({' + '.join(s.describe() for s in self.name)})"
