"""Which client library a node script uses (rospy or rclpy), and how `ros2 run` would start an ament_python node.

A script that imports rclpy is a ROS 2 node, one that imports rospy (or neither) a ROS 1 node. A ROS 2 script inside
an ament_python package (``package.xml`` + ``setup.py`` with ``console_scripts`` entry points, as ``ros2 pkg create
--build-type ament_python`` lays it out) is started through its entry point, as the wrapper that colcon installs
does: the module is imported under its package name and its function's return value is the exit status. Nothing
here runs the student's code: setup.py is read as a syntax tree.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

from grader.runtime.scripts import read_script

ROS1, ROS2 = "ros1", "ros2"
_SETUP_MAX_BYTES = 256 * 1024


@dataclass(frozen=True)
class EntryPoint:
    """``<executable> = <module>:<function>`` from a package's setup.py, for the script being graded."""

    package: str  # the ROS package (the folder holding setup.py and package.xml)
    executable: str
    module: str
    function: str
    root: Path  # the folder to put on sys.path so that ``module`` imports (the package's own folder)


def _imports(source: str) -> list[str]:
    """Top-level module names the script imports, in source order (empty if it does not parse)."""
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    names: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [alias.name.split(".")[0] for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.append(node.module.split(".")[0])
    return names


def client_library(script: Path) -> str:
    """ROS2 when the script imports rclpy, else ROS1 (rospy, or a script that imports neither)."""
    raw = read_script(script)
    if isinstance(raw, str):
        return ROS1
    imports = _imports(raw.decode("utf-8", "replace"))
    return ROS2 if "rclpy" in imports else ROS1


def _package_root(script: Path) -> Path | None:
    """The nearest folder above the script holding both setup.py and package.xml."""
    for folder in script.resolve().parents:
        if (folder / "setup.py").is_file() and (folder / "package.xml").is_file():
            return folder
    return None


def _console_scripts(setup: Path) -> list[str]:
    """The ``console_scripts`` strings of setup.py's ``setup(entry_points=...)``, read without running it."""
    raw = read_script(setup)
    if isinstance(raw, str) or len(raw) > _SETUP_MAX_BYTES:
        return []
    try:
        tree = ast.parse(raw.decode("utf-8", "replace"))
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values):
                if isinstance(key, ast.Constant) and key.value == "console_scripts" \
                        and isinstance(value, (ast.List, ast.Tuple)):
                    found += [e.value for e in value.elts if isinstance(e, ast.Constant) and isinstance(e.value, str)]
    return found


def _package_name(root: Path, setup: Path) -> str:
    """setup.py's ``package_name = '...'`` (the template's spelling), else the folder's name."""
    raw = read_script(setup)
    if not isinstance(raw, str):
        try:
            for node in ast.parse(raw.decode("utf-8", "replace")).body:
                if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "package_name"
                                                        for t in node.targets) \
                        and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
                    return node.value.value
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            pass
    return root.name


def entry_point(script: Path) -> EntryPoint | None:
    """The console_scripts entry point that runs ``script``'s module, when the script is in an ament_python package."""
    root = _package_root(script)
    if root is None:
        return None
    try:
        module = ".".join(script.resolve().relative_to(root).with_suffix("").parts)
    except ValueError:
        return None
    setup = root / "setup.py"
    for spec in _console_scripts(setup):
        name, sep, target = spec.partition("=")
        target_module, colon, function = target.strip().partition(":")
        if sep and colon and target_module.strip() == module:
            return EntryPoint(_package_name(root, setup), name.strip(), module, function.strip(), root)
    return None


def package_findings(script: Path, entry: EntryPoint | None) -> list[str]:
    """What `colcon build` and `ros2 run` would trip over for a ROS 2 script, each with the fix."""
    root = _package_root(script)
    if root is None or entry is not None:
        return []
    module = ".".join(script.resolve().relative_to(root).with_suffix("").parts)
    return [f"{script.name} is in the ament_python package {root.name}, but setup.py has no console_scripts entry "
            f"point for {module}, so `ros2 run` would say 'No executable found'. Add "
            f"'{script.stem} = {module}:main' to entry_points in setup.py (it was graded by running the file)."]
