"""rclpy.publisher.Publisher: type-checked publishing as PUBLISH frames of CDR bytes."""
from __future__ import annotations

import rosgrade_channel as ch

from . import _graph, _runtime
from ._qos_events import IncompatibleQoSHandler
from ._rclpy_pybind11 import DESTROYED, PUBLISHER_CONTEXT_INVALID, InvalidHandle, RCLError
from .duration import Duration
from .qos import DurabilityPolicy, offered_policies, wire_policies


class Publisher:
    """Publishes on one topic. Created by Node.create_publisher."""

    def __init__(self, node, msg_type, topic: str, qos_profile, callback_group) -> None:
        self._node = node
        self.msg_type = msg_type
        self.topic = topic
        self.qos_profile = qos_profile
        self.callback_group = callback_group
        self._events = IncompatibleQoSHandler(node, "pub", topic, callback_group)
        self.event_handlers: list = [self._events]
        self._handle: int | None = _graph.register(
            "pub", topic, msg_type, qos_profile.keeps(),
            qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL, node.context,
            wire_policies(offered_policies(qos_profile)))
        self._events.handle = self._handle
        node.add_waitable(self._events)

    def _check_handle(self) -> int:
        if self._handle is None:
            raise InvalidHandle(DESTROYED)
        return self._handle

    def publish(self, msg) -> None:
        """Send a message; TypeError for another type, RCLError once the context has been shut down."""
        handle = self._check_handle()
        if not isinstance(msg, (self.msg_type, bytes)):
            raise TypeError("Expected {}, got {}".format(self.msg_type, type(msg)))
        if not self._node.context.ok():
            raise RCLError("Failed to publish: " + PUBLISHER_CONTEXT_INVALID)
        if isinstance(msg, bytes):
            data = msg
        else:
            import rosgrade_rosidl
            data = rosgrade_rosidl.serialize(msg)
        _runtime.charge()
        _runtime.link().send_message(ch.PUBLISH, handle, data)

    def get_subscription_count(self) -> int:
        """Subscriptions matched so far (0 before discovery has matched any)."""
        _runtime.charge()
        return _graph.connections(self._check_handle())

    @property
    def topic_name(self) -> str:
        self._check_handle()
        return self.topic

    @property
    def handle(self):
        return self

    def assert_liveliness(self) -> None:
        self._check_handle()

    def wait_for_all_acked(self, timeout: Duration = Duration(seconds=-1)) -> bool:
        self._check_handle()
        return True

    def destroy(self) -> None:
        if self._handle is not None:
            _graph.unregister(self._handle)
            self._handle = None
            self._node.remove_waitable(self._events)

