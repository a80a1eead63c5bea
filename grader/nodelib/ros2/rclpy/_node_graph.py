"""rclpy Node's graph queries: what a node sees of the run's graph (its process's nodes, and the others the grader
shows it at its sim time once DDS discovery has made them visible: rclpy/_graph.py).

A mixin of ``Node``, kept apart so that node.py stays one job: it uses the node's entity lists, context, name and
``handle`` check."""
from __future__ import annotations

from rosgrade_node import runtime

from . import _graph, names
from ._rclpy_pybind11 import NodeNameNonExistentError
from .client import Client
from .publisher import Publisher
from .service import Service
from .subscription import Subscription


class NodeGraph:
    """get_node_names*, get_*_names_and_types[_by_node] and count_* of rclpy's Node."""

    # This process's endpoints it knows itself; the run's other nodes (the world's and /rosgrade included) come from
    # the grader at the node's sim time, once DDS discovery has made them visible (rclpy/_graph.py).
    def get_topic_names_and_types(self, no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        """Every topic on the graph the node sees, with its types, sorted by name."""
        self.handle
        pairs = [*_graph.NODE_PUBLISHERS, *((topic, t) for _k, topic, t in _graph.endpoints.values()),
                 *((topic, _graph.interface_type(t)) for topic, t in runtime.world_topics)]
        for node in _graph.others():
            pairs += node["pub"] + node["sub"]
        return _graph.names_and_types(pairs)

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every service on the graph the node sees (parameter services included), sorted by name as rcl gives them.
        COM2009's number_game.py logs the first one's name."""
        self.handle
        pairs = [pair for node in self._local_nodes() for pair in node._own("srv")]
        return _graph.names_and_types(pairs + [srv for node in _graph.others() for srv in node["srv"]])

    def get_node_names(self) -> list[str]:
        return [name for name, _ in self.get_node_names_and_namespaces()]

    def _local_nodes(self) -> list[NodeGraph]:
        """The live nodes of this node's context (its DDS participant), which the grader sees as one process."""
        return [node for node in (ref() for ref in self._context._nodes) if node is not None and not node._destroyed]

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """This process's nodes and the others it has discovered (a DDS discovery's order is not ROS's: sorted)."""
        self.handle
        mine = [(node._name, node._namespace) for node in self._local_nodes()]
        return mine + sorted(_graph.split_node_name(n["name"]) for n in _graph.others())

    def get_fully_qualified_node_names(self) -> list[str]:
        self.handle
        mine = [node.get_fully_qualified_name() for node in self._local_nodes()]
        return mine + sorted(node["name"] for node in _graph.others())

    def _own(self, kind: str) -> list[tuple[str, str]]:
        """This node's (name, type) of ``kind``, with the endpoints rclpy makes for the node itself and those of its
        action servers and clients (rcl lists them all)."""
        entities = {"pub": self._publishers, "sub": self._subscriptions, "srv": self._services,
                    "cli": self._clients}[kind]
        entity_class = {"pub": Publisher, "sub": Subscription, "srv": Service, "cli": Client}[kind]
        entities = [*entities, *(e for w in self._waitables for e in vars(w).values() if isinstance(e, entity_class))]
        if kind in ("pub", "sub"):
            builtin = [pair for pair in self._builtin_topics() if (pair[0] == "/clock") == (kind == "sub")]
            return builtin + [(e.topic_name, _graph.type_of(e.msg_type)[0]) for e in entities if e._handle is not None]
        return [(e.srv_name, _graph.type_of(e.srv_type)[0]) for e in entities if not e._destroyed]

    def _endpoints_of(self, node_name: str, node_namespace: str, kind: str) -> list[tuple[str, list[str]]]:
        """A node's endpoints of ``kind`` ("pub", "sub", "srv", "cli"); an unknown node is rcl's error."""
        self.handle
        fq = node_namespace.rstrip("/") + "/" + node_name
        for node in self._local_nodes():
            if node.get_fully_qualified_name() == fq:
                return _graph.names_and_types(node._own(kind))
        for node in _graph.others():
            if node["name"] == fq:
                return _graph.names_and_types(node[kind])
        what = {"pub": "publisher", "sub": "subscriber", "srv": "service", "cli": "client"}[kind]
        raise NodeNameNonExistentError(f"cannot get {what} names and types for nonexistent node: error not set")

    def get_publisher_names_and_types_by_node(self, node_name: str, node_namespace: str,
                                              no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        return self._endpoints_of(node_name, node_namespace, "pub")

    def get_subscriber_names_and_types_by_node(self, node_name: str, node_namespace: str,
                                               no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        return self._endpoints_of(node_name, node_namespace, "sub")

    def get_service_names_and_types_by_node(self, node_name: str, node_namespace: str) -> list[tuple[str, list[str]]]:
        return self._endpoints_of(node_name, node_namespace, "srv")

    def get_client_names_and_types_by_node(self, node_name: str, node_namespace: str) -> list[tuple[str, list[str]]]:
        """A node's clients: this node's own; the grader does not know other nodes' clients until they call."""
        return self._endpoints_of(node_name, node_namespace, "cli")

    def _count(self, name: str, kind: str) -> int:
        """Endpoints of ``kind`` on the topic or service: this process's nodes' own and the other nodes' it sees."""
        self.handle
        if kind in ("pub", "sub"):
            fq = names.expand_topic_name(name, self._name, self._namespace)
            names.validate_full_topic_name(fq)
        else:
            fq = self.resolve_service_name(name)
        return sum(1 for node in [*(n._own(kind) for n in self._local_nodes()), *(o[kind] for o in _graph.others())]
                   for endpoint, _ in node if endpoint == fq)

    def count_publishers(self, topic_name: str) -> int:
        return self._count(topic_name, "pub")

    def count_subscribers(self, topic_name: str) -> int:
        return self._count(topic_name, "sub")

    def count_clients(self, service_name: str) -> int:
        return self._count(service_name, "cli")

    def count_services(self, service_name: str) -> int:
        return self._count(service_name, "srv")
