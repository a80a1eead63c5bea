"""rclpy.service.Service: a server the grader routes calls to; requests wait for an executor to take them.

The grader hands each request to the node in a BATCH (SERVE registered it); an executor spinning the node takes the
oldest request when it gets to the service, runs the callback with ``(request, srv_type.Response())`` and sends what
it returned (RESPOND), as rclpy's executor does with ``send_response``.
"""
from __future__ import annotations

from collections import deque

import rosgrade_channel as ch

from . import _graph, _runtime
from ._rclpy_pybind11 import DESTROYED, InvalidHandle


class Service:
    def __init__(self, node, srv_type, srv_name: str, callback, callback_group, qos_profile) -> None:
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.callback = callback
        self.callback_group = callback_group
        self.qos_profile = qos_profile
        self._node = node
        self._requests: deque[tuple[int, bytes]] = deque()
        self._destroyed = False
        self._handle = next(_graph._handle_ids)
        name, type_hash = _graph.type_of(srv_type)
        _runtime.scheduler().add_sink(self._handle, self._push, sources=True)
        _runtime.link().send_json(ch.SERVE, {"id": self._handle, "service": srv_name, "type": name,
                                             "md5sum": type_hash})

    def _push(self, data: bytes, source) -> None:
        self._requests.append((source[0], data))

    def has_request(self) -> bool:
        return bool(self._requests)

    def take_request(self):
        """(request, header) of the oldest request; the header is its number, which send_response needs."""
        import rosgrade_rosidl
        seq, data = self._requests.popleft()
        return rosgrade_rosidl.deserialize(self.srv_type.Request, data), seq

    @property
    def service_name(self) -> str:
        return self.srv_name

    @property
    def handle(self):
        if self._destroyed:
            raise InvalidHandle(DESTROYED)
        return self

    def send_response(self, response, header) -> None:
        """Answer the request ``header`` names; a TypeError for anything but this service's Response, as rclpy."""
        import rosgrade_rosidl
        if not isinstance(response, self.srv_type.Response):
            raise TypeError()
        self.handle
        _runtime.charge()
        _runtime.link().send(ch.encode_header_bytes(ch.RESPOND, {"id": self._handle, "seq": header, "status": "ok",
                                                                 "error": ""}, rosgrade_rosidl.serialize(response)))

    def destroy(self) -> None:
        """Stop serving (UNREGISTER): later calls find no server."""
        if not self._destroyed:
            self._destroyed = True
            self._requests.clear()
            _runtime.scheduler().remove_sink(self._handle)
            _runtime.link().send_json(ch.UNREGISTER, {"id": self._handle})

