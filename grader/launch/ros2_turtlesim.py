"""turtlesim in a ROS 2 launch file: ``turtlesim_node`` is rosgrade's one turtlesim world, whose names are those the
node has in the root namespace (``/turtle1/cmd_vel``, ``/spawn``, ``/turtle1/rotate_absolute``...).

When the launch file starts it in a namespace (``Node(package='turtlesim', namespace='turtlesim1', ...)``) or remaps
its names, every other node gets remap rules that bridge the two, as the ROS 1 launch path does
(``grader.launch.turtlesim``): the name the launched turtlesim would use (``/turtlesim1/turtle1/cmd_vel``) leads to the
world's, and the world's own name, which nothing would serve under ``ros2 launch``, to an unserved one, so a node in
another namespace reaches no turtle. rcl applies the first rule that matches a name, so a node's own rule whose target
is one of these names is rewritten to where the bridge leads. The launch file's own ``ros2`` command lines, which the
grader carries out (``ros2 service call /turtlesim1/spawn``, ``ros2 param set /turtlesim1/sim background_r 120``),
reach the world the same way.

A launch file that starts turtlesim_node more than once (the launch tutorial's turtlesim_mimic_launch.py) gets a
turtlesim window for each: the first one in the root namespace (else the first one) is bridged as above and graded;
each other is a window of its own under the names it was launched with (``/turtlesim2/turtle1/cmd_vel``), which
needs no bridge, so it may not be remapped.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from grader.launch import names
from grader.launch.ros2_acts import KINDS, LaunchActs, renamed, world_params
from grader.launch.model import LaunchError
from grader.launch.turtlesim import UNSERVED, WORLD_NAMES, first_window, is_world
from grader.nodelib.common.rosgrade_param_files import ParamFileError
from sim.scenario import TurtlesimWindow

ACTION = "turtle1/rotate_absolute"  # Jazzy's turtle1 action; rosgrade's nodes remap its five parts one by one
ACTION_PARTS = ("_action/send_goal", "_action/cancel_goal", "_action/get_result", "_action/feedback",
                "_action/status")
ROS2_WORLD_NAMES = (*WORLD_NAMES, ACTION, *(f"{ACTION}/{part}" for part in ACTION_PARTS))
WORLD_NODE_NAME = "/turtlesim"  # the world's node: its parameters and parameter services live under it
_REMAP_FLAGS = ("-r", "--remap")


@dataclass(frozen=True)
class Ros2Turtlesim:
    """The launch file's turtlesim_node (its process) and the names it would use that differ from the world's."""

    process: dict[str, Any]
    launched: dict[str, str]  # world name (/turtle1/cmd_vel) -> the launched node's (/turtlesim1/turtle1/cmd_vel)
    windows: tuple[TurtlesimWindow, ...] = ()  # the other turtlesim_nodes, each a window under its own names
    notes: tuple[str, ...] = ()  # what the report says about those windows


def _identity(process: dict[str, Any]) -> tuple[str, str]:
    """The node's name and namespace as launch starts it (the executable's own node name when launch gives none)."""
    namespace = names.canonical(process.get("namespace") or "") or "/"
    namespace = namespace if namespace.startswith("/") else "/" + namespace
    return process.get("node_name") or process["executable"], namespace


def _full_name(process: dict[str, Any]) -> str:
    node_name, namespace = _identity(process)
    return f"{namespace.rstrip('/')}/{node_name}"


def expand(name: str, node_name: str, namespace: str) -> str:
    """``name`` as rcl expands it for a node: global, private (``~``) or relative to the node's namespace."""
    if name.startswith("~"):
        return names.canonical(f"{namespace.rstrip('/')}/{node_name}/{name[1:]}")
    return names.canonical(name if name.startswith("/") else f"{namespace.rstrip('/')}/{name}")


def _rules(args: list[str]) -> list[tuple[int, str, str]]:
    """The node's name remap rules in its argv: (index of the rule's word, from, to); no __node/__ns, no node scope."""
    rules = []
    for index in range(1, len(args)):
        if args[index - 1] in _REMAP_FLAGS and ":=" in args[index]:
            source, _, target = args[index].partition(":=")
            if not source.startswith("__") and ":" not in source:
                rules.append((index, source, target))
    return rules


def world(processes: list[dict[str, Any]], file_name: str) -> Ros2Turtlesim | None:
    """The launch file's turtlesim_nodes (None without one): the first window and the others; LaunchError for remaps
    that merge the first one's names, or windows rosgrade cannot tell apart."""
    process = first_window(processes)
    if process is None:
        return None
    windows, notes = _other_windows([p for p in processes if is_world(p) and p is not process], process, file_name)
    node_name, namespace = _identity(process)
    remaps = {expand(s, node_name, namespace): expand(t, node_name, namespace) for _, s, t in _rules(process["args"])}
    launched = {}
    for leaf in ROS2_WORLD_NAMES:
        name = expand(leaf, node_name, namespace)
        launched["/" + leaf] = remaps.get(name, name)
    if len(set(launched.values())) < len(launched):
        raise LaunchError(f"{file_name}: the remappings of turtlesim_node give two of its topics or services the same "
                          "name; rosgrade cannot run turtlesim that way")
    return Ros2Turtlesim(process, {w: name for w, name in launched.items() if w != name}, windows, notes)


def _other_windows(others: list[dict[str, Any]], first: dict[str, Any],
                   file_name: str) -> tuple[tuple[TurtlesimWindow, ...], tuple[str, ...]]:
    """A window for each turtlesim_node besides the first, under the name it was launched with, and findings."""
    windows, notes, seen = [], [], {_full_name(first)}
    for process in others:
        node, namespace = _full_name(process), _identity(process)[1]
        if node in seen or namespace == "/":
            raise LaunchError(f"{file_name} starts turtlesim_node {len(others) + 1} times, and {node} would share "
                              "its topics and services with another: start each turtlesim in a namespace of its own "
                              "(Node(..., namespace='turtlesim2'))")
        if _rules(process["args"]):
            raise LaunchError(f"{file_name} remaps the names of its turtlesim_node {node}; rosgrade runs a second "
                              "turtlesim window under the names of its namespace only: remap the nodes that talk to "
                              "it instead")
        seen.add(node)
        try:
            params = world_params(process)
        except ParamFileError as exc:
            notes.append(f"{file_name} gives turtlesim_node {node} parameters rcl refuses: {exc.problem}.")
            params = {}
        try:
            windows.append(TurtlesimWindow(node=node, params=params))
        except ValidationError:
            raise LaunchError(f"{file_name} starts turtlesim_node as {node}, which is not a valid ROS node name (each "
                              "part a letter or _ then letters, digits or _)") from None
        notes.append(f"{file_name} starts a second turtlesim window, {node}: its turtles are recorded under its names "
                     f"({namespace.rstrip('/')}/turtle1/pose), and the task is graded on the first window's turtle.")
    return tuple(windows), tuple(notes)


def bridged(args: list[str], process: dict[str, Any], turtlesim: Ros2Turtlesim | None) -> list[str]:
    """The node's argv with its own rules' targets led to the world and the bridge's rules after them."""
    if turtlesim is None or not turtlesim.launched:
        return list(args)
    node_name, namespace = _identity(process)
    leads = {launched: world_name for world_name, launched in turtlesim.launched.items()}
    for world_name in turtlesim.launched:
        leads.setdefault(world_name, UNSERVED + world_name)
    out = list(args)
    remapped = set()
    for index, source, target in _rules(out):
        remapped.add(expand(source, node_name, namespace))
        lead = leads.get(expand(target, node_name, namespace))
        if lead is not None:
            out[index] = f"{source}:={lead}"
    extra = [word for source, target in sorted(leads.items()) if source not in remapped
             for word in ("-r", f"{source}:={target}")]
    return [*out, "--ros-args", *extra] if extra else out


def finding(turtlesim: Ros2Turtlesim | None, file_name: str) -> list[str]:
    """What the report says about a turtlesim_node launched under other names than the world's, and other windows."""
    if turtlesim is None:
        return []
    if not turtlesim.launched:
        return list(turtlesim.notes)
    moved = ", ".join(f"{turtlesim.launched[w]} (recorded as {w})" for w in ("/turtle1/cmd_vel", "/turtle1/pose")
                      if w in turtlesim.launched)
    return [f"{file_name} starts turtlesim_node as {_full_name(turtlesim.process)}, so its turtle uses "
            f"{moved or 'other service names'}, as with ros2 launch; turtlesim's usual names reach no turtle.",
            *turtlesim.notes]


def bridged_acts(acts: LaunchActs, turtlesim: Ros2Turtlesim | None) -> LaunchActs:
    """The launch file's ros2 command lines with the launched turtlesim's names led to the world's (its node name to
    the world's node, for ``ros2 param set``), the names to lead the scenario's own acts through, and its other
    turtlesim windows."""
    if turtlesim is None:
        return acts
    names = {launched: world_name for world_name, launched in turtlesim.launched.items()}
    if names:
        names[_full_name(turtlesim.process)] = WORLD_NODE_NAME
    return LaunchActs(**{kind: renamed(getattr(acts, kind), names) for kind in KINDS},
                      world_params=acts.world_params, turtlesim_windows=list(turtlesim.windows), world_names=names)
