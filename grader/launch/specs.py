"""Turn what a launch file starts into the runtime's node specs: find each node's script in the student's package.

roslaunch finds ``type`` as an executable file anywhere in package ``pkg``; the usual mistakes (a ``pkg`` that is
the folder's name rather than package.xml's, a ``type`` without ``.py``, a script without ``chmod +x``) get a
message that says what roslaunch would have said and what to change. turtlesim's nodes are the grader's
(``grader.launch.turtlesim``): ``turtlesim_node`` is the world, not a process, and ``turtle_teleop_key`` and ``mimic``
run the grader's rospy scripts (``grader.provided_nodes``) with the launch file's name, namespace and remaps.
"""
from __future__ import annotations

import os
import stat
from collections.abc import Mapping
from pathlib import Path

from grader.launch import known, turtlesim
from grader.launch.model import Launch, LaunchError, LaunchNode
from grader.provided_nodes import launched_script
from grader.rubric import GRADER_NODES
from grader.runtime.client_library import ROS1
from grader.runtime.scripts import SKIPPED_DIRS, candidates
from grader.runtime.spec import NodeSpec

MAX_NODES = 16  # each node is a process of its own; a course launch file starts two or three

def _scripts_in(folder: Path) -> list[str]:
    return sorted({p.name for p in folder.rglob("*.py") if not set(p.parts) & SKIPPED_DIRS})[:8]


def _executable(path: Path) -> bool:
    return bool(path.stat().st_mode & (stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH))


def _package(node: LaunchNode, packages: Mapping[str, Path]) -> Path:
    if node.pkg in packages:
        return packages[node.pkg]
    if node.pkg in known.SIMULATED_PACKAGES:
        raise LaunchError(f"{node.where}: node {node.name} (pkg=\"{node.pkg}\" type=\"{node.type}\"): "
                          f"{known.not_available(node.pkg)}")
    # The script is in one of the student's packages: the usual slip is the folder's name instead of package.xml's.
    owner = next((name for name, folder in sorted(packages.items()) if candidates(folder, node.type)), None)
    if owner is not None:
        raise LaunchError(f"{node.where}: pkg=\"{node.pkg}\" is not your package's name: {node.type} is in the "
                          f"package whose package.xml says <name>{owner}</name>, and roslaunch finds packages by "
                          f"that name, not by the folder's. Write pkg=\"{owner}\".")
    listed = ", ".join(sorted(packages)) or "none (no package.xml found in the submission)"
    raise LaunchError(f"{node.where}: node {node.name}: {known.not_available(node.pkg)}; your packages: {listed}")


def _script(node: LaunchNode, folder: Path, allow_not_executable: bool) -> tuple[Path, list[str]]:
    found = candidates(folder, node.type)
    if not found:
        hint = ""
        if not node.type.endswith(".py") and candidates(folder, node.type + ".py"):
            hint = f" type= is the script's file name with its extension: write type=\"{node.type}.py\"."
        scripts = ", ".join(_scripts_in(folder)) or "none"
        raise LaunchError(f"{node.where}: type=\"{node.type}\" matches no file in package {node.pkg} "
                          f"(its Python scripts: {scripts}).{hint}")
    script, notes = found[0], []
    if len(found) > 1:
        others = ", ".join(str(p.relative_to(folder)) for p in found[1:4])
        notes.append(f"Several files in {node.pkg} are named {node.type}; ran {script.relative_to(folder)} "
                     f"(also found: {others}).")
    if not _executable(script):
        said = (f"roslaunch would refuse node {node.name}: \"Cannot locate node of type [{node.type}] in package "
                f"[{node.pkg}]. Make sure file exists in package path and permission is set to executable "
                f"(chmod +x)\". Run `chmod +x {script.relative_to(folder)}`")
        if not allow_not_executable:
            raise LaunchError(f"{node.where}: {said}.")
        notes.append(f"{said}; this task ran it with python3 anyway.")
    return script, notes


def _provided(node: LaunchNode) -> Path:
    """The grader's script for a node of a package whose nodes it provides (turtle_teleop_key, mimic: Noetic's)."""
    script = launched_script(node.pkg, node.type, ROS1)
    if script is not None:
        return GRADER_NODES / script
    *some, last = known.NODE_PACKAGES[node.pkg]
    raise LaunchError(f"{node.where}: node {node.name}: type=\"{node.type}\" is not a node of {node.pkg} the grader "
                      f"provides; it provides {', '.join(some)} and {last}")


def node_specs(launch: Launch, packages: Mapping[str, Path], stdin: str | None = None,
               allow_not_executable: bool = False) -> tuple[tuple[NodeSpec, ...], list[str]]:
    """One NodeSpec per ``<node>`` (every parameter of the launch, its remaps, name and namespace) and findings;
    a ``turtlesim_node`` starts none (it is the world), and the others get remaps to reach it where it is."""
    if not launch.nodes:
        raise LaunchError(f"{launch.file.name} starts no <node>: add a <node pkg=... type=... name=...> for your "
                          "script")
    if len(launch.nodes) > MAX_NODES:
        raise LaunchError(f"{launch.file.name} starts {len(launch.nodes)} nodes; the grader runs at most {MAX_NODES} "
                          "in one task")
    specs: list[NodeSpec] = []
    notes = list(launch.notes)
    world = turtlesim.world_node(launch)
    for node in launch.nodes:
        if world is not None and world.simulates(node):
            continue  # the task's world, not a process
        provided = node.pkg in known.NODE_PACKAGES and node.pkg not in packages
        if provided:
            script, found = _provided(node), []
        else:
            script, found = _script(node, _package(node, packages), allow_not_executable)
        notes += found
        if node.respawn:
            notes.append(f"{node.where}: respawn=\"true\" on {node.name} is not modelled: the grader does not "
                         "restart a node that ends.")
        remaps = turtlesim.bridge(node, world)
        args = (*node.args, *(f"{source}:={target}" for source, target in remaps), f"__name:={node.name}")
        specs.append(NodeSpec(script=Path(os.path.abspath(script)), args=args, stdin=stdin,
                              ros_namespace=node.namespace.rstrip("/") or None,  # as roslaunch sets ROS_NAMESPACE
                              params={**launch.params, **turtlesim.world_params(launch, world)},
                              required=node.required, output=node.output, provided=provided))
    if not specs:
        raise LaunchError(f"{launch.file.name} starts only turtlesim_node ({world.node.where}): add a <node> for "
                          "your script")
    return tuple(specs), notes
