"""Launch files: read roslaunch XML into the nodes, parameters and world a run needs (the runtime never sees XML);
ROS 2 launch files (Python, XML, YAML) are evaluated in the node sandbox by the ``launch`` package of the ROS 2 import
root (``ros2_eval``) and become node specs in ``ros2_specs``."""
from __future__ import annotations

from grader.launch.model import Launch, LaunchError, LaunchNode, Where, WorldLaunch
from grader.launch.output import dump_params, node_names
from grader.launch.packages import enclosing_package, find_packages
from grader.launch.reader import read_launch

__all__ = ["Launch", "LaunchError", "LaunchNode", "Where", "WorldLaunch", "dump_params", "enclosing_package",
           "find_packages", "node_names", "read_launch"]
