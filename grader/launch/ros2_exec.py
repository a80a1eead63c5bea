"""A launch file's ExecuteProcess that starts a ROS node (`ros2 run PKG EXE [args]`, `python3 SCRIPT.py [args]`, a
script of the submission run by its path), read as the node it starts: `ros2 run` hands the executable its own
arguments unchanged (no name, namespace or parameter file of launch's), so the node gets exactly those, and starts
when launch starts the ExecuteProcess. A command line through a shell is read as the shell would read one simple
command; a compound one (pipes, redirections, `&&`, `;`) or a shell expansion is said not to be run."""
from __future__ import annotations

import os
import shlex
from pathlib import Path
from typing import Any

from grader.launch.ros2_index import EXTERNAL_PACKAGES, INSTALL, WORLD_PACKAGES
from grader.workspace import WorkspaceError
from grader.workspace.model import Workspace

_OPERATOR_CHARS = set("|&;<>()")
_PYTHONS = ("python3", "python")
MAX_PARAMS_FILE = 1_000_000  # bytes of a parameter file named on an ExecuteProcess's command line


class ExecError(Exception):
    """An ExecuteProcess command line that starts a node rosgrade cannot start as written (the reason)."""


def shell_words(text: str) -> list[str]:
    """The words of a shell command line that is one simple command, as the shell splits them; ExecError when it
    is not one (several commands, pipes, redirections) or needs the shell to expand something."""
    if "$" in text or "`" in text:
        raise ExecError("it needs the shell to expand `$`/`` ` `` (variables or command output), which rosgrade "
                        "does not do")
    lexer = shlex.shlex(text, posix=True, punctuation_chars=True)
    lexer.whitespace_split = True
    try:
        words = list(lexer)
    except ValueError as exc:
        raise ExecError(f"it does not parse as a shell's command line ({exc})") from None
    operators = sorted({word for word in words if set(word) <= _OPERATOR_CHARS})
    if operators:
        raise ExecError(f"it is not a single command (it uses {' '.join(operators)}); start each node with an "
                        "ExecuteProcess or a Node of its own")
    return words


def _words(process: dict[str, Any]) -> list[str]:
    return shell_words(" ".join(process["cmd"])) if process.get("shell") else list(process["cmd"])


def _ros_names(args: list[str]) -> tuple[str | None, str | None]:
    """The node name and namespace the node's own remap rules give it (`-r __node:=`, `-r __ns:=`)."""
    node_name = namespace = None
    for flag, rule in zip(args, args[1:]):
        if flag in ("-r", "--remap"):
            source, _, target = rule.partition(":=")
            if source in ("__node", "__name"):
                node_name = target
            elif source == "__ns":
                namespace = target
    return node_name, namespace


def _params_files(args: list[str], workspace: Workspace) -> list[dict[str, Any]]:
    """Each `--params-file PATH` of the node's arguments with the file's content (a file of the submission)."""
    files = []
    root = workspace.root.resolve()
    for flag, path in zip(args, args[1:]):
        if flag != "--params-file":
            continue
        resolved = (root / path).resolve()
        if root not in resolved.parents or not resolved.is_file() or resolved.stat().st_size > MAX_PARAMS_FILE:
            raise ExecError(f"its parameter file {path} is not a file of the submission")
        files.append({"path": path, "content": resolved.read_text(encoding="utf-8", errors="replace")})
    return files


def _node(process: dict[str, Any], package: str, executable: str, args: list[str], workspace: Workspace,
          script: Path | None = None) -> dict[str, Any]:
    node_name, namespace = _ros_names(args)
    node = {**process, "kind": "node", "package": package, "executable": executable, "args": args,
            "node_name": node_name, "namespace": namespace, "params_files": _params_files(args, workspace),
            "world": package in WORLD_PACKAGES, "external": package in EXTERNAL_PACKAGES}
    if script is not None:
        node["script"] = str(script)
    return node


def _ros2_run(process: dict[str, Any], rest: list[str], workspace: Workspace) -> dict[str, Any]:
    """`ros2 run [--prefix P] PACKAGE EXECUTABLE [args]`: the executable with the rest as its arguments."""
    if rest and (rest[0] == "--prefix" or rest[0].startswith("--prefix=")):
        raise ExecError("`ros2 run --prefix` runs another program before the node, which rosgrade does not do")
    if len(rest) < 2:
        raise ExecError("`ros2 run` needs a package and an executable")
    package, executable, args = rest[0], rest[1], rest[2:]
    if package in WORLD_PACKAGES or package in EXTERNAL_PACKAGES:
        return _node(process, package, executable, args, workspace)
    try:
        workspace.executable(package, executable)
    except WorkspaceError as exc:
        raise ExecError(f"`ros2 run` would print: {exc}") from None
    return _node(process, package, executable, args, workspace)


def _script(process: dict[str, Any], path: str, args: list[str], workspace: Workspace) -> dict[str, Any]:
    """A program of the submission run by its path (relative paths from the submission's folder)."""
    parts = Path(path).parts
    if path.startswith(INSTALL + "/") and len(parts) == 7 and parts[4] == "lib":
        return _ros2_run(process, [parts[5], parts[6], *args], workspace)  # an installed executable's path
    root = workspace.root.resolve()
    script = (root / path).resolve()
    if root not in script.parents or not script.is_file():
        raise ExecError(f"{path} is not a file of the submission")
    package = workspace.enclosing(script)
    return _node(process, package.name if package else "", script.name, args, workspace, script)


def exec_node(process: dict[str, Any], workspace: Workspace) -> dict[str, Any]:
    """The process as the node it starts (kind "node") when it is an ExecuteProcess that starts one; the process
    itself otherwise; ExecError when it would start a node rosgrade cannot start as written."""
    if process.get("kind") != "process":
        return process
    words = _words(process)
    if not words:
        return process
    program = os.path.basename(words[0])
    if program == "ros2" and words[1:2] == ["run"]:
        return _ros2_run(process, words[2:], workspace)
    if program == "ros2" and words[1:2] == ["launch"]:
        raise ExecError("rosgrade does not run `ros2 launch` inside a launch file; include the other launch file "
                        "with IncludeLaunchDescription, which starts the same nodes")
    if program == "ros2":
        return process  # a ros2 command line the grader carries out (ros2_acts), or a finding there
    if program.startswith(_PYTHONS) and len(words) > 1:
        rest = words[1:]
        while rest and rest[0].startswith("-"):
            if rest[0] in ("-m", "-c"):
                raise ExecError(f"`{program} {rest[0]}` does not run a script of the submission; start the node "
                                "with `ros2 run PACKAGE EXECUTABLE` or a Node")
            rest = rest[1:]  # the interpreter's own options (-u...)
        return _script(process, rest[0], rest[1:], workspace) if rest else process
    if "/" in words[0]:
        return _script(process, words[0], words[1:], workspace)
    return process


def exec_nodes(processes: list[dict[str, Any]], workspace: Workspace,
               file_name: str) -> tuple[list[dict[str, Any]], list[str]]:
    """The launch file's processes with each ExecuteProcess that starts a node read as that node, and findings for
    those not run (each then of kind "not_run", so that nothing else carries it out)."""
    out: list[dict[str, Any]] = []
    findings: list[str] = []
    for process in processes:
        try:
            out.append(exec_node(process, workspace))
        except ExecError as exc:
            findings.append(f"{file_name} runs `{' '.join(process['cmd'])}`, which rosgrade did not run: {exc}.")
            out.append({**process, "kind": "not_run"})
    return out, findings
