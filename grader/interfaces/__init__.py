"""A submission's own .msg/.srv/.action types: read as data (rosbags' parser) into one type catalog per run."""
from __future__ import annotations

from grader.interfaces.catalog import CatalogError, builtin_types, catalog_for, node_payload
from grader.interfaces.reading import InterfaceSet, read_interfaces
from grader.workspace.model import Workspace

__all__ = ["CatalogError", "InterfaceSet", "catalog_for", "node_payload", "read_interfaces", "run_interfaces"]


def run_interfaces(workspace: Workspace, flavour: str) -> InterfaceSet:
    """The interfaces a run of ``flavour`` ("ros1" or "ros2") gets from the workspace's packages, with findings and
    the payload its nodes are given."""
    interfaces = read_interfaces(workspace.packages(), flavour, builtin_types(flavour))
    interfaces.payload = node_payload(interfaces)
    return interfaces
