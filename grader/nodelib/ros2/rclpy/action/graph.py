"""rclpy.action's graph queries, as rcl_action answers them: an action is a topic ending in ``/_action/feedback``
whose type is ``<action type>_FeedbackMessage``; a node serves the actions whose feedback it publishes and is a client
of those whose feedback it subscribes to. A node here knows the run's graph as its ``get_topic_names_and_types``
does: its process's own endpoints and the world's topics."""
from __future__ import annotations

from .._graph import endpoints
from .._rclpy_pybind11 import RCLError

_FEEDBACK = "/_action/feedback"
_MESSAGE = "_FeedbackMessage"


def _actions(topics) -> list[tuple[str, list[str]]]:
    found = []
    for topic, types in topics:
        action_types = sorted(t[:-len(_MESSAGE)] for t in types if t.endswith(_MESSAGE))
        if topic.endswith(_FEEDBACK) and action_types:
            found.append((topic[:-len(_FEEDBACK)], action_types))
    return sorted(found)


def get_action_names_and_types(node) -> list[tuple[str, list[str]]]:
    """Every action on the graph the node knows, with its types."""
    return _actions(node.get_topic_names_and_types())


def _by_node(node, remote_node_name: str, remote_node_namespace: str, kind: str, what: str):
    if (remote_node_name, remote_node_namespace) not in node.get_node_names_and_namespaces():
        raise RCLError(f"Failed to get action {what} names and type: error not set")
    topics: dict[str, set[str]] = {}
    for handle_kind, topic, type_name in endpoints.values():
        if handle_kind == kind:
            topics.setdefault(topic, set()).add(type_name)
    return _actions(sorted(topics.items()))


def get_action_server_names_and_types_by_node(node, remote_node_name: str,
                                              remote_node_namespace: str) -> list[tuple[str, list[str]]]:
    """The actions a node serves (it publishes their feedback); an unknown node is rcl_action's RCLError."""
    return _by_node(node, remote_node_name, remote_node_namespace, "pub", "server")


def get_action_client_names_and_types_by_node(node, remote_node_name: str,
                                              remote_node_namespace: str) -> list[tuple[str, list[str]]]:
    """The actions a node is a client of (it subscribes to their feedback); an unknown node is an RCLError."""
    return _by_node(node, remote_node_name, remote_node_namespace, "sub", "client")
