"""The runtime's node specs for what a ROS 2 launch file starts: each node of the submission with the argv launch_ros
builds for it and its parameter files handed over by content; turtlesim_node is the world (bridged to when launched in
a namespace), turtlesim's turtle_teleop_key and mimic run as the grader's shipped nodes, and what rosgrade does not run
(external packages, other programs, delays) is said in a finding."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from grader.launch import ros2_turtlesim
from grader.launch.model import LaunchError
from grader.launch.ros2_acts import LaunchActs, launch_acts
from grader.launch.ros2_cli import external_include_notes
from grader.launch.ros2_exec import exec_nodes
from grader.launch.ros2_hints import hint_for
from grader.launch.ros2_eval import Ros2LaunchError, evaluate
from grader.launch.ros2_index import installed, not_installed
from grader.launch.specs import MAX_NODES
from grader.launch.turtlesim import is_world
from grader.provided_nodes import companions, launched_script, provided_spec
from grader.rubric import GRADER_NODES
from grader.runtime.client_library import ROS2, EntryPoint, client_library, entry_point, import_roots
from grader.runtime.spec import NodeSpec, Start, file_arg
from grader.workspace import WorkspaceError
from grader.workspace.model import Workspace


def _argv(process: dict[str, Any]) -> tuple[tuple[str, ...], tuple[tuple[str, bytes], ...]]:
    """The node's arguments with each --params-file given as a file handed to the node (its content)."""
    args: list[str] = []
    files: list[tuple[str, bytes]] = []
    contents = iter(process.get("params_files", []))
    for index, word in enumerate(process["args"]):
        if index > 0 and process["args"][index - 1] == "--params-file":
            name = f"launch_params_{len(files) + 1}.yaml"
            files.append((name, str(next(contents)["content"]).encode()))
            args.append(file_arg(name))
        else:
            args.append(word)
    return tuple(args), tuple(files)


def _start(process: dict[str, Any], started: dict[str, tuple[int, float]]) -> tuple[Start, str | None]:
    """When the node starts in the run (``started``: the run's nodes so far by launch name, with their delay), and a
    finding when the run cannot start it as launch would (after a process rosgrade does not run)."""
    delay = float(process.get("delay") or 0.0)
    after = process.get("after")
    if not after:
        return Start(delay_s=delay, said=f"{delay:g} s after the start (TimerAction)" if delay else ""), None
    trigger = after.get("process", "the launch")
    verb = {"exit": "exits", "start": "starts"}.get(after["event"], "shuts down")
    if trigger in started:
        index, trigger_delay = started[trigger]  # named as launch names its processes: odom_subscriber-1
        return Start(delay_s=max(0.0, round(delay - trigger_delay, 9)), after=index, on=after["event"],
                     said=f"when {trigger} {verb}"), None
    # After a process the run does not have (a ros2 command the grader carries out, a program not run): from
    # launch's own time for that process.
    return Start(delay_s=delay), f"starts when {trigger} {verb}; rosgrade starts it at {delay:g} s"


def _student_node(process: dict[str, Any], workspace: Workspace, file: Path) -> tuple[Path, EntryPoint | None]:
    """The script of the submission the node runs and the console_scripts entry point that runs it: the one of the
    executable launch names (several may share a module), none for a script run by its path (a file, as python runs
    it); LaunchError when the package does not have the executable."""
    if "script" in process:
        return Path(process["script"]), None
    try:
        found = workspace.executable(process["package"], process["executable"])
    except WorkspaceError as exc:
        raise LaunchError(f"{file.name}: {exc}") from None
    script = found.script.resolve()
    entry = entry_point(script, workspace)
    if entry is None or found.entry is None:
        return script, entry
    module, _, function = found.entry.partition(":")
    return script, replace(entry, executable=found.name, module=module, function=function)


def ros2_node_specs(file: Path, workspace: Workspace, args: dict[str, str],
                    stdin: str | None) -> tuple[tuple[NodeSpec, ...], list[str], LaunchActs]:
    """The nodes `ros2 launch` would start from `file`, as node specs, with findings and what the grader carries out
    for its ros2 command lines; LaunchError if it fails. An ExecuteProcess that starts a node (`ros2 run`, a script)
    is that node."""
    package = workspace.enclosing(file)
    if package is not None and package.build_type != "catkin" and not installed(package, file):
        raise LaunchError(not_installed(package, file))
    try:
        result = evaluate(file, workspace, list(args.items())).result
    except Ros2LaunchError as exc:
        raise LaunchError(str(exc)) from None
    error = result.get("error")
    if error:
        where = f" (at {error['where']})" if error.get("where") else ""
        hint = hint_for(error["message"], workspace)
        said = f"{file.name}: [ERROR] [launch]: {error['message']}{where}"
        # launch's own text, then what to change, as its own sentence
        raise LaunchError(said + (("" if said.endswith((".", "!", "?")) else ".") + f" {hint}" if hint else ""))
    declared = {a["name"] for a in result.get("arguments", [])}
    findings = [f"{file.name} {note}" for note in external_include_notes(result)]
    findings += [f"{file.name} declares no argument {name}, so `ros2 launch` ignored the task's {name}:={value}: "
                f"declare it with DeclareLaunchArgument('{name}') and use LaunchConfiguration('{name}') where the "
                "value is needed." for name, value in args.items() if name not in declared]
    processes, exec_findings = exec_nodes(result["processes"], workspace, file.name)
    acts, act_findings, handled = launch_acts(processes, file.name)
    findings += exec_findings + act_findings
    turtlesim = ros2_turtlesim.world(processes, file.name)
    findings += ros2_turtlesim.finding(turtlesim, file.name)
    acts = ros2_turtlesim.bridged_acts(acts, turtlesim)
    specs: list[NodeSpec] = []
    started: dict[str, tuple[int, float]] = {}  # launch's name of each node the run starts -> (index, delay)
    for index, process in enumerate(processes):
        if index in handled or is_world(process) or process["kind"] == "not_run":
            continue
        if process["kind"] != "node":
            findings.append(f"{file.name} starts `{' '.join(process['cmd'])}`: rosgrade runs the nodes of a launch "
                            "file and carries out its `ros2 service call`, `ros2 param set`, `ros2 topic pub` and "
                            "`ros2 action send_goal` commands, but no other program; it was not run.")
            continue
        label = f"{process['package']} {process['executable']}"
        shipped = launched_script(process["package"], process["executable"], ROS2)
        if shipped is None and (process.get("world") or process.get("external")):
            findings.append(f"{file.name} starts {label}, which rosgrade does not run (not part of the graded "
                            "simulation).")
            continue
        script, entry = (GRADER_NODES / shipped, None) if shipped is not None \
            else _student_node(process, workspace, file)
        if (process.get("after") or {}).get("event") == "shutdown":
            findings.append(f"{file.name}: {label} starts when launch shuts down (OnShutdown); rosgrade does not run "
                            "it, as launch starts nothing once it is shutting down.")
            continue
        start, said = _start(process, started)
        if said:
            findings.append(f"{file.name}: {label} {said}.")
        started[process["name"]] = (len(specs), float(process.get("delay") or 0.0))
        argv, files = _argv(process)
        argv = tuple(ros2_turtlesim.bridged(list(argv), process, turtlesim))
        output = "screen" if process.get("output") == "screen" else "log"
        if shipped is not None:
            specs.append(replace(provided_spec(shipped, workspace), args=argv, stdin=stdin, files=files,
                                 output=output, start=start))
            continue
        flavour = client_library(script, workspace)
        specs.append(NodeSpec(script=script, args=argv, stdin=stdin, flavour=flavour,
                              entry=entry, import_roots=import_roots(script, workspace, flavour),
                              files=files, output=output, start=start))
    specs += [provided_spec(script, workspace) for script in companions([s.script.name for s in specs if s.provided])]
    if len(specs) > MAX_NODES:
        raise LaunchError(f"{file.name} starts {len(specs)} nodes; a task runs at most {MAX_NODES}")
    if not specs:
        raise LaunchError(f"{file.name} starts none of your nodes (`ros2 launch` would start: "
                          f"{', '.join(p['name'] for p in result['processes']) or 'nothing'})")
    return tuple(specs), findings, acts
