"""The node process's registrations with the grader: INIT once, ADVERTISE/SUBSCRIBE/UNREGISTER per endpoint.

Matching (discovery) is the grader's, as for rospy: a publisher reaches the subscriptions that exist
``CONNECT_DELAY_NS`` after it registered, a later subscription at once, the world's topics from the start; what a
publisher sends before it has matched is lost (the grader records it under ``/rosgrade/lost/``), which is real ROS 2's
"messages published before discovery are dropped" made deterministic. ``get_subscription_count()`` is the grader's
connection count for the handle (``BATCH.connections``), 0 until it has matched. A TRANSIENT_LOCAL publisher
registers with ``latch: true``: the grader hands its last message to each subscription when it matches.
"""
from __future__ import annotations

import itertools
import sys

import rosgrade_channel as ch
from rosgrade_node import runtime

from . import _runtime
from ._rclpy_pybind11 import RCLError

# The publishers rclpy makes for every node (its /rosout one unless enable_rosout=False).
NODE_PUBLISHERS = (("/parameter_events", "rcl_interfaces/msg/ParameterEvent"), ("/rosout", "rcl_interfaces/msg/Log"))
_handle_ids = itertools.count(1)
_init_sent = False
# Open endpoints: handle -> (kind "pub"/"sub", topic, type name), for the graph queries.
endpoints: dict[int, tuple[str, str, str]] = {}
# Open endpoints: handle -> the context (one DDS participant each) it was created in.
_contexts: dict[int, object] = {}
# rmw_fastrtps' refusal of a second type on a topic name within one participant, as Jazzy's rclpy raises it. For a
# subscription, rcl then overwrites the error with "invalid allocator" while cleaning up (rcutils says so on stderr,
# and the leftover error is printed once more), and that is the RCLError's text.
_INCOMPATIBLE = {
    "pub": "Failed to create publisher: create_publisher() called for existing topic name {topic} with incompatible "
           "type {type}, at /project/src/publisher.cpp:145, at /project/src/rcl/publisher.c:117",
    "sub": "create_subscription() called for existing topic name {topic} with incompatible type {type}, at "
           "/project/src/subscription.cpp:517, at /project/src/rcl/subscription.c:112",
}
_INVALID_ALLOCATOR = "invalid allocator, at /project/src/rcl/subscription.c:261"
_ERROR_OVERWRITTEN = ("\n>>> [rcutils|error_handling.c:108] rcutils_set_error_state()\nThis error state is being "
                      "overwritten:\n\n  '{old}'\n\nwith this new error message:\n\n  '{new}'\n\nrcutils_reset_error() "
                      "should be called after error handling to avoid this.\n<<<\n{new}\n")


def type_of(msg_type) -> tuple[str, str]:
    """(type name, RIHS01 hash) of a message or service class."""
    import rosgrade_rosidl
    return rosgrade_rosidl.type_name(msg_type), rosgrade_rosidl.type_hash(msg_type)


def send_init(fq_name: str, log_level: int, disable_signals: bool) -> None:
    """INIT for the process's first node (the grader knows one name per process)."""
    global _init_sent
    if _init_sent:
        return
    _init_sent = True
    sched = _runtime.scheduler()
    _runtime.link().send_json(ch.INIT, {"name": fq_name[:ch.MAX_NAME_CHARS], "anonymous": False,
                                        "log_level": log_level, "disable_signals": disable_signals})
    sched.node_initialized = True


def dds_type_name(type_name: str) -> str:
    """'geometry_msgs/msg/Twist' -> 'geometry_msgs::msg::dds_::Twist_' (the DDS type rmw registers)."""
    *scope, name = type_name.split("/")
    return "::".join([*scope, "dds_", name + "_"])


def check_topic_type(kind: str, topic: str, msg_type, context, builtin: list[tuple[str, str]]) -> None:
    """RCLError when ``topic`` already carries another type in ``context``: an open endpoint of it, or one of the
    endpoints its nodes make themselves (``builtin``: /rosout, /parameter_events, /clock under sim time)."""
    name, _ = type_of(msg_type)
    types = [t for h, (_, tp, t) in endpoints.items() if tp == topic and _contexts.get(h) is context]
    types += [t for tp, t in builtin if tp == topic]
    if any(t != name for t in types):
        error = _INCOMPATIBLE[kind].format(topic="rt" + topic, type=dds_type_name(name))
        if kind == "sub":
            sys.stderr.write(_ERROR_OVERWRITTEN.format(old=error, new=_INVALID_ALLOCATOR))
            error = "Failed to create subscription: " + _INVALID_ALLOCATOR
        raise RCLError(error)


def register(kind: str, topic: str, msg_type, depth: int | None, latch: bool, context,
             qos: tuple[str, str]) -> int:
    """ADVERTISE ("pub") or SUBSCRIBE ("sub") in ``context`` with the resolved (reliability, durability) it offers
    or requests (the grader routes by them); returns the handle."""
    name, type_hash = type_of(msg_type)
    handle = next(_handle_ids)
    _contexts[handle] = context
    _runtime.link().send_json(ch.ADVERTISE if kind == "pub" else ch.SUBSCRIBE, {
        "id": handle, "topic": topic, "type": name, "md5sum": type_hash,
        "queue_size": depth if depth is not None else 0, "latch": latch, "qos": list(qos)})
    endpoints[handle] = (kind, topic, name)
    return handle


def unregister(handle: int) -> None:
    _contexts.pop(handle, None)
    if endpoints.pop(handle, None) is not None and runtime.link is not None:
        runtime.link.send_json(ch.UNREGISTER, {"id": handle})
        if runtime.scheduler is not None:
            runtime.scheduler.remove_sink(handle)


def connections(handle: int) -> int:
    return runtime.scheduler.connections.get(handle, 0) if runtime.scheduler is not None else 0


def interface_type(name: str, kind: str = "msg") -> str:
    """'nav_msgs/Odometry' -> 'nav_msgs/msg/Odometry' (``kind`` "srv" for services; the grader may name world types
    either way)."""
    pkg, sep, rest = name.partition("/")
    return name if not sep or "/" in rest else f"{pkg}/{kind}/{rest}"


def split_node_name(fq_name: str) -> tuple[str, str]:
    """'/ns/talker' -> ('talker', '/ns'); '/talker' -> ('talker', '/')."""
    namespace, _, name = fq_name.rpartition("/")
    return name, namespace or "/"


def others() -> list[dict]:
    """The run's other nodes this process has discovered (rosgrade_node.graph_view), types named as rclpy names them;
    a node of the run also has the publishers rclpy makes for every node (/parameter_events, /rosout)."""
    from rosgrade_node.graph_view import other_nodes
    found = []
    for node in other_nodes():
        builtin = list(NODE_PUBLISHERS) if node["kind"] == "node" else []
        found.append({"name": node["name"], "cli": [],
                      "pub": builtin + [(t, interface_type(n)) for t, n in node["pub"]],
                      "sub": [(t, interface_type(n)) for t, n in node["sub"]],
                      "srv": [(s, interface_type(n, "srv")) for s, n in node["srv"]]})
    return found


def names_and_types(pairs) -> list[tuple[str, list[str]]]:
    """[(name, [types])] sorted by name, as rcl gives them, from (name, type) pairs."""
    found: dict[str, set[str]] = {}
    for name, type_name in pairs:
        found.setdefault(name, set()).add(type_name)
    return [(name, sorted(types)) for name, types in sorted(found.items())]
