"""rclpy.client.Client: calls routed by the grader to the service's server (a node's or the world's), in sim time.

A CALL goes to the grader; the response comes back in a later BATCH on the client's handle and the request's Future
completes when an executor spinning the node takes it (as a real response arrives through the wait set). A call
nobody answers (no such service, another srv type) never completes its Future, as with a ROS 2 server that never
matches. ``wait_for_service`` polls every 0.25 s of sim time, as rclpy does.
"""
from __future__ import annotations

import threading
import time
from collections import deque

import rosgrade_channel as ch

from . import _graph, _runtime
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
        self._handle = next(_graph._handle_ids)
        _runtime.scheduler().add_sink(self._handle, self._push, sources=True)

    def _push(self, data: bytes, source) -> None:
        """An answer: a response is kept for an executor to take; a failure never completes the Future."""
        seq, status, _ = source
        if status == ch.SERVICE_OK and not self._destroyed:
            import rosgrade_rosidl
            self._responses.append((seq, rosgrade_rosidl.deserialize(self.srv_type.Response, data)))

    def _check(self) -> None:
        if self._destroyed:
            raise InvalidHandle(DESTROYED)

    def _check_thread(self) -> None:
        if not _runtime.scheduler().holds_token():
            raise RuntimeError(f"rosgrade: service [{self.srv_name}] was called from a thread rosgrade does not manage")

    def call_async(self, request) -> Future:
        """Send ``request``; the Future completes when an executor spinning the node takes the response."""
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        self._check()
        future = Future()
        self._pending[self._sequence + 1] = future
        future.add_done_callback(self.remove_pending_request)
        self.send_request(request)
        return future

    def send_request(self, request) -> int:
        """Send ``request`` (CALL); returns its sequence number, which its response comes back with (an action
        client's requests, whose futures are its own)."""
        import rosgrade_rosidl
        self._check_thread()
        self._sequence += 1
        _runtime.charge()
        name, type_hash = _graph.type_of(self.srv_type)
        _runtime.link().send(ch.encode_header_bytes(ch.CALL, {
            "service": self.srv_name, "type": name, "md5sum": type_hash, "probe": False, "id": self._handle,
            "seq": self._sequence}, rosgrade_rosidl.serialize(request)))
        return self._sequence

    def call(self, request, timeout_sec: float | None = None):
        """Send ``request`` and wait for the response; another thread must spin the node meanwhile. None when
        ``timeout_sec`` passes first (Jazzy's rclpy; Kilted's raises TimeoutError)."""
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        event = threading.Event()
        future = self.call_async(request)
        future.add_done_callback(lambda _: event.set())
        if not future.done():
            if not event.wait(timeout_sec):
                self.remove_pending_request(future)
        exception = future.exception()
        if exception is not None:
            raise exception
        return future.result()

    def has_response(self) -> bool:
        return bool(self._responses)

    def take_sequenced_response(self):
        """(sequence number, response) of the oldest kept response."""
        return self._responses.popleft()

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
        """Whether anything serves this service now (a probe CALL, answered at once)."""
        self._check()
        self._check_thread()
        _runtime.charge()
        reply, _ = _runtime.link().call({"service": self.srv_name, "type": "*", "md5sum": "*", "probe": True,
                                         "id": 0, "seq": 0}, b"")
        return reply.get("status") == ch.SERVICE_OK

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
        if not self._destroyed:
            _runtime.scheduler().remove_sink(self._handle)
        self._destroyed = True
        self._responses.clear()

