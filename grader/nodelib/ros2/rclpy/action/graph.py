"""rclpy.action's graph queries, as rcl_action answers them: an action is a topic ending in ``/_action/feedback``
whose type is ``<action type>_FeedbackMessage``; a node serves the actions whose feedback it publishes and is a client
of those whose feedback it subscribes to. A node here knows the run's graph as its ``get_topic_names_and_types``
does: its process's own endpoints, the world's topics and the other nodes it has discovered."""
from __future__ import annotations

from .._graph import endpoints, names_and_types
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
    """A node's actions: this process's (its endpoints, action entities included), or another's from the graph."""
    if (remote_node_name, remote_node_namespace) not in node.get_node_names_and_namespaces():
        raise RCLError(f"Failed to get action {what} names and type: error not set")
    if any((n._name, n._namespace) == (remote_node_name, remote_node_namespace) for n in node._local_nodes()):
        return _actions(names_and_types((topic, t) for k, topic, t in endpoints.values() if k == kind))
    return _actions(node._endpoints_of(remote_node_name, remote_node_namespace, kind))


def get_action_server_names_and_types_by_node(node, remote_node_name: str,
                                              remote_node_namespace: str) -> list[tuple[str, list[str]]]:
    """The actions a node serves (it publishes their feedback); an unknown node is rcl_action's RCLError."""
    return _by_node(node, remote_node_name, remote_node_namespace, "pub", "server")


def get_action_client_names_and_types_by_node(node, remote_node_name: str,
                                              remote_node_namespace: str) -> list[tuple[str, list[str]]]:
    """The actions a node is a client of (it subscribes to their feedback); an unknown node is an RCLError."""
    return _by_node(node, remote_node_name, remote_node_namespace, "sub", "client")
