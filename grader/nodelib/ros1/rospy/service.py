"""rospy services over the grader channel: ServiceProxy calls, ``wait_for_service`` probes and ``rospy.Service``.

The grader routes a CALL to the service's server (the world's, such as turtlesim's ``/spawn``, or a node's
``rospy.Service``) and the answer comes back in a later BATCH, in sim time: the world answers at once, a node once
its handler has run. The calling thread waits meanwhile, as rospy's does on its socket. Failures raise
ServiceException with real rospy's words. A ``rospy.Service`` handles each request in a thread of its own (rospy
runs one per connection) and answers what the handler returned, or the error rospy sends for it.
"""
from __future__ import annotations

import io
import itertools
import sys
import traceback

import genpy
import rosgrade_channel as ch
from rosgrade_node import runtime

from . import core, names, rostime, topics
from .exceptions import ROSException, ROSInterruptException
from .msg import args_kwds_to_message

# rospy's wait_for_service sleeps this long between two looks at the master.
_PROBE_PERIOD_NS = 300_000_000
# The node's services by resolved name (rospy's ServiceManager refuses a name twice).
_services: dict[str, Service] = {}


class ServiceException(Exception):
    """Exception class for service-related errors (not a ROSException, as in rospy)."""


def _check_thread(resolved: str) -> None:
    if not runtime.scheduler.holds_token():
        raise ServiceException("rosgrade: service [%s] was called from a thread rosgrade does not manage" % resolved)


def _failure(resolved: str, status: str, error: str) -> ServiceException:
    """The ServiceException rospy raises for a call that did not succeed."""
    if status == ch.SERVICE_UNAVAILABLE:
        return ServiceException("service [%s] unavailable" % resolved)
    if status == ch.SERVICE_REFUSED:
        return ServiceException("unable to connect to service: remote error reported: %s" % error)
    if status == ch.SERVICE_LOST:
        return ServiceException("transport error completing service call: unable to receive data from sender, check "
                                "sender's logs for details")
    # rospy reads the server's error text as bytes and formats them with %s (b'' for a roscpp handler's false)
    return ServiceException("service [%s] responded with an error: %s" % (resolved, error.encode()))


def _served(resolved: str) -> bool:
    """Whether anything serves ``resolved`` now (rospy's probe connection, md5sum '*'), charged as a library call."""
    _check_thread(resolved)
    rostime.charge()
    reply, _ = runtime.link.call({"service": resolved, "type": "*", "md5sum": "*", "probe": True, "id": 0, "seq": 0},
                                 b"")
    return reply.get("status") == ch.SERVICE_OK


def wait_for_service(service: str, timeout=None) -> None:
    """Block until something serves ``service``, looking every 0.3 s of sim time as rospy does.

    ``timeout`` (seconds or Duration; 0 is a ValueError): ROSException once it has passed; ROSInterruptException when
    the node shuts down first.
    """
    if timeout is not None and isinstance(timeout, genpy.Duration):
        timeout = timeout.to_sec()
    if timeout == 0.0:
        raise ValueError("timeout must be non-zero")
    resolved = names.resolve_name(service)
    sched = runtime.scheduler
    deadline = sched.world_ns + round(timeout * 1e9) if timeout else None
    while not core._shutdown_flag and (deadline is None or sched.world_ns < deadline):
        if _served(resolved):
            return
        wake = sched.world_ns + _PROBE_PERIOD_NS
        while sched.world_ns < wake and not core._shutdown_flag:
            sched.block(deadline_ns=wake, ready=lambda: core._shutdown_flag)
    if core._shutdown_flag:
        raise ROSInterruptException("rospy shutdown")
    raise ROSException("timeout exceeded while waiting for service %s" % resolved)


class ServiceProxy:
    """A client of one service: ``proxy(request)``, ``proxy(*fields)`` or ``proxy(**fields)`` return the response.

    ``persistent`` and ``headers`` are accepted; every call is answered the same way (there is no connection to keep).
    """

    def __init__(self, name: str, service_class, persistent: bool = False, headers=None) -> None:
        self.resolved_name = names.resolve_name(name)
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.persistent = persistent
        self.headers = headers
        # The answers come in BATCH deliveries on this handle, by call number.
        self._handle = next(topics._handle_ids)
        self._calls = itertools.count(1)
        self._answers: dict[int, tuple[str, str, bytes]] = {}
        runtime.scheduler.add_sink(self._handle, self._push, sources=True)

    def _push(self, data: bytes, source) -> None:
        seq, status, error = source
        self._answers[seq] = (status, error, data)

    def wait_for_service(self, timeout=None) -> None:
        wait_for_service(self.resolved_name, timeout=timeout)

    def __call__(self, *args, **kwds):
        return self.call(*args, **kwds)

    def call(self, *args, **kwds):
        """Call the service; ServiceException when it is unavailable, refuses this srv type or fails."""
        request = args_kwds_to_message(self.request_class, args, kwds)
        if not isinstance(request, genpy.Message):
            raise TypeError("request object is not a valid request message instance")
        if self.request_class._type != request._type:
            raise TypeError("request object type [%s] does not match service type [%s]"
                            % (request.__class__, self.request_class))
        buff = io.BytesIO()
        request.serialize(buff)  # genpy's SerializationError goes to the caller, as in rospy
        _check_thread(self.resolved_name)
        rostime.charge()
        seq = next(self._calls)
        runtime.link.send(ch.encode_header_bytes(ch.CALL, {
            "service": self.resolved_name, "type": self.service_class._type, "md5sum": self.service_class._md5sum,
            "probe": False, "id": self._handle, "seq": seq}, buff.getvalue()))
        sched = runtime.scheduler
        while seq not in self._answers and not core._shutdown_flag:
            sched.block(ready=lambda: seq in self._answers or core._shutdown_flag)
        if seq not in self._answers:
            raise ROSInterruptException("node shutdown interrupted service call")
        status, error, data = self._answers.pop(seq)
        if status != ch.SERVICE_OK:
            raise _failure(self.resolved_name, status, error)
        return self.response_class().deserialize(data)

    def close(self) -> None:
        """Nothing to close: no connection is kept."""


class Service:
    """A service of this node: the grader routes each call to it; ``handler(request)`` runs in a thread of its own
    and its return value is converted to the response as rospy converts it."""

    def __init__(self, name: str, service_class, handler, buff_size: int = 65536, error_handler=None) -> None:
        self.resolved_name = names.resolve_name(name)
        if self.resolved_name in _services:
            raise ServiceException("service [%s] already registered" % self.resolved_name)
        _services[self.resolved_name] = self
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.handler = handler
        self.error_handler = error_handler or self._default_error_handler
        self.done = False
        self._handle = next(topics._handle_ids)
        runtime.scheduler.add_sink(self._handle, self._push, sources=True)
        runtime.link.send_json(ch.SERVE, {"id": self._handle, "service": self.resolved_name,
                                          "type": service_class._type, "md5sum": service_class._md5sum})

    def _push(self, data: bytes, source):
        """A request: rospy handles each connection in a thread of its own."""
        seq = source[0]
        return runtime.scheduler.spawn("Thread-%d" % seq, lambda: self._handle_request(seq, data))

    def _handle_request(self, seq: int, data: bytes) -> None:
        """Run the handler and RESPOND, as rospy's ServiceImpl._handle_request answers."""
        status, error, response = ch.SERVICE_OK, "", b""
        try:
            request = self.request_class().deserialize(data)
            answer = convert_return_to_response(self.handler(request), self.response_class)
            buff = io.BytesIO()
            answer.serialize(buff)
            response = buff.getvalue()
        except ServiceException as e:
            status, error = ch.SERVICE_FAILED, "service cannot process request: %s" % e
        except Exception as e:  # noqa: BLE001 - rospy sends any handler error to the caller
            exc_type, exc_value, tb = sys.exc_info()
            self.error_handler(e, exc_type, exc_value, tb)
            status, error = ch.SERVICE_FAILED, "error processing request: %s" % e
        if self.done:
            return
        runtime.link.send(ch.encode_header_bytes(ch.RESPOND, {"id": self._handle, "seq": seq, "status": status,
                                                              "error": error[:ch.MAX_MESSAGE_CHARS]}, response))

    @staticmethod
    def _default_error_handler(e, exc_type, exc_value, tb) -> None:
        core.logerr("Error processing request: %s\n%s" % (e, traceback.format_exception(exc_type, exc_value, tb)))

    def shutdown(self, reason: str = "") -> None:
        """Stop serving (UNREGISTER): later calls find no server."""
        if not self.done:
            self.done = True
            _services.pop(self.resolved_name, None)
            runtime.scheduler.remove_sink(self._handle)
            runtime.link.send_json(ch.UNREGISTER, {"id": self._handle})

    def spin(self) -> None:
        from .client import spin
        spin()


def convert_return_to_response(response, response_class):
    """A handler's return value as the response: rospy's rules (a response, a dict of fields, one value, a tuple)."""
    if isinstance(response, genpy.Message) and response._type == response_class._type:
        return response
    if type(response) == dict:  # noqa: E721 - rospy's own test
        try:
            return response_class(**response)
        except AttributeError as e:
            raise ServiceException("handler returned invalid value: %s" % str(e)) from None
    if response is None:
        raise ServiceException("service handler returned None")
    if type(response) not in [list, tuple]:
        try:
            return response_class(response)
        except TypeError as e:
            raise ServiceException("handler returned invalid value: %s" % str(e)) from None
    try:
        return response_class(*response)
    except TypeError as e:
        raise ServiceException("handler returned wrong number of values: %s" % str(e)) from None
