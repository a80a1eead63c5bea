"""rospy services as a client of the world's: calls and ``wait_for_service`` probes go to the grader in lockstep.

The grader answers a CALL at once, at the node's current sim time, from the services the world serves (turtlesim's
``/spawn``, ``/clear``, ...), so a call costs one library-call quantum of sim time and its outcome depends only on the
run. Failures raise ServiceException with real rospy's words. A node's own ``rospy.Service`` is accepted but nobody
can call it: the grader routes calls to the world only.
"""
from __future__ import annotations

import io

import genpy
import rosgrade_channel as ch
from rosgrade_node import runtime

from . import core, names, rostime
from .exceptions import ROSException, ROSInterruptException
from .msg import args_kwds_to_message

# rospy's wait_for_service sleeps this long between two looks at the master.
_PROBE_PERIOD_NS = 300_000_000


class ServiceException(Exception):
    """Exception class for service-related errors (not a ROSException, as in rospy)."""


def _exchange(resolved: str, srv_type: str, md5sum: str, request: bytes, probe: bool) -> tuple[str, str, bytes]:
    """One CALL to the grader, charged as a library call: (status, the server's error text, response bytes)."""
    sched = runtime.scheduler
    if not sched.holds_token():
        raise ServiceException("rosgrade: service [%s] was called from a thread rosgrade does not manage" % resolved)
    rostime.charge()
    reply, response = runtime.link.call(
        {"service": resolved, "type": srv_type, "md5sum": md5sum, "probe": probe}, request)
    return str(reply.get("status")), str(reply.get("error") or ""), response


def _failure(resolved: str, status: str, error: str) -> ServiceException:
    """The ServiceException rospy raises for a call that did not succeed."""
    if status == ch.SERVICE_UNAVAILABLE:
        return ServiceException("service [%s] unavailable" % resolved)
    if status == ch.SERVICE_REFUSED:
        return ServiceException("unable to connect to service: remote error reported: %s" % error)
    # rospy reads the server's error text as bytes and formats them with %s (b'' for a roscpp handler's false)
    return ServiceException("service [%s] responded with an error: %s" % (resolved, error.encode()))


def _served(resolved: str) -> bool:
    """Whether the world serves ``resolved`` now (rospy's probe connection, md5sum '*')."""
    status, _, _ = _exchange(resolved, "*", "*", b"", probe=True)
    return status == ch.SERVICE_OK


def wait_for_service(service: str, timeout=None) -> None:
    """Block until the world serves ``service``, looking every 0.3 s of sim time as rospy does.

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
        status, error, data = _exchange(self.resolved_name, self.service_class._type, self.service_class._md5sum,
                                        buff.getvalue(), probe=False)
        if status != ch.SERVICE_OK:
            raise _failure(self.resolved_name, status, error)
        return self.response_class().deserialize(data)

    def close(self) -> None:
        """Nothing to close: no connection is kept."""


class Service:
    """A service nobody can call (the grader routes calls to the world only); kept so that nodes offering one run."""

    def __init__(self, name: str, service_class, handler, buff_size: int = 65536, error_handler=None) -> None:
        self.resolved_name = names.resolve_name(name)
        self.service_class = service_class
        self.handler = handler

    def shutdown(self, reason: str = "") -> None:
        """Nothing to unregister."""

    def spin(self) -> None:
        from .client import spin
        spin()
