"""rclpy.subscription.Subscription: a reader whose deliveries (CDR bytes from BATCH frames) wait in a KEEP_LAST
queue of the QoS depth until an executor takes them."""
from __future__ import annotations

import inspect
from collections import deque

from . import _graph, _runtime
from ._rclpy_pybind11 import DESTROYED, InvalidHandle
from .qos import DurabilityPolicy


def _wants_info(callback) -> bool:
    """Whether the callback takes (msg, MessageInfo), as rclpy decides from its signature."""
    try:
        params = [p for p in inspect.signature(callback).parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    except (TypeError, ValueError):
        return False
    return len(params) == 2


class Subscription:
    """Created by Node.create_subscription."""

    def __init__(self, node, msg_type, topic: str, callback, callback_group, qos_profile, raw: bool) -> None:
        self._node = node
        self.msg_type = msg_type
        self.topic = topic
        self.callback = callback
        self.callback_group = callback_group
        self.qos_profile = qos_profile
        self.raw = raw
        self.event_handlers: list = []
        self._with_info = _wants_info(callback)
        self._keep = qos_profile.keeps()
        self._queue: deque[tuple[bytes, int]] = deque()
        self._handle: int | None = _graph.register(
            "sub", topic, msg_type, self._keep, qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL,
            node.context)
        _runtime.scheduler().add_sink(self._handle, self._push)

    def _push(self, data: bytes):
        """A delivery: keep the newest ``depth`` messages (KEEP_LAST drops the oldest)."""
        self._queue.append((data, _runtime.system_ns()))
        if self._keep is not None:
            while len(self._queue) > self._keep:
                self._queue.popleft()
        return None

    def has_message(self) -> bool:
        return bool(self._queue)

    def take(self):
        """(message or raw bytes, MessageInfo dict) of the oldest queued delivery, or None."""
        if not self._queue:
            return None
        data, received = self._queue.popleft()
        info = {"source_timestamp": received, "received_timestamp": received}
        if self.raw:
            return data, info
        import rosgrade_rosidl
        return rosgrade_rosidl.deserialize(self.msg_type, data), info

    def dispatch(self, msg, info) -> None:
        if self._with_info:
            self.callback(msg, info)
        else:
            self.callback(msg)

    def get_publisher_count(self) -> int:
        _runtime.charge()
        return _graph.connections(self._check_handle())

    def _check_handle(self) -> int:
        if self._handle is None:
            raise InvalidHandle(DESTROYED)
        return self._handle

    @property
    def topic_name(self) -> str:
        self._check_handle()
        return self.topic

    @property
    def handle(self):
        return self

    def destroy(self) -> None:
        if self._handle is not None:
            _graph.unregister(self._handle)
            self._handle = None
            self._queue.clear()

