"""rclpy.client.Client: calls to the world's services through the grader's CALL/REPLY, in lockstep.

The grader answers a CALL at once; the response is kept and the request's Future completes when an executor
spinning the node takes it (as a real response arrives through the wait set). A call nobody answers (no such
service, another srv type, a failing handler) never completes its Future, as with a ROS 2 server that never
responds. ``wait_for_service`` polls every 0.25 s of sim time, as rclpy does.
"""
from __future__ import annotations

import threading
import time
from collections import deque

import rosgrade_channel as ch

from . import _runtime
from ._rclpy_pybind11 import DESTROYED, InvalidHandle
from .task import Future


class Client:
    def __init__(self, node, srv_type, srv_name: str, qos_profile, callback_group) -> None:
        self._node = node
        self.context = node.context
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.qos_profile = qos_profile
        self.callback_group = callback_group
        self._pending: dict[int, Future] = {}
        self._responses: deque[tuple[int, object]] = deque()
        self._sequence = 0
        self._destroyed = False

    def _check(self) -> None:
        if self._destroyed:
            raise InvalidHandle(DESTROYED)

    def _exchange(self, request_bytes: bytes, probe: bool) -> tuple[str, bytes]:
        from . import _graph
        sched = _runtime.scheduler()
        if not sched.holds_token():
            raise RuntimeError(f"rosgrade: service [{self.srv_name}] was called from a thread rosgrade does not manage")
        _runtime.charge()
        if probe:
            name, type_hash = "*", "*"
        else:
            name, type_hash = _graph.type_of(self.srv_type)
        reply, response = _runtime.link().call(
            {"service": self.srv_name, "type": name, "md5sum": type_hash, "probe": probe}, request_bytes)
        return str(reply.get("status")), response

    def call_async(self, request) -> Future:
        """Send ``request``; the Future completes when an executor spinning the node takes the response."""
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        self._check()
        import rosgrade_rosidl
        self._sequence += 1
        future = Future()
        self._pending[self._sequence] = future
        future.add_done_callback(self.remove_pending_request)
        status, data = self._exchange(rosgrade_rosidl.serialize(request), probe=False)
        if status == ch.SERVICE_OK:
            self._responses.append((self._sequence, rosgrade_rosidl.deserialize(self.srv_type.Response, data)))
        return future

    def call(self, request, timeout_sec: float | None = None):
        """Send ``request`` and wait for the response; another thread must spin the node meanwhile."""
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        event = threading.Event()
        future = self.call_async(request)
        future.add_done_callback(lambda _: event.set())
        if not future.done():
            if not event.wait(timeout_sec):
                self.remove_pending_request(future)
                raise TimeoutError()
        exception = future.exception()
        if exception is not None:
            raise exception
        return future.result()

    def has_response(self) -> bool:
        return bool(self._responses)

    def take_response(self):
        """(future, response) of the oldest kept response, or None when its request was given up."""
        sequence, response = self._responses.popleft()
        future = self._pending.get(sequence)
        return None if future is None else (future, response)

    def get_pending_request(self, sequence_number: int) -> Future:
        return self._pending[sequence_number]

    def remove_pending_request(self, future: Future) -> None:
        for seq, pending in list(self._pending.items()):
            if pending is future:
                del self._pending[seq]
                break

    def service_is_ready(self) -> bool:
        """Whether the world serves this service now (a probe CALL)."""
        self._check()
        status, _ = self._exchange(b"", probe=True)
        return status == ch.SERVICE_OK

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        sleep_time = 0.25
        if timeout_sec is None:
            timeout_sec = float("inf")
        while self.context.ok() and not self.service_is_ready() and timeout_sec > 0.0:
            time.sleep(sleep_time)
            timeout_sec -= sleep_time
        return self.service_is_ready()

    @property
    def service_name(self) -> str:
        return self.srv_name

    @property
    def handle(self):
        return self

    def destroy(self) -> None:
        self._destroyed = True
        self._responses.clear()

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *exc) -> None:
        self.destroy()
