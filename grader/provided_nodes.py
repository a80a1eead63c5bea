"""The grader's own nodes a rubric starts beside the student's (``[[grader_nodes]]``), in the run's ROS version.

A rubric names a shipped node once (``turtle_teleop_key.py``); a ROS 2 run gets its ROS 2 variant when the grader ships
one (``turtle_teleop_key_ros2.py``), as ``ros2 run turtlesim turtle_teleop_key`` is Jazzy's node, not Noetic's. Jazzy's
teleop sends its rotate keys (G B V C D E R T, F to cancel) to turtlesim's ``rotate_absolute`` action, which a grader
node serves beside the world (``turtlesim_rotate_absolute.py``): it is started with the teleop when the rubric does not
start it already, since in a real run turtlesim itself would serve it.
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


def script_for(script: str, flavour: str) -> str:
    """The shipped script a rubric's ``script`` names in a run of ``flavour``: its ROS 2 variant when there is one."""
    stem = script.removesuffix(".py")
    variant = f"{stem}{ROS2_SUFFIX}.py"
    if flavour == ROS2 and not stem.endswith(ROS2_SUFFIX) and (GRADER_NODES / variant).is_file():
        return variant
    return script


def provided_specs(nodes: Sequence[GraderNode], flavour: str, workspace: Workspace) -> tuple[NodeSpec, ...]:
    """The node specs of a rubric's grader nodes for a run whose student nodes are of ``flavour`` (plus the
    rotate_absolute server a ROS 2 teleop needs), each confined as a student's node and marked as provided."""
    scripts = [(script_for(node.script, flavour), tuple(node.args)) for node in nodes]
    names = {script for script, _ in scripts}
    if ROS2_TELEOP in names and ROTATE_SERVER not in names:
        scripts.append((ROTATE_SERVER, ()))
    return tuple(NodeSpec(script=GRADER_NODES / script, args=args, provided=True,
                          flavour=client_library(GRADER_NODES / script, workspace))
                 for script, args in scripts)
