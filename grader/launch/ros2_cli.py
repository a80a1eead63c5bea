"""`rosgrade launch` for ROS 2 launch files: find the file as `ros2 launch` would, evaluate it confined, and print
its processes (--nodes), its arguments (--show-args, as `ros2 launch --show-args`) or all of it (--json)."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from grader.launch.ros2_eval import Evaluation, Ros2LaunchError, evaluate
from grader.launch.ros2_hints import hint_for
from grader.launch.ros2_index import installed, not_installed, workspace_for
from grader.launch.turtlesim import first_window, is_world
from grader.provided_nodes import launched_script
from grader.runtime.client_library import ROS2
from grader.workspace import WorkspaceError, read_workspace

__all__ = ["Ros2LaunchError", "command", "is_ros2_target"]
from grader.workspace.model import enclosing_folder, read_package

ROS2_SUFFIXES = (".py", ".yaml", ".yml")
MAX_SNIFF_BYTES = 1 << 16


def is_ros2_file(path: Path, package_build_type: str | None = None) -> bool:
    """Whether a launch file is for `ros2 launch`: Python or YAML; XML when its package is an ament one, or (no
    package) when its nodes are written with ROS 2's exec= rather than roslaunch's type=."""
    if path.name.endswith(ROS2_SUFFIXES):
        return True
    if package_build_type is not None:
        return package_build_type != "catkin"
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            head = handle.read(MAX_SNIFF_BYTES)
    except OSError:
        return path.name.endswith(".launch.xml")
    return " exec=" in head or "\texec=" in head or "\nexec=" in head


def build_type_of(path: Path) -> str | None:
    """The build type of the package a file is in (None: in no package)."""
    folder = enclosing_folder(path.resolve())
    package = read_package(folder) if folder is not None else None
    return package.build_type if package is not None else None


def find_installed(workspace_dir: Path, package: str, file_name: str) -> Path:
    """The launch file `ros2 launch PACKAGE FILE` would run: one the package's build installs into its share."""
    workspace = read_workspace(workspace_dir)
    found = workspace.package(package)
    if found is None:
        raise Ros2LaunchError(f"Package '{package}' not found: \"package '{package}' not found, searching: "
                              f"['/opt/ros/jazzy']\" (no package.xml with <name>{package}</name> under "
                              f"{workspace_dir})")
    candidates = sorted(p for p in found.folder.rglob(file_name) if "build" not in p.parts and "install" not in p.parts)
    for path in candidates:
        if installed(found, path):
            return path
    if candidates:
        raise Ros2LaunchError(not_installed(found, candidates[0]))
    raise Ros2LaunchError(f"file '{file_name}' was not found in the share directory of package '{package}'")


def _full_name(process: dict[str, Any]) -> str:
    name = process.get("node_name")
    if name is None:
        return f"{process['executable']} (the name its code gives it)"
    namespace = process.get("namespace") or "/"
    return (namespace.rstrip("/") + "/" + name) if not name.startswith("/") else name


def _trigger(process: dict[str, Any]) -> str:
    after = process.get("after")
    parts = []
    if after:
        parts.append(f"when {after['process']} {'exits' if after['event'] == 'exit' else 'starts'}"
                     if after.get("process") else "at shutdown")
    if process.get("delay"):
        parts.append(f"after {process['delay']:g} s")
    return f"  [{', '.join(parts)}]" if parts else ""


def external_include_notes(result: dict[str, Any]) -> list[str]:
    """What the launch file includes from packages rosgrade provides itself (a simulator's world launch file)."""
    notes = []
    for include in result.get("external_includes", []):
        given = " ".join(f"{k}:={v}" for k, v in include["arguments"].items())
        notes.append(f"includes {include['package']}'s {Path(include['file']).name}{' ' + given if given else ''}: "
                     "that package is not the submission's; rosgrade provides the simulation itself (a task's world "
                     "and start pose are its rubric's), so the include starts nothing here")
    return notes


def nodes_text(result: dict[str, Any]) -> str:
    """One line per process launch would start, in its start order."""
    lines = []
    first = first_window(result.get("processes", []))
    for process in result.get("processes", []):
        if process["kind"] == "node":
            external = " (external: not run by rosgrade)" if process.get("external") else ""
            if is_world(process):
                external = (" (simulated by rosgrade)" if process is first else
                            " (simulated by rosgrade: another turtlesim window, under its own names)")
            elif launched_script(process["package"], process["executable"], ROS2) is not None:
                external = " (run by rosgrade as turtlesim's own node)"
            elif process.get("world"):
                external = " (not run by rosgrade)"
            lines.append(f"{_full_name(process)}  ({process['package']} {process['executable']}){external}"
                         f"{_trigger(process)}")
        else:
            shell = " (shell)" if process["shell"] else ""
            lines.append(f"{' '.join(process['cmd'])}{shell}{_trigger(process)}")
    return "".join(line + "\n" for line in lines)


def args_text(arguments: list[dict[str, Any]]) -> str:
    """The arguments, as `ros2 launch --show-args` prints them."""
    text = "Arguments (pass arguments as '<name>:=<value>'):\n"
    for argument in arguments:
        star = "*" if argument["conditional"] else ""
        text += f"\n    '{argument['name']}':{star}\n        {argument['description']}\n"
        if argument["default"] is not None:
            text += f"        (default: {argument['default']})\n"
    if not arguments:
        text += "\n  No arguments.\n"
    elif any(a["conditional"] for a in arguments):
        text += "\n* argument(s) which are only used if specific conditions occur\n"
    return text


def run(file: Path, workspace_dir: Path | None, values: dict[str, str], mode: str) -> tuple[str, list[str]]:
    """What `rosgrade launch` prints for a ROS 2 launch file, and notes for stderr; Ros2LaunchError on failure."""
    try:
        workspace = workspace_for(file, workspace_dir)
    except WorkspaceError as exc:
        raise Ros2LaunchError(str(exc)) from None
    evaluation: Evaluation = evaluate(file, workspace, list(values.items()), show_args=mode == "show-args")
    result = evaluation.result
    error = result.get("error")
    if error:
        where = f"\n  at {error['where']}" if error.get("where") else ""
        hint = hint_for(error["message"], workspace)
        raise Ros2LaunchError(f"[ERROR] [launch]: {error['message']}{where}" + (f"\n  {hint}" if hint else ""))
    if mode == "show-args":
        return args_text(result["arguments"]), []
    declared = {a["name"] for a in result.get("arguments", [])}
    notes = [f"argument {name}:={value} is not declared by the launch file (ros2 launch accepts it silently; it "
             "changes nothing unless a LaunchConfiguration reads it)" for name, value in values.items()
             if name not in declared]
    notes += [f"[INFO] [launch.user]: {log['text']}" for log in result.get("logs", [])]
    notes += external_include_notes(result)
    if mode == "json":
        return json.dumps(result, indent=2) + "\n", notes
    return nodes_text(result), notes


def is_ros2_target(file: Path, words: list[str], workspace_dir: Path | None) -> bool:
    """Whether `rosgrade launch FILE words...` names a ROS 2 launch file (`PATH` or `PKG FILE`)."""
    if file.is_file():
        return is_ros2_file(file, build_type_of(file))
    if not words or ":=" in words[0]:
        return False
    if words[0].endswith(ROS2_SUFFIXES):
        return True
    try:
        package = read_workspace(workspace_dir or Path.cwd()).package(str(file))
    except WorkspaceError:
        return False
    return package is not None and package.build_type != "catkin"


def command(file: Path, words: list[str], workspace_dir: Path | None, mode: str) -> tuple[str, list[str]]:
    """`rosgrade launch` on a ROS 2 launch file: `PATH args...` or `PKG FILE args...` (installed files only)."""
    words = list(words)
    if mode == "dump-params":
        raise Ros2LaunchError("--dump-params prints roslaunch's parameter server; for a ROS 2 launch file use --json "
                              "(each node's parameter files) or --show-args")
    if not file.is_file() and words and ":=" not in words[0]:
        try:
            file = find_installed(workspace_dir or Path.cwd(), str(file), words.pop(0))
        except WorkspaceError as exc:
            raise Ros2LaunchError(str(exc)) from None
    values: dict[str, str] = {}
    for item in words:
        name, sep, value = item.partition(":=")
        if not sep or not name:
            raise Ros2LaunchError(f"{item!r} is not a launch argument; pass them as name:=value")
        values[name] = value
    return run(file, workspace_dir, values, mode)
