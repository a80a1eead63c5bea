"""The rest of rospy's graph API: published topics, cached parameters, remap_name and SubscribeListener.

rosgrade has no master: the topics published are what the world declared at START (plus /clock and /rosout, which
Gazebo and every node publish), this node's own publishers and the run's other nodes' (the grader's graph view, which
knows a registration at once, as the master does).
"""
from __future__ import annotations

from rosgrade_node import runtime
from rosgrade_node.graph_view import other_nodes

from . import names, params, topics

_ALWAYS = (("/clock", "rosgraph_msgs/Clock"), ("/rosout", "rosgraph_msgs/Log"), ("/rosout_agg", "rosgraph_msgs/Log"))


def get_published_topics(namespace="/"):
    """[[topic, type], ...] of every topic published in the graph under ``namespace``."""
    found = {topic: type_name for topic, type_name in _ALWAYS}
    found.update((topic, type_name) for topic, type_name in runtime.world_topics)
    found.update((reg.resolved_name, reg.data_class._type) for reg in list(topics._open.values())
                 if reg.reg_type == "pub")
    found.update((topic, type_name) for node in other_nodes() for topic, type_name in node["pub"])
    prefix = namespace if namespace.endswith("/") else namespace + "/"
    return [[topic, type_name] for topic, type_name in sorted(found.items())
            if namespace == "/" or topic.startswith(prefix) or topic == namespace]


def get_param_cached(param_name, default=params._unspecified):
    """get_param: rosgrade's parameter server is in the node's own process, so every read is already local."""
    return params.get_param(param_name, default)


def remap_name(name, caller_id=None, resolved=True):
    """``name`` remapped by a command-line ``from:=to`` argument (resolved against the caller), else unchanged."""
    if not caller_id:
        caller_id = names.get_caller_id()
    mappings = names.get_mappings()
    if name in mappings:
        return names.resolve_in(mappings[name], caller_id)
    return name


class SubscribeListener:
    """Callbacks a Publisher calls when a subscriber connects or disconnects (subclass and override)."""

    def peer_subscribe(self, topic_name, topic_publish, peer_publish) -> None:
        """A subscriber connected to ``topic_name``."""

    def peer_unsubscribe(self, topic_name, num_peers) -> None:
        """A subscriber left ``topic_name``; ``num_peers`` remain."""
