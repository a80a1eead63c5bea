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

import rosgrade_channel as ch
from rosgrade_node import runtime

from . import _runtime

_handle_ids = itertools.count(1)
_init_sent = False
# Open endpoints: handle -> (kind "pub"/"sub", topic, type name), for the graph queries.
endpoints: dict[int, tuple[str, str, str]] = {}


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


def register(kind: str, topic: str, msg_type, depth: int | None, latch: bool) -> int:
    """ADVERTISE ("pub") or SUBSCRIBE ("sub"); returns the handle."""
    name, type_hash = type_of(msg_type)
    handle = next(_handle_ids)
    _runtime.link().send_json(ch.ADVERTISE if kind == "pub" else ch.SUBSCRIBE, {
        "id": handle, "topic": topic, "type": name, "md5sum": type_hash,
        "queue_size": depth if depth is not None else 0, "latch": latch})
    endpoints[handle] = (kind, topic, name)
    return handle


def unregister(handle: int) -> None:
    if endpoints.pop(handle, None) is not None and runtime.link is not None:
        runtime.link.send_json(ch.UNREGISTER, {"id": handle})
        if runtime.scheduler is not None:
            runtime.scheduler.remove_sink(handle)


def connections(handle: int) -> int:
    return runtime.scheduler.connections.get(handle, 0) if runtime.scheduler is not None else 0
