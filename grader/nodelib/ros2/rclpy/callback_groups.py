"""rclpy.callback_groups: which callbacks may run at the same time (MultiThreadedExecutor)."""
from __future__ import annotations


class CallbackGroup:
    def __init__(self) -> None:
        self.entities: list = []

    def add_entity(self, entity) -> None:
        self.entities.append(entity)

    def has_entity(self, entity) -> bool:
        return entity in self.entities

    def can_execute(self, entity) -> bool:
        raise NotImplementedError()

    def beginning_execution(self, entity) -> bool:
        raise NotImplementedError()

    def ending_execution(self, entity) -> None:
        raise NotImplementedError()


class ReentrantCallbackGroup(CallbackGroup):
    """Any number of its callbacks may run at once."""

    def can_execute(self, entity) -> bool:
        return True

    def beginning_execution(self, entity) -> bool:
        return True

    def ending_execution(self, entity) -> None:
        pass


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """One of its callbacks at a time."""

    def __init__(self) -> None:
        super().__init__()
        self._active_entity = None

    def can_execute(self, entity) -> bool:
        return self._active_entity is None

    def beginning_execution(self, entity) -> bool:
        if self._active_entity is None:
            self._active_entity = entity
            return True
        return False

    def ending_execution(self, entity) -> None:
        self._active_entity = None
