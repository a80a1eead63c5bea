"""The default incompatible-QoS event handler rclpy gives every publisher and subscription: a waitable of the node
that logs one warning per incompatible peer discovered (the grader names them in BATCH ``qos``; a subscription to the
robot's topics finds its own when the first message it cannot take arrives)."""
from __future__ import annotations

import rosgrade_qos

from . import _runtime
from .waitable import Waitable

_TEXTS = {"pub": rosgrade_qos.PUBLISHER_WARNING, "sub": rosgrade_qos.SUBSCRIPTION_WARNING}


class IncompatibleQoSHandler(Waitable):
    """Added to the node by its publisher or subscription; ready while a warning is due."""

    def __init__(self, node, kind: str, topic: str, callback_group) -> None:
        super().__init__(callback_group)
        self._node, self._text, self._topic = node, _TEXTS[kind], topic
        self.handle: int | None = None  # the endpoint's, once registered
        self._due: list[str] = []  # policies found by the endpoint itself

    def due(self, policy: str) -> None:
        self._due.append(policy)

    def is_ready(self, wait_set) -> bool:
        return bool(self._due) or bool(_runtime.scheduler().qos_events.get(self.handle))

    def take_data(self) -> list[str]:
        taken, self._due = self._due + _runtime.scheduler().qos_events.pop(self.handle, []), []
        return taken

    async def execute(self, taken_data: list[str]) -> None:
        for policy in taken_data:
            self._node.get_logger().warning(self._text.format(topic=self._topic, policy=policy))
