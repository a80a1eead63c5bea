"""rclpy.guard_condition.GuardCondition: a flag an executor waits on."""
from __future__ import annotations

from ._rclpy_pybind11 import DESTROYED, InvalidHandle


class GuardCondition:
    def __init__(self, callback, callback_group, context=None) -> None:
        self.callback = callback
        self.callback_group = callback_group
        self._triggered = False
        self._destroyed = False

    def trigger(self) -> None:
        if self._destroyed:
            raise InvalidHandle(DESTROYED)
        self._triggered = True

    def destroy(self) -> None:
        self._destroyed = True
