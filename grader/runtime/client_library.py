"""Which client library a node script uses (rospy or rclpy), how `ros2 run` would start it (and give it parameters),
and what it may import.

A script that imports rclpy is a ROS 2 node, one that imports rospy a ROS 1 node; a script that imports neither, or
that does not parse (its import lines are then read as text), takes its package's (``package.xml``'s build type and
dependencies), and a lone script is a ROS 1 node. A ROS 2 script inside an ament_python package is started through
its console_scripts entry point, as the wrapper that colcon installs does; an ament_cmake script (COM2009's template:
``scripts/`` installed with ``install(PROGRAMS ...)``) runs as the file. Either way the node may import the Python
packages its workspace's build installs (``ament_python_install_package``, setup.py's packages). Everything about
packages comes from the workspace model (``grader.workspace``), which reads the package files and never runs them.
"""
from __future__ import annotations

import ast
import importlib.util
import json
import re
import stat
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import yaml

from grader.nodelib import import_roots as client_roots
from grader.runtime.scripts import read_script
from grader.workspace import Package, Workspace, read_workspace
from grader.workspace.python_source import parse

ROS1, ROS2 = "ros1", "ros2"
MAX_IMPORT_ROOTS = 16  # folders a node gets on its import path from the workspace; a course workspace needs 1-3
_TEXT_IMPORT = re.compile(r"^[ \t]*(?:import[ \t]+([\w.]+(?:[ \t]*,[ \t]*[\w.]+)*)|from[ \t]+(\w+))", re.M)


@dataclass(frozen=True)
class EntryPoint:
    """``<executable> = <module>:<function>`` from a package's setup.py, for the script being graded."""

    package: str  # the ROS package (the folder holding setup.py and package.xml)
    executable: str
    module: str
    function: str
    root: Path  # the folder to put on sys.path so that ``module`` imports (the package's own folder)


def _import_pairs(source: str) -> list[tuple[str, str]] | None:
    """(top-level module, next part or "") of every import, in source order; None when the script does not parse."""
    try:
        tree = parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    names: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.append(node.module)
    return [(parts[0], parts[1] if len(parts) > 1 else "") for parts in (name.split(".") for name in names)]


def _text_imports(source: str) -> list[str]:
    """Top-level names on the script's import lines, read as text (for a script Python cannot parse)."""
    names: list[str] = []
    for match in _TEXT_IMPORT.finditer(source):
        listed = match.group(1).split(",") if match.group(1) else [match.group(2)]
        names += [item.strip().split(".")[0] for item in listed]
    return names


def _workspace(script: Path, workspace: Workspace | None) -> Workspace:
    return workspace if workspace is not None else read_workspace(script)


def _package_library(package: Package | None) -> str | None:
    """The client library a package's files say its nodes use, or None when they do not say."""
    if package is None:
        return None
    if package.build_type != "catkin" or ("rclpy" in package.depends and "rospy" not in package.depends):
        return ROS2
    return ROS1


def client_library(script: Path, workspace: Workspace | None = None) -> str:
    """ROS2 for an rclpy script, ROS1 for a rospy one; otherwise its package's library (ROS1 for a lone script)."""
    raw = read_script(script)
    if isinstance(raw, str):
        return ROS1
    source = raw.decode("utf-8", "replace")
    pairs = _import_pairs(source)
    imports = [top for top, _ in pairs] if pairs is not None else _text_imports(source)
    if "rclpy" in imports:
        return ROS2
    if "rospy" in imports:
        return ROS1
    return _package_library(_workspace(script, workspace).enclosing(script)) or ROS1


def entry_point(script: Path, workspace: Workspace | None = None) -> EntryPoint | None:
    """The console_scripts entry point that runs ``script``'s module, when the script is in an ament_python package."""
    package = _workspace(script, workspace).enclosing(script)
    if package is None or package.build_type != "ament_python":
        return None
    found = package.executable_for(script)
    if found is None or found.entry is None:
        return None
    module, _, function = found.entry.partition(":")
    return EntryPoint(package.setup_package_name or package.folder.name, found.name, module, function,
                      package.folder)


def import_roots(script: Path, workspace: Workspace | None = None, flavour: str = ROS2) -> tuple[Path, ...]:
    """The folders to put on the node's import path so that it imports the Python packages the workspace's build
    installs (its own package's first), as a sourced colcon (ROS2) or catkin (ROS1) workspace would."""
    ws = _workspace(script, workspace)
    own = ws.enclosing(script)
    same = [p for p in ([own] if own else []) + list(ws.packages()) if (p.build_type == "catkin") == (flavour == ROS1)]
    roots = dict.fromkeys(item.root.resolve() for package in same for item in package.python_packages)
    return tuple(roots)[:MAX_IMPORT_ROOTS]


def _relative(script: Path, package: Package) -> str:
    try:
        return script.resolve().relative_to(package.folder.resolve()).as_posix()
    except ValueError:
        return script.name


def _ament_python_findings(script: Path, package: Package, entry: EntryPoint | None) -> list[str]:
    if entry is not None:
        return []
    module = ".".join(Path(_relative(script, package)).with_suffix("").parts)
    return [f"{script.name} is in the ament_python package {package.folder.name}, but setup.py has no console_scripts "
            f"entry point for {module}, so `ros2 run` would say 'No executable found'. Add "
            f"'{script.stem} = {module}:main' to entry_points in setup.py (it was graded by running the file)."]


def _ament_cmake_findings(script: Path, package: Package) -> list[str]:
    """What `ros2 run <package> <script>.py` would trip over after `colcon build --symlink-install` (COM2009's)."""
    rel = _relative(script, package)
    run = f"`ros2 run {package.name} {script.name}`"
    installed = package.executable_for(script)
    if installed is None:
        return [f"{rel} is not installed by CMakeLists.txt, so {run} would say 'No executable found'. Add {rel} to "
                "install(PROGRAMS ... DESTINATION lib/${PROJECT_NAME}) in CMakeLists.txt (it was graded by running "
                "the file)."]
    raw = read_script(script)
    notes: list[str] = []
    first_line = raw.split(b"\n", 1)[0] if isinstance(raw, bytes) else b"#!"
    if not first_line.startswith(b"#!"):
        notes.append(f"{rel} has no shebang line: {run} would fail with 'Exec format error'. Make "
                     "`#!/usr/bin/env python3` the very first line.")
    elif first_line.endswith(b"\r"):
        notes.append(f"{rel} has Windows (CRLF) line endings: {run} would fail with \"/usr/bin/env: 'python3\\r': No "
                     "such file or directory\". Save it with LF line endings.")
    if not installed.executable_install:
        notes.append(f"CMakeLists.txt installs {rel} as a plain file, so {run} would say 'No executable found'. "
                     "Install it with install(PROGRAMS ...) instead.")
    elif not script.stat().st_mode & (stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH):
        notes.append(f"{rel} is not executable: built with `colcon build --symlink-install`, {run} would say 'No "
                     f"executable found'. Run `chmod +x {rel}`.")
    return notes


def _importable(name: str, script: Path) -> bool:
    """Whether ``import name`` finds something without the workspace's packages (beside the script, the standard
    library, the client library, the interpreter's site-packages)."""
    places = [script.parent, *client_roots(ROS2)]
    if any((place / name).is_dir() or (place / f"{name}.py").is_file() for place in places):
        return True
    try:
        return name in sys.stdlib_module_names or importlib.util.find_spec(name) is not None
    except (ImportError, ValueError):
        return False


def _import_findings(script: Path, ws: Workspace) -> list[str]:
    """A module the build does not install, or a wrong package name in an import, as `ros2 run` would meet it."""
    raw = read_script(script)
    pairs = _import_pairs(raw.decode("utf-8", "replace")) if isinstance(raw, bytes) else None
    installed = {item.name: item for item in ws.python_packages()}
    notes: list[str] = []
    for top, sub in dict.fromkeys(pairs or ()):
        item = installed.get(top)
        if item is not None and not item.declared:
            spelled = "${PROJECT_NAME}_modules" if top == f"{item.root.name}_modules" else top
            notes.append(f"{script.name} imports {top}, but {item.root.name}/CMakeLists.txt does not install it, so "
                         f"`ros2 run` would stop with \"ModuleNotFoundError: No module named '{top}'\". Add "
                         f"`ament_python_install_package({spelled})` to that CMakeLists.txt (it was graded as if it "
                         "did).")
        elif item is None and not _importable(top, script):
            near = [name for name, other in installed.items()
                    if (sub and ((other.folder / sub).is_dir() or (other.folder / f"{sub}.py").is_file()))
                    or (top.endswith("_modules") and name.endswith("_modules"))]
            if near:
                notes.append(f"{script.name} imports {top}, which no package of the submission installs: the node "
                             f"stops with \"ModuleNotFoundError: No module named '{top}'\". Your workspace installs "
                             f"{near[0]}: import from {near[0]}{'.' + sub if sub else ''} instead.")
    return notes


def package_findings(script: Path, entry: EntryPoint | None, workspace: Workspace | None = None) -> list[str]:
    """What `colcon build` and `ros2 run` would trip over for a ROS 2 script, each with the fix."""
    ws = _workspace(script, workspace)
    package = ws.enclosing(script)
    if package is None:
        return []
    notes = list(package.findings) if package.build_type != "catkin" else []
    if package.build_type == "ament_python":
        notes += _ament_python_findings(script, package, entry)
    elif package.build_type == "ament_cmake":
        notes += _ament_cmake_findings(script, package)
    return notes + _import_findings(script, ws)


def param_args(flavour: str, params: Mapping[str, str | bool | int | float]) -> tuple[str, ...]:
    """Command-line words that give a node these parameters: rospy's private ``_name:=value``, rclpy's
    ``--ros-args -p name:=value``. Both read the value as YAML, so it is written as YAML: a string that YAML would take
    for another type (``"1.0"``, ``"true"``) is quoted; the argv reaches the node with no shell to strip the quotes."""
    def text(value: str | bool | int | float) -> str:
        if isinstance(value, str):
            try:
                plain = yaml.safe_load(value) == value
            except yaml.YAMLError:
                plain = False
            return value if plain else json.dumps(value)
        return json.dumps(value)  # true/false, 3, 0.5: YAML reads JSON's scalars as their own type

    if flavour == ROS2:
        return ("--ros-args", *(word for name, value in params.items() for word in ("-p", f"{name}:={text(value)}")))
    return tuple(f"_{name}:={text(value)}" for name, value in params.items())
