"""The grader's own nodes a rubric starts beside the student's (``[[grader_nodes]]``), in the run's ROS version.

A rubric names a shipped node once (``turtle_teleop_key.py``); a ROS 2 run gets its ROS 2 variant when the grader ships
one (``turtle_teleop_key_ros2.py``), as ``ros2 run turtlesim turtle_teleop_key`` is Jazzy's node, not Noetic's. Jazzy's
teleop sends its rotate keys (G B V C D E R T, F to cancel) to turtlesim's ``rotate_absolute`` action, which a grader
node serves beside the world (``turtlesim_rotate_absolute.py``): it is started with the teleop when the rubric does not
start it already, since in a real run turtlesim itself would serve it. A launch file's ``turtle_teleop_key`` or
``mimic`` of package turtlesim (roslaunch's or ROS 2 launch's) runs the shipped script that stands for it
(``TURTLESIM_EXECUTABLES``), the same way: ``turtle_mimic.py`` (Noetic's) or ``turtle_mimic_ros2.py`` (Jazzy's).
"""
from __future__ import annotations

from collections.abc import Sequence

from grader.rubric import GRADER_NODES, GraderNode
from grader.runtime import NodeSpec
from grader.runtime.client_library import ROS2, client_library
from grader.workspace import Workspace

ROS2_SUFFIX = "_ros2"  # turtle_teleop_key.py -> turtle_teleop_key_ros2.py
ROS2_TELEOP = f"turtle_teleop_key{ROS2_SUFFIX}.py"
ROTATE_SERVER = "turtlesim_rotate_absolute.py"  # what Jazzy's turtlesim serves as /turtle1/rotate_absolute
# turtlesim's executables a launch file may start that the grader ships (`rosrun`/`ros2 run turtlesim <executable>`)
TURTLESIM_EXECUTABLES = {"turtle_teleop_key": "turtle_teleop_key.py", "mimic": "turtle_mimic.py"}


def script_for(script: str, flavour: str) -> str:
    """The shipped script a rubric's ``script`` names in a run of ``flavour``: its ROS 2 variant when there is one."""
    stem = script.removesuffix(".py")
    variant = f"{stem}{ROS2_SUFFIX}.py"
    if flavour == ROS2 and not stem.endswith(ROS2_SUFFIX) and (GRADER_NODES / variant).is_file():
        return variant
    return script


def companions(scripts: Sequence[str]) -> list[str]:
    """The shipped nodes that must run beside ``scripts`` (the rotate_absolute server a ROS 2 teleop needs), once."""
    return [ROTATE_SERVER] if ROS2_TELEOP in scripts and ROTATE_SERVER not in scripts else []


def provided_spec(script: str, workspace: Workspace, args: Sequence[str] = ()) -> NodeSpec:
    """A shipped node's spec, confined as a student's node and marked as provided."""
    return NodeSpec(script=GRADER_NODES / script, args=tuple(args), provided=True,
                    flavour=client_library(GRADER_NODES / script, workspace))


def launched_script(package: str, executable: str, flavour: str) -> str | None:
    """The shipped script a launch file's node of ``package`` runs as in a run of ``flavour`` (None: not shipped)."""
    script = TURTLESIM_EXECUTABLES.get(executable) if package == "turtlesim" else None
    return None if script is None else script_for(script, flavour)


def provided_specs(nodes: Sequence[GraderNode], flavour: str, workspace: Workspace) -> tuple[NodeSpec, ...]:
    """The node specs of a rubric's grader nodes for a run whose student nodes are of ``flavour`` (plus the
    rotate_absolute server a ROS 2 teleop needs), each confined as a student's node and marked as provided."""
    scripts = [(script_for(node.script, flavour), tuple(node.args)) for node in nodes]
    scripts += [(script, ()) for script in companions([script for script, _ in scripts])]
    return tuple(provided_spec(script, workspace, args) for script, args in scripts)
