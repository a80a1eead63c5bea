"""rclpy.waitable: the base of entities an executor waits on as one (action servers and clients)."""
from __future__ import annotations


class NumberOfEntities:
    __slots__ = ["num_subscriptions", "num_guard_conditions", "num_timers", "num_clients", "num_services",
                 "num_events"]

    def __init__(self, num_subs: int = 0, num_gcs: int = 0, num_timers: int = 0, num_clients: int = 0,
                 num_services: int = 0, num_events: int = 0) -> None:
        self.num_subscriptions = num_subs
        self.num_guard_conditions = num_gcs
        self.num_timers = num_timers
        self.num_clients = num_clients
        self.num_services = num_services
        self.num_events = num_events

    def __add__(self, other: NumberOfEntities) -> NumberOfEntities:
        result = NumberOfEntities()
        for attr in self.__slots__:
            setattr(result, attr, getattr(self, attr) + getattr(other, attr))
        return result


class Waitable:
    """Entities an executor takes together: ``is_ready`` says whether any has data, ``take_data`` takes it in the
    spinning thread and the coroutine ``execute`` runs the callbacks (rosgrade's executor passes no wait set)."""

    def __init__(self, callback_group) -> None:
        self.callback_group = callback_group
        self.callback_group.add_entity(self)
        self._futures: list = []

    def __enter__(self) -> None:
        pass

    def __exit__(self, *exc) -> None:
        pass

    def add_future(self, future) -> None:
        self._futures.append(future)

    def remove_future(self, future) -> None:
        self._futures.remove(future)

    def is_ready(self, wait_set) -> bool:
        raise NotImplementedError("Must be implemented by subclass")

    def take_data(self):
        raise NotImplementedError("Must be implemented by subclass")

    async def execute(self, taken_data) -> None:
        raise NotImplementedError("Must be implemented by subclass")

    def get_num_entities(self) -> NumberOfEntities:
        raise NotImplementedError("Must be implemented by subclass")

    def add_to_wait_set(self, wait_set) -> None:
        raise NotImplementedError("Must be implemented by subclass")
