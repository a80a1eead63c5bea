"""turtlesim's nodes in a student's launch file: ``turtlesim_node`` is rosgrade's turtlesim world, and
``turtle_teleop_key`` a node the grader ships (``grader/nodes/turtle_teleop_key.py``), run confined like the
student's nodes.

The world's topics and services have the names ``turtlesim_node`` has in the root namespace (``/turtle1/cmd_vel``,
``/spawn``...). When the launch file starts it elsewhere (``ns=``, a ``<group ns>``, ``<remap>``), every other node
gets remaps that bridge the two: the name the launched turtlesim would use (``/sim/turtle1/cmd_vel``) leads to the
world's, and the world's own name, which nothing would serve in real ROS, to an unserved one, so a node in the wrong
namespace reaches no turtle, as with roslaunch. rospy applies one remap per name, so a node's own ``<remap>`` whose
target is one of these names is rewritten to where the bridge leads.

A launch file that starts turtlesim_node more than once (the roslaunch tutorial's turtlemimic.launch) gets a window
for each: the first one in the root namespace (else the first one) is bridged as above and graded; each other is a
window under the names it was launched with (``/turtlesim2/turtle1/cmd_vel``), so it may not be remapped.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from grader.launch import names
from grader.launch.model import Launch, LaunchError, LaunchNode
from sim.scenario import TurtlesimWindow

PACKAGE = "turtlesim"
WORLD_NODE = "turtlesim_node"
TELEOP_NODE = "turtle_teleop_key"
TELEOP_SCRIPT = Path(__file__).resolve().parents[1] / "nodes" / "turtle_teleop_key.py"
ROBOT = "turtlesim"  # the rubric robot that is turtlesim's world
# turtle_frame.cpp's services and turtle1's topics and services, relative to turtlesim_node's namespace.
WORLD_NAMES = ("clear", "reset", "spawn", "kill", "turtle1/cmd_vel", "turtle1/pose", "turtle1/color_sensor",
               "turtle1/set_pen", "turtle1/teleport_absolute", "turtle1/teleport_relative")
UNSERVED = "/no_turtlesim_here"  # where a world name goes when the launched turtlesim does not use it
WORLD_NAME = "/turtlesim"  # the world's node name: its private parameters (background_r...) live under it


@dataclass(frozen=True)
class TurtlesimNode:
    """The launch file's ``turtlesim_node`` and the names it would use that differ from the world's."""

    node: LaunchNode
    launched: dict[str, str]  # world name (/turtle1/cmd_vel) -> the launched node's name for it (/sim/turtle1/cmd_vel)
    others: tuple[LaunchNode, ...] = ()  # further turtlesim_nodes: windows under their own names

    @property
    def windows(self) -> list[TurtlesimWindow]:
        """The further windows; their parameters are on the run's parameter server, as roslaunch sets them."""
        return [TurtlesimWindow(node=node.full_name) for node in self.others]

    @property
    def world_names(self) -> dict[str, str]:
        """The launched node's names (and its node name) that lead to the world's, for the scenario's own acts."""
        if not self.launched:
            return {}
        return {**{launched: world for world, launched in self.launched.items()}, self.node.full_name: WORLD_NAME}

    def simulates(self, node: LaunchNode) -> bool:
        """Whether ``node`` is one of the turtlesim windows (not a process the run starts)."""
        return node is self.node or any(node is other for other in self.others)


def is_world(process: dict[str, Any]) -> bool:
    """Whether a ROS 2 launch file's process is turtlesim_node (the world, not a process rosgrade starts)."""
    return (process.get("kind") == "node" and process.get("package") == PACKAGE
            and process.get("executable") == WORLD_NODE)


def first_window(processes: list[dict[str, Any]]) -> dict[str, Any] | None:
    """The ROS 2 launch file's turtlesim_node that is the run's first window, with turtlesim's own names: the first
    one started in the root namespace, else the first one (None without any)."""
    started = [p for p in processes if is_world(p)]
    rooted = [p for p in started if not (p.get("namespace") or "").strip("/")]
    return (rooted or started or [None])[0]


def resolve(node: LaunchNode, name: str) -> str:
    """``name`` as the node resolves it: global, private (``~``) to the node, or relative to its namespace."""
    if name.startswith("~"):
        return names.canonical(f"{node.full_name}/{name[1:]}")
    return names.canonical(names.join(node.namespace, name))


def world_node(launch: Launch) -> TurtlesimNode | None:
    """The launch file's turtlesim_nodes (None without one): the first window and the others; LaunchError for a remap
    that merges the first one's names, or windows the grader cannot tell apart."""
    started = [n for n in launch.nodes if n.pkg == PACKAGE and n.type == WORLD_NODE]
    if not started:
        return None
    node = next((n for n in started if n.namespace == "/"), started[0])
    others = tuple(n for n in started if n is not node)
    seen = {node.full_name}
    for other in others:
        if other.namespace == "/" or other.full_name in seen:
            raise LaunchError(f"{other.where}: this turtlesim_node would share its topics and services with the one "
                              f"at {node.where if other.namespace == '/' else 'the same name'}: start each turtlesim "
                              "in a namespace of its own (<group ns=\"turtlesim2\">)")
        if other.remaps:
            raise LaunchError(f"{other.where}: the grader runs a second turtlesim window under the names of its "
                              "namespace only: remove its <remap> and remap the nodes that talk to it instead")
        try:
            TurtlesimWindow(node=other.full_name)  # the scenario's own check of a window's node name
        except ValidationError:
            raise LaunchError(f"{other.where}: turtlesim_node {other.full_name} is not a valid ROS node name (each "
                              "part a letter or _ then letters, digits or _)") from None
        seen.add(other.full_name)
    remaps = {resolve(node, source): resolve(node, target) for source, target in node.remaps}
    launched = {}
    for leaf in WORLD_NAMES:
        name = resolve(node, leaf)
        launched["/" + leaf] = remaps.get(name, name)
    if len(set(launched.values())) < len(launched):
        raise LaunchError(f"{node.where}: the remaps of turtlesim_node give two of its topics or services the same "
                          "name; the grader cannot run turtlesim that way")
    return TurtlesimNode(node, {world: name for world, name in launched.items() if world != name}, others)


def bridge(node: LaunchNode, turtlesim: TurtlesimNode | None) -> tuple[tuple[str, str], ...]:
    """The node's remaps with the bridge to the world's names added (its own remaps first, their targets bridged)."""
    if turtlesim is None or not turtlesim.launched:
        return node.remaps
    leads = {launched: world for world, launched in turtlesim.launched.items()}
    for world in turtlesim.launched:
        if world not in leads:
            leads[world] = UNSERVED + world
    own = [(source, leads.get(resolve(node, target), target)) for source, target in node.remaps]
    remapped = {resolve(node, source) for source, _ in node.remaps}
    return (*own, *((source, target) for source, target in sorted(leads.items()) if source not in remapped))


def _private(launch: Launch, turtlesim: TurtlesimNode | None) -> dict[str, object]:
    """The parameters the launch file sets under turtlesim_node's name (its private ones: background_r...)."""
    if turtlesim is None:
        return {}
    prefix = turtlesim.node.full_name + "/"
    return {name: value for name, value in sorted(launch.params.items()) if name.startswith(prefix)}


def world_params(launch: Launch, turtlesim: TurtlesimNode | None) -> dict[str, object]:
    """turtlesim_node's private parameters where the world reads them (under /turtlesim), set before it starts as
    roslaunch sets them; nothing to add when the launch file names it /turtlesim already."""
    if turtlesim is None or turtlesim.node.full_name == WORLD_NAME:
        return {}
    cut = len(turtlesim.node.full_name)
    return {WORLD_NAME + name[cut:]: value for name, value in _private(launch, turtlesim).items()}


def check_robot(launch: Launch, turtlesim: TurtlesimNode | None, robot: str) -> list[str]:
    """Findings on the world the launch file starts against the task's robot; LaunchError when they cannot meet."""
    if turtlesim is not None and robot != ROBOT:
        raise LaunchError(f"{turtlesim.node.where}: the launch file starts turtlesim_node, but this task is graded "
                          f"on a {robot}, not on turtlesim: remove the turtlesim node (a {robot} listens on /cmd_vel)")
    if robot != ROBOT:
        return []
    if launch.worlds:
        world = launch.worlds[0]
        raise LaunchError(f"{world.where}: {world.package}/{world.file} starts Gazebo with a {world.robot}, but this "
                          "task is graded on turtlesim: start <node pkg=\"turtlesim\" type=\"turtlesim_node\" "
                          "name=\"sim\"/> instead")
    notes = []
    if turtlesim is None:
        notes.append(f"{launch.file.name} starts no turtlesim_node, so roslaunch alone would show no turtle; the "
                     "grader ran turtlesim anyway. Add <node pkg=\"turtlesim\" type=\"turtlesim_node\" name=\"sim\"/>.")
    elif turtlesim.launched:
        moved = ", ".join(f"{turtlesim.launched[w]} (recorded as {w})" for w in ("/turtle1/cmd_vel", "/turtle1/pose")
                          if w in turtlesim.launched)
        notes.append(f"{turtlesim.node.where}: turtlesim_node runs as {turtlesim.node.full_name}, so its turtle uses "
                     f"{moved or 'other service names'}, as with roslaunch; turtlesim's usual names reach no turtle.")
    private = _private(launch, turtlesim)
    if private and turtlesim.node.full_name != WORLD_NAME:
        notes.append(f"{turtlesim.node.where}: the grader's turtlesim runs as {WORLD_NAME}: it starts with "
                     f"{', '.join(private)} as its own parameters, but a change to them while it runs does not "
                     "reach it (it reads them again on /clear and /reset under its own name).")
    notes += [f"{other.where}: a second turtlesim window, {other.full_name}: its turtles are recorded under its names "
              f"({other.namespace}turtle1/pose), and the task is graded on the first window's turtle."
              for other in (turtlesim.others if turtlesim is not None else ())]
    return notes
