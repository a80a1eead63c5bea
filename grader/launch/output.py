"""The text ``roslaunch --dump-params`` and ``roslaunch --nodes`` print for a launch file, byte for byte."""
from __future__ import annotations

import yaml

from grader.launch.model import Launch


def dump_params(launch: Launch) -> str:
    """The parameters as YAML, keys sorted, followed by an empty line (as roslaunch writes them)."""
    return yaml.safe_dump(launch.params) + "\n"


def node_names(launch: Launch) -> str:
    """The resolved name of every node, one per line, in the order they are declared."""
    return "\n".join(node.full_name for node in launch.nodes) + "\n"
